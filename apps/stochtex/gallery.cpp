// stochtex gallery: every preset rendered beside its colormap and its two
// noises (a graph preset beside its stages), as sheets in one folder with an
// index.html to browse them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "common.h"
#include "progress.h"
#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/presets.h"
#include "stochtex/report/table.h"
#include "stochtex/studies/pattern_sheet.h"

namespace stochtex::cli {
namespace fs = std::filesystem;

void registerGallery(CLI::App& app) {
    struct Args {
        std::string dir;
        int size = 512;
        int threads = 0;
        std::vector<std::string> only;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("gallery", "Render every preset with its colormap and noises");
    addOutputFolderFlag(*cmd, args->dir, "Output folder (created if missing)");
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

        std::ostringstream html;
        html << "<!doctype html><html><head><meta charset='utf-8'><title>stochtex gallery</title>"
                "<style>body{font-family:sans-serif;background:#222;color:#ddd;margin:2em}"
                "figure{margin:0 0 2em 0}img{max-width:100%;image-rendering:pixelated}"
                "figcaption{margin:.4em 0}</style></head><body><h1>stochtex gallery</h1>"
                "<p>Each sheet: the pattern S = H&#8728;N (left); the colormap H (x right, y up), H shaded by "
                "where N falls, and the two tiled noises N<sub>x</sub>, N<sub>y</sub> over the same region.</p>\n";
        ProgressLine progress("gallery");
        size_t index = 0;
        for (const auto& name : names) {
            progress.update(double(index++) / double(names.size()), name);
            const PatternSpec spec = loadPreset(name);
            // A graph with a non-linear node before its output: its stages instead of H and N.
            const PatternSheet ps = needsGraphEvaluator(spec)
                                        ? graphSheet(GraphPattern::build(spec), *spec.graph, spec.scale, args->size)
                                        : patternSheet(Pattern::build(spec), spec.scale, args->size, name);
            const Image& img = ps.pattern;
            const Image& sheet = ps.sheet;

            writeImage((fs::path(args->dir) / (name + ".png")).string(), img);
            writeImage((fs::path(args->dir) / (name + "-sheet.png")).string(), sheet, kNoTransfer);
            std::string description;
            const auto j = nlohmann::json::parse(presetText(name));
            if (j.contains("description")) description = j["description"].get<std::string>();
            html << "<figure><img src='" << name << "-sheet.png' alt='" << name << "'><figcaption><b>" << name
                 << "</b> &mdash; " << htmlEscape(description) << "</figcaption></figure>\n";
        }
        html << "</body></html>\n";
        writeFileAtomic((fs::path(args->dir) / "index.html").string(), html.str());
        progress.finish();
        std::printf("gallery: %zu presets in %s (open %s)\n", names.size(), args->dir.c_str(),
                    (fs::path(args->dir) / "index.html").string().c_str());
    });
}

}  // namespace stochtex::cli
