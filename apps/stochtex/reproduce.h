#pragma once
// The flags and outputs shared by the `reproduce` subcommands.
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "common.h"
#include "stochtex/core/progress.h"
#include "stochtex/studies/estimator_renders.h"
#include "stochtex/studies/graph_filtering.h"
#include "stochtex/studies/normal_maps.h"
#include "stochtex/studies/paper.h"
#include "stochtex/studies/phasor_figures.h"

namespace stochtex::cli {

struct ReproduceArgs {
    std::string dir;
    Table1Options table;
    Figure4Options figure4;
    Figure12Options figure12;
    std::optional<double> roughness;  // figure 12: overrides the normal map's
    Figure4Options figure11 = figure11Options();
    Figure10Options figure10;
    Figure14Options figure14 = figure14Options();
    std::string figure14Pattern;  // a graph file instead of the preset
    EstimatorRendersOptions estimators;
    int sheetSize = 384;
    int threads = 0;
};
// -o and --threads; with table: --count, --footprints, --seed,
// --footprint-seed; with a figure (&args.figure4 or &args.figure11): --size,
// --reference-samples, --filter, and --preset for figure 4, --footprints for
// figure 11.
void addReproduceFlags(CLI::App& sub, ReproduceArgs& args, bool table, Figure4Options* figure);
// -o DIR and --threads, which every reproduce subcommand takes.
void addReproduceOutputFlags(CLI::App& sub, ReproduceArgs& args);
// --reference-tolerance: when the brute-force images have converged (studies/reference_samples.h).
void addReferenceToleranceFlag(CLI::App& sub, double& tolerance);
// --filter smooth|paper: the prefiltered tables of a study's filtered renders.
void addPrefilterFlag(CLI::App& sub, PrefilterMode& mode);
// figure10's flags: --size, --comparison-size, --frequency, --bandwidth,
// --orientation, --density, --seed.
void addFigure10Flags(CLI::App& sub, ReproduceArgs& args);
// Figure 12: --preset, --size (the view's width; height 5/8 of it),
// --reference-samples, --tilt, --aniso, --roughness.
void addFigure12Flags(CLI::App& sub, ReproduceArgs& args);
// Loads the preset and validates every option: InputError before any work.
void prepareReproduce(ReproduceArgs& args);
// The same for figure 12 (its preset and options).
void prepareFigure12(ReproduceArgs& args);
// `reproduce all`: figures 11, 12 and 14 take figure 4's size and reference
// samples (scaled), then are prepared as above.
void prepareReproduceAll(ReproduceArgs& args);
// Writes a part's report into dir; returns what to print after `text`:
// "wrote <files> to <dir>".
std::string writeReproduction(const std::string& dir, const Report& report, const std::string& text = "");

// Runs one reproduction with --threads and a progress line titled
// "reproduce <name>", then prints the report `run` returns.
void runReproduction(const ReproduceArgs& args, const std::string& name,
                     const std::function<std::string(const Progress&)>& run);

void registerReproduceAll(CLI::App& reproduce, std::shared_ptr<ReproduceArgs> args);
// `reproduce figure14` (reproduce_figure14.cpp).
void registerReproduceFigure14(CLI::App& reproduce, std::shared_ptr<ReproduceArgs> args);
// `reproduce estimators` (reproduce_estimators.cpp).
void registerReproduceEstimators(CLI::App& reproduce, std::shared_ptr<ReproduceArgs> args);

}  // namespace stochtex::cli
