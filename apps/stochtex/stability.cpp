// stochtex stability: flicker of a zoom-out sequence, per filter mode.
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "common.h"
#include "stochtex/analysis/zoom_stability.h"
#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/filtered_pattern.h"

namespace stochtex::cli {
namespace fs = std::filesystem;

void registerStability(CLI::App& app) {
    struct Args {
        PatternSource source;
        std::string dir;
        std::vector<std::string> filters{"none", "paper", "smooth", "reference"};
        int frames = 64, size = 128, aniso = 1, referenceSamples = 32, threads = 0;
        double from = 1, to = 128;
        bool writeFrames = false;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("stability",
                                   "Zoom-out sequence per filter mode: mean |frame − next frame| after undoing the zoom");
    addPatternSource(*cmd, args->source);
    cmd->add_option("-o,--output", args->dir, "Output folder for stability.csv (and frames)")->required();
    cmd->add_option("--filters", args->filters, "Filter modes to compare")->delimiter(',');
    cmd->add_option("--frames", args->frames, "Number of frames")->check(CLI::Range(2, 1000));
    cmd->add_option("--size", args->size, "Frame size in pixels")->check(CLI::Range(8, 2048));
    cmd->add_option("--from", args->from, "First scale (texels per pixel)");
    cmd->add_option("--to", args->to, "Last scale");
    cmd->add_option("--aniso", args->aniso, "Anisotropic probes K");
    cmd->add_option("--reference-samples", args->referenceSamples, "Max samples per axis for the reference");
    cmd->add_flag("--write-frames", args->writeFrames, "Also write every frame as PNG");
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args] {
        if (!(args->from > 0) || !(args->to > 0) || !std::isfinite(args->from) || !std::isfinite(args->to) ||
            args->to > 1e6 || args->from > 1e6)
            throw InputError("--from/--to must be finite scales in (0, 1e6]");
        std::vector<FilterOptions> modes;
        for (const auto& f : args->filters) {
            FilterOptions o;
            o.mode = parseFilterMode(f);
            o.aniso = args->aniso;
            o.referenceMaxSamples = args->referenceSamples;
            modes.push_back(o);
        }
        const PatternSpec spec = loadPatternSource(args->source);
        std::error_code ec;
        fs::create_directories(args->dir, ec);
        if (ec || !fs::is_directory(args->dir)) throw InputError(args->dir + ": cannot create output folder");
        ThreadLimit limit(args->threads);
        const Pattern pattern = Pattern::build(spec);
        std::ostringstream csv;
        csv << "filter,mean_difference,max_difference\n";
        std::ostringstream perFrame;
        perFrame << "filter,frame,scale,difference\n";
        std::printf("%-10s %12s %12s   (%d frames, scale %g -> %g, %dx%d)\n", "filter", "mean |dI|", "max |dI|",
                    args->frames, args->from, args->to, args->size, args->size);
        for (size_t m = 0; m < modes.size(); ++m) {
            const FilteredPattern filtered(pattern, modes[m]);
            const std::string name = args->filters[m];
            const ZoomStability z = measureZoomStability(
                [&](double s) {
                    Camera cam;
                    cam.view.width = cam.view.height = args->size;
                    cam.view.scale = s;
                    // Zoom about a fixed texture point: the view centre stays at texel (0, 0).
                    cam.view.offsetU = cam.view.offsetV = -0.5 * args->size * s;
                    return filtered.render(cam);
                },
                args->frames, args->from, args->to,
                [&](int k) {
                    std::fprintf(stderr, "\r%s: frame %d/%d", name.c_str(), k + 1, args->frames);
                    if (k + 1 == args->frames) std::fprintf(stderr, "\n");
                });
            if (args->writeFrames) {
                // Frames are cheap to re-render next to the measurement; keep the loop above simple.
                for (size_t k = 0; k < z.scales.size(); ++k) {
                    Camera cam;
                    cam.view.width = cam.view.height = args->size;
                    cam.view.scale = z.scales[k];
                    cam.view.offsetU = cam.view.offsetV = -0.5 * args->size * z.scales[k];
                    char file[64];
                    std::snprintf(file, sizeof file, "%s-%03zu.png", name.c_str(), k);
                    writeImage((fs::path(args->dir) / file).string(), filtered.render(cam));
                }
            }
            std::printf("%-10s %12.5f %12.5f\n", name.c_str(), z.mean, z.max);
            csv << name << ',' << z.mean << ',' << z.max << '\n';
            for (size_t k = 0; k < z.differences.size(); ++k)
                perFrame << name << ',' << k << ',' << z.scales[k] << ',' << z.differences[k] << '\n';
        }
        writeFileAtomic((fs::path(args->dir) / "stability.csv").string(), csv.str());
        writeFileAtomic((fs::path(args->dir) / "stability-frames.csv").string(), perFrame.str());
        std::printf("wrote %s/stability.csv and stability-frames.csv\n", args->dir.c_str());
    });
}

}  // namespace stochtex::cli
