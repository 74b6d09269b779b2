#pragma once
// Pieces shared by the CLI commands: the pattern source (file or preset),
// the view flags, inline-or-file JSON arguments, output checks.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/gpu/gpu_pattern.h"
#include "stochtex/pattern/filtered_pattern.h"
#include "stochtex/report/page.h"
#include "stochtex/report/table.h"
#include "stochtex/pattern/pattern.h"
#include "stochtex/pattern/pattern_spec.h"

namespace stochtex::cli {

struct PatternSource {
    std::string file;
    std::string preset;
    std::optional<int64_t> seed;
};
void addPatternSource(CLI::App& cmd, PatternSource& src);
PatternSpec loadPatternSource(const PatternSource& src);

struct ViewFlags {
    std::vector<int> size;          // N or W,H
    std::optional<double> scale;
    std::vector<double> offset;     // X,Y in texels
};
void addViewFlags(CLI::App& cmd, ViewFlags& flags);
View makeView(const PatternSpec& spec, const ViewFlags& flags);

// A JSON argument: inline if it starts with '{' (or '"'), else a file path.
struct JsonArgument {
    nlohmann::json json;
    std::string source;
    std::filesystem::path baseDir;
};
JsonArgument readJsonArgument(const std::string& arg);

// Fails early (before any work) if path is not a .png/.exr in an existing folder.
void checkImageOutput(const std::string& path);

void addThreadsFlag(CLI::App& cmd, int& threads);

// --filter MODE over kFilterModeNames (the default shown is the value's).
void addFilterModeFlag(CLI::App& cmd, FilterMode& mode, const std::string& help);

// A study's progress line on stderr.
void printProgress(const std::string& line);

// --pipeline fragment|compute of the --gpu commands; parsePipeline throws
// InputError naming the flag for any other value.
void addPipelineFlag(CLI::App& cmd, std::string& pipeline);
GpuPattern::Pipeline parsePipeline(const std::string& pipeline);

// An InputError as the user reads it: a library parameter error is prefixed
// with the flag that sets the parameter ("--aniso: aniso must be in [1, 16],
// got 0"); any other error as it is.
std::string describeInputError(const InputError& e);

// -o,--output FOLDER, required (what: its help text).
void addOutputFolderFlag(CLI::App& cmd, std::string& dir, const std::string& what = "Output folder");

// Registration of each command (one file each).
void registerRender(CLI::App& app);
void registerGallery(CLI::App& app);
void registerNoise(CLI::App& app);
void registerColormap(CLI::App& app);
void registerPresets(CLI::App& app);
void registerStability(CLI::App& app);
void registerZoom(CLI::App& app);
void registerCorrelation(CLI::App& app);
void registerContrast(CLI::App& app);
void registerAnalyze(CLI::App& app);
void registerReproduce(CLI::App& app);
void registerScene(CLI::App& app);
void registerView(CLI::App& app);
void registerBake(CLI::App& app);
void registerBakeImage(CLI::App& app);

}  // namespace stochtex::cli
