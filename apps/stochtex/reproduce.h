#pragma once
// The flags and outputs shared by the `reproduce` subcommands.
#include <memory>
#include <string>

#include "common.h"
#include "stochtex/studies/paper.h"

namespace stochtex::cli {

struct ReproduceArgs {
    std::string dir;
    Table1Options table;
    Figure4Options figure4;
    int sheetSize = 384;
    int threads = 0;
};
// -o and --threads; with table: --count, --footprints, --seed,
// --footprint-seed; with figure4: --preset, --size, --reference-samples, --filter.
void addReproduceFlags(CLI::App& sub, ReproduceArgs& args, bool table, bool figure4);
// Loads the preset and validates every option: InputError before any work.
void prepareReproduce(ReproduceArgs& args);

// Writes table1.csv, table1.md and the plots; returns the tables as Markdown.
std::string writeTable1(const Table1Result& r, const std::string& dir);
// Writes figure4.png, figure4.csv and the images per footprint.
void writeFigure4(const Figure4Result& r, const std::string& dir);

void registerReproduceAll(CLI::App& reproduce, std::shared_ptr<ReproduceArgs> args);

}  // namespace stochtex::cli
