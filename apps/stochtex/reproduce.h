#pragma once
// The flags and outputs shared by the `reproduce` subcommands.
#include <memory>
#include <optional>
#include <string>

#include "common.h"
#include "stochtex/studies/normal_maps.h"
#include "stochtex/studies/paper.h"

namespace stochtex::cli {

struct ReproduceArgs {
    std::string dir;
    Table1Options table;
    Figure4Options figure4;
    Figure12Options figure12;
    std::optional<double> roughness;  // figure 12: overrides the normal map's
    int sheetSize = 384;
    int threads = 0;
};
// -o and --threads; with table: --count, --footprints, --seed,
// --footprint-seed; with figure4: --preset, --size, --reference-samples, --filter.
void addReproduceFlags(CLI::App& sub, ReproduceArgs& args, bool table, bool figure4);
// Figure 12: --preset, --size (the view's width; height 5/8 of it),
// --reference-samples, --tilt, --aniso, --roughness.
void addFigure12Flags(CLI::App& sub, ReproduceArgs& args);
// Loads the preset and validates every option: InputError before any work.
void prepareReproduce(ReproduceArgs& args);
// The same for figure 12 (its preset and options).
void prepareFigure12(ReproduceArgs& args);
// Writes figure12.png, figure12.csv and the images.
void writeFigure12(const Figure12Result& r, const std::string& dir);

// Writes table1.csv, table1.md and the plots; returns the tables as Markdown.
std::string writeTable1(const Table1Result& r, const std::string& dir);
// Writes figure4.png, figure4.csv and the images per footprint.
void writeFigure4(const Figure4Result& r, const std::string& dir);

void registerReproduceAll(CLI::App& reproduce, std::shared_ptr<ReproduceArgs> args);

}  // namespace stochtex::cli
