// stochtex reproduce: the paper's accuracy evidence, one command each —
// Table 1 (estimator errors), Figure 4 (filtered vs reference images and
// error maps), Figures 7–9 (colormap layouts, palettes, noise spectra) — and
// `all`, which runs them and writes an index.html (reproduce_all.cpp).
#include <cstdio>

#include "common.h"
#include "reproduce.h"
#include "stochtex/core/parallel.h"
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
        sub.add_option("--seed", a.table.seed, "Seed of the noises (footprint centres use --footprint-seed)");
        sub.add_option("--footprint-seed", a.table.errors.seed, "Seed of the footprint centres");
    }
    if (figure4) {
        sub.add_option("--preset", a.figure4.name, "Pattern of Figure 4")->capture_default_str();
        sub.add_option("--size", a.figure4.size, "Image size per footprint")->capture_default_str();
        sub.add_option("--reference-samples", a.figure4.referenceSamples, "Max reference samples per axis");
        addFilterModeFlag(sub, a.figure4.mode, "Table used with the estimators: smooth or paper");
    }
}

void prepareReproduce(ReproduceArgs& a) {
    a.figure4.pattern = loadPreset(a.figure4.name);  // unknown preset: fail before any work
    validateFigure4(a.figure4);
    validateTable1(a.table);
    validateFigures7to9(a.sheetSize);
}

void registerReproduce(CLI::App& app) {
    auto args = std::make_shared<ReproduceArgs>();
    auto* cmd = app.add_subcommand("reproduce", "Regenerate the paper's evidence: table1, figure4, figures7-9, all");
    cmd->require_subcommand(1);
    auto* table1Cmd = cmd->add_subcommand("table1", "Table 1: mean errors of μ̂ and σ̂ against exact footprint statistics");
    addReproduceFlags(*table1Cmd, *args, true, false);
    table1Cmd->callback([args] {
        prepareReproduce(*args);
        ThreadLimit limit(args->threads);
        const std::string md = writeTable1(table1(args->table, printProgress), args->dir);
        std::printf("%s\nwrote table1.csv, table1.md and plots to %s\n", md.c_str(), args->dir.c_str());
    });
    auto* figure4Cmd = cmd->add_subcommand("figure4", "Figure 4: reference, exact-statistics and estimated filtering");
    addReproduceFlags(*figure4Cmd, *args, false, true);
    figure4Cmd->callback([args] {
        prepareReproduce(*args);
        ThreadLimit limit(args->threads);
        const Figure4Result r = figure4(args->figure4, printProgress);
        writeFigure4(r, args->dir);
        std::printf("%s\nwrote figure4.png, figure4.csv and the images to %s\n", r.table.markdown().c_str(),
                    args->dir.c_str());
    });
    auto* figures79 = cmd->add_subcommand("figures7-9", "Figures 7–9: colormap layouts, palettes, noise spectra");
    addReproduceFlags(*figures79, *args, false, false);
    figures79->add_option("--size", args->sheetSize, "Pattern size in each sheet")->capture_default_str();
    figures79->callback([args] {
        prepareReproduce(*args);
        ThreadLimit limit(args->threads);
        ensureFolder(args->dir);
        writeFigures(args->dir, figures7to9(args->sheetSize, printProgress));
        std::printf("wrote figure7.png, figure8.png, figure9.png to %s\n", args->dir.c_str());
    });
    registerReproduceAll(*cmd, args);
}

}  // namespace stochtex::cli
