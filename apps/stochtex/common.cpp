#include "common.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string_view>
#include <utility>

#include <unistd.h>  // access

#include "stochtex/core/budget.h"
#include "stochtex/core/error.h"
#include "stochtex/core/names.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/presets.h"

namespace stochtex::cli {
namespace fs = std::filesystem;

void addPatternSource(CLI::App& cmd, PatternSource& src) {
    auto* file = cmd.add_option("pattern,--pattern", src.file,
                                "Pattern: a JSON file or inline JSON ({\"noise_x\":...}; see docs/PATTERNS.md)");
    auto* preset = cmd.add_option("--preset,-p", src.preset, "Embedded preset name (stochtex presets lists them)");
    file->excludes(preset);
    addSeedFlag(cmd, "--seed", src.seed, "Override the pattern seed");
}

PatternSpec loadPatternSource(const PatternSource& src) {
    if (src.file.empty() && src.preset.empty()) throw InputError("give a pattern file or --preset NAME");
    PatternSpec spec;
    if (src.file.empty()) {
        spec = loadPreset(src.preset);
    } else {
        const JsonArgument json = readJsonArgument(src.file);  // inline like noise and colormap specs
        spec = parsePatternSpec(JsonReader(json.json, json.source), json.baseDir);
    }
    if (src.seed) spec.seed = *src.seed;
    return spec;
}

std::string patternSourceText(const PatternSource& src) {
    return src.file.empty() ? std::string(presetText(src.preset)) : readJsonArgument(src.file).text;
}

namespace {

bool prefiltersColormap(const FilterOptions& options) {
    return options.source != StatisticsSource::Point && options.response.kind == ResponseKind::PrefilteredColormap;
}

}  // namespace

PatternSpec loadPatternSource(const PatternSource& src, const FilterOptions& options) {
    PatternSpec spec = loadPatternSource(src);
    if (!prefiltersColormap(options) || spec.colormap.source == ColormapSpec::Source::Image) return spec;
    try {
        validatePrefilteredResolution(spec.colormap.resolution, spec.colormap.resolution);
    } catch (const InputError& e) {
        throw InputError((src.file.empty() ? "preset " + src.preset : readJsonArgumentSource(src.file)) +
                         ": /colormap/resolution: " + e.what() + " (--filter " + filterName(options) + ")");
    }
    return spec;
}

PatternSpec loadPatternSource(const CLI::App& cmd, const PatternSource& src, FilterOptions& options) {
    PatternSpec spec = loadPatternSource(src, options);
    const CLI::Option* flag = cmd.get_option_no_throw("--estimator");
    if (spec.estimator && (!flag || flag->count() == 0)) options.estimator = *spec.estimator;
    return spec;
}

PatternSpec loadPatternSource(const PatternSource& src, const std::vector<FilterOptions>& filters) {
    for (const FilterOptions& f : filters)
        if (prefiltersColormap(f)) return loadPatternSource(src, f);
    return loadPatternSource(src);
}

void addViewFlags(CLI::App& cmd, ViewFlags& flags) {
    cmd.add_option("--size", flags.size, "Output size in pixels: N or W,H (default: the pattern's)")
        ->delimiter(',')
        ->expected(1, 2);
    cmd.add_option("--scale", flags.scale, "Example texels per output pixel (>1 zooms out; default: the pattern's)");
    cmd.add_option("--offset", flags.offset, "Texture-space offset X,Y in example texels")->delimiter(',')->expected(2);
}

View makeView(const PatternSpec& spec, const ViewFlags& flags, ViewUse use) {
    // Errors name size, scale or offset: main adds the flag.
    return patternView(spec, flags.size, flags.scale, flags.offset, use);
}

std::string readJsonArgumentSource(const std::string& arg) {
    const size_t first = arg.find_first_not_of(" \t\n");
    return first != std::string::npos && arg[first] == '{' ? "<inline JSON>" : arg;
}

JsonArgument readJsonArgument(const std::string& arg) {
    JsonArgument a;
    a.source = readJsonArgumentSource(arg);
    if (a.source != arg) {
        a.text = arg;
        a.json = JsonReader::parse(a.text, a.source);
        a.baseDir = ".";
    } else {
        a.text = readJsonText(arg);
        a.json = JsonReader::parse(a.text, arg);
        a.baseDir = fs::path(arg).has_parent_path() ? fs::path(arg).parent_path() : fs::path(".");
    }
    return a;
}

void checkImageOutput(const std::string& path, int bits) {
    checkImageOutputFormat(path, WriteOptions{bits});
    checkOutputFile(path);
}

namespace {
// A CLI11 check (run on the text, before conversion) that the value is a seed.
CLI::Validator seedValidator() {
    return CLI::Validator(
        [](std::string& s) -> std::string {
            const std::string problem = "seed must be an integer in [0, 4294967295], got \"" + s + "\"";
            if (s.empty() || s.size() > 10 || s.find_first_not_of("0123456789") != std::string::npos) return problem;
            return std::stoull(s) > 4294967295ULL ? problem : std::string();
        },
        "UINT32");
}
}  // namespace

CLI::Option* addSeedFlag(CLI::App& cmd, const std::string& flag, std::optional<uint32_t>& seed,
                         const std::string& help) {
    return cmd.add_option(flag, seed, help)->check(seedValidator());
}

CLI::Option* addSeedFlag(CLI::App& cmd, const std::string& flag, uint32_t& seed, const std::string& help) {
    return cmd.add_option(flag, seed, help)->check(seedValidator())->capture_default_str();
}

CLI::Option* addBitsFlag(CLI::App& cmd, int& bits) {
    return cmd.add_option("--bits", bits, "Bits per channel of PNG and TIFF output: 8 or 16 (JPEG: 8)")
        ->check(CLI::Validator(
            [](std::string& s) -> std::string {
                return s == "8" || s == "16" ? std::string() : "bits must be 8 or 16, got \"" + s + "\"";
            },
            "8|16"))
        ->capture_default_str();
}

void checkBitsApply(const CLI::Option* bits, const std::string& output) {
    const bool exr = output.size() >= 4 && output.compare(output.size() - 4, 4, ".exr") == 0;
    refuseWithoutEffect(bits, !exr, "with an .exr output (EXR stores 32-bit floats)");
}

void refuseWithoutEffect(const CLI::Option* option, bool hasEffect, const std::string& why) {
    if (!option || option->count() == 0 || hasEffect) return;
    refuseOption(option, "has no effect " + why);
}

std::string optionFlag(const CLI::Option* option) {
    return option->get_lnames().empty() ? "-" + option->get_snames().front() : "--" + option->get_lnames().front();
}

void refuseOption(const CLI::Option* option, const std::string& message) {
    throw InputError(optionFlag(option) + ": " + message);
}

void refuseOption(const CLI::App& cmd, const std::string& name, const std::string& message) {
    refuseOption(cmd.get_option(name), message);
}

std::array<int, 2> sizeFlagValue(const CLI::Option* option, const std::vector<int>& size, int maxSide) {
    const int w = size.at(0), h = size.size() > 1 ? size[1] : size[0];
    if (w < 1 || h < 1 || w > maxSide || h > maxSide)
        refuseOption(option, "size must be in [1, " + std::to_string(maxSide) + "] per side, got " + std::to_string(w) +
                                 "x" + std::to_string(h));
    return {w, h};
}

void addThreadsFlag(CLI::App& cmd, int& threads) {
    cmd.add_option("--threads,-j", threads, "Worker threads (0 = all cores; output is identical for any value)")
        ->check(CLI::Range(0, 1024));
}

void addFilterFlag(CLI::App& cmd, std::function<void(const NamedFilter&)> set, const std::string& shown,
                   const std::string& help, const EnumNames<NamedFilter>& names) {
    cmd.add_option_function<std::string>(
           "--filter", [set](const std::string& s) { set(parseFilter(s)); }, help)
        ->check(nameValidator(names, "filter"))
        ->type_name("ENUM")
        ->default_str(shown);
    // A filter names a statistics source: the library's errors about it are the flag's.
    bindParameter(cmd, cmd.get_option("--filter"), "source");
}

void addFilterFlag(CLI::App& cmd, FilterOptions& options, const std::string& help,
                   const EnumNames<NamedFilter>& names) {
    addFilterFlag(
        cmd, [&options](const NamedFilter& f) { options.use(f); }, filterName(options), help, names);
}

const EnumNames<NamedFilter>& gpuFilterNames() {
    static const EnumNames<NamedFilter> names = [] {
        EnumNames<NamedFilter> out;
        for (const auto& entry : kFilterNames)
            if (gpuHasSource(entry.second.source)) out.push_back(entry);
        return out;
    }();
    return names;
}

void addResponseFlags(CLI::App& cmd, ResponseFlags& flags) {
    cmd.add_option("--response", flags.kind,
                   "What the statistics become: prefiltered-colormap (the pattern's colours) | lean (its "
                   "normal_map, shaded; docs/PATTERNS.md) | normal | roughness | height (its normal_map's PBR maps, "
                   "as data)")
        ->transform(enumTransformer(kResponseKindNames, "response"))
        ->default_str(enumName(kResponseKindNames, ResponseKind::PrefilteredColormap));
    cmd.add_flag("--no-covariance", flags.noCovariance,
                 "--response lean without the slopes' covariance (paper Fig. 12's variant)");
}

void applyResponseFlags(const CLI::App& cmd, const ResponseFlags& flags, FilterOptions& options) {
    if (flags.kind) options.response.kind = *flags.kind;
    refuseWithoutEffect(cmd.get_option_no_throw("--no-covariance"), options.response.kind == ResponseKind::Lean,
                        "without --response lean (only the normal map's slopes are correlated)");
    if (flags.noCovariance) options.response.covariance = false;
}

CLI::Option* addEstimatorFlag(CLI::App& cmd, FilterOptions& options) {
    return addEnumFlag(cmd, "--estimator", options.estimator, kVarianceEstimatorNames, "estimator",
                       "Footprint estimator: paper | deliot-heitz (one variance per LOD) | sub-probes (the paper's, "
                       "each probe as 2x2 one level finer: 4x the fetches, 0.24-0.43x its sigma error at 2-8 texels "
                       "on Table 1, 1.4-2.1x its time) | sub-probes-4x4 (4x4 two levels finer: 16x the fetches, "
                       "0.04-0.45x its sigma error at 2-16 texels, 3-5.3x its time) | sub-probes-8x8-fine-means "
                       "(8x8 three levels finer, each one's mean from 2x2 reads one level finer: 64-320x the fetches, "
                       "0.00-0.21x its sigma error at 2-32 texels and 0.18-0.68x at 64-128, renders at 0.98-1.02x the "
                       "exact floor at 2-32 texels a pixel, 20-115x its time on the CPU; docs/RESULTS.md)");
}

CLI::Option* addAnisoFlag(CLI::App& cmd, int& aniso) {
    aniso = kDefaultAniso;
    return addParameterOption(cmd, anisoParam(), aniso);
}

void refuseUnusedFilterFlags(const CLI::App& cmd, const FilterOptions& options) {
    const std::string filter = "with --filter " + filterName(options);
    const bool estimators = options.source == StatisticsSource::Estimators;
    const bool bruteForce = options.source == StatisticsSource::Exact || options.source == StatisticsSource::Reference;
    refuseWithoutEffect(cmd.get_option_no_throw("--aniso"), estimators,
                        filter + " (only the estimators of paper and smooth take anisotropic probes)");
    refuseWithoutEffect(cmd.get_option_no_throw("--estimator"), estimators,
                        filter + " (only paper and smooth estimate the variance)");
    refuseWithoutEffect(cmd.get_option_no_throw("--pack8"), estimators,
                        filter + " (only paper and smooth read the pyramids)");
    refuseWithoutEffect(cmd.get_option_no_throw("--reference-samples"), bruteForce,
                        filter + " (only exact and reference sample the footprint)");
}

void refuseUnusedFilterFlags(const CLI::App& cmd, const std::vector<FilterOptions>& filters) {
    const auto any = [&](auto uses) { return std::any_of(filters.begin(), filters.end(), uses); };
    refuseWithoutEffect(cmd.get_option_no_throw("--aniso"),
                        any([](const FilterOptions& f) { return f.source == StatisticsSource::Estimators; }),
                        "without paper or smooth in --filters (only their estimators take anisotropic probes)");
    refuseWithoutEffect(cmd.get_option_no_throw("--reference-samples"), any([](const FilterOptions& f) {
                            return f.source == StatisticsSource::Exact || f.source == StatisticsSource::Reference;
                        }),
                        "without exact or reference in --filters (only they sample the footprint)");
}

void addCameraFlags(CLI::App& cmd, Camera& camera, bool withFov) {
    addEnumFlag(cmd, "--view", camera.kind, Camera::kKindNames, "view",
                "zoom (flat, --scale texels per pixel) | plane (perspective ground plane)");
    addParameterOption(cmd, cameraTiltParam(), camera.tiltDeg);
    if (withFov) addParameterOption(cmd, cameraFovParam(), camera.fovDeg);
}

void refuseUnusedCameraFlags(const CLI::App& cmd, const Camera& camera) {
    const bool plane = camera.kind == Camera::Kind::Plane;
    refuseWithoutEffect(cmd.get_option_no_throw("--tilt"), plane, "in the zoom view (only --view plane is tilted)");
    refuseWithoutEffect(cmd.get_option_no_throw("--fov"), plane,
                        "in the zoom view (only --view plane has a field of view)");
}

void addPipelineFlag(CLI::App& cmd, GpuView::Pipeline& pipeline) {
    addEnumFlag(cmd, "--pipeline", pipeline, kGpuPipelineNames, "pipeline",
                "--gpu: fragment (full-screen triangle) | compute (GLSL 4.30 kernel; reaches every shader unit of "
                "compute GPUs, ~27x faster on an H100)");
}

namespace {

// The option of cmd or of a command above it (--help, --version, --quiet
// are the top level's) that a command-line word names, or null.
const CLI::Option* findOption(const CLI::App* cmd, const std::string& word) {
    for (; cmd; cmd = cmd->get_parent())
        if (const CLI::Option* o = cmd->get_option_no_throw(word)) return o;
    return nullptr;
}

std::vector<std::string> optionNames(const CLI::App* cmd) {
    std::vector<std::string> names;
    for (; cmd; cmd = cmd->get_parent())
        for (const CLI::Option* o : cmd->get_options()) {
            for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
            for (const std::string& n : o->get_snames()) names.push_back("-" + n);
        }
    return names;
}

// A suggestion for an unknown option. A one-letter option is no typo of
// another one-letter option: "-V" suggests the long option it may stand for
// (--version), when exactly one starts with its letter.
std::string suggestOption(const std::string& name, const CLI::App* cmd) {
    const std::vector<std::string> names = optionNames(cmd);
    if (name.size() != 2) return didYouMean(name, names);
    std::vector<std::string> longNames;
    const char letter = char(std::tolower(static_cast<unsigned char>(name[1])));
    for (const std::string& n : names)
        if (n.size() > 3 && n[1] == '-' && n[2] == letter) longNames.push_back(n);
    return longNames.size() == 1 ? " (did you mean " + longNames.front() + "?)" : "";
}

// "render: ", "reproduce table1: ", or "" at the top level (main says "stochtex").
std::string commandPath(const CLI::App* cmd) {
    std::string path;
    for (; cmd && cmd->get_parent(); cmd = cmd->get_parent()) path = cmd->get_name() + (path.empty() ? "" : " " + path);
    return path.empty() ? "" : path + ": ";
}

}  // namespace

void tidyDefaults(CLI::App& app) {
    for (CLI::Option* o : app.get_options({}))
        if (const std::string d = o->get_default_str(); d.size() >= 2 && d.front() == '[' && d.back() == ']')
            o->default_str(d.substr(1, d.size() - 2));
    for (CLI::App* sub : app.get_subcommands({})) tidyDefaults(*sub);
}

std::string explainParseError(const CLI::App& app, const std::vector<std::string>& args) {
    const CLI::App* cmd = &app;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& word = args[i];
        if (word == "--") break;
        // An option: -x, -xVALUE, --name or --name=VALUE (not a negative number).
        if (word.size() > 1 && word[0] == '-' &&
            std::isalpha(static_cast<unsigned char>(word[word[1] == '-' ? 2 : 1]))) {
            const std::string name = word[1] == '-' ? word.substr(0, word.find('=')) : word.substr(0, 2);
            const CLI::Option* option = findOption(cmd, name);
            if (!option) return commandPath(cmd) + "unknown option " + name + suggestOption(name, cmd);
            // Its value is the next word unless attached.
            if (option->get_items_expected_max() > 0 && name == word && i + 1 < args.size()) ++i;
            continue;
        }
        const auto named = cmd->get_subcommands([&](const CLI::App* s) { return s->check_name(word); });
        if (!named.empty()) {
            cmd = named.front();
            continue;
        }
        // A word that is no option: a command's name where one is expected.
        if (cmd->get_require_subcommand_min() > 0 && cmd->get_subcommands({}).size() > 0) {
            std::vector<std::string> names;
            for (const CLI::App* sub : cmd->get_subcommands({})) names.push_back(sub->get_name());
            return commandPath(cmd) + "unknown command \"" + word + "\"" + didYouMean(word, names);
        }
    }
    return {};
}

namespace {

// Per command, the parameters its options were bound to (bindParameter).
std::map<const CLI::App*, std::map<std::string, std::string>>& parameterBindings() {
    static std::map<const CLI::App*, std::map<std::string, std::string>> bindings;
    return bindings;
}

}  // namespace

CLI::Option* bindParameter(const CLI::App& cmd, CLI::Option* option, const std::string& parameter) {
    const std::vector<std::string>& longNames = option->get_lnames();
    parameterBindings()[&cmd][parameter] = longNames.empty() ? option->get_name() : "--" + longNames.front();
    return option;
}

namespace {

// The flag of cmd itself bound to `parameter` where it was declared, or "".
std::string boundFlag(const CLI::App& cmd, const std::string& parameter) {
    const auto bound = parameterBindings().find(&cmd);
    if (bound == parameterBindings().end()) return {};
    const auto it = bound->second.find(parameter);
    return it == bound->second.end() ? std::string() : it->second;
}

// The option of cmd itself named after `parameter` (kebabCase: --radial-bins
// sets radialBins, as OptionMember names its flags; a positional by the
// parameter's own name), unless a declaration bound it to other parameters
// (ShaderToy's --size sets width and height, not a study window's size);
// "" when there is none.
std::string namedFlag(const CLI::App& cmd, const std::string& parameter) {
    const auto bound = parameterBindings().find(&cmd);
    const auto boundElsewhere = [&](const std::string& flag) {
        if (bound == parameterBindings().end()) return false;
        for (const auto& [p, f] : bound->second)
            if (f == flag) return true;
        return false;
    };
    const std::string named = kebabCase(parameter);
    for (const CLI::Option* o : cmd.get_options()) {
        const std::vector<std::string>& longNames = o->get_lnames();
        if (std::find(longNames.begin(), longNames.end(), named) != longNames.end())
            return boundElsewhere("--" + named) ? std::string() : "--" + named;
        if (longNames.empty() && o->get_positional() && o->get_name(true) == parameter)
            return boundElsewhere(parameter) ? std::string() : parameter;
    }
    return {};
}

}  // namespace

const CLI::App* commandThatRan(const CLI::App& app) {
    const CLI::App* cmd = &app;
    while (!cmd->get_subcommands().empty()) cmd = cmd->get_subcommands().front();
    return cmd;
}

std::string describeInputError(const InputError& e, const CLI::App* ran) {
    if (e.parameter().empty()) return e.what();
    // A declaration's binding outranks a name, wherever in the chain: flow's
    // --dt sets timeStep even under a ShaderToy source that has a --fps.
    for (const CLI::App* cmd = ran; cmd; cmd = cmd->get_parent())
        if (const std::string flag = boundFlag(*cmd, e.parameter()); !flag.empty()) return flag + ": " + e.what();
    for (const CLI::App* cmd = ran; cmd; cmd = cmd->get_parent())
        if (const std::string flag = namedFlag(*cmd, e.parameter()); !flag.empty()) return flag + ": " + e.what();
    return e.what();
}

std::string budgetAdvice() {
    const double factor = budgetFactor();
    if (factor >= kMaxBudgetFactor) return " (with --budget 64, the most it allows)";
    const double more = std::min(factor * 4, kMaxBudgetFactor);
    return " (--budget " + formatValue(more) + " allows " + formatValue(more) + "× the budgets" +
           (factor == 1 ? "" : "; now ×" + formatValue(factor)) + ")";
}

void addOutputFolderFlag(CLI::App& cmd, std::string& dir, const std::string& what) {
    cmd.add_option("-o,--output", dir, what)->required();
}

void addOutputImageFlag(CLI::App& cmd, std::string& path, const std::string& what) {
    addOutputFolderFlag(cmd, path, what);  // the same flag; only the help differs
}

}  // namespace stochtex::cli
