// Fuzz target: the bytes of an image file (PNG, EXR or anything else) read
// as an exemplar (range check, gray, square, Gaussianized) and as a
// colormap. readImage takes a path, so each input is first written to a
// file in a folder of this process's own, which is also OpenCV's temporary
// folder (imdecode copies EXR bytes to a temporary file): a file OpenCV
// leaves there after an input is a finding too (no file left behind).
#include <stdlib.h>
#include <unistd.h>

#include <fstream>

#include "fuzz_target.h"

namespace {
namespace fs = std::filesystem;

struct ScratchFolder {
    stochtex::fuzz::TempFolder folder{"stochtex-fuzz-image"};
    const fs::path& dir = folder.path();
    const fs::path input = dir / "input";
    ScratchFolder() {
        setenv("OPENCV_TEMP_PATH", dir.c_str(), 1);  // before OpenCV's first temporary file
    }
    // Files other than the input: what OpenCV left behind. Removed, so that
    // one finding is reported once.
    std::vector<fs::path> leftovers() const {
        std::vector<fs::path> found;
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path() != input) found.push_back(e.path());
        for (const auto& p : found) fs::remove(p);
        return found;
    }
};

const ScratchFolder& scratch() {
    static const ScratchFolder folder;
    return folder;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace stochtex;
    const std::string path = scratch().input.string();
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    fuzz::run([&] {
        NoiseSpec noise;
        noise.source = NoiseSpec::Source::Image;
        noise.image = path;
        ColormapSpec colormap;
        colormap.source = ColormapSpec::Source::Image;
        colormap.image = path;
        try {
            (void)buildNoiseExample(noise, "fuzz");
        } catch (const InputError&) {  // not an exemplar; it may still be a colormap
        }
        (void)buildColormap(colormap);
    });
    const auto left = scratch().leftovers();
    if (!left.empty()) {
        std::fprintf(stderr, "fuzz: reading the image left %zu temporary file(s), e.g. %s\n", left.size(),
                     left.front().c_str());
        std::abort();
    }
    return 0;
}
