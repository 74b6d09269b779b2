#include "common.h"

#include <cstdio>
#include <filesystem>
#include <string_view>
#include <utility>

#include <unistd.h>  // access

#include "stochtex/core/error.h"
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

PatternSpec loadPatternSource(const PatternSource& src, const FilterOptions& options) {
    PatternSpec spec = loadPatternSource(src);
    const bool prefilters =
        options.source != StatisticsSource::Point && options.response.kind == ResponseKind::PrefilteredColormap;
    if (!prefilters || spec.colormap.source == ColormapSpec::Source::Image) return spec;
    try {
        validatePrefilteredResolution(spec.colormap.resolution, spec.colormap.resolution);
    } catch (const InputError& e) {
        throw InputError((src.file.empty() ? "preset " + src.preset : readJsonArgumentSource(src.file)) +
                         ": /colormap/resolution: " + e.what() + " (--filter " + filterName(options) + ")");
    }
    return spec;
}

void addViewFlags(CLI::App& cmd, ViewFlags& flags) {
    cmd.add_option("--size", flags.size, "Output size in pixels: N or W,H (default: the pattern's)")
        ->delimiter(',')
        ->expected(1, 2);
    cmd.add_option("--scale", flags.scale, "Example texels per output pixel (>1 zooms out; default: the pattern's)");
    cmd.add_option("--offset", flags.offset, "Texture-space offset X,Y in example texels")->delimiter(',')->expected(2);
}

View makeView(const PatternSpec& spec, const ViewFlags& flags) {
    View v;
    v.width = spec.width;
    v.height = spec.height;
    v.scale = spec.scale;
    if (!flags.size.empty()) {
        v.width = flags.size[0];
        v.height = flags.size.size() > 1 ? flags.size[1] : flags.size[0];
    }
    if (flags.scale) v.scale = *flags.scale;
    if (!flags.offset.empty()) {
        v.offsetU = flags.offset[0];
        v.offsetV = flags.offset[1];
    }
    validateView(v);  // errors name size, scale or offset: main adds the flag
    return v;
}

std::string readJsonArgumentSource(const std::string& arg) {
    const size_t first = arg.find_first_not_of(" \t\n");
    return first != std::string::npos && arg[first] == '{' ? "<inline JSON>" : arg;
}

JsonArgument readJsonArgument(const std::string& arg) {
    JsonArgument a;
    a.source = readJsonArgumentSource(arg);
    if (a.source != arg) {
        a.json = JsonReader::parse(arg, a.source);
        a.baseDir = ".";
    } else {
        a.json = readJsonFile(arg);
        a.baseDir = fs::path(arg).has_parent_path() ? fs::path(arg).parent_path() : fs::path(".");
    }
    return a;
}

void checkImageOutput(const std::string& path, int bits) {
    checkImageOutputFormat(path, WriteOptions{bits});
    const fs::path p(path);
    std::error_code ec;
    const fs::path folder = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if (!fs::is_directory(folder, ec)) throw InputError(path + ": directory " + folder.string() + " does not exist");
    // Checked now, not when the finished image is renamed into place.
    if (fs::is_directory(p, ec)) throw InputError(path + ": is a folder");
    if (access(folder.c_str(), W_OK) != 0)
        throw InputError(path + ": directory " + folder.string() + " is not writable");
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

void addBitsFlag(CLI::App& cmd, int& bits) {
    cmd.add_option("--bits", bits, "Bits per channel of PNG and TIFF output: 8 or 16 (JPEG: 8)")
        ->check(CLI::Validator(
            [](std::string& s) -> std::string {
                return s == "8" || s == "16" ? std::string() : "bits must be 8 or 16, got \"" + s + "\"";
            },
            "8|16"))
        ->capture_default_str();
}

void addThreadsFlag(CLI::App& cmd, int& threads) {
    cmd.add_option("--threads,-j", threads, "Worker threads (0 = all cores; output is identical for any value)")
        ->check(CLI::Range(0, 1024));
}

void addFilterFlag(CLI::App& cmd, std::function<void(const NamedFilter&)> set, const std::string& shown,
                   const std::string& help) {
    cmd.add_option_function<std::string>(
           "--filter", [set](const std::string& s) { set(parseFilter(s)); }, help)
        ->check(nameValidator(kFilterNames, "filter"))
        ->type_name("ENUM")
        ->default_str(shown);
}

void addFilterFlag(CLI::App& cmd, FilterOptions& options, const std::string& help) {
    addFilterFlag(
        cmd, [&options](const NamedFilter& f) { options.use(f); }, filterName(options), help);
}

void addAnisoFlag(CLI::App& cmd, int& aniso) {
    aniso = FilterOptions{}.aniso;
    cmd.add_option("--aniso", aniso, "Anisotropic probes K (1 = isotropic trilinear, up to 16)")->capture_default_str();
}

void addCameraFlags(CLI::App& cmd, Camera& camera, bool withFov) {
    addEnumFlag(cmd, "--view", camera.kind, Camera::kKindNames, "view",
                "zoom (flat, --scale texels per pixel) | plane (perspective ground plane)");
    cmd.add_option("--tilt", camera.tiltDeg, "Plane view: tilt from looking straight down, degrees [0, 89]")
        ->capture_default_str();
    if (withFov) cmd.add_option("--fov", camera.fovDeg, "Plane view: vertical field of view, degrees")->capture_default_str();
}

bool isGpuFilter(const FilterOptions& options) {
    return options.source == StatisticsSource::Point || options.source == StatisticsSource::Estimators;
}

void printProgress(const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); }

void addPipelineFlag(CLI::App& cmd, GpuPattern::Pipeline& pipeline) {
    addEnumFlag(cmd, "--pipeline", pipeline, kGpuPipelineNames, "pipeline",
                "--gpu: fragment (full-screen triangle) | compute (GLSL 4.30 kernel; reaches every shader unit of "
                "compute GPUs, ~27x faster on an H100)");
}

// Library parameter → the flag that sets it. One table for every command:
// where two commands set a parameter from differently named flags, the
// command checks that flag itself (as correlation does for --layers-list).
namespace {
constexpr std::pair<std::string_view, std::string_view> kParameterFlags[] = {
    {"filter", "--filter"},
    {"source", "--filter"},
    {"aniso", "--aniso"},
    {"referenceMaxSamples", "--reference-samples"},
    {"tiltDeg", "--tilt"},
    {"fovDeg", "--fov"},
    {"size", "--size"},
    {"scale", "--scale"},
    {"offset", "--offset"},
    {"object", "--object"},
    {"tiling", "--tiling"},
    {"derivatives", "--derivatives"},
    {"count", "--count"},
    {"footprints", "--footprints"},
    {"layers", "--layers"},
    {"maxScale", "--max-scale"},
    {"envelopeSigma", "--envelope-sigma"},
    {"time", "--time"},
    {"scaling", "--scaling"},
    {"offsets", "--offsets"},
    {"interpolation", "--interpolation"},
    {"instances", "--instances"},
    {"layersList", "--layers-list"},
    {"frames", "--frames"},
    {"from", "--from"},
    {"to", "--to"},
    {"filters", "--filters"},
};
}  // namespace

std::string describeInputError(const InputError& e) {
    for (const auto& [parameter, flag] : kParameterFlags)
        if (e.parameter() == parameter) return std::string(flag) + ": " + e.what();
    return e.what();
}

void addOutputFolderFlag(CLI::App& cmd, std::string& dir, const std::string& what) {
    cmd.add_option("-o,--output", dir, what)->required();
}

void addOutputImageFlag(CLI::App& cmd, std::string& path, const std::string& what) {
    addOutputFolderFlag(cmd, path, what);  // the same flag; only the help differs
}

}  // namespace stochtex::cli
