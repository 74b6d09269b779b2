// The flags and outputs shared by the `reproduce` subcommands (reproduce.h).
#include "reproduce.h"

#include <algorithm>
#include <cstdio>

#include "progress.h"
#include "stochtex/core/parallel.h"
#include "stochtex/pattern/presets.h"

namespace stochtex::cli {

void addReproduceOutputFlags(CLI::App& sub, ReproduceArgs& a) {
    addOutputFolderFlag(sub, a.dir);
    addThreadsFlag(sub, a.threads);
}

void addReferenceToleranceFlag(CLI::App& sub, double& tolerance) {
    sub.add_option("--reference-tolerance", tolerance,
                   "Samples double until the reference moves less than this (mean RGB distance)")
        ->capture_default_str();
}

void addPrefilterFlag(CLI::App& sub, PrefilterMode& mode) {
    addEnumFlag(sub, "--filter", mode, kPrefilterModeNames, "prefilter",
                "Prefiltered tables of the filtered renders: smooth or paper");
}

void addFigure10Flags(CLI::App& sub, ReproduceArgs& a) {
    addReproduceOutputFlags(sub, a);
    Figure10Options& f = a.figure10;
    addParameterOptions(sub, figure10Members(), f);
    sub.add_option("--frequency", f.field.frequency, "Frequency of both phasor fields, cycles per period")
        ->capture_default_str();
    sub.add_option("--bandwidth", f.field.bandwidth, "Spectral bandwidth of both fields, cycles per period")
        ->capture_default_str();
    sub.add_option("--orientation", f.field.orientation, "Wave direction of both fields, degrees")
        ->capture_default_str();
    sub.add_option("--density", f.field.density, "Gabor kernels per cell of the procedural noise")
        ->capture_default_str();
    addSeedFlag(sub, "--seed", f.field.seed, "Seed of the procedural noise's kernels");
}

void addReproduceFlags(CLI::App& sub, ReproduceArgs& a, bool table, Figure4Options* figure) {
    addReproduceOutputFlags(sub, a);
    if (table) {
        sub.add_option("--count", a.table.errors.count, "Random footprints per size")->capture_default_str();
        sub.add_option("--footprints", a.table.errors.footprints, "Footprint sides in texels")->delimiter(',');
        addSeedFlag(sub, "--seed", a.table.seed, "Seed of the noises (footprint centres use --footprint-seed)");
        addSeedFlag(sub, "--footprint-seed", a.table.errors.seed, "Seed of the footprint centres");
    }
    if (figure) {
        Figure4Options& f = *figure;
        if (figure == &a.figure4) sub.add_option("--preset", f.name, "Pattern of Figure 4")->capture_default_str();
        // (figure 4's --footprints would clash with table1's in `reproduce all`)
        if (figure == &a.figure11 && !table)
            sub.add_option("--footprints", f.footprints, "Footprint sides in texels")->delimiter(',');
        addParameterOptions(sub, figure4Members(), f);
        addReferenceToleranceFlag(sub, f.referenceTolerance);
        // Figures 4 and 11 compare the estimators' statistics with the
        // reference: --filter chooses only the response, among the filters
        // over the estimators (the validator refuses the others).
        const auto setResponse = [&f](const NamedFilter& named) { f.response = named.response; };
        // The names this flag takes, the table's entries over the estimators (help and refusal list only them).
        static const EnumNames<NamedFilter> estimatorFilters = [] {
            EnumNames<NamedFilter> out;
            for (const auto& entry : kFilterNames)
                if (entry.second.source == StatisticsSource::Estimators) out.push_back(entry);
            return out;
        }();
        addFilterFlag(sub, setResponse, filterName(FilterOptions{}.use({StatisticsSource::Estimators, f.response})),
                      "Table used with the estimators: smooth or paper", estimatorFilters);
    }
}

void prepareReproduce(ReproduceArgs& a) {
    a.figure4.pattern = loadPreset(a.figure4.name);  // unknown preset: fail before any work
    validateFigure4(a.figure4);
    validateFigure4(a.figure11);
    validateFigure10(a.figure10);
    validateTable1(a.table);
    validateFigures7to9(a.sheetSize);
}

}  // namespace stochtex::cli

namespace stochtex::cli {

void addFigure12Flags(CLI::App& sub, ReproduceArgs& a) {
    addReproduceOutputFlags(sub, a);
    Figure12Options& f = a.figure12;
    sub.add_option("--preset", f.name, "Pattern with a normal map")->capture_default_str();
    sub.add_option_function<int>(
           "--size", [&f](int w) { f.width = w, f.height = w * 5 / 8; }, "Width of the global view (height: 5/8 of it)")
        ->default_str(std::to_string(f.width));
    addParameterOptions(sub, figure12Members(), f);
    addParameterOption(sub, cameraTiltParam(), f.tiltDeg);
    addParameterOption(sub, anisoParam(), f.aniso);
    sub.add_option("--roughness", a.roughness, "Base Beckmann roughness (default: the preset's)");
}

void prepareFigure12(ReproduceArgs& a) {
    a.figure12.pattern = loadPreset(a.figure12.name);
    if (a.roughness && a.figure12.pattern.normalMap) {
        a.figure12.pattern.normalMap->shading.roughness = *a.roughness;
        a.figure12.pattern.normalMap->shading = validatedShading(a.figure12.pattern.normalMap->shading);
    }
    validateFigure12(a.figure12);
}

void prepareReproduceAll(ReproduceArgs& a) {
    // Figure 11 is Figure 4's comparison for the phasor pattern: the same
    // image size, reference samples and table.
    a.figure11.size = a.figure4.size;
    a.figure11.referenceSamples = a.figure4.referenceSamples;
    a.figure11.response = a.figure4.response;
    a.figure11.referenceTolerance = a.figure4.referenceTolerance;
    // Figure 12's global view is 5/4 of Figure 4's side wide (640 × 400 by
    // default), with at most its reference samples.
    a.figure12.width = std::max(32, a.figure4.size * 5 / 4);
    a.figure12.height = std::max(32, a.figure12.width * 5 / 8);
    a.figure12.referenceSamples = std::min(a.figure12.referenceSamples, a.figure4.referenceSamples);
    prepareFigure12(a);
    // Figure 14 at half Figure 4's side (its reference costs more per pixel).
    a.figure14.size = std::max(16, a.figure4.size / 2);
    a.figure14.referenceSamples = std::min(a.figure14.referenceSamples, a.figure4.referenceSamples);
    a.figure14.referenceTolerance = a.figure4.referenceTolerance;
    validateFigure14(a.figure14);
}

std::string writeReproduction(const std::string& dir, const Report& report, const std::string& text) {
    const std::vector<std::string> files = writeReport(dir, report);
    return text + (text.empty() ? "" : "\n") + "wrote " + listNames(files) + " to " + dir;
}

void runReproduction(const ReproduceArgs& args, const std::string& name,
                     const std::function<std::string(const Progress&)>& run) {
    ThreadLimit limit(args.threads);
    ProgressLine progress("reproduce " + name);
    const std::string report = run(progress.callback());
    progress.finish();
    std::printf("%s\n", report.c_str());
}

}  // namespace stochtex::cli
