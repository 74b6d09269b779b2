#include "stochtex/studies/pattern_sheet.h"

#include "stochtex/report/plot.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/graph_pattern.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace stochtex {

namespace {

// The colormap h (y up) darkened where N rarely falls, N being the two
// leaves' values over the view (renderNode: clamped to [0, 1], where the
// bins end anyway): shows which part of H the pattern actually uses.
Image colormapUsage(const Image& nx, const Image& ny, const ColormapTable& h, int size) {
    std::vector<double> hist(size_t(size) * size_t(size), 0.0);
    for (int py = 0; py < nx.height(); ++py)
        for (int px = 0; px < nx.width(); ++px) {
            const int i = std::clamp(int(nx.at(px, py, 0) * size), 0, size - 1);
            const int j = std::clamp(int((1.0f - ny.at(px, py, 0)) * size), 0, size - 1);
            hist[size_t(j) * size_t(size) + size_t(i)] += 1.0;
        }
    // Smooth the counts so the density reads as a shape, not as dots.
    cv::Mat counts(size, size, CV_64F, hist.data());
    cv::GaussianBlur(counts, counts, cv::Size(0, 0), 1.5);
    const double peak = *std::max_element(hist.begin(), hist.end());
    Image base = resizeSmooth(srgbFromLinear(h.toImage()), size, size);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const double d = peak > 0 ? std::sqrt(hist[size_t(j) * size_t(size) + size_t(i)] / peak) : 0.0;
            const float shade = float(0.15 + 0.85 * std::min(1.0, 4.0 * d));
            for (int c = 0; c < 3; ++c) base.at(i, j, c) *= shade;
        }
    return base;
}

}  // namespace

PatternSheet patternSheet(const PatternSpec& file, double scale, int size, const std::string& label) {
    const GraphPattern program = GraphPattern::build(file);
    // H ∘ N shows its two noises and its colormap; any other program its nodes.
    const ColormapTable* colormap = program.plainColormap();
    if (!colormap) {
        if (!file.graph) throw std::logic_error("patternSheet: a plain pattern's program is not H ∘ N");
        return graphSheet(program, *file.graph, scale, size);
    }
    const std::string& nx = program.leafIds()[0];
    const std::string& ny = program.leafIds()[1];
    const ColormapTable& h = *colormap;
    const int big = size, small = size / 2;
    View view;
    view.width = view.height = big;
    view.scale = scale;
    PatternSheet out;
    out.pattern = program.render(view);
    View half = view;
    half.width = half.height = small;
    half.scale = view.scale * 2.0;
    // A normal map's shading, as `render --response lean --filter none` draws it.
    const int lean = file.normalMap ? big : 0;
    Image sheet(big + lean + 2 * small, big, 3);
    // The sheet is composed in sRGB codes (report/page.h, Figure): colours are
    // encoded as they go in, the noises are data shown as grey.
    paste(sheet, srgbFromLinear(out.pattern), 0, 0);
    drawLabel(sheet, 0, big, big, label.c_str());
    if (lean) {
        paste(sheet, srgbFromLinear(GraphPattern::build(file, {ResponseKind::Lean}).render(view)), big, 0);
        drawLabel(sheet, big, big, big, "LEAN shading");
    }
    const int right = big + lean;
    paste(sheet, resizeSmooth(srgbFromLinear(h.toImage()), small, small), right, 0);
    paste(sheet, colormapUsage(program.renderNode(view, nx), program.renderNode(view, ny), h, small), right + small, 0);
    paste(sheet, program.renderNode(half, nx), right, small);
    paste(sheet, program.renderNode(half, ny), right + small, small);
    drawLabel(sheet, right, small, small, "colormap H");
    drawLabel(sheet, right + small, small, small, "H where N falls");
    drawLabel(sheet, right, big, small, "noise N_x");
    drawLabel(sheet, right + small, big, small, "noise N_y");
    out.sheet = std::move(sheet);
    return out;
}

}  // namespace stochtex

namespace stochtex {

PatternSheet graphSheet(const GraphPattern& graph, const TextureGraph& nodes, double scale, int size) {
    // The stages at half the side over the same region.
    const int side = std::max(32, size / 2);
    const View view{side, side, scale * size / side};
    std::vector<Image> images;
    std::vector<std::string> captions;
    const auto add = [&](const std::string& id) {
        images.push_back(srgbFromLinear(graph.renderNode(view, id)));
        // A lean node's slope leaves ("ID.slope_u") are no node of the file.
        const auto node = std::find_if(nodes.nodes.begin(), nodes.nodes.end(), [&](const GraphNode& n) { return n.id == id; });
        captions.push_back(node == nodes.nodes.end() ? id + " (slope)" : id + " (" + node->info->name + ")");
    };
    for (const std::string& id : graph.leafIds()) add(id);
    for (const GraphPattern::Operation& op : graph.operations()) add(op.id);
    return {graph.render(View{size, size, scale}), sheet({images}, {captions})};
}

}  // namespace stochtex
