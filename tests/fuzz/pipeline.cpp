// Fuzz target: a pattern file through the whole pipeline: parse, build
// (examples at most 32 texels, colormap at most 32 entries a side), then
// render 8×8 pixels unfiltered and with every filter, in the zoom view at
// the pattern's scale and in the plane view with anisotropic probes.
#include "fuzz_target.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/filtered_pattern.h"
#include "stochtex/pattern/pattern.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace stochtex;
    return fuzz::run([&] {
        const nlohmann::json j = JsonReader::parse(fuzz::text(data, size), "fuzz.json");
        PatternSpec spec = parsePatternSpec(JsonReader(j, "fuzz.json"), fuzz::imagesDir());
        for (NoiseSpec& n : spec.noise) {
            if (!fuzz::readsOnlyFuzzImages(n)) return;
            fuzz::shrink(n);
        }
        if (!fuzz::readsOnlyFuzzImages(spec.colormap)) return;
        fuzz::shrink(spec.colormap);
        spec.width = fuzz::shrink(spec.width, fuzz::kOutputLimit);
        spec.height = fuzz::shrink(spec.height, fuzz::kOutputLimit);

        const Pattern pattern = Pattern::build(spec);
        const View view{spec.width, spec.height, spec.scale};
        (void)pattern.render(view);

        Camera zoom;
        zoom.view = view;
        Camera plane = zoom;
        plane.kind = Camera::Kind::Plane;
        plane.tiltDeg = 75;
        for (const auto& [name, filter] : kFilterNames) {
            FilterOptions options;
            options.use(filter);
            options.referenceMaxSamples = 8;  // keeps exact and reference at ≤ 64 samples a pixel
            (void)FilteredPattern(pattern, options).render(zoom);
        }
        FilterOptions aniso;
        aniso.use(parseFilter("smooth"));
        aniso.aniso = 8;
        (void)FilteredPattern(pattern, aniso).render(plane);
    });
}
