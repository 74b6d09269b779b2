#include "stochtex/gpu/export.h"

#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/gpu/programs.h"
#include "stochtex/gpu/shader.h"
#include "stochtex/image/image_io.h"
#include "stochtex/kernel/pattern_params.h"

namespace stochtex {

namespace fs = std::filesystem;

std::string exportedShaderInclude(ResponseKind response) {
    const bool lean = response == ResponseKind::Lean;
    std::string text =
        "// stochtex: filtered colour-mapped noise (Grenier et al. 2022), exported by `stochtex bake`.\n"
        "// Include after a `#version 330 core` (or `#version 300 es` + highp precision) line.\n"
        "// Entry point: vec4 stochtex_sample(vec2 uv), uv in example periods; the\n"
        "// footprint comes from this fragment's derivatives of uv. It returns LINEAR-light\n"
        "// RGB (not sRGB codes): draw into an sRGB framebuffer (GL_FRAMEBUFFER_SRGB) or\n"
        "// encode it before display. The textures to bind and the PatternParameters\n"
        "// block to fill are described in README.md.\n";
    if (lean)
        text +=
            "// This pattern is a LEAN-mapped normal map (paper §6.5): stochtex_sample is its\n"
            "// shading under the uLean* uniforms (README.md). To light it yourself, take the\n"
            "// footprint's slope lobe, LeanLobe stochtex_lean_lobe(vec2 uv), and shade with\n"
            "// leanShade(lobe, light, view, albedo, specular) or your own BRDF over leanNdf(lobe, h);\n"
            "// directions in the texture frame (x along u, y along v, z up).\n";
    text += "\n";
    for (const auto& stem : shaderChunks(recipeFiles(programRecipe("export-include"), response)))
        text += shaderText(stem) + "\n";
    text += "vec4 stochtex_sample(vec2 uv) { return vec4(filteredColour(uv, dFdx(uv), dFdy(uv)), 1.0); }\n";
    if (lean)
        text +=
            "// The filtered slopes of the footprint of uv as a Beckmann lobe (mean slope and\n"
            "// covariance, the base roughness uLeanRoughness included).\n"
            "LeanLobe stochtex_lean_lobe(vec2 uv) {\n"
            "    FootprintMoments m = footprintStatistics(uv, dFdx(uv), dFdy(uv));\n"
            "    return footprintLobe(m.mean, m.var, m.cov);\n"
            "}\n";
    return text;
}

namespace {

// The table's colour space, which is what stochtex_sample returns: the
// colormap's values as the pattern gives them, filtered as numbers (no
// transfer function is applied or undone on the way).
constexpr const char* kTableColourSpace =
    "linear-light RGB (the pattern's sRGB colours decoded once, before filtering; a colormap declared "
    "`\"transfer\": \"linear\"` keeps its values)";

// A file the export wrote and what it holds, for the README's file table
// (which is built from these, so it lists exactly the files written).
struct WrittenFile {
    std::string names;  // one name, or a levelled family's names
    std::string format;
    std::string content;
};

// How writeImage stores an EXR: OpenCV writes ZIP-compressed scanlines and
// names 3 channels B, G, R; the values are data, never colour-managed.
std::string exrFormat(const Image& image, const WriteOptions& w) {
    return "OpenEXR, " + std::to_string(image.width()) + " × " + std::to_string(image.height()) + ", " +
           std::to_string(image.channels()) + " channels (R, G, B) of " +
           (w.exrHalf ? "16-bit half float" : "32-bit float") + ", ZIP-compressed scanlines";
}

void writeStats(const StatsPyramid& p, const std::string& dir, const std::string& stem, nlohmann::json& list,
                const std::string& green, std::vector<WrittenFile>& files) {
    std::string names, sizes;
    for (int l = 0; l < p.levels(); ++l) {
        const std::string file = stem + "_" + std::to_string(l) + ".exr";
        const Image level = p.interleavedLevel(l, 3);  // EXR has no 2-channel layout
        writeImage((fs::path(dir) / file).string(), level);
        list.push_back(file);
        names += (l ? ", `" : "`") + file + "`";
        if (l == 0) sizes = exrFormat(level, {});
    }
    files.push_back({names, sizes + " at level 0, halving per level down to 1 × 1",
                     "level l of the pyramid: R = mean E_l, G = " + green + ", B = 0 (noise-domain data, linear)"});
}

// README.md; @BLOCK@, @SIZE@ and @MEMBERS@ are filled from the parameter
// block's one table (kernel::kPatternParamFields).
const char* kReadme = R"(# stochtex export

Filtered colour-mapped noise (Grenier et al., CGF 2022) for your own OpenGL
(3.3 core) or WebGL 2 / GLES 3.0 program. `manifest.json` lists the data.

## Textures

| uniform | type | content |
| --- | --- | --- |
| `uStatsX`, `uStatsY` | `sampler2D`, RG32F, mip levels 0…L | level l = `stats_x_l.exr` (R = mean, G = variance) |
| `uCovariance` | `sampler2D`, RG32F, mip levels | `covariance_l.exr` if `covariance`, else bind `uStatsX` |
@TABLE@
All are read with `texelFetch` (no filtering needed); set `GL_TEXTURE_MAX_LEVEL`
to L so the pyramids are mipmap-complete.

## Colour space

`table.exr` holds linear-light RGB (`manifest.json`: `"colour_space": "linear"`;
the pattern's sRGB colours were decoded once, before filtering), and
`stochtex_sample` returns linear RGB: write it to an sRGB framebuffer
(`GL_FRAMEBUFFER_SRGB`, an `SRGB8_ALPHA8` target) or encode it before display,
as `stochtex render` does for PNG. Upload `table.exr` as float, never as an sRGB
texture. A colormap declared `"transfer": "linear"` (data: heights, roughness)
is exported as its values, unencoded. The statistics EXRs hold noise values
(data).

@LEAN@## Files

| file | format | content |
| --- | --- | --- |
@FILES@
## Parameters: the `@BLOCK@` uniform block

`stochtex.glsl` declares `layout(std140) uniform @BLOCK@ { PatternParams uPattern; };`.
Fill one buffer of @SIZE@ bytes with the members below (4-byte values at these
std140 offsets; an int that is a switch holds 0 or 1), upload it as a uniform
buffer and attach it to the block:
`glUniformBlockBinding(program, glGetUniformBlockIndex(program, "@BLOCK@"), n)`,
`glBindBufferBase(GL_UNIFORM_BUFFER, n, buffer)`.

| offset | type | member | meaning | from `manifest.json` |
| --- | --- | --- | --- | --- |
@MEMBERS@
## Use

```glsl
#version 330 core
#include "stochtex.glsl"   // or paste it
in vec2 vUv;               // your texture coordinates, in example periods
out vec4 colour;
void main() { colour = stochtex_sample(vUv * 8.0); }
```
)";

// The rows and section only one response kind has.
constexpr const char* kTableRow =
    "| `uTable` | `sampler2DArray`, RGBA16F or RGBA32F (`table.precision`), `levels²` layers of `width × height` "
    "| layer k = rows `[k·height, (k+1)·height)` of `table.exr`; texture row j = that layer's row j |\n";
const char* kLeanSection = R"(## LEAN shading (normal map)

This export is a procedural normal map (`"response": "lean"`): the pyramids
hold the statistics of its two slopes ∂z/∂x, ∂z/∂y (tiled with one set of
offsets, so their covariance is exported too), and there is no table.
`stochtex_sample` returns the shaded radiance: an anisotropic Beckmann lobe
of the footprint's mean slope and slope covariance plus the base roughness
(LEAN mapping, Olano & Baker 2010), lit by a directional light of unit
irradiance. Set these uniforms from `manifest.json`'s `lean` (directions in
the texture frame: x along u, y along v, z up; unit length):

| uniform | type | from `manifest.json` |
| --- | --- | --- |
| `uLeanLight` | `vec3` | `lean.light`: towards the light |
| `uLeanView` | `vec4` | `lean.view`: xyz towards the eye, w = 1; w = 0 means straight down (set xyz to your eye direction per fragment and w = 1 for a perspective view) |
| `uLeanAlbedo` | `vec3` | `lean.albedo`: diffuse reflectance, linear |
| `uLeanRoughness` | `float` | `lean.roughness`: base Beckmann roughness m |
| `uLeanSpecular` | `float` | `lean.specular`: weight of the lobe's reflection |
| `uLeanCovariance` | `bool` | `lean.covariance`: read the slopes' covariance |

To light it with your own lights and BRDF, call `LeanLobe stochtex_lean_lobe(vec2 uv)`
(mean slope `mean`, covariance `sigma` = (Σxx, Σyy, Σxy)) and evaluate
`leanNdf(lobe, h)` for a unit half vector h, or `leanShade(lobe, light, view, albedo, specular)`.

)";

std::string readme(const std::vector<WrittenFile>& files, bool lean) {
    std::string fileRows;
    for (const WrittenFile& f : files) fileRows += "| " + f.names + " | " + f.format + " | " + f.content + " |\n";
    std::string members;
    for (const kernel::PatternParamField& f : kernel::kPatternParamFields) {
        const std::string type = f.count > 1 ? std::string(f.type) + "[" + std::to_string(f.count) + "]" : f.type;
        members += "| " + std::to_string(f.offset) + " | `" + type + "` | `" + f.name + "` | " + f.meaning + " | " +
                   f.manifest + " |\n";
    }
    const std::pair<std::string, std::string> fills[] = {{"@BLOCK@", kPatternBlockName},
                                                         {"@SIZE@", std::to_string(sizeof(kernel::PatternParams))},
                                                         {"@MEMBERS@", members},
                                                         {"@FILES@", fileRows},
                                                         {"@TABLE@", lean ? "" : kTableRow},
                                                         {"@LEAN@", lean ? kLeanSection : ""}};
    std::string text = kReadme;
    for (const auto& [key, value] : fills)
        for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
            text.replace(at, key.size(), value);
    return text;
}

// table.exr (the prefiltered colormap response's data) and its manifest entry.
void writeTable(const FilteredPattern& f, const std::string& dir, const ExportOptions& exportOptions,
                nlohmann::json& m, std::vector<WrittenFile>& files) {
    const PrefilteredColormap& table = f.table();
    const int n = int(table.sigmas().size());
    const int rx = f.blendingSpaceColormap().resolutionX(), ry = f.blendingSpaceColormap().resolutionY();
    const Image atlas = table.atlas(rx, ry);
    WriteOptions w;
    w.exrHalf = exportOptions.halfTable;
    writeImage((fs::path(dir) / "table.exr").string(), atlas, w);
    m["table"] = {{"file", "table.exr"}, {"levels", n},
                  {"width", rx},          {"height", ry},
                  {"sigmas", table.sigmas()}, {"precision", exportOptions.halfTable ? "half" : "float"}};
    files.push_back({"`table.exr`", exrFormat(atlas, w),
                     "the prefiltered table H̄: " + std::to_string(n * n) + " layers of " + std::to_string(rx) + " × " +
                         std::to_string(ry) + " RGB colours stacked vertically (T⁻¹ folded in), no alpha; " +
                         kTableColourSpace});
}

// The lean response's shading: what the uLean* uniforms hold.
nlohmann::json leanManifest(const LeanShading& l, bool covariance) {
    const std::array<double, 3> view = l.view.value_or(std::array<double, 3>{0, 0, 1});
    return {{"light", l.light},
            {"view", {view[0], view[1], view[2], l.view ? 1.0 : 0.0}},
            {"albedo", {l.albedo[0], l.albedo[1], l.albedo[2]}},
            {"roughness", l.roughness},
            {"specular", l.specular},
            {"covariance", covariance}};
}

}  // namespace

void exportPattern(const Pattern& pattern, const FilterOptions& options, const std::string& dir,
                   const ExportOptions& exportOptions) {
    if (options.source != StatisticsSource::Estimators)
        throw InputError::parameter("source", "must be estimators to export (filter paper or smooth), got " +
                                                  enumName(kStatisticsSourceNames, options.source));
    const FilteredPattern f(pattern, options);  // validates the options
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) throw InputError(dir + ": cannot create output folder");
    const FootprintEstimator& est = f.estimator();
    const TiledField& field = f.field();  // the colour noises, or the normal map's slopes
    const bool lean = options.response.kind == ResponseKind::Lean;
    nlohmann::json m;
    m["version"] = 1;
    m["filter"] = filterName(options);
    m["response"] = enumName(kResponseKindNames, options.response.kind);
    m["example_size"] = field.exampleSize();
    m["levels"] = est.maxLod() + 1;
    m["means"] = {field.channel(0).example().mean(), field.channel(1).example().mean()};
    m["seeds"] = {field.channel(0).offsetSeed(), field.channel(1).offsetSeed()};
    m["grid_density"] = field.gridDensity();
    m["covariance"] = est.covariancePyramid() != nullptr;
    m["aniso"] = options.aniso;
    nlohmann::json averages = {{"x", nlohmann::json::array()}, {"y", nlohmann::json::array()}, {"cov", nlohmann::json::array()}};
    for (int l = 0; l <= est.maxLod(); ++l) {
        averages["x"].push_back(est.pyramid(0).averageMoment(l));
        averages["y"].push_back(est.pyramid(1).averageMoment(l));
        averages["cov"].push_back(est.covariancePyramid() ? est.covariancePyramid()->averageMoment(l) : 0.0f);
    }
    m["average_moments"] = averages;
    m["stats"] = {{"x", nlohmann::json::array()}, {"y", nlohmann::json::array()}, {"covariance", nlohmann::json::array()}};
    std::vector<WrittenFile> files;
    writeStats(est.pyramid(0), dir, "stats_x", m["stats"]["x"], "variance V_l of N_x", files);
    writeStats(est.pyramid(1), dir, "stats_y", m["stats"]["y"], "variance V_l of N_y", files);
    if (est.covariancePyramid())
        writeStats(*est.covariancePyramid(), dir, "covariance", m["stats"]["covariance"],
                   "covariance C_l of N_x and N_y (R is E_l of N_x)", files);
    m["colour_space"] = "linear";  // table.exr and stochtex_sample: linear light, never sRGB codes
    if (lean)
        m["lean"] = leanManifest(pattern.normalMap()->shading, options.response.covariance);
    else
        writeTable(f, dir, exportOptions, m, files);
    writeFileAtomic((fs::path(dir) / "manifest.json").string(), m.dump(2) + "\n");
    files.push_back({"`manifest.json`", "JSON (UTF-8)", "parameters and the lists of data files"});
    writeFileAtomic((fs::path(dir) / "stochtex.glsl").string(), exportedShaderInclude(options.response.kind));
    files.push_back({"`stochtex.glsl`", "GLSL 3.30 core / ES 3.00 source, no `#version` line",
                     "`vec4 stochtex_sample(vec2 uv)` and what it calls"});
    files.push_back({"`README.md`", "Markdown (UTF-8)", "this file"});
    writeFileAtomic((fs::path(dir) / "README.md").string(), readme(files, lean));
}

}  // namespace stochtex
