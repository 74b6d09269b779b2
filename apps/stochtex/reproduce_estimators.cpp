// stochtex reproduce estimators: the rendered error of each footprint
// estimator against the supersampled reference, per pattern and view, beside
// the exact statistics' floor (studies/estimator_renders.h; issue 32).
#include "common.h"
#include "reproduce.h"

namespace stochtex::cli {

void registerReproduceEstimators(CLI::App& reproduce, std::shared_ptr<ReproduceArgs> args) {
    auto* sub = reproduce.add_subcommand(
        "estimators", "Beyond the paper: each footprint estimator's rendered error per pattern and view");
    addReproduceOutputFlags(*sub, *args);
    EstimatorRendersOptions& e = args->estimators;
    addParameterOptions(*sub, estimatorRendersMembers(), e);
    sub->add_option("--presets", e.presets, "Patterns (presets)")
        ->delimiter(',')
        ->default_str("marble,woven,phasor-stripes,figure14,lean-ridges");
    sub->add_option("--scales", e.scales, "Zoom views, texels per pixel")->delimiter(',')->default_str("2,8,32,128");
    sub->add_flag("--no-plane{false}", e.plane, "Leave out the plane view");
    addReferenceToleranceFlag(*sub, e.referenceTolerance);
    addAnisoFlag(*sub, e.aniso);
    addPrefilterFlag(*sub, e.prefilter);
    sub->callback([args] {
        validateEstimatorRenders(args->estimators);
        runReproduction(*args, "estimators", [&](const Progress& p) {
            const EstimatorRendersResult r = estimatorRenders(args->estimators, p);
            return writeReproduction(args->dir, estimatorRendersReport(r), r.table.markdown());
        });
    });
}

}  // namespace stochtex::cli
