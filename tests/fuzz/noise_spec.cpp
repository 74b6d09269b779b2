// Fuzz target: a noise spec (the `noise` command's JSON) parsed and built
// into a tiling-and-blending example (spectral synthesis or an image of
// tests/fuzz/images, Gaussianized or not), at most 32 texels wide.
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace stochtex;
    return fuzz::run([&] {
        const nlohmann::json j = JsonReader::parse(fuzz::text(data, size), "fuzz.json");
        NoiseSpec spec = parseNoiseSpec(JsonReader(j, "fuzz.json"), fuzz::imagesDir());
        if (!fuzz::readsOnlyFuzzImages(spec)) return;
        fuzz::shrink(spec);
        (void)buildNoiseExample(spec, "fuzz.json");
    });
}
