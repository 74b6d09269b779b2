// stochtex reproduce: the paper's accuracy evidence, one command each —
// Table 1 (estimator errors), Figure 4 (filtered vs reference images and
// error maps), Figures 7–9 (colormap layouts, palettes, noise spectra),
// Figure 10 (phasor variants; procedural phasor noise beside ours), Figure 11
// (filtering the phasor sine pattern), Figure 12 (LEAN-mapped normal maps),
// Figure 14 (a texture graph filtered by moment matching) — and
// `all`, which runs them and writes an index.html (reproduce_all.cpp); beyond
// the paper, `estimators` (each footprint estimator's rendered error).
#include "reproduce.h"
#include "common.h"

namespace stochtex::cli {

void registerReproduce(CLI::App& app) {
    auto args = std::make_shared<ReproduceArgs>();
    auto* cmd = app.add_subcommand("reproduce",
                                   "Regenerate the paper's evidence: table1, figure4, figure10, figure11, figure12, "
                                   "figure14, figures7-9, all; and estimators");
    cmd->require_subcommand(1);
    auto* table1Cmd =
        cmd->add_subcommand("table1", "Table 1: mean errors of μ̂ and σ̂ against exact footprint statistics");
    addReproduceFlags(*table1Cmd, *args, true, nullptr);
    table1Cmd->callback([args] {
        prepareReproduce(*args);
        runReproduction(*args, "table1", [&](const Progress& p) {
            const Table1Result r = table1(args->table, p);
            std::string md;
            for (const Table& t : r.tables) md += "\n" + t.markdown();
            return writeReproduction(args->dir, table1Report(r), md);
        });
    });
    const auto addFigure = [&](const std::string& figure, const std::string& help, Figure4Options* options) {
        auto* sub = cmd->add_subcommand(figure, help);
        addReproduceFlags(*sub, *args, false, options);
        sub->callback([args, figure, options] {
            prepareReproduce(*args);
            runReproduction(*args, figure, [&](const Progress& p) {
                const Figure4Result r = stochtex::figure4(*options, p);
                return writeReproduction(args->dir, figure4Report(r, figure), r.table.markdown());
            });
        });
    };
    addFigure("figure4", "Figure 4: reference, exact-statistics and estimated filtering", &args->figure4);
    auto* figure10Cmd =
        cmd->add_subcommand("figure10", "Figure 10: the phasor variants, and procedural phasor noise beside ours");
    addFigure10Flags(*figure10Cmd, *args);
    figure10Cmd->callback([args] {
        prepareReproduce(*args);
        runReproduction(*args, "figure10", [&](const Progress& p) {
            const Figure10Result r = figure10(args->figure10, p);
            return writeReproduction(args->dir, figure10Report(r), r.table.markdown());
        });
    });
    addFigure("figure11", "Figure 11: filtering the phasor sine pattern: reference, estimated, error", &args->figure11);
    auto* figures79 = cmd->add_subcommand("figures7-9", "Figures 7–9: colormap layouts, palettes, noise spectra");
    addReproduceFlags(*figures79, *args, false, nullptr);
    figures79->add_option("--size", args->sheetSize, "Pattern size in each sheet")->capture_default_str();
    figures79->callback([args] {
        prepareReproduce(*args);
        ensureFolder(args->dir);
        runReproduction(*args, "figures7-9", [&](const Progress& p) {
            return writeReproduction(args->dir, figures7to9Report(figures7to9(args->sheetSize, p)));
        });
    });
    auto* figure12Cmd = cmd->add_subcommand("figure12", "Figure 12: LEAN-mapped procedural normal map, four variants");
    addFigure12Flags(*figure12Cmd, *args);
    figure12Cmd->callback([args] {
        prepareFigure12(*args);
        runReproduction(*args, "figure12", [&](const Progress& p) {
            const Figure12Result r = figure12(args->figure12, p);
            return writeReproduction(args->dir, figure12Report(r), r.table.markdown());
        });
    });
    registerReproduceFigure14(*cmd, args);
    registerReproduceEstimators(*cmd, args);
    registerReproduceAll(*cmd, args);
}

}  // namespace stochtex::cli
