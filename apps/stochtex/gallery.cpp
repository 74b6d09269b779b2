// stochtex gallery: every preset (or the pattern and graph files given)
// rendered beside its colormap and its two noises (a graph beside its
// stages; a normal map's LEAN shading beside the colours), as sheets in one
// folder with an index.html to browse them.
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
#include "stochtex/pattern/pattern_parts.h"
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
        std::vector<std::string> only, files;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("gallery", "Render every preset (or the files given) with its colormap and noises");
    cmd->add_option("files", args->files, "Pattern or texture graph files (JSON) to show instead of the presets");
    addOutputFolderFlag(*cmd, args->dir, "Output folder (created if missing)");
    cmd->add_option("--size", args->size, "Pattern size in pixels")->check(CLI::Range(64, 4096));
    cmd->add_option("--preset", args->only, "Only these presets (repeatable)");
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args, cmd] {
        ThreadLimit limit(args->threads);
        // Each entry: a preset's name or a file's path; all parsed before any work.
        struct Entry {
            std::string name, description;
            PatternSpec spec;
        };
        std::vector<Entry> entries;
        if (!args->files.empty() && !args->only.empty())
            refuseOption(*cmd, "--preset", "give presets or files, not both");
        for (const std::string& file : args->files) {
            const nlohmann::json j = readJsonFile(file);
            entries.push_back(
                {fs::path(file).stem().string(), j.value("description", std::string()), loadPatternFile(file)});
        }
        if (args->files.empty())
            for (const std::string& n : args->only.empty() ? presetNames() : args->only) {
                const nlohmann::json j = nlohmann::json::parse(presetText(n));
                entries.push_back({n, j.value("description", std::string()), loadPreset(n)});
            }
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
        std::vector<std::string> written;
        for (const Entry& e : entries) {
            progress.update(double(index++) / double(entries.size()), e.name);
            // Two files of one name in different folders get distinct sheets.
            std::string name = e.name;
            for (int k = 2; std::find(written.begin(), written.end(), name) != written.end(); ++k)
                name = e.name + "-" + std::to_string(k);
            written.push_back(name);
            const PatternSpec& spec = e.spec;
            const PatternSheet ps = patternSheet(spec, spec.scale, args->size, name);
            writeImage((fs::path(args->dir) / (name + ".png")).string(), ps.pattern);
            writeImage((fs::path(args->dir) / (name + "-sheet.png")).string(), ps.sheet, kNoTransfer);
            html << "<figure><img src='" << htmlEscape(name) << "-sheet.png' alt='" << htmlEscape(name)
                 << "'><figcaption><b>" << htmlEscape(name) << "</b> &mdash; " << htmlEscape(e.description)
                 << "</figcaption></figure>\n";
        }
        html << "</body></html>\n";
        writeFileAtomic((fs::path(args->dir) / "index.html").string(), html.str());
        progress.finish();
        std::printf("gallery: %zu %s in %s (open %s)\n", entries.size(), args->files.empty() ? "presets" : "patterns",
                    args->dir.c_str(), (fs::path(args->dir) / "index.html").string().c_str());
    });
}

}  // namespace stochtex::cli
