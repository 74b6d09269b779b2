// The flags and outputs shared by the `reproduce` subcommands (reproduce.h).
#include "reproduce.h"
#include "stochtex/pattern/presets.h"

namespace stochtex::cli {

std::string writeTable1(const Table1Result& r, const std::string& dir) {
    ensureFolder(dir);
    writeText(dir, "table1.csv", r.data.csv());
    std::string md;
    for (const auto& t : r.tables) md += "\n" + t.markdown();
    writeText(dir, "table1.md", "# Table 1: estimator errors (absolute (relative) mean errors)\n" + md);
    writeFigures(dir, r.figures);
    return md;
}

void writeFigure4(const Figure4Result& r, const std::string& dir) {
    ensureFolder(dir);
    writeFigures(dir, r.figures);
    writeText(dir, "figure4.csv", r.table.csv());
}

void addReproduceFlags(CLI::App& sub, ReproduceArgs& a, bool table, bool figure4) {
    addOutputFolderFlag(sub, a.dir);
    addThreadsFlag(sub, a.threads);
    if (table) {
        sub.add_option("--count", a.table.errors.count, "Random footprints per size")->capture_default_str();
        sub.add_option("--footprints", a.table.errors.footprints, "Footprint sides in texels")->delimiter(',');
        addSeedFlag(sub, "--seed", a.table.seed, "Seed of the noises (footprint centres use --footprint-seed)");
        addSeedFlag(sub, "--footprint-seed", a.table.errors.seed, "Seed of the footprint centres");
    }
    if (figure4) {
        sub.add_option("--preset", a.figure4.name, "Pattern of Figure 4")->capture_default_str();
        sub.add_option("--size", a.figure4.size, "Image size per footprint")->capture_default_str();
        sub.add_option("--reference-samples", a.figure4.referenceSamples, "Max reference samples per axis");
        // Figure 4 compares the estimators' statistics with the exact ones:
        // --filter chooses only the response.
        const auto setResponse = [&a](const NamedFilter& f) {
            if (f.source != StatisticsSource::Estimators)
                throw InputError::parameter("filter",
                                            "must be smooth or paper for figure 4 (the estimators through a "
                                            "table), got " +
                                                filterName(FilterOptions{}.use(f)));
            a.figure4.response = f.response;
        };
        addFilterFlag(sub, setResponse,
                      filterName(FilterOptions{}.use({StatisticsSource::Estimators, a.figure4.response})),
                      "Table used with the estimators: smooth or paper");
    }
}

void prepareReproduce(ReproduceArgs& a) {
    a.figure4.pattern = loadPreset(a.figure4.name);  // unknown preset: fail before any work
    validateFigure4(a.figure4);
    validateTable1(a.table);
    validateFigures7to9(a.sheetSize);
}

}  // namespace stochtex::cli

namespace stochtex::cli {

void addFigure12Flags(CLI::App& sub, ReproduceArgs& a) {
    addOutputFolderFlag(sub, a.dir);
    addThreadsFlag(sub, a.threads);
    Figure12Options& f = a.figure12;
    sub.add_option("--preset", f.name, "Pattern with a normal map")->capture_default_str();
    sub.add_option_function<int>("--size", [&f](int w) { f.width = w, f.height = w * 5 / 8; },
                                 "Width of the global view (height: 5/8 of it)")
        ->default_str(std::to_string(f.width));
    sub.add_option("--reference-samples", f.referenceSamples, "Max reference samples per axis")->capture_default_str();
    sub.add_option("--tilt", f.tiltDeg, "Camera tilt from straight down, degrees")->capture_default_str();
    sub.add_option("--aniso", f.aniso, "Max anisotropic probes K")->capture_default_str();
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

void writeFigure12(const Figure12Result& r, const std::string& dir) {
    ensureFolder(dir);
    writeFigures(dir, r.figures);
    writeText(dir, "figure12.csv", r.table.csv());
}

}  // namespace stochtex::cli
