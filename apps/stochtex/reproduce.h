#pragma once
// The flags and outputs shared by the `reproduce` subcommands.
#include <memory>
#include <string>

#include "common.h"
#include "stochtex/studies/paper.h"
#include "stochtex/studies/phasor_figures.h"

namespace stochtex::cli {

struct ReproduceArgs {
    std::string dir;
    Table1Options table;
    Figure4Options figure4;
    Figure4Options figure11 = figure11Options();
    Figure10Options figure10;
    int sheetSize = 384;
    int threads = 0;
};
// -o and --threads; with table: --count, --footprints, --seed,
// --footprint-seed; with a figure (&args.figure4 or &args.figure11): --size,
// --reference-samples, --filter, and --preset for figure 4, --footprints for
// figure 11.
void addReproduceFlags(CLI::App& sub, ReproduceArgs& args, bool table, Figure4Options* figure);
// figure10's flags: --size, --comparison-size, --frequency, --bandwidth,
// --orientation, --density, --seed.
void addFigure10Flags(CLI::App& sub, ReproduceArgs& args);
// Loads the preset and validates every option: InputError before any work.
void prepareReproduce(ReproduceArgs& args);

// Writes table1.csv, table1.md and the plots; returns the tables as Markdown.
std::string writeTable1(const Table1Result& r, const std::string& dir);
// Writes <figure>.png, <figure>.csv and the images per footprint (figures 4, 11).
void writeFigure4(const Figure4Result& r, const std::string& figure, const std::string& dir);
// Writes figure10.png, figure10_comparison.png and figure10.csv.
void writeFigure10(const Figure10Result& r, const std::string& dir);

void registerReproduceAll(CLI::App& reproduce, std::shared_ptr<ReproduceArgs> args);

}  // namespace stochtex::cli
