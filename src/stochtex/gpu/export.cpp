#include "stochtex/gpu/export.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/gpu/engine_shaders.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/gpu/packed_stats.h"
#include "stochtex/gpu/programs.h"
#include "stochtex/gpu/shader.h"
#include "stochtex/image/image_io.h"
#include "stochtex/kernel/pattern_params.h"

namespace stochtex {

namespace fs = std::filesystem;

const EnumNames<ExportFormat> kExportFormatNames{
    {"float", ExportFormat::Float}, {"half", ExportFormat::Half}, {"8bit", ExportFormat::Rgba8}};

// Bounds ~1.3× the largest of each statistic measured over the test's
// cases (ExportFormats.RenderWithinTheirStatedAccuracy prints them). The
// largest errors are single pixels at one texel per pixel on a colormap's
// steepest edges, where a mean rounded by the format moves the colour most.
const std::vector<ExportFormatAccuracy> kExportFormatAccuracy{
    {ExportFormat::Float, "pyramids RG32F (8 bytes per leaf texel), colour tables RGB16F (RGB32F: float table)", 3e-4,
     2.5e-4, 8.5e-5},
    {ExportFormat::Half, "pyramids RG16F (4 bytes per leaf texel), colour tables RGB16F", 7e-2, 7e-3, 4e-4},
    {ExportFormat::Rgba8,
     "pyramids RGBA8 per leaf pair (2 bytes per leaf texel), colour tables SRGB8, field tables RGB16", 0.5, 7e-2, 5e-3},
};

namespace {

const char* kIncludeHeader =
    "// stochtex: filtered colour-mapped noise (Grenier et al. 2022), exported by `stochtex bake`.\n"
    "// Include after a `#version 330 core` line (OpenGL), `#version 300 es` + highp precision\n"
    "// (WebGL 2, GLES), or `#version 450` compiled for Vulkan (glslangValidator -V).\n"
    "// Entry points, uv in example periods: vec4 stochtex_sample(vec2 uv), its footprint\n"
    "// from this fragment's derivatives of uv; vec4 stochtex_sample_grad(vec2 uv, vec2 ddx,\n"
    "// vec2 ddy), the footprint from explicit derivatives (as textureGrad: compute,\n"
    "// deferred or ray-traced shading); for surfaces without uv, vec4\n"
    "// stochtex_sample_triplanar(vec3 p, vec3 n) and stochtex_sample_triplanar_grad(p, n,\n"
    "// dpdx, dpdy), p in example periods (three projections blended by the normal n,\n"
    "// each filtered with its own footprint). All return LINEAR-light RGB (not sRGB codes):\n"
    "// draw into an sRGB framebuffer (GL_FRAMEBUFFER_SRGB) or encode it before display.\n"
    "// The textures to bind (manifest.json's \"textures\", each with its Vulkan \"binding\")\n"
    "// and the PatternParameters block to fill (binding 0) are described in README.md.\n\n"
    "// Vulkan needs a set and binding on every block and sampler; OpenGL binds by name.\n"
    "// Define STOCHTEX_BINDING(n) before the include to place them elsewhere.\n"
    "#ifndef STOCHTEX_BINDING\n"
    "#ifdef VULKAN\n"
    "#define STOCHTEX_BINDING(n) layout(set = 0, binding = n)\n"
    "#else\n"
    "#define STOCHTEX_BINDING(n)\n"
    "#endif\n"
    "#endif\n";

const char* kSampleFunction =
    "vec4 stochtex_sample_grad(vec2 uv, vec2 ddx, vec2 ddy) { return vec4(filteredColour(uv, ddx, ddy), 1.0); }\n"
    "vec4 stochtex_sample(vec2 uv) { return stochtex_sample_grad(uv, dFdx(uv), dFdy(uv)); }\n"
    "vec4 stochtex_sample_triplanar_grad(vec3 p, vec3 n, vec3 dpdx, vec3 dpdy) {\n"
    "    return vec4(triplanarColour(p, n, dpdx, dpdy, true), 1.0);\n"
    "}\n"
    "vec4 stochtex_sample_triplanar(vec3 p, vec3 n) { return stochtex_sample_triplanar_grad(p, n, dFdx(p), dFdy(p)); "
    "}\n";

}  // namespace

std::string exportedGraphInclude(const GraphPattern& graph, GraphMoments moments, const GraphEstimator& estimator) {
    std::string text = std::string(kIncludeHeader) +
                       "// This pattern is a texture graph (docs/GRAPHS.md): its program, generated for it,\n"
                       "// defines filteredColour (moment matching through its prefiltered tables). Its seeds\n"
                       "// and means are constants here; the PatternParameters block holds\n"
                       "// gridDensity, invExampleSize, aniso, smoothTable and tableLevels.\n\n";
    const std::vector<std::pair<std::string, std::string>> program = {
        {kGraphProgramStem, graphProgramSource(graph, moments, estimator)}};
    for (const auto& stem : shaderChunks(programRecipe("export-graph-include").main, program))
        text += (stem == kGraphProgramStem ? generatedShaderText(program[0].second) : shaderText(stem)) + "\n";
    return text + kSampleFunction;
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

// How writeImage stores an EXR (ExrStreamWriter): ZIP-compressed blocks of
// scanlines, 3 channels named B, G, R; the values are data, never
// colour-managed.
std::string exrFormat(const Image& image, const WriteOptions& w) {
    return "OpenEXR, " + std::to_string(image.width()) + " × " + std::to_string(image.height()) + ", " +
           std::to_string(image.channels()) + " channels (R, G, B) of " +
           (w.exrHalf ? "16-bit half float" : "32-bit float") + ", ZIP-compressed scanlines";
}

// The README's name for a levelled family of files.
std::string fileFamily(const nlohmann::json& list) {
    std::string names;
    for (const nlohmann::json& f : list) names += (names.empty() ? "`" : ", `") + f.get<std::string>() + "`";
    return names;
}

// Writes a pyramid's levels as stem_l.exr (float32, or half with `half`);
// their names go into `list`.
void writeStats(const StatsPyramid& p, const std::string& dir, const std::string& stem, nlohmann::json& list,
                const std::string& green, bool half, std::vector<WrittenFile>& files) {
    std::string sizes;
    WriteOptions w;
    w.exrHalf = half;
    for (int l = 0; l < p.levels(); ++l) {
        const std::string file = stem + "_" + std::to_string(l) + ".exr";
        const Image level = p.interleavedLevel(l, 3);  // EXR has no 2-channel layout
        writeImage((fs::path(dir) / file).string(), level, w);
        list.push_back(file);
        if (l == 0) sizes = exrFormat(level, w);
    }
    files.push_back({fileFamily(list), sizes + " at level 0, halving per level down to 1 × 1",
                     "level l of the pyramid: R = mean E_l, G = " + green + ", B = 0 (noise-domain data, linear)"});
}

// Writes stem_l.png for l < levels, each the 8-bit codes level(l) makes
// (packed_stats.h; no transfer function), their names into `list`, and the
// family's row of the README's file table saying `content`.
void writeCodedLevels(int levels, const std::function<Image(int)>& level, const std::string& dir,
                      const std::string& stem, nlohmann::json& list, const std::string& content,
                      std::vector<WrittenFile>& files) {
    std::string sizes;
    for (int l = 0; l < levels; ++l) {
        const Image coded = level(l);
        const std::string file = stem + "_" + std::to_string(l) + ".png";
        writeImage((fs::path(dir) / file).string(), coded, kNoTransfer);
        list.push_back(file);
        if (l == 0)
            sizes = "PNG, " + std::to_string(coded.width()) + " × " + std::to_string(coded.height()) + ", RGBA 8-bit";
    }
    files.push_back({fileFamily(list), sizes + " at level 0, halving per level down to 1 × 1", content});
}

// README.md; @BLOCK@, @SIZE@ and @MEMBERS@ are filled from the parameter
// block's one table (kernel::kPatternParamFields).
const char* kReadme = R"(# stochtex export

Filtered colour-mapped noise (Grenier et al., CGF 2022) for your own OpenGL
(3.3 core), WebGL 2 / GLES 3.0 or Vulkan (GLSL 4.50 compiled to SPIR-V)
program. `manifest.json` lists the data.

## Textures

| uniform | Vulkan binding | type | content |
| --- | --- | --- | --- |
@TEXTURES@
`manifest.json`'s `"textures"` lists the same: each sampler uniform with its
files (`"pyramid"`: one file per mip level; `"table"`: one file of `layers`
stacked `width × height` layers).
All are read with `texelFetch` (no filtering needed): upload each in the GL
format its row names (an 8-bit file's codes as they are: `RGBA8` is
unsigned normalised, `SRGB8` decodes sRGB to linear when read); set each
pyramid's `GL_TEXTURE_MAX_LEVEL` to its last mip level (its row above:
levels 0…N) so that it is mipmap-complete.
@UNREAD@
## Formats

The data is stored in one of three formats (`manifest.json`: `"format"`),
chosen when exporting. What each costs against `float` with a float table: the absolute difference of the rendered
linear RGB, over pixel channels (bounds a test holds every format to, over
the presets camouflage, phasor-stripes, marble, lean-ridges and the graph
figure14 at 1, 4 and 16 texels per pixel). The largest differences are
single pixels at one texel per pixel on a colormap's steepest edges, where
a rounded mean moves the colour most; 99% of pixels stay within the
percentile column.

| format | GPU storage | largest | 99th percentile | mean |
| --- | --- | --- | --- | --- |
@FORMATS@

## Colour space

The tables hold linear-light RGB (`manifest.json`: `"colour_space": "linear"`;
the pattern's sRGB colours were decoded once, before filtering), and
`stochtex_sample` returns linear RGB: write it to an sRGB framebuffer
(`GL_FRAMEBUFFER_SRGB`, an `SRGB8_ALPHA8` target) or encode it before display,
as `stochtex render` does for PNG. Each texture's `"colour_space"` says how
its file holds them: `linear` (the EXR tables: upload as float, never as an
sRGB texture), `srgb` (the 8-bit format's PNG tables: sRGB codes of those
linear values; upload as `SRGB8` so that reading decodes them) or `data`
(the statistics: noise values, no transfer function). A colormap declared
`"transfer": "linear"` (data: heights, roughness) is exported as its values,
through the same coding.

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
`glBindBufferBase(GL_UNIFORM_BUFFER, n, buffer)`. Under Vulkan the block is
`layout(set = 0, binding = 0)` (`manifest.json`: `"block_binding"`) and each
sampler a combined image sampler at its binding above.

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

Where the fragment's derivatives are not the footprint (a compute shader, a
deferred or ray-traced pass), give them: `stochtex_sample_grad(uv, ddx,
ddy)`, with ddx and ddy the change of uv over one pixel along x and y (as
`textureGrad` takes them). On a surface without texture coordinates,
`stochtex_sample_triplanar(p, n)` projects the pattern along x, y and z (p
in example periods, n the normal; each projection filtered with its own
footprint, blended by n's components to the fourth power);
`stochtex_sample_triplanar_grad(p, n, dpdx, dpdy)` takes p's derivatives. For Vulkan, compile `#version 450` with the
include for SPIR-V (`glslangValidator -V`, which defines `VULKAN`): every
block and sampler then has `layout(set = 0, binding = n)`; define
`STOCHTEX_BINDING(n)` before the include to choose another set or offset.

## Engines: HLSL, Unity, Godot

The same program in other languages, translated from the SPIR-V of
`stochtex.glsl` (glslang, then SPIRV-Cross), with the same entry points,
textures and parameters:

* `stochtex.hlsl` (shader model 5.0: Direct3D 11/12). Each sampler of the
  table above is a `Texture2D<float4>` / `Texture2DArray<float4>` of the same
  name at register `t`n (n its Vulkan binding) with a `SamplerState
  sampler_<name>` at `s`n (all reads are `Load`s: any sampler state does);
  the parameters are `cbuffer @BLOCK@` at `b0`, the same @SIZE@ bytes.
  Define `STOCHTEX_REGISTER(r)` empty before the include to let the compiler
  assign registers. Lean programs: set the static globals `gEyeDirection`
  and `gLightDirection` before sampling.
* `stochtex_unity.hlsl`: for a Shader Graph Custom Function node (Type File,
  Name `StochtexSample`, `StochtexSampleGrad`, `StochtexSampleTriplanar` or
  `StochtexSampleTriplanarGrad`; float and half precision) or an `#include`
  in a hand-written shader; it includes `stochtex.hlsl` with
  registers left to Unity. Bind the textures by name (point filtering,
  without generated mip maps: load each level from its file) and the block
  with `Shader.SetGlobalConstantBuffer("@BLOCK@", buffer, 0, @SIZE@)`.
* `stochtex.gdshaderinc` (Godot 4): `#include "stochtex.gdshaderinc"` in a
  spatial shader and call `stochtex_sample(UV * 8.0).rgb` in `fragment()`
  (linear RGB, as `ALBEDO` takes it); `stochtex.gdshader` is such a shader,
  the include's text inlined, ready for a ShaderMaterial. Godot has no uniform blocks: each
  member is a uniform of its own, @GODOT@; the samplers are uniforms of the
  names above, declared `filter_nearest, repeat_disable`. Lean programs'
  `gEyeDirection` and `gLightDirection` are uniforms there (one direction
  per material).

What is checked here (`make test`): `stochtex.hlsl` and the Unity file are
compiled by glslang's HLSL front end (as a pixel shader calling every entry
point) to SPIR-V that `spirv-val` accepts; the Godot include is checked for
the constructs Godot's language lacks (uniform blocks, layout qualifiers,
mutable globals, prototypes, precision statements) and, its uniform hints
removed, compiled as GLSL ES 3.00 by glslang. Not checked: Microsoft's
compilers (FXC, DXC), Unity's and Godot's own compilers (none runs here),
and any rendering in those engines.
)";

// The README's row for a sampler of manifest.json's "textures".
std::string textureRow(const nlohmann::json& t) {
    const std::string uniform =
        "`" + t["uniform"].get<std::string>() + "` | " + std::to_string(t["binding"].get<int>());
    const std::string format = t["format"].get<std::string>();
    if (t["kind"] == "pyramid") {
        const std::string first = t["files"].front(), last = t["files"].back();
        return "| " + uniform + " | `sampler2D`, " + format + ", mip levels 0…" +
               std::to_string(t["files"].size() - 1) + " | level l from `" + first + "` … `" + last + "` (" +
               t["content"].get<std::string>() + ") |\n";
    }
    return "| " + uniform + " | `sampler2DArray`, " + format + ", " + std::to_string(t["layers"].get<int>()) +
           " layers of " + std::to_string(t["width"].get<int>()) + " × " + std::to_string(t["height"].get<int>()) +
           " | layer k = rows `[k·height, (k+1)·height)` of `" + t["file"].get<std::string>() +
           "`; texture row j = that layer's row j |\n";
}

// The README's table of formats: each with its cost and measured accuracy,
// this export's marked.
std::string formatRows(ExportFormat written) {
    std::string rows;
    char bounds[96];
    for (const ExportFormatAccuracy& a : kExportFormatAccuracy) {
        std::snprintf(bounds, sizeof bounds, "%.0e | %.0e | %.0e", a.maxError, a.p99Error, a.meanError);
        rows += "| `" + enumName(kExportFormatNames, a.format) + "`" + (a.format == written ? " (this export)" : "") +
                " | " + a.storage + " | " + bounds + " |\n";
    }
    return rows;
}

const char* kProgramLightSection = R"(## Lighting (lean nodes)

The program lights its own colour: a `lean` node (a pattern file's normal
map under the lean response is one) shades its footprint's slope lobe, an
anisotropic Beckmann lobe of the mean slope and slope covariance plus the
base roughness (LEAN mapping, Olano & Baker 2010), under a directional light
of unit irradiance. Its light, view, albedo, roughness and specular weight
are constants of `stochtex.glsl` (`manifest.json`'s `graph.lean` lists
them). Two globals of `stochtex.glsl` light it from your scene instead;
set them before each `stochtex_sample` (directions in the texture frame:
x along u, y along v, z up; unit length):

| global | type | meaning |
| --- | --- | --- |
| `gLightDirection` | `vec4` | xyz towards your light, w = 1 (w = 0, the default: the node's own light) |
| `gEyeDirection` | `vec3` | towards the eye at this fragment (default (0, 0, 1), straight down); a node with a fixed view keeps its own |

)";

// The samplers `include` declares, in order, each with its binding
// (STOCHTEX_BINDING(n): Vulkan's; gpu_graph.cpp declares one per line).
std::vector<std::pair<std::string, int>> declaredSamplers(const std::string& include) {
    std::vector<std::pair<std::string, int>> out;
    const std::regex declaration(R"(STOCHTEX_BINDING\((\d+)\) uniform sampler\w+ (\w+);)");
    for (std::sregex_iterator it(include.begin(), include.end(), declaration), end; it != end; ++it)
        out.emplace_back((*it)[2].str(), std::stoi((*it)[1].str()));
    return out;
}

// The samplers `include` declares that manifest.json's textures do not
// list: the unfiltered path's, which stochtex_sample never calls.
std::vector<std::string> unlistedSamplers(const std::string& include, const nlohmann::json& textures) {
    std::vector<std::string> out;
    for (const auto& sampler : declaredSamplers(include)) {
        const std::string& name = sampler.first;  // (clang 14 captures no structured binding)
        const bool listed = std::any_of(textures.begin(), textures.end(),
                                        [&](const nlohmann::json& t) { return t["uniform"] == name; });
        if (!listed) out.push_back(name);
    }
    return out;
}

// shading: the section on how the colour is lit ("" when it is not).
std::string readme(const std::vector<WrittenFile>& files, const nlohmann::json& textures, const std::string& shading,
                   const std::string& include, ExportFormat format, const EngineShaders& engines) {
    std::string godotParameters;
    for (size_t i = 0; i < engines.godotParameters.size(); ++i)
        godotParameters += std::string(i == 0                                    ? ""
                                       : i + 1 == engines.godotParameters.size() ? " and "
                                                                                 : ", ") +
                           "`" + engines.godotParameters[i] + "`";
    std::string textureRows;
    for (const nlohmann::json& t : textures) textureRows += textureRow(t);
    std::string unread;
    const std::vector<std::string> unlisted = unlistedSamplers(include, textures);
    for (const std::string& name : unlisted) unread += (unread.empty() ? "`" : ", `") + name + "`";
    if (!unread.empty()) {
        const bool one = unlisted.size() == 1;
        unread = "\n`stochtex.glsl` also declares " + unread +
                 " (the unfiltered path's), which `stochtex_sample` never reads: " + (one ? "it" : "they") +
                 " may stay unbound (a compiler drops " + (one ? "it" : "them") +
                 "; a driver that keeps one active wants a texture of its type on its unit).\n";
    }
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
                                                         {"@TEXTURES@", textureRows},
                                                         {"@UNREAD@", unread},
                                                         {"@FORMATS@", formatRows(format)},
                                                         {"@LEAN@", shading},
                                                         {"@GODOT@", godotParameters}};
    std::string text = kReadme;
    for (const auto& [key, value] : fills)
        for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
            text.replace(at, key.size(), value);
    return text;
}

// How a table is stored: an EXR of floats (half or float32) or 8-bit sRGB
// codes in a PNG.
enum class TableStorage { Half, Float, Srgb8, Unorm16 };

// A prefiltered table's atlas as `stem` + its extension, its manifest entry
// and its "textures" entry for `uniform`.
nlohmann::json writeTable(const PrefilteredColormap& table, int rx, int ry, const std::string& stem,
                          const std::string& uniform, const std::string& what, const std::string& dir,
                          TableStorage storage, nlohmann::json& textures, std::vector<WrittenFile>& files) {
    const int n = int(table.sigmas().size());
    const Image atlas = table.atlas(rx, ry);
    // 16-bit codes hold only [0, 1] (UNORM): a field table beyond it stays float.
    if (storage == TableStorage::Unorm16 && !fitsUnorm16(atlas)) storage = TableStorage::Float;
    const bool srgb = storage == TableStorage::Srgb8, unorm = storage == TableStorage::Unorm16;
    const std::string file = stem + (srgb || unorm ? ".png" : ".exr");
    WriteOptions w;  // PNG: 8-bit sRGB codes of the linear colours (the default transfer)
    w.exrHalf = storage == TableStorage::Half;
    if (unorm) w = {.bitDepth = 16, .transfer = Transfer::Linear};
    writeImage((fs::path(dir) / file).string(), atlas, w);
    const std::string precision = srgb ? "srgb8" : unorm ? "unorm16" : w.exrHalf ? "half" : "float";
    textures.push_back({{"uniform", uniform},
                        {"kind", "table"},
                        {"file", file},
                        {"layers", n * n},
                        {"width", rx},
                        {"height", ry},
                        {"precision", precision},
                        {"format", srgb        ? "SRGB8"
                                   : unorm     ? "RGB16"
                                   : w.exrHalf ? "RGB16F"
                                               : "RGB32F"},
                        {"colour_space", srgb    ? "srgb"
                                         : unorm ? "data"
                                                 : "linear"}});
    const std::string size = std::to_string(rx) + " × " + std::to_string(n * n * ry);
    const std::string format = srgb    ? "PNG, " + size + ", RGB 8-bit sRGB codes (upload as SRGB8)"
                               : unorm ? "PNG, " + size + ", RGB 16-bit linear codes of [0, 1] (upload as RGB16)"
                                       : exrFormat(atlas, w);
    files.push_back({"`" + file + "`", format,
                     what + ": " + std::to_string(n * n) + " layers of " + std::to_string(rx) + " × " +
                         std::to_string(ry) + " RGB colours stacked vertically (T⁻¹ folded in), no alpha; " +
                         kTableColourSpace});
    return {{"file", file},          {"levels", n}, {"width", rx}, {"height", ry}, {"sigmas", table.sigmas()},
            {"precision", precision}};
}

nlohmann::json pyramidTexture(const std::string& uniform, const nlohmann::json& files, const std::string& format,
                              const std::string& content) {
    return {{"uniform", uniform}, {"kind", "pyramid"},      {"files", files},
            {"format", format},   {"colour_space", "data"}, {"content", content}};
}

// A pair's codes for manifest.json, per level.
nlohmann::json codingJson(const std::vector<GraphEstimator::LevelCoding>& levels, bool covariance) {
    nlohmann::json out = nlohmann::json::array();
    for (const GraphEstimator::LevelCoding& l : levels)
        out.push_back(covariance ? nlohmann::json{{"offset", l.covariance[0]}, {"scale", l.covariance[1]}}
                                 : nlohmann::json{{"offset", l.offset}, {"scale", l.scale}});
    return out;
}

// Creates the export folder; InputError naming it if that fails.
void makeFolder(const std::string& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) throw InputError(dir + ": cannot create output folder");
}

// manifest.json, stochtex.glsl and README.md, after the data.
// The parameter block's values as GLSL literals, by member name.
std::map<std::string, std::string> parameterLiterals(const kernel::PatternParams& params) {
    std::map<std::string, std::string> out;
    for (const kernel::PatternParamField& f : kernel::kPatternParamFields) {
        const char* at = reinterpret_cast<const char*>(&params) + f.offset;
        char text[48];
        if (std::string_view(f.type) == "float") {
            float v;
            std::memcpy(&v, at, sizeof v);
            std::snprintf(text, sizeof text, "%.9g", double(v));
            if (!std::strpbrk(text, ".eEn")) std::strcat(text, ".0");  // a float literal, never an int
        } else if (std::string_view(f.type) == "int") {
            int v;
            std::memcpy(&v, at, sizeof v);
            std::snprintf(text, sizeof text, "%d", v);
        } else {
            continue;  // no vector members today; Godot would take them as uniforms without defaults
        }
        out[f.name] = text;
    }
    return out;
}

void writeDescription(const std::string& dir, nlohmann::json& m, const std::string& include,
                      std::vector<WrittenFile>& files, const std::string& shading, ExportFormat format,
                      const kernel::PatternParams& params) {
    m["colour_space"] = "linear";  // the tables and stochtex_sample: linear light, never sRGB codes
    // Vulkan's bindings, as the include declares them (set 0 unless STOCHTEX_BINDING says otherwise).
    m["block_binding"] = 0;
    for (const auto& [name, binding] : declaredSamplers(include))
        for (nlohmann::json& t : m["textures"])
            if (t["uniform"] == name) t["binding"] = binding;
    writeFileAtomic((fs::path(dir) / "manifest.json").string(), m.dump(2) + "\n");
    files.push_back(
        {"`manifest.json`", "JSON (UTF-8)", "parameters, the textures to bind and the lists of data files"});
    writeFileAtomic((fs::path(dir) / "stochtex.glsl").string(), include);
    files.push_back({"`stochtex.glsl`", "GLSL 3.30 core / ES 3.00 / Vulkan GLSL 4.50 source, no `#version` line",
                     "`vec4 stochtex_sample(vec2 uv)`, `stochtex_sample_grad(uv, ddx, ddy)`, "
                     "`stochtex_sample_triplanar(p, n)`, `stochtex_sample_triplanar_grad(p, n, dpdx, dpdy)` and what "
                     "they call"});
    // The engine flavours, translated from the include (engine_shaders.h).
    const EngineShaders engines = engineShaders(include, parameterLiterals(params));
    const std::pair<const char*, const std::string*> engineFiles[] = {{"stochtex.hlsl", &engines.hlsl},
                                                                      {"stochtex_unity.hlsl", &engines.unity},
                                                                      {"stochtex.gdshaderinc", &engines.godot},
                                                                      {"stochtex.gdshader", &engines.godotShader}};
    for (const auto& [name, text] : engineFiles) writeFileAtomic((fs::path(dir) / name).string(), *text);
    files.push_back({"`stochtex.hlsl`", "HLSL source, shader model 5.0", "the program's entry points as HLSL"});
    files.push_back({"`stochtex_unity.hlsl`", "HLSL source (Unity)",
                     "Shader Graph Custom Function entry points over `stochtex.hlsl`"});
    files.push_back(
        {"`stochtex.gdshaderinc`", "Godot 4 shading language include", "the program's entry points for Godot"});
    files.push_back({"`stochtex.gdshader`", "Godot 4 spatial shader",
                     "the include's text and a `fragment()` that samples the pattern over the mesh's UV"});
    files.push_back({"`README.md`", "Markdown (UTF-8)", "this file"});
    writeFileAtomic((fs::path(dir) / "README.md").string(),
                    readme(files, m["textures"], shading, include, format, engines));
}

}  // namespace

void exportGraph(const GraphPattern& graph, const FilterOptions& options, const std::string& dir,
                 const ExportOptions& exportOptions) {
    if (options.source != StatisticsSource::Estimators)
        throw InputError::parameter("source", "must be estimators to export (filter paper or smooth), got " +
                                                  enumName(kStatisticsSourceNames, options.source));
    const FilteredGraph f(graph, options);  // validates the options; the pyramids and tables
    makeFolder(dir);
    nlohmann::json m;
    m["version"] = 1;
    m["filter"] = filterName(options);
    m["estimator"] =
        enumName(kVarianceEstimatorNames, options.estimator);  // deliot-heitz: level averages in stochtex.glsl
    m["response"] = enumName(kResponseKindNames, options.response.kind);
    // The block's members (kPatternParamFields; the program's seeds and means are its constants).
    m["example_size"] = graph.exampleSize();
    m["levels"] = f.estimator(0).maxLod() + 1;  // of the first leaf's pyramids
    m["grid_density"] = graph.grid().densityV;  // along v; along u and the period for a tileable pattern:
    m["grid_density_u"] = graph.grid().densityU;
    m["grid_period"] = {graph.grid().period.x, graph.grid().period.y};
    m["aniso"] = options.aniso;
    nlohmann::json& textures = m["textures"] = nlohmann::json::array();
    nlohmann::json& leaves = m["graph"]["leaves"] = nlohmann::json::array();
    std::vector<WrittenFile> files;
    GraphEstimator estimator = graphEstimator(f, options);
    const ExportFormat format = exportOptions.format;
    m["format"] = enumName(kExportFormatNames, format);
    if (format == ExportFormat::Rgba8) {
        // One RGBA8 pyramid per pair (a leaf without a partner fills both halves).
        estimator.packedPairs = true;
        for (size_t p = 0; p < graph.leafPairs().size(); ++p) {
            const std::array<const StatsPyramid*, 2> pyramids = pairPyramids(graph, f, int(p));
            std::array<std::string, 2> ids;
            for (int k = 0; k < graph.leafCount(); ++k)
                if (graph.leafLocation(k)[0] == int(p))
                    ids[size_t(graph.leafLocation(k)[1])] = graph.leafIds()[size_t(k)];
            nlohmann::json list = nlohmann::json::array();
            std::vector<GraphEstimator::LevelCoding>& coding = estimator.pyramidCoding.emplace_back();
            writeCodedLevels(
                pyramids[0]->levels(),
                [&](int l) { return packedPairLevel(*pyramids[0], *pyramids[1], l, coding.emplace_back()); }, dir,
                "stats_" + std::to_string(p), list,
                "level l of the pair's pyramid: R, G = means E_l of its leaves x, y; B, A = their variances V_l; 8-bit "
                "codes of noise-domain data (no transfer function), decoded as offset + scale · texel per level and "
                "channel (manifest.json's `coding`, constants of `stochtex.glsl`)",
                files);
            nlohmann::json texture =
                pyramidTexture("uGraphPairStats" + std::to_string(p), list, "RGBA8",
                               "R, G = means of leaves \"" + ids[0] + "\", \"" + (ids[1].empty() ? ids[0] : ids[1]) +
                                   "\"; B, A = their variances; 8-bit codes, per level value = offset + scale · "
                                   "texel, `coding` in manifest.json");
            texture["coding"] = codingJson(coding, false);
            textures.push_back(std::move(texture));
        }
        for (int k = 0; k < graph.leafCount(); ++k) {
            const auto [pair, channel] = graph.leafLocation(k);
            leaves.push_back({{"id", graph.leafIds()[size_t(k)]}, {"pair", pair}, {"channel", "xy"[channel]}});
        }
    } else {
        const bool half = format == ExportFormat::Half;
        for (int k = 0; k < graph.leafCount(); ++k) {
            const std::string& id = graph.leafIds()[size_t(k)];
            const auto [pair, channel] = graph.leafLocation(k);
            nlohmann::json list = nlohmann::json::array();
            writeStats(f.estimator(pair).pyramid(channel), dir, "stats_" + std::to_string(k), list,
                       "variance V_l of leaf \"" + id + "\"", half, files);
            textures.push_back(pyramidTexture("uGraphStats" + std::to_string(k), list, half ? "RG16F" : "RG32F",
                                              "R = mean, G = variance"));
            leaves.push_back({{"id", id}, {"files", list}});
        }
    }
    // The covariance pyramids of the pairs whose covariance a lean node reads.
    nlohmann::json& covariances = m["graph"]["covariances"] = nlohmann::json::array();
    for (size_t p = 0; p < graph.leafPairs().size(); ++p) {
        if (!graph.pairCovariance(int(p))) continue;
        nlohmann::json list = nlohmann::json::array();
        const StatsPyramid& pyramid = *f.estimator(int(p)).covariancePyramid();
        const std::string stem = "covariance_" + std::to_string(p), uniform = "uGraphCov" + std::to_string(p);
        if (format == ExportFormat::Rgba8) {
            std::vector<GraphEstimator::LevelCoding>& coding = estimator.pyramidCoding[p];
            writeCodedLevels(
                pyramid.levels(), [&](int l) { return codedCovarianceLevel(pyramid, l, coding[size_t(l)]); }, dir, stem,
                list,
                "level l of the pair's covariance: G = C_l (R = the first leaf's E_l, B = 0, A = 1); 8-bit codes "
                "decoded as offset + scale · texel per level (manifest.json's `coding`)",
                files);
            nlohmann::json texture = pyramidTexture(uniform, list, "RGBA8",
                                                    "G = covariance; 8-bit codes, per level value = offset + scale "
                                                    "· texel, `coding` in manifest.json");
            texture["coding"] = codingJson(estimator.pyramidCoding[p], true);
            textures.push_back(std::move(texture));
        } else {
            const bool half = format == ExportFormat::Half;
            writeStats(
                pyramid, dir, stem, list,
                "covariance C_l of leaf pair " + std::to_string(p) + " (a lean node's slopes; R is E_l of the first)",
                half, files);
            textures.push_back(
                pyramidTexture(uniform, list, half ? "RG16F" : "RG32F", "R = the first leaf's mean, G = covariance"));
        }
        covariances.push_back({{"pair", p}, {"files", list}});
    }
    nlohmann::json& tables = m["graph"]["tables"] = nlohmann::json::array();
    for (size_t t = 0; t < graph.tables().size(); ++t) {
        if (!graph.readsTable(int(t), true, true)) continue;  // an op's table its function of sources replaces
        const ColormapTable& h = graph.tables()[t].blended;
        const std::string& node = graph.tableNode(int(t));
        // A field's (g, g²) table is never half: the next table reads g, and
        // a g rounded by up to 2⁻¹¹ of it moves across that table's edges.
        // The 8-bit format stores it as 16-bit codes (steps of 2⁻¹⁶) where
        // it lies in [0, 1], else as floats.
        const bool field = graph.tables()[t].field;
        const TableStorage storage = field && format == ExportFormat::Rgba8 ? TableStorage::Unorm16
                                     : field                                ? TableStorage::Float
                                     : format == ExportFormat::Rgba8        ? TableStorage::Srgb8
                                     : format == ExportFormat::Half         ? TableStorage::Half
                                     : exportOptions.halfTable              ? TableStorage::Half
                                                                            : TableStorage::Float;
        tables.push_back(writeTable(f.table(int(t)), h.resolutionX(), h.resolutionY(), "table_" + std::to_string(t),
                                    "uGraphPrefiltered" + std::to_string(t),
                                    "the prefiltered table of node \"" + node + "\"", dir, storage, textures, files));
        tables.back()["node"] = node;
        // The axes read as a Beta of (mean, σ) (kernel tableLayerBlend; the
        // include's lookup already does).
        tables.back()["beta_axes"] = {graph.tables()[t].beta[0], graph.tables()[t].beta[1]};
    }
    // Every table has the same σ levels (tableLevels); a graph of compose and
    // lean nodes alone has none.
    if (!tables.empty()) m["table"] = tables.front();
    // What an engine reads of each op beside the GLSL (a lean node's
    // shading, as the program's constants hold it), by node type: graph.lean
    // (an empty list when the graph has none of that type).
    for (const std::string& type : opManifestTypes()) m["graph"][type] = nlohmann::json::array();
    for (const GraphPattern::Operation& op : graph.operations())
        if (nlohmann::json entry = opManifest(op.params); !entry.is_null()) {
            entry["node"] = op.id;
            m["graph"][op.info->name].push_back(std::move(entry));
        }
    writeDescription(dir, m, exportedGraphInclude(graph, GraphMoments::Matched, estimator), files,
                     graph.shadesLight() ? kProgramLightSection : "", format, patternParams(graph, options));
}

void exportPatternSpec(const PatternSpec& spec, const FilterOptions& options, const std::string& dir,
                       const ExportOptions& exportOptions) {
    exportGraph(GraphPattern::build(spec, options.response), options, dir, exportOptions);
}

}  // namespace stochtex
