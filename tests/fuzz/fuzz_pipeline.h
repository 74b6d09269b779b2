#pragma once
// What the pipeline and graph fuzz targets share: a parsed pattern file cut
// to tiny sizes, built into its program and rendered through every filter,
// in the zoom and the plane view.
#include "fuzz_target.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/graph_pattern.h"

namespace stochtex::fuzz {

// Examples at most 32 texels, colormaps and curves at most 32 entries a
// side, the output at most 8×8. False (skip the input) when the spec reads an
// image outside imagesDir().
inline bool shrinkSpec(PatternSpec& spec) {
    for (NoiseSpec& n : spec.noise) {
        if (!readsOnlyFuzzImages(n)) return false;
        shrink(n);
    }
    if (!readsOnlyFuzzImages(spec.colormap)) return false;
    shrink(spec.colormap);
    if (spec.normalMap) {
        if (!readsOnlyFuzzImages(spec.normalMap->height)) return false;
        shrink(spec.normalMap->height);
    }
    if (spec.graph) {
        auto graph = std::make_shared<TextureGraph>(*spec.graph);
        for (GraphNode& n : graph->nodes) {
            if (!readsOnlyFuzzImages(n.noise) || !readsOnlyFuzzImages(n.colormap)) return false;
            shrink(n.noise);
            shrink(n.colormap);
            if (const auto r = n.numbers.find("resolution"); r != n.numbers.end())  // a curve's table
                r->second = shrink(int(r->second), kColormapLimit);
        }
        spec.graph = graph;
    }
    spec.width = shrink(spec.width, kOutputLimit);
    spec.height = shrink(spec.height, kOutputLimit);
    return true;
}

// Renders the program unfiltered and through every filter: the zoom at the
// view's scale, the plane with anisotropic probes.
inline void renderEveryFilter(const GraphPattern& program, const View& view) {
    (void)program.render(view);
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

}  // namespace stochtex::fuzz
