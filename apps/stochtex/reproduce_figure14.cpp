// stochtex reproduce figure14: paper Figure 14, a graph cascading two 2D
// transfer functions, and how moment matching filters it (studies/graph_filtering.h).
#include "common.h"
#include "reproduce.h"

namespace stochtex::cli {

void registerReproduceFigure14(CLI::App& reproduce, std::shared_ptr<ReproduceArgs> args) {
    auto* sub = reproduce.add_subcommand(
        "figure14", "Figure 14: a graph of two transfer functions, filtered by moment matching vs the reference");
    addOutputFolderFlag(*sub, args->dir);
    addThreadsFlag(*sub, args->threads);
    Figure14Options& f = args->figure14;
    sub->add_option("--pattern", args->figure14Pattern, "A graph file instead of the preset figure14");
    addParameterOptions(*sub, figure14Members(), f);
    sub->add_option("--reference-tolerance", f.referenceTolerance,
                    "Samples double until the reference moves less than this (mean RGB distance)")
        ->capture_default_str();
    sub->add_option("--footprints", f.footprints, "Footprint sides in texels")->delimiter(',');
    addEnumFlag(*sub, "--filter", f.prefilter, kPrefilterModeNames, "prefilter",
                "Prefiltered tables of the filtered renders: smooth or paper");
    sub->callback([args] {
        if (!args->figure14Pattern.empty()) {
            args->figure14.pattern = loadPatternFile(args->figure14Pattern);
            args->figure14.name = args->figure14.pattern.name;
        }
        validateFigure14(args->figure14);
        runReproduction(*args, "figure14", [&](const Progress& p) {
            const Figure14Result r = figure14(args->figure14, p);
            return writeReproduction(args->dir, figure14Report(r), r.table.markdown());
        });
    });
}

}  // namespace stochtex::cli
