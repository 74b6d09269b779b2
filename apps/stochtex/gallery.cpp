// stochtex gallery: every preset rendered beside its colormap and its two
// noises, as sheets in one folder with an index.html to browse them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "common.h"
#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/presets.h"

namespace stochtex::cli {
namespace fs = std::filesystem;

namespace {

// The colormap (y up) darkened where N rarely falls: shows which part of H
// the pattern actually uses.
Image colormapUsage(const Pattern& pattern, const View& view, int size) {
    std::vector<double> hist(size_t(size) * size_t(size), 0.0);
    const double invW = 1.0 / pattern.exampleSize();
    for (int py = 0; py < view.height; ++py)
        for (int px = 0; px < view.width; ++px) {
            const auto n = pattern.field((view.offsetU + (px + 0.5) * view.scale) * invW,
                                         (view.offsetV + (py + 0.5) * view.scale) * invW);
            const int i = std::clamp(int(n[0] * size), 0, size - 1);
            const int j = std::clamp(int((1.0f - n[1]) * size), 0, size - 1);
            hist[size_t(j) * size_t(size) + size_t(i)] += 1.0;
        }
    // Smooth the counts so the density reads as a shape, not as dots.
    cv::Mat h(size, size, CV_64F, hist.data());
    cv::GaussianBlur(h, h, cv::Size(0, 0), 1.5);
    const double peak = *std::max_element(hist.begin(), hist.end());
    Image base = resizeSmooth(pattern.colormap().toImage(), size, size);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const double d = peak > 0 ? std::sqrt(hist[size_t(j) * size_t(size) + size_t(i)] / peak) : 0.0;
            const float shade = float(0.15 + 0.85 * std::min(1.0, 4.0 * d));
            for (int c = 0; c < 3; ++c) base.at(i, j, c) *= shade;
        }
    return base;
}

}  // namespace

void registerGallery(CLI::App& app) {
    struct Args {
        std::string dir;
        int size = 512;
        int threads = 0;
        std::vector<std::string> only;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("gallery", "Render every preset with its colormap and noises");
    cmd->add_option("-o,--output", args->dir, "Output folder (created if missing)")->required();
    cmd->add_option("--size", args->size, "Pattern size in pixels")->check(CLI::Range(64, 4096));
    cmd->add_option("--preset", args->only, "Only these presets (repeatable)");
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args] {
        ThreadLimit limit(args->threads);
        const std::vector<std::string> names = args->only.empty() ? presetNames() : args->only;
        for (const auto& n : names) (void)presetText(n);  // fail on unknown names before any work
        std::error_code ec;
        fs::create_directories(args->dir, ec);
        if (ec || !fs::is_directory(args->dir)) throw InputError(args->dir + ": cannot create output folder");

        const int big = args->size, small = args->size / 2;
        std::ostringstream html;
        html << "<!doctype html><html><head><meta charset='utf-8'><title>stochtex gallery</title>"
                "<style>body{font-family:sans-serif;background:#222;color:#ddd;margin:2em}"
                "figure{margin:0 0 2em 0}img{max-width:100%;image-rendering:pixelated}"
                "figcaption{margin:.4em 0}</style></head><body><h1>stochtex gallery</h1>"
                "<p>Each sheet: the pattern S = H&#8728;N (left); the colormap H (x right, y up), H shaded by "
                "where N falls, and the two tiled noises N<sub>x</sub>, N<sub>y</sub> over the same region.</p>\n";
        int index = 0;
        for (const auto& name : names) {
            ++index;
            std::fprintf(stderr, "[%d/%zu] %s\n", index, names.size(), name.c_str());
            const PatternSpec spec = loadPreset(name);
            const Pattern pattern = Pattern::build(spec);
            View view;
            view.width = view.height = big;
            view.scale = spec.scale;
            const Image img = pattern.render(view);
            View half = view;
            half.width = half.height = small;
            half.scale = view.scale * 2.0;

            Image sheet(big + 2 * small, big, 3);
            paste(sheet, img, 0, 0);
            paste(sheet, resizeSmooth(pattern.colormap().toImage(), small, small), big, 0);
            paste(sheet, colormapUsage(pattern, view, small), big + small, 0);
            paste(sheet, toRgb(pattern.renderNoise(0, half)), big, small);
            paste(sheet, toRgb(pattern.renderNoise(1, half)), big + small, small);
            drawLabel(sheet, 0, big, big, name.c_str());
            drawLabel(sheet, big, small, small, "colormap H");
            drawLabel(sheet, big + small, small, small, "H where N falls");
            drawLabel(sheet, big, big, small, "noise N_x");
            drawLabel(sheet, big + small, big, small, "noise N_y");

            writeImage((fs::path(args->dir) / (name + ".png")).string(), img);
            writeImage((fs::path(args->dir) / (name + "-sheet.png")).string(), sheet);
            std::string description;
            const auto j = nlohmann::json::parse(presetText(name));
            if (j.contains("description")) description = j["description"].get<std::string>();
            html << "<figure><img src='" << name << "-sheet.png' alt='" << name << "'><figcaption><b>" << name
                 << "</b> &mdash; " << htmlEscape(description) << "</figcaption></figure>\n";
        }
        html << "</body></html>\n";
        writeFileAtomic((fs::path(args->dir) / "index.html").string(), html.str());
        std::printf("gallery: %zu presets in %s (open %s)\n", names.size(), args->dir.c_str(),
                    (fs::path(args->dir) / "index.html").string().c_str());
    });
}

}  // namespace stochtex::cli
