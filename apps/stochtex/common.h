#pragma once
// Pieces shared by the CLI commands: the pattern source (file or preset),
// the view flags, inline-or-file JSON arguments, output checks.
#include <CLI/CLI.hpp>
#include <array>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "stochtex/core/atomic_file.h"
#include "stochtex/core/enum_names.h"
#include "stochtex/core/error.h"
#include "stochtex/gpu/gpu_view.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/report/page.h"
#include "stochtex/report/table.h"

namespace stochtex::cli {

struct PatternSource {
    std::string file;
    std::string preset;
    std::optional<uint32_t> seed;
};
// PATTERN or --pattern FILE | --preset NAME (one is required; no default),
// and --seed to override the pattern's.
void addPatternSource(CLI::App& cmd, PatternSource& src);
PatternSpec loadPatternSource(const PatternSource& src);
// The pattern as the user gave it (the preset's text, the inline JSON or
// the file's text), for pages that show their source as written.
std::string patternSourceText(const PatternSource& src);
// The same for a render with these filter options, refused before any work
// when they prefilter the colormap and it is too fine for that (an analytic,
// phasor or painted one: its resolution is known; an image's is checked when
// it is read).
PatternSpec loadPatternSource(const PatternSource& src, const FilterOptions& options);
// The same for a command with one filter and --estimator, which takes the
// pattern file's estimator ("estimator") where --estimator was not given.
PatternSpec loadPatternSource(const CLI::App& cmd, const PatternSource& src, FilterOptions& options);
// The same for a command that renders with several filters (stability's
// --filters): checked as the first of them that prefilters the colormap.
PatternSpec loadPatternSource(const PatternSource& src, const std::vector<FilterOptions>& filters);

struct ViewFlags {
    std::vector<int> size;  // N or W,H
    std::optional<double> scale;
    std::vector<double> offset;  // X,Y in texels
};
void addViewFlags(CLI::App& cmd, ViewFlags& flags);
View makeView(const PatternSpec& spec, const ViewFlags& flags, ViewUse use = ViewUse::Render);

// A JSON argument: inline if it starts with '{' (or '"'), else a file path.
struct JsonArgument {
    std::string text;  // as given: the inline argument or the file's text
    nlohmann::json json;
    std::string source;
    std::filesystem::path baseDir;
};
JsonArgument readJsonArgument(const std::string& arg);
// How messages name the argument: "<inline JSON>" or the file path.
std::string readJsonArgumentSource(const std::string& arg);

// Fails early (before any work) unless path has an image extension whose
// format holds `bits` (checkImageOutputFormat), is not a folder, and is in
// an existing folder that can be written.
void checkImageOutput(const std::string& path, int bits = 8);
// The same without the format is the library's checkOutputFile (core/atomic_file.h).

// --seed (or another seed flag): an integer in [0, 4294967295], the range of
// every seed; anything else is refused with the reason, before conversion.
CLI::Option* addSeedFlag(CLI::App& cmd, const std::string& flag, std::optional<uint32_t>& seed,
                         const std::string& help);
CLI::Option* addSeedFlag(CLI::App& cmd, const std::string& flag, uint32_t& seed, const std::string& help);

// --bits 8|16, the PNG bit depth (default 8).
CLI::Option* addBitsFlag(CLI::App& cmd, int& bits);
// InputError naming --bits when it was given for an output it cannot change
// (EXR stores 32-bit floats).
void checkBitsApply(const CLI::Option* bits, const std::string& output);

// Options that would change nothing in the mode the command runs in are
// refused rather than silently ignored: InputError "FLAG: has no effect
// WHY" when `option` was given and !hasEffect (main exits 2).
void refuseWithoutEffect(const CLI::Option* option, bool hasEffect, const std::string& why);
// What the user gives `option` by: its first long name, else its short one ("--size", "-o").
std::string optionFlag(const CLI::Option* option);
// Refuses an option's value: InputError "FLAG: MESSAGE" (main exits 2), the
// flag named by the option itself, so no message spells a flag by hand and a
// renamed flag renames its errors (tests/lint/no_hand_built_flag_errors.sh).
[[noreturn]] void refuseOption(const CLI::Option* option, const std::string& message);
// The same for cmd's option `name` ("--size"), which must exist (CLI11's
// OptionNotFound otherwise: a bug, exit 1).
[[noreturn]] void refuseOption(const CLI::App& cmd, const std::string& name, const std::string& message);
// An "N or W,H" size flag's value as {width, height}, each side in
// [1, maxSide]; refused through `option` otherwise.
std::array<int, 2> sizeFlagValue(const CLI::Option* option, const std::vector<int>& size, int maxSide);

// CLI11's transformer over an enum's name table (the table the library, the
// JSON reader and the bake manifest use). It reads the name with parseEnum,
// so a bad one reads `--flag: parameter must be a or b, got "x"` like a
// library error (CLI::CheckedTransformer would list the enum's numbers); the
// help lists the names. enumNameError: parseEnum's message for a name not
// in the table, empty for one that is.
template <class E>
std::string enumNameError(const EnumNames<E>& names, const std::string& s, const std::string& parameter) {
    try {
        parseEnum(names, s, parameter);
        return {};
    } catch (const InputError& e) {
        return e.what();
    }
}
template <class E>
CLI::Validator enumTransformer(const EnumNames<E>& names, const std::string& parameter) {
    return CLI::Validator(
        [names, parameter](std::string& s) {
            const std::string error = enumNameError(names, s, parameter);
            if (error.empty()) s = std::to_string(static_cast<std::underlying_type_t<E>>(*findEnum(names, s)));
            return error;
        },
        "{" + canonicalNames(names, ", ") + "}");
}

// The check half of enumTransformer, for tables whose values are not enums
// (kFilterNames): the name is left as it is for the option's callback.
template <class E>
CLI::Validator nameValidator(const EnumNames<E>& names, const std::string& parameter) {
    return CLI::Validator([names, parameter](std::string& s) { return enumNameError(names, s, parameter); },
                          "{" + canonicalNames(names, ", ") + "}");
}

// Says that `option` sets the library parameter `parameter` in command
// `cmd`, for the library's errors about it (describeInputError). A flag
// named after its parameter in kebab case (--radial-bins: radialBins) needs
// no binding; the others are bound where they are declared: the correlation
// plots' extent, "plotSize", is --size in `correlation` (--plot-size in
// `analyze`), --filter sets the statistics source. Returns option.
CLI::Option* bindParameter(const CLI::App& cmd, CLI::Option* option, const std::string& parameter);

// A flag whose value is one name of the table; the default shown is the value's.
template <class E>
CLI::Option* addEnumFlag(CLI::App& cmd, const std::string& flag, E& value, const EnumNames<E>& names,
                         const std::string& parameter, const std::string& help) {
    CLI::Option* option = cmd.add_option(flag, value, help)
                              ->transform(enumTransformer(names, parameter))
                              ->default_str(enumName(names, value));
    return bindParameter(cmd, option, parameter);
}

// --threads,-j N: default 0 = all cores.
void addThreadsFlag(CLI::App& cmd, int& threads);

// --filter NAME over kFilterNames: a named pair of statistics source and
// response, handed to `set` (which may throw InputError for a pair the
// command cannot use); `shown` is the default the help lists.
// `names`: the filters the command takes (its help lists them, and any other
// is refused by name).
void addFilterFlag(CLI::App& cmd, std::function<void(const NamedFilter&)> set, const std::string& shown,
                   const std::string& help, const EnumNames<NamedFilter>& names = kFilterNames);
// --filter NAME setting both axes of `options`; the default is the options'
// own (each command documents why it starts where it does).
void addFilterFlag(CLI::App& cmd, FilterOptions& options, const std::string& help,
                   const EnumNames<NamedFilter>& names = kFilterNames);
// The named filters the GPU renders (none, paper, smooth): the --filter of
// the commands that draw with OpenGL only (scene, view, bake-image's bands).
const EnumNames<NamedFilter>& gpuFilterNames();

// --response NAME (kResponseKindNames) and --no-covariance: the response
// axis of the filter (pattern/filter_options.h). --filter names a pair with the
// prefiltered colormap; --response lean shades the pattern's normal map
// instead, from the statistics the filter names (none: the point's slope;
// paper/smooth: the estimators; exact; reference: supersampled shading).
struct ResponseFlags {
    std::optional<ResponseKind> kind;
    bool noCovariance = false;  // lean without ĉov (paper Fig. 12's variant)
};
void addResponseFlags(CLI::App& cmd, ResponseFlags& flags);
// Sets options.response from the flags (after --filter, which sets both
// axes); --no-covariance without the lean response is refused.
void applyResponseFlags(const CLI::App& cmd, const ResponseFlags& flags, FilterOptions& options);

// --estimator NAME (kVarianceEstimatorNames): the footprint estimator of
// paper and smooth (refused with the other filters: refuseUnusedFilterFlags).
CLI::Option* addEstimatorFlag(CLI::App& cmd, FilterOptions& options);
// --aniso K (anisoParam(): 1..16, the library checks the range), set to its default, 8.
CLI::Option* addAnisoFlag(CLI::App& cmd, int& aniso);
// The checks of the filter-dependent flags: --aniso (and --estimator, --pack8:
// the estimators' only) need paper or smooth, --reference-samples needs
// exact or reference; each refused (refuseWithoutEffect) when given for a
// filter that ignores it. Flags a command does not have are skipped.
void refuseUnusedFilterFlags(const CLI::App& cmd, const FilterOptions& options);
// The same for a list of filters (--filters): --aniso refused unless one of
// them is paper or smooth, --reference-samples unless one is exact or reference.
void refuseUnusedFilterFlags(const CLI::App& cmd, const std::vector<FilterOptions>& filters);

// --view zoom|plane, --tilt and (withFov) --fov: the camera's defaults
// (pattern/camera.h) are the flags'.
void addCameraFlags(CLI::App& cmd, Camera& camera, bool withFov = true);
// --tilt and --fov refused in the zoom view (refuseWithoutEffect).
void refuseUnusedCameraFlags(const CLI::App& cmd, const Camera& camera);

// --pipeline fragment|compute of the --gpu commands (default fragment).
void addPipelineFlag(CLI::App& cmd, GpuView::Pipeline& pipeline);

// Every option of app and its commands shows its default in --help (main
// sets always_capture_default); a list reads as it is typed ("768,512", not
// CLI11's "[768,512]"), and an empty one not at all (its help text says
// what is used, e.g. "the pattern's").
void tidyDefaults(CLI::App& app);

// A parse error's message as the user reads it when CLI11's would not say
// what is wrong (CLI11 reports "A subcommand is required" for `rendr`): an
// unknown command or option among args (argv without the program), named
// with the command it was given to and the nearest known name; empty when
// the arguments show no such mistake (CLI11's own message is then right).
std::string explainParseError(const CLI::App& app, const std::vector<std::string>& args);

// The option a library parameter's entry describes (ParamInfo: the flag, the
// help and the range it shows), bound to the parameter so that the
// library's errors about it name the flag; its default shown is `value`'s.
template <class T>
CLI::Option* addParameterOption(CLI::App& cmd, const ParamInfo& p, T& value) {
    const std::string range = "[" + formatValue(p.min) + ", " + formatValue(p.max) + "]";
    CLI::Option* option = cmd.add_option("--" + p.flag, value, p.description + ", in " + range);
    return bindParameter(cmd, option->capture_default_str(), p.name);
}

// The option of one member of an option struct (OptionMember), setting o's member.
template <class Options>
CLI::Option* addMemberOption(CLI::App& cmd, const OptionMember<Options>& m, Options& o) {
    return std::visit([&](auto p) { return addParameterOption(cmd, m.info, o.*p); }, m.member);
}

// An option for each member `members` describes, in the table's order.
template <class Options>
void addParameterOptions(CLI::App& cmd, std::span<const OptionMember<Options>> members, Options& o) {
    for (const OptionMember<Options>& m : members) addMemberOption(cmd, m, o);
}

// An InputError as the user reads it: a library parameter error is prefixed
// with the flag that sets the parameter ("--aniso: aniso must be in [1, 16],
// got 0") in `ran` (the command that ran) or the nearest command above it
// — the option bound to the parameter (bindParameter) or named after it;
// one no command sets, and any other error, as it is.
std::string describeInputError(const InputError& e, const CLI::App* ran = nullptr);
// What follows a budget's refusal (InputError::isOverBudget, a watchdog's
// overrun): how --budget raises it, e.g. " (--budget 4 allows 4× the budgets)".
std::string budgetAdvice();
// The innermost command the parsed arguments chose (app itself if none).
const CLI::App* commandThatRan(const CLI::App& app);

// -o,--output FOLDER, required (what: its help text).
void addOutputFolderFlag(CLI::App& cmd, std::string& dir, const std::string& what = "Output folder");
// -o,--output IMAGE, required (checkImageOutput checks it before any work).
void addOutputImageFlag(CLI::App& cmd, std::string& path,
                        const std::string& what = std::string("Output image (") + kImageOutputFormats + ")");

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
void registerSpectrum(CLI::App& app);
void registerFlow(CLI::App& app);
void registerCoherence(CLI::App& app);
void registerFractalize(CLI::App& app);
void registerStimuli(CLI::App& app);
void registerMarble(CLI::App& app);
void registerNodes(CLI::App& app);
void registerReproduce(CLI::App& app);
void registerScene(CLI::App& app);
void registerView(CLI::App& app);
void registerBake(CLI::App& app);
void registerBakeImage(CLI::App& app);
void registerWeb(CLI::App& app);
void registerShadertoy(CLI::App& app);

}  // namespace stochtex::cli
