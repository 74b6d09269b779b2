// Fuzz target: the bytes of a mesh file read by the scene's loader
// (loadMesh): the first byte picks the extension (.obj, .gltf or .glb), the
// rest is the file. A glTF that names other files reads them only through
// loadMesh's bounded callbacks (regular files, no expansion), so an input
// naming /dev/zero or a missing buffer is a refusal, not a hang.

#include <fstream>

#include "fuzz_target.h"
#include "stochtex/gpu/mesh_file.h"

namespace {
namespace fs = std::filesystem;

// The inputs' folder, removed when the fuzzer exits.
const fs::path& scratch() {
    static const stochtex::fuzz::TempFolder dir("stochtex-fuzz-mesh");
    return dir.path();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace stochtex;
    if (size == 0) return 0;
    static const char* const kExtensions[] = {".obj", ".gltf", ".glb"};
    const fs::path path = scratch() / (std::string("input") + kExtensions[data[0] % 3]);
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    }
    fuzz::run([&] { (void)loadMesh(path.string()); });
    std::error_code ec;
    fs::remove(path, ec);
    return 0;
}
