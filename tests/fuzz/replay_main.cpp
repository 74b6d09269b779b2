// Replays stored inputs through a fuzz target without libFuzzer, for the
// normal (GCC) build: each argument is a file or a folder of files; each
// file is one LLVMFuzzerTestOneInput call, as libFuzzer would make it. A
// finding aborts (fuzz_target.h), so the exit code says which file failed
// by the last "replay:" line printed.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>
#include <algorithm>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace fs = std::filesystem;

namespace {
void replay(const fs::path& file) {
    std::printf("replay: %s\n", file.c_str());
    std::fflush(stdout);
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
}
}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s FILE_OR_FOLDER...\n", argv[0]);
        return 2;
    }
    int count = 0;
    for (int i = 1; i < argc; ++i) {
        const fs::path arg = argv[i];
        if (!fs::is_directory(arg)) {
            if (!fs::is_regular_file(arg)) {
                std::fprintf(stderr, "replay: %s: no such file or folder\n", argv[i]);
                return 2;
            }
            replay(arg);
            ++count;
            continue;
        }
        std::vector<fs::path> files;  // sorted, so runs are reproducible
        for (const auto& e : fs::recursive_directory_iterator(arg))
            if (e.is_regular_file()) files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (const auto& f : files) replay(f);
        count += int(files.size());
    }
    std::printf("replay: %d inputs, no finding\n", count);
    return 0;
}
