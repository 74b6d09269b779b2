// Fuzz target: a colormap spec (the `colormap` command's JSON) parsed,
// rasterized at most 32 entries a side and prefiltered in both modes.
#include "fuzz_target.h"
#include "stochtex/pattern/prefiltered_colormap.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace stochtex;
    return fuzz::run([&] {
        const nlohmann::json j = JsonReader::parse(fuzz::text(data, size), "fuzz.json");
        ColormapSpec spec = parseColormapSpec(JsonReader(j, "fuzz.json"), fuzz::imagesDir());
        if (!fuzz::readsOnlyFuzzImages(spec)) return;
        fuzz::shrink(spec);
        const ColormapTable h = buildColormap(spec);
        for (PrefilterMode mode : {PrefilterMode::Paper, PrefilterMode::Smooth}) {
            const PrefilteredColormap table(h, mode);
            (void)table.sample(0.5f, 0.5f, 0.05f, 0.1f);
        }
    });
}
