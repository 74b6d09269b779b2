// Fuzz target: a pattern file through the whole pipeline: parse, build
// (examples at most 32 texels, colormaps and curves at most 32 entries a
// side), then render 8×8 pixels unfiltered and with every filter, in the zoom
// view at the pattern's scale and in the plane view with anisotropic probes.
// Every file is its program (GraphPattern, FilteredGraph); a file with a
// normal map also under the lean response.
#include "fuzz_target.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/graph_pattern.h"

namespace {

// Renders the program through every filter.
void renderEveryFilter(const stochtex::GraphPattern& program, const stochtex::View& view) {
    using namespace stochtex;
    Camera zoom;
    zoom.view = view;
    Camera plane = zoom;
    plane.kind = Camera::Kind::Plane;
    plane.tiltDeg = 75;
    for (const auto& [name, filter] : kFilterNames) {
        FilterOptions options;
        options.use(filter);
        options.referenceMaxSamples = 8;  // keeps exact and reference at ≤ 64 samples a pixel
        (void)FilteredGraph(program, options).render(zoom);
    }
    FilterOptions aniso;
    aniso.use(parseFilter("smooth"));
    aniso.aniso = 8;
    (void)FilteredGraph(program, aniso).render(plane);
}

}  // namespace

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
        if (spec.normalMap) {
            if (!fuzz::readsOnlyFuzzImages(spec.normalMap->height)) return;
            fuzz::shrink(spec.normalMap->height);
        }
        if (spec.graph) {
            auto graph = std::make_shared<TextureGraph>(*spec.graph);
            for (GraphNode& n : graph->nodes) {
                if (!fuzz::readsOnlyFuzzImages(n.noise) || !fuzz::readsOnlyFuzzImages(n.colormap)) return;
                fuzz::shrink(n.noise);
                fuzz::shrink(n.colormap);
                if (const auto r = n.numbers.find("resolution"); r != n.numbers.end())  // a curve's table
                    r->second = fuzz::shrink(int(r->second), fuzz::kColormapLimit);
            }
            spec.graph = graph;
        }
        spec.width = fuzz::shrink(spec.width, fuzz::kOutputLimit);
        spec.height = fuzz::shrink(spec.height, fuzz::kOutputLimit);
        const View view{spec.width, spec.height, spec.scale};

        const GraphPattern program = GraphPattern::build(spec);  // every file's program
        (void)program.render(view);
        renderEveryFilter(program, view);
        if (spec.normalMap) {  // under the lean response: its normal map's program
            const GraphPattern lean = GraphPattern::build(spec, {ResponseKind::Lean});
            (void)lean.render(view);
            renderEveryFilter(lean, view);
        }
    });
}
