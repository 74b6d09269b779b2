// stochtex reproduce figure14: paper Figure 14, a graph cascading two 2D
// transfer functions, and how moment matching filters it (studies/graph_filtering.h).
#include "common.h"
#include "reproduce.h"

namespace stochtex::cli {

void registerReproduceFigure14(CLI::App& reproduce, std::shared_ptr<ReproduceArgs> args) {
    auto* sub = reproduce.add_subcommand(
        "figure14", "Figure 14: a graph of two transfer functions, filtered by moment matching vs the reference");
    addReproduceOutputFlags(*sub, *args);
    Figure14Options& f = args->figure14;
    sub->add_option("--pattern", args->figure14Pattern, "A graph file instead of the preset figure14");
    addParameterOptions(*sub, figure14Members(), f);
    addReferenceToleranceFlag(*sub, f.referenceTolerance);
    sub->add_option("--footprints", f.footprints, "Footprint sides in texels")->delimiter(',');
    addPrefilterFlag(*sub, f.prefilter);
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
