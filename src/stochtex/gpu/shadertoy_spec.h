#pragma once
// A ShaderToy-style program as files (issue "The workbench"; thesis ch. 3,
// GLcv): an Image pass and up to four buffer passes (Buffer A–D), each a
// GLSL file defining mainImage(out vec4 fragColor, in vec2 fragCoord), an
// optional Common file put before every pass, and each pass's four channel
// inputs iChannel0–3. This is the description only (no GL); ShadertoyHost
// (gpu/shadertoy.h) runs it.
//
// A program is a folder or a manifest:
// * a folder holds image.glsl, and optionally common.glsl,
//   buffer_a.glsl … buffer_d.glsl and sound.glsl; its passes read no channels unless the
//   folder also holds shadertoy.json, which is then the manifest;
// * a manifest (a .json file) names the files, relative to itself:
//   { "name": "…",
//     "common": "common.glsl",
//     "passes": { "buffer_a": { "code": "a.glsl", "channels": [CHANNEL, …] },
//                 "cube_a":   { "code": "cube.glsl", "size": 1024, "channels": [ … ] },
//                 "image":    { "code": "image.glsl", "channels": [ … ] },
//                 "sound":    { "code": "sound.glsl" } },
//     "uniforms": { "uGain": {"type": "float", "value": 0.5}, … },
//     "instance": "uInstance",
//     "pattern": { "preset": "marble" | "file": "p.json", "filter": "smooth" } }
//   CHANNEL (up to four, null for none):
//     {"type": "buffer", "buffer": "a", "frame": "latest" | "previous" | "current"}
//     {"type": "image", "path": "tex.png", "vflip": true}
//     {"type": "keyboard"}
//     {"type": "noise", "kind": "gray" | "rgba", "size": 64, "seed": 0}
//     {"type": "volume", "kind": "gray" | "rgba", "size": 32, "seed": 0}  (a 3D noise texture: iChannelN is a sampler3D)
//     {"type": "cubemap", "faces": ["px.png", "nx.png", "py.png", "ny.png", "pz.png", "nz.png"]}
//     {"type": "cubemap", "equirect": "sky.exr"}  (iChannelN is a samplerCube)
//     {"type": "video", "path": "clip.mp4", "loop": true, "vflip": true}  (the frame at iTime)
//     {"type": "cube_a", "frame": "latest" | "previous" | "current"}  (the Cube A pass's cube map: a samplerCube)
//   each with "filter": "nearest" | "linear" | "mipmap" and
//   "wrap": "clamp" | "repeat" (ShaderToy's defaults: images, noise and
//   volumes mipmap and repeat, cubemaps mipmap and clamp, videos linear and clamp, buffers linear and clamp, the keyboard nearest and
//   clamp).
//   "uniforms" adds the program's own (float, int, vec2, vec3, vec4); the
//   int uniform named by "instance" is the instance of a texture source
//   (a seed for statistics over instances).
//   "pattern" gives every pass a stochtex pattern (a preset, or a pattern
//   or graph file) as the include `stochtex bake` exports: vec4
//   stochtex_sample(vec2 uv), uv in example periods, the footprint from the
//   fragment's derivatives, filtered ("paper" or "smooth"), linear light
//   (srgbFromLinear3 turns it into display codes).
//
// Passes run in ShaderToy's order, Buffer A to D, Cube A, then Image. A buffer read
// as "latest" gives its last output: this frame's when it runs before the
// reader, the previous frame's otherwise (a pass reading itself: feedback).
// "previous" always gives the previous frame's; "current" requires the
// buffer to run before the reader (InputError otherwise: a pass cycle).
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "stochtex/core/enum_names.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/pattern_spec.h"

namespace stochtex {

class JsonReader;

enum class ChannelFilter { Nearest, Linear, Mipmap };
inline const EnumNames<ChannelFilter> kChannelFilterNames{
    {"nearest", ChannelFilter::Nearest}, {"linear", ChannelFilter::Linear}, {"mipmap", ChannelFilter::Mipmap}};
enum class ChannelWrap { Clamp, Repeat };
inline const EnumNames<ChannelWrap> kChannelWrapNames{{"clamp", ChannelWrap::Clamp}, {"repeat", ChannelWrap::Repeat}};

struct ShadertoyChannel {
    enum class Kind { None, Buffer, Image, Keyboard, Noise, Volume, Cubemap, Video, CubePass };
    enum class Frame { Latest, Previous, Current };
    Kind kind = Kind::None;
    int buffer = 0;  // Buffer: 0–3 for A–D (CubePass: 4, Cube A)
    Frame frame = Frame::Latest;  // Buffer, CubePass
    std::filesystem::path image;  // Image, Video (resolved); Cubemap: an equirectangular image, or empty
    bool loop = true;             // Video: from the start again after the last frame, else held there
    std::vector<std::filesystem::path> faces;  // Cubemap: six images, +x, −x, +y, −y, +z, −z
    bool vflip = true;            // Image: row 0 of the file at the top, as ShaderToy shows it
    bool rgbaNoise = true;        // Noise, Volume: four channels, else gray in all four
    int noiseSize = 64;           // Noise: a power of two in [8, 1024]; Volume: its side, a power of two in [4, 128]
    uint32_t noiseSeed = 0;
    ChannelFilter filter = ChannelFilter::Linear;
    ChannelWrap wrap = ChannelWrap::Clamp;
};

struct ShadertoyPass {
    std::string name;  // buffer_a … buffer_d, cube_a, image
    std::filesystem::path code;  // its file; for a pass embedded in a ShaderToy export, its name in messages
    std::string source;          // the code of an embedded pass (empty: read `code`)
    std::array<ShadertoyChannel, 4> channels{};
};

struct ShadertoyUniform {
    enum class Type { Float, Int, Vec2, Vec3, Vec4 };
    std::string name;
    Type type = Type::Float;
    std::array<double, 4> value{};
};
inline const EnumNames<ShadertoyUniform::Type> kShadertoyUniformTypeNames{
    {"float", ShadertoyUniform::Type::Float}, {"int", ShadertoyUniform::Type::Int},
    {"vec2", ShadertoyUniform::Type::Vec2},   {"vec3", ShadertoyUniform::Type::Vec3},
    {"vec4", ShadertoyUniform::Type::Vec4}};

struct ShadertoySpec {
    std::string name;
    std::filesystem::path common;       // empty: none
    std::string commonSource;           // Common's code when embedded in an export (empty: read `common`)
    // The buffers present, in order A–D, Cube A (ShaderToy's `void
    // mainCubemap(out vec4, in vec2 fragCoord, in vec3 rayOri, in vec3
    // rayDir)`, rendered to the six faces of a cube map), then the image pass (last).
    std::vector<ShadertoyPass> passes;
    int cubeSize = 1024;  // Cube A's face size (ShaderToy's: 1024), a power of two in [8, 2048]
    // The Sound pass (ShaderToy's `vec2 mainSound(int sample, float time)`,
    // or the older `vec2 mainSound(float time)`), rendered apart from the
    // frames: ShadertoyHost::renderSound.
    std::optional<ShadertoyPass> sound;
    std::vector<ShadertoyUniform> uniforms;
    std::string instanceUniform;  // empty: none
    std::optional<PatternSpec> pattern;  // the stochtex_sample include's pattern
    FilterOptions patternFilter;         // its filter (estimators: paper or smooth)
    // The pass that renders buffer b (0–3), or −1 when the program has none.
    int bufferPass(int buffer) const;
};

// The names of the passes in ShaderToy's order: buffer_a … buffer_d, cube_a,
// image (a buffer's index is its channel's `buffer`; Cube A's is 4).
const std::array<const char*, 6>& shadertoyPassNames();

// Reads a program folder or manifest file. InputError naming the file and,
// for a manifest, the JSON pointer: a missing or unreadable file, an unknown
// pass, channel type, filter, wrap or uniform type, a channel reading a
// buffer the program lacks, a pass cycle ("current" reads), a reserved or
// invalid uniform name.
//
// A .json file that is ShaderToy's own export (isShadertoyExport) is read
// as one: parseShadertoyExport. A folder may name its files as ShaderToy's
// tabs do: Image.glsl, Common.glsl, "Buffer A.glsl" … "Buffer D.glsl".
ShadertoySpec loadShadertoy(const std::string& path, const std::string& mediaDir = "");

// ShaderToy's export format: {"Shader": {"info": {"name": …}, "renderpass":
// [{"type": "image" | "buffer" | "common", "name": "Buffer A", "code": …,
// "inputs": [{"id", "src" or "filepath", "ctype" or "type", "channel",
// "sampler": {"filter", "wrap", "vflip", "srgb"}}], "outputs": [{"id"}]}]}},
// the inner object alone, or an array of one. Buffer inputs find their
// buffer by the output id (or ShaderToy's own ids, or the preview's file
// name); ShaderToy's four noise textures (Gray and RGBA Noise, Small and
// Medium) become the host's noise channels of the same kind and size; any
// other texture is read from `mediaDir` (default: the export's folder) by
// its file name. Pass code stays embedded (ShadertoyPass::source), named
// "<export> (Buffer A)" in compiler messages. InputError with the JSON
// pointer: sound and cubemap passes, cubemap, volume, video, music, webcam
// and mic inputs (named as unsupported), a missing texture file, an sRGB
// sampler.
bool isShadertoyExport(const nlohmann::json& j);
// Our manifest (shadertoy.json) as loadShadertoy reads it, its paths resolved
// against `baseDir`.
ShadertoySpec parseShadertoyManifest(const JsonReader& r, const std::filesystem::path& baseDir);
ShadertoySpec parseShadertoyExport(const JsonReader& r, const std::filesystem::path& json,
                                   const std::filesystem::path& mediaDir);
// The spec as our manifest (paths relative to `dir`); `codeFiles` gives the
// file, relative to `dir`, written for an embedded pass ("common" for Common).
nlohmann::json shadertoyManifest(const ShadertoySpec& spec, const std::filesystem::path& dir,
                                 const std::map<std::string, std::string>& codeFiles = {});
// Writes the program as a folder: shadertoy.json and a .glsl file per
// embedded pass (buffer_a.glsl, …, image.glsl, common.glsl); the manifest's
// path. InputError naming `output` when the folder is a file or holds any of
// those files already (nothing is written then).
std::string convertShadertoy(const ShadertoySpec& spec, const std::string& folder);

}  // namespace stochtex
