#include "stochtex/studies/pattern_sheet.h"

#include "stochtex/analysis/plot.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/filtered_pattern.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace stochtex {

namespace {

// The colormap (y up) darkened where N rarely falls: shows which part of H
// the pattern actually uses.
Image colormapUsage(const Pattern& pattern, const View& view, int size) {
    std::vector<double> hist(size_t(size) * size_t(size), 0.0);
    const double invW = 1.0 / pattern.exampleSize();
    for (int py = 0; py < view.height; ++py)
        for (int px = 0; px < view.width; ++px) {
            const auto [u, v] = pixelUv(view, invW, px, py);
            const auto n = pattern.field(u, v);
            const int i = std::clamp(int(n[0] * size), 0, size - 1);
            const int j = std::clamp(int((1.0f - n[1]) * size), 0, size - 1);
            hist[size_t(j) * size_t(size) + size_t(i)] += 1.0;
        }
    // Smooth the counts so the density reads as a shape, not as dots.
    cv::Mat h(size, size, CV_64F, hist.data());
    cv::GaussianBlur(h, h, cv::Size(0, 0), 1.5);
    const double peak = *std::max_element(hist.begin(), hist.end());
    Image base = resizeSmooth(srgbFromLinear(pattern.colormap().toImage()), size, size);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const double d = peak > 0 ? std::sqrt(hist[size_t(j) * size_t(size) + size_t(i)] / peak) : 0.0;
            const float shade = float(0.15 + 0.85 * std::min(1.0, 4.0 * d));
            for (int c = 0; c < 3; ++c) base.at(i, j, c) *= shade;
        }
    return base;
}

}  // namespace

PatternSheet patternSheet(const Pattern& pattern, const PatternSpec& file, double scale, int size,
                          const std::string& label) {
    const int big = size, small = size / 2;
    View view;
    view.width = view.height = big;
    view.scale = scale;
    PatternSheet out;
    out.pattern = pattern.render(view);
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
        const GraphPattern normals = GraphPattern::build(file, {ResponseKind::Lean});
        paste(sheet, srgbFromLinear(normals.render(view)), big, 0);
        drawLabel(sheet, big, big, big, "LEAN shading");
    }
    const int right = big + lean;
    paste(sheet, resizeSmooth(srgbFromLinear(pattern.colormap().toImage()), small, small), right, 0);
    paste(sheet, colormapUsage(pattern, view, small), right + small, 0);
    paste(sheet, toRgb(pattern.renderNoise(0, half)), right, small);
    paste(sheet, toRgb(pattern.renderNoise(1, half)), right + small, small);
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
