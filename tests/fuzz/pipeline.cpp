// Fuzz target: a pattern file through the whole pipeline: parse, build
// (examples at most 32 texels, colormaps and curves at most 32 entries a
// side), then render 8×8 pixels unfiltered and with every filter, in the zoom
// view at the pattern's scale and in the plane view with anisotropic probes.
// Every file is its program (GraphPattern, FilteredGraph); a file with a
// normal map also under the lean response.
#include "fuzz_pipeline.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace stochtex;
    return fuzz::run([&] {
        const nlohmann::json j = JsonReader::parse(fuzz::text(data, size), "fuzz.json");
        PatternSpec spec = parsePatternSpec(JsonReader(j, "fuzz.json"), fuzz::imagesDir());
        if (!fuzz::shrinkSpec(spec)) return;
        const View view{spec.width, spec.height, spec.scale};
        fuzz::renderEveryFilter(GraphPattern::build(spec), view);  // every file's program
        if (spec.normalMap)                                        // under the lean response: its normal map's program
            fuzz::renderEveryFilter(GraphPattern::build(spec, {ResponseKind::Lean}), view);
    });
}
