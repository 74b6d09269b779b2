#pragma once
// What every fuzz target shares (docs/TESTING.md, "Fuzzing"). A target is
// one LLVMFuzzerTestOneInput; libFuzzer drives it in the clang build
// (STOCHTEX_FUZZ=ON) and replay_main.cpp feeds it stored inputs in the
// normal build. The property checked is the CLI's contract: a bad input is
// an InputError (exit code 2). Any other exception, a crash or a sanitizer
// report is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <typeinfo>

#include "owned_folder.h"
#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/pattern/pattern_spec.h"

namespace stochtex::fuzz {

// Runs one input; aborts (a finding) on anything but success or an InputError.
template <class F>
int run(F&& body) {
    // One thread: TBB workers would make a finding harder to reproduce and
    // the fuzzer shares its machine; results never depend on it.
    static ThreadLimit oneThread(1);
    // STOCHTEX_FUZZ_VERBOSE=1 prints each input's refusal: how to see that
    // seeds get past the parser rather than all failing at its first check.
    static const bool verbose = std::getenv("STOCHTEX_FUZZ_VERBOSE") != nullptr;
    try {
        body();
        if (verbose) std::fprintf(stderr, "fuzz: accepted\n");
    } catch (const InputError& e) {
        if (verbose) std::fprintf(stderr, "fuzz: InputError: %s\n", e.what());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz: escaped %s: %s\n", typeid(e).name(), e.what());
        std::abort();
    } catch (...) {
        std::fprintf(stderr, "fuzz: escaped a non-std exception\n");
        std::abort();
    }
    return 0;
}

// A fresh folder of this process's own under the temp folder (named
// <prefix>-XXXXXX), removed with the object: a target that must write its
// inputs to files keeps one for its life, so that nothing is left behind.
class TempFolder : public test::OwnedFolder {
public:
    explicit TempFolder(const std::string& prefix) : OwnedFolder(fresh(prefix)) {}
};

inline std::string text(const uint8_t* data, size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

// The folder of the small images specs may name (tests/fuzz/images): the
// base folder of every spec read, and the only place a spec may read from,
// so a mutated path never makes a target read /dev or /proc.
inline const std::filesystem::path& imagesDir() {
    static const std::filesystem::path dir = std::filesystem::canonical(STOCHTEX_FUZZ_IMAGES);
    return dir;
}

inline bool insideImagesDir(const std::filesystem::path& p) {
    std::error_code ec;
    const std::filesystem::path c = std::filesystem::weakly_canonical(p, ec);
    if (ec) return false;
    const std::filesystem::path rel = c.lexically_relative(imagesDir());
    return !rel.empty() && *rel.begin() != ".." && rel.is_relative();
}

// Tiny sizes, so one input runs in milliseconds: applied after parsing (the
// parser's own limits are what is fuzzed there) and before building. Halving
// keeps a size's parity with powers of two (non-powers stay non-powers).
inline int shrink(int size, int limit) {
    while (size > limit) size /= 2;
    return size;
}

constexpr int kExampleLimit = 32, kColormapLimit = 32, kOutputLimit = 8;

inline void shrink(NoiseSpec& n) { n.spectrum.size = shrink(n.spectrum.size, kExampleLimit); }
inline void shrink(ColormapSpec& c) { c.resolution = shrink(c.resolution, kColormapLimit); }

// False if a spec names an image outside imagesDir() (the input is skipped).
inline bool readsOnlyFuzzImages(const NoiseSpec& n) {
    return n.source != NoiseSpec::Source::Image || insideImagesDir(n.image);
}
inline bool readsOnlyFuzzImages(const ColormapSpec& c) {
    return c.source != ColormapSpec::Source::Image || insideImagesDir(c.image);
}

}  // namespace stochtex::fuzz
