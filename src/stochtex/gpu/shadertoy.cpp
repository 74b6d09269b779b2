#include "stochtex/gpu/shadertoy.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <regex>
#include <stdexcept>
#include <vector>

#include "stochtex/core/budget.h"
#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/core/watchdog.h"
#include "stochtex/gpu/export.h"
#include "stochtex/gpu/gl_objects.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/gpu/render_target.h"
#include "stochtex/gpu/shader.h"
#include "stochtex/gpu/uploads.h"
#include "stochtex/image/image_io.h"
#include "stochtex/image/video_reader.h"
#include "stochtex/kernel/cube_map.h"

namespace stochtex {

void validateShadertoySettings(const ShadertoySettings& s) {
    if (s.width < 1 || s.width > 8192)
        throw InputError::parameter("width", "must be in [1, 8192], got " + std::to_string(s.width));
    if (s.height < 1 || s.height > 8192)
        throw InputError::parameter("height", "must be in [1, 8192], got " + std::to_string(s.height));
    if (!(std::isfinite(s.fps) && s.fps > 0 && s.fps <= 1000))
        throw InputError::parameter("fps", "must be in (0, 1000], got " + formatValue(s.fps));
    if (!(std::isfinite(s.startTime) && s.startTime >= 0 && s.startTime <= 1e6))
        throw InputError::parameter("startTime", "must be in [0, 1e6] s, got " + formatValue(s.startTime));
    const auto& d = s.date;
    const bool leap = (d[0] % 4 == 0 && d[0] % 100 != 0) || d[0] % 400 == 0;
    const int days[12] = {31, leap ? 29 : 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (d[0] < 1 || d[0] > 9999 || d[1] < 1 || d[1] > 12 || d[2] < 1 || d[2] > days[d[1] - 1] || d[3] < 0 ||
        d[3] > 23 || d[4] < 0 || d[4] > 59 || d[5] < 0 || d[5] > 59)
        throw InputError::parameter("date",
                                    "must be a calendar date and time (year 1–9999, month 1–12, a day of that "
                                    "month, hour 0–23, minute and second 0–59)");
    for (const int key : s.keys)
        if (key < 0 || key > 255)
            throw InputError::parameter("keys",
                                        "must be key codes 0–255 (JavaScript keyCode), got " + std::to_string(key));
    for (size_t k = 0; k < s.inputs.size(); ++k) {
        validateShadertoyInput(s.inputs[k]);
        if (k > 0 && s.inputs[k].frame < s.inputs[k - 1].frame)
            throw InputError::parameter("input", "events must come in order of frame: frame " +
                                                     std::to_string(s.inputs[k].frame) + " after frame " +
                                                     std::to_string(s.inputs[k - 1].frame));
    }
    if (s.hwPerformance != 0 && s.hwPerformance != 1)
        throw InputError::parameter("hwPerformance",
                                    "must be 0 (a phone) or 1 (a desktop), got " + std::to_string(s.hwPerformance));
}

void checkShadertoyMemory(const ShadertoySpec& spec, const ShadertoySettings& s) {
    // Two RGBA32F targets per buffer, one for the image; a third more with mipmaps.
    const double frame = double(s.width) * s.height * 16.0 * 4.0 / 3.0;
    const bool cube = spec.bufferPass(4) >= 0;
    const double cubeBytes = cube ? 2.0 * 6.0 * double(spec.cubeSize) * spec.cubeSize * 16.0 * 4.0 / 3.0 : 0.0;
    const double bytes = frame * double(2 * (int(spec.passes.size()) - (cube ? 2 : 1)) + 1) + cubeBytes;
    const long long budget = budgeted(kMaxShadertoyBytes);
    if (bytes > double(budget))
        throw InputError::overBudget("width", "the " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                                  " frame's buffers would take " + formatValue(bytes / (1 << 20)) +
                                                  " MiB, more than " + std::to_string(budget >> 20) +
                                                  " MiB; use a smaller size");
}

namespace {

// A GL sampler object: filtering and wrapping of one channel, apart from its texture.
void deleteSampler(GLuint id) { glDeleteSamplers(1, &id); }
using Sampler = gl::Handle<deleteSampler>;

constexpr int kKeys = ShadertoyInputState::kKeys;

// Lets a texture made without mipmaps (floatTexture, RenderTarget) have
// them, and builds them from level 0. The channel's sampler chooses the filter.
void withMipmaps(GLuint texture) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
    glGenerateMipmap(GL_TEXTURE_2D);
}
constexpr int kPatternUnits = 16;  // a pattern's GpuView binds at most these (checkGraphTextureUnits)

// The names of ShaderToy before WebGL 2 (2017) that published shaders still
// use, and what they are now. Each is defined only for sources that use it
// and neither define nor declare it themselves (a shader's own
// `#define texture2D(s, uv) …` or `vec4 texture2D(…)` shim must not collide).
std::string legacyAliases(const std::vector<std::string>& texts) {
    static const std::pair<const char*, const char*> kAliases[] = {
        {"iGlobalTime", "iTime"}, {"texture2D", "texture"}, {"texture2DLod", "textureLod"}};
    std::string out;
    for (const auto& [old, now] : kAliases) {
        const std::regex used("\\b" + std::string(old) + "\\b");
        // Its own macro, or a variable or function of a GLSL type by that name.
        const std::regex own("#\\s*define\\s+" + std::string(old) +
                             "\\b|\\b(void|float|int|uint|bool|[biu]?vec[234]|mat[234](x[234])?|sampler\\w*)\\s+" +
                             std::string(old) + "\\s*[(=;,]");
        bool uses = false, owns = false;
        for (const std::string& t : texts) {
            uses = uses || std::regex_search(t, used);
            owns = owns || std::regex_search(t, own);
        }
        if (uses && !owns) out += std::string("#define ") + old + " " + now + "\n";
    }
    return out;
}

// The uniforms every pass declares (ShaderToy's), then the program's own,
// and the output; mainImage's wrapper after the user's files. aliases:
// legacyAliases of the program's sources.
std::string prelude(const ShadertoySpec& spec, const ShadertoySettings& settings, const std::string& aliases) {
    std::string s =
        "// stochtex ShaderToy host: ShaderToy's uniforms.\n"
        "#define HW_PERFORMANCE " +
        std::to_string(settings.hwPerformance) + "\n" + aliases +
        "uniform vec3 iResolution;\nuniform float iTime;\nuniform float iTimeDelta;\nuniform int iFrame;\n"
        "uniform float iFrameRate;\nuniform vec4 iMouse;\nuniform vec4 iDate;\nuniform float iSampleRate;\n"
        "uniform vec3 iChannelResolution[4];\nuniform float iChannelTime[4];\n";
    for (const ShadertoyUniform& u : spec.uniforms)
        s += "uniform " + enumName(kShadertoyUniformTypeNames, u.type) + " " + u.name + ";\n";
    return s + "out vec4 stochtexFragColour;\n";
}
// A pass's iChannel0–3, each of the sampler type its channel needs (a
// volume's is a sampler3D), as ShaderToy declares them.
std::string channelDeclarations(const ShadertoyPass& pass) {
    std::string s;
    for (size_t i = 0; i < 4; ++i)
        s += std::string("uniform ") +
             (pass.channels[i].kind == ShadertoyChannel::Kind::Volume ? "sampler3D"
              : pass.channels[i].kind == ShadertoyChannel::Kind::Cubemap ||
                      pass.channels[i].kind == ShadertoyChannel::Kind::CubePass
                  ? "samplerCube"
                  : "sampler2D") +
             " iChannel" + std::to_string(i) + ";\n";
    return s;
}

// The Sound pass's wrapper: the texel (x, y) of a 512 × 512 block is sample
// block + 512 y + x, at time sample / iSampleRate (ShaderToy's layout; it
// plays left and right from red and green). `withIndex`: the pass's
// mainSound takes the sample number too (ShaderToy since 2020).
constexpr int kSoundBlock = 512;
std::string soundMain(bool withIndex) {
    return std::string(
               "uniform int stochtexSoundStart;\nvoid main() {\n"
               "    int s = stochtexSoundStart + int(gl_FragCoord.y) * 512 + int(gl_FragCoord.x);\n"
               "    vec2 v = ") +
           (withIndex ? "mainSound(s, float(s) / iSampleRate)" : "mainSound(float(s) / iSampleRate)") +
           ";\n    stochtexFragColour = vec4(v, 0.0, 1.0);\n}\n";
}

// Cube A's wrapper: the face drawn (0–5: +x, −x, +y, −y, +z, −z) and the
// fragment's place on it give the ray's direction as GL's cube map
// selection reads it back (kernel/cube_map.glsl), from the origin.
const char* kCubeMain =
    "uniform int stochtexCubeFace;\n"
    "void main() {\n    vec4 colour = vec4(0.0);\n"
    "    vec2 st = gl_FragCoord.xy / iResolution.xy;\n"
    "    vec3 dir = normalize(cubeFaceDirection(stochtexCubeFace, st.x, st.y));\n"
    "    mainCubemap(colour, gl_FragCoord.xy, vec3(0.0), dir);\n    stochtexFragColour = colour;\n}\n";

const char* kMain =
    "void main() {\n    vec4 colour = vec4(0.0);\n    mainImage(colour, gl_FragCoord.xy);\n    stochtexFragColour = "
    "colour;\n}\n";

GLint minFilter(ChannelFilter f) {
    return f == ChannelFilter::Nearest ? GL_NEAREST : f == ChannelFilter::Linear ? GL_LINEAR : GL_LINEAR_MIPMAP_LINEAR;
}

// An image as a browser uploads it to WebGL: grey is (v, v, v, 1), grey
// and alpha (v, v, v, a); colour keeps its channels (RGB reads alpha 1).
Image asBrowserUploads(const Image& img) {
    if (img.channels() > 2) return img;
    Image out(img.width(), img.height(), 4, Image::Uninitialized{});
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const float v = img.at(x, y, 0);
            out.at(x, y, 0) = out.at(x, y, 1) = out.at(x, y, 2) = v;
            out.at(x, y, 3) = img.channels() == 2 ? img.at(x, y, 1) : 1.0f;
        }
    return out;
}

// A texture of the image's channels (1–4: R, RG, RGB, RGBA as GL reads
// them; uploads' floatTexture), rows flipped when vflip so that the file's
// top row is at v = 1, with its mip chain when a channel reads mipmaps.
gl::Texture imageTexture(const Image& img, bool vflip, bool mipmaps) {
    std::vector<float> rows(img.data().size());
    const size_t stride = size_t(img.width()) * size_t(img.channels());
    for (int y = 0; y < img.height(); ++y) {
        // GL's row 0 is v = 0, the bottom: the file's last row when flipped.
        const int from = vflip ? img.height() - 1 - y : y;
        std::copy(img.row(from), img.row(from) + stride, rows.begin() + std::ptrdiff_t(size_t(y) * stride));
    }
    gl::Texture t = floatTexture(img.width(), img.height(), img.channels(), rows.data());
    if (mipmaps) withMipmaps(t.id());
    return t;
}

// The offset, in texels, between the channels of ShaderToy's RGBA noise
// textures: green is red at (x − 37, y − 17), alpha blue there, so that
// the one-fetch 3D value noise published shaders use (the lattice's slice z
// read at xy + (37, 17)·z, green for z and red for z + 1) is continuous
// across slices.
constexpr int kNoiseSliceOffset[2] = {37, 17};

// ShaderToy's noise textures, drawn from the project's hash: every texel's
// red and blue uniform in [0, 1) and independent, green and alpha the same
// values offset by kNoiseSliceOffset (rgba), or one value in all four (gray).
Image noiseImage(int size, bool rgba, uint32_t seed) {
    const uint32_t key = deriveSeed(seed, 0x6e6f6973u);
    const auto texel = [&](int x, int y) {
        const UInt3 h = pcg3d({uint32_t(x), uint32_t(y), key});
        return std::array<float, 2>{unitFloat(h.x), unitFloat(h.z)};
    };
    Image img(size, size, 4, Image::Uninitialized{});
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const std::array<float, 2> rb = texel(x, y);
            if (!rgba) {
                for (int c = 0; c < 4; ++c) img.at(x, y, c) = rb[0];
                continue;
            }
            // size is a power of two: the offset texel wraps by a mask.
            const std::array<float, 2> ga =
                texel((x - kNoiseSliceOffset[0]) & (size - 1), (y - kNoiseSliceOffset[1]) & (size - 1));
            img.at(x, y, 0) = rb[0];
            img.at(x, y, 1) = ga[0];
            img.at(x, y, 2) = rb[1];
            img.at(x, y, 3) = ga[1];
        }
    return img;
}

// A 3D texture of RGBA floats (x fastest, then y, then z), its mip chain when asked.
gl::Texture volumeTexture(const std::vector<float>& rgba, int size, bool mipmaps) {
    gl::Texture t = gl::newTexture();
    glBindTexture(GL_TEXTURE_3D, t.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA32F, size, size, size, 0, GL_RGBA, GL_FLOAT, rgba.data());
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, mipmaps ? 1000 : 0);
    if (mipmaps) glGenerateMipmap(GL_TEXTURE_3D);
    glBindTexture(GL_TEXTURE_3D, 0);
    return t;
}

// A cube face resampled from an equirectangular image (bilinear, around in
// longitude, clamped at the poles): the image's centre column looks along
// −z, the column a quarter in along −x, three quarters in along +x, its top
// row up (+y), as panoramas are commonly stored.
Image equirectangularFace(const Image& pano, int face, int size) {
    const int c = pano.channels();
    Image out(size, size, c, Image::Uninitialized{});
    constexpr double kPi = 3.14159265358979323846;
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const kernel::vec3 d =
                kernel::cubeFaceDirection(face, (float(i) + 0.5f) / float(size), (float(j) + 0.5f) / float(size));
            const double len = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
            const double u = 0.5 + std::atan2(double(d.x), -double(d.z)) / (2 * kPi);
            const double v = std::acos(std::clamp(double(d.y) / len, -1.0, 1.0)) / kPi;
            const double x = u * pano.width() - 0.5, y = std::clamp(v * pano.height() - 0.5, 0.0, pano.height() - 1.0);
            const int x0 = int(std::floor(x)), y0 = int(std::floor(y)), y1 = std::min(y0 + 1, pano.height() - 1);
            const double fx = x - x0, fy = y - y0;
            const int xa = ((x0 % pano.width()) + pano.width()) % pano.width(), xb = (xa + 1) % pano.width();
            for (int k = 0; k < c; ++k)
                out.at(i, j, k) = float((1 - fy) * ((1 - fx) * pano.at(xa, y0, k) + fx * pano.at(xb, y0, k)) +
                                        fy * ((1 - fx) * pano.at(xa, y1, k) + fx * pano.at(xb, y1, k)));
        }
    return out;
}

// A cube map of six square faces of one size (+x, −x, +y, −y, +z, −z, row 0
// of each image at t = 0, as GL's cube faces are laid out), RGBA32F, its mip
// chain when asked.
gl::Texture cubeTexture(const std::array<Image, 6>& faces, bool mipmaps) {
    gl::Texture t = gl::newTexture();
    glBindTexture(GL_TEXTURE_CUBE_MAP, t.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    static const GLenum kFormats[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    for (int f = 0; f < 6; ++f) {
        const Image& img = faces[size_t(f)];
        glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA32F, img.width(), img.height(), 0,
                     kFormats[img.channels() - 1], GL_FLOAT, img.data().data());
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, mipmaps ? 1000 : 0);
    if (mipmaps) glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    return t;
}

// Cube A's target: an RGBA32F cube map of size² faces (zeros), mipmaps when read so.
gl::Texture cubeTarget(int size, bool mipmaps) {
    gl::Texture t = gl::newTexture();
    glBindTexture(GL_TEXTURE_CUBE_MAP, t.id());
    for (int f = 0; f < 6; ++f)
        glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA32F, size, size, 0, GL_RGBA, GL_FLOAT,
                     nullptr);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, mipmaps ? 1000 : 0);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    if (mipmaps) glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    return t;
}

// The channels' textures in all, estimated from the images' headers before
// any is read (20 channels of 4096² images took ~8 GB; ShaderToy's own are
// at most 1024²), at most 1 GiB (two 4096² images with mipmaps): RGBA
// floats, a third more with mipmaps; a video is read a frame at a time and
// not counted. InputError
// naming the channel where the total passes the budget.
void checkChannelBudget(const ShadertoySpec& spec) {
    constexpr long long kTexelBytes = 16;
    const long long maxBytes = budgeted(1ll << 30);
    long long total = 0;
    for (const ShadertoyPass& pass : spec.passes)
        for (size_t i = 0; i < pass.channels.size(); ++i) {
            const ShadertoyChannel& ch = pass.channels[i];
            long long texels = 0;
            switch (ch.kind) {
                case ShadertoyChannel::Kind::Image: {
                    const auto [w, h] = readImageSize(ch.image.string());
                    texels = (long long)w * h;
                    break;
                }
                case ShadertoyChannel::Kind::Cubemap: {
                    const auto [w, h] = readImageSize((ch.image.empty() ? ch.faces.at(0) : ch.image).string());
                    const long long face = ch.image.empty() ? w : std::clamp(w / 4, 1, 2048);
                    texels = 6 * face * (ch.image.empty() ? h : face);
                    break;
                }
                case ShadertoyChannel::Kind::Noise: texels = (long long)ch.noiseSize * ch.noiseSize; break;
                case ShadertoyChannel::Kind::Volume:
                    texels = (long long)ch.noiseSize * ch.noiseSize * ch.noiseSize;
                    break;
                default:
                    break;  // buffers are the passes' own; the keyboard is 256×3; a video is read a frame at a time
            }
            total += texels * kTexelBytes * (ch.filter == ChannelFilter::Mipmap ? 4 : 3) / 3;
            if (total > maxBytes)
                throw InputError::overBudget("", spec.name + ": pass " + pass.name + ": channel " + std::to_string(i) +
                                                     ": the channels' textures take " + std::to_string(total >> 20) +
                                                     " MiB up to here; at most " + std::to_string(maxBytes >> 20) +
                                                     " MiB in all (RGBA floats, 16 bytes a texel)");
        }
}

// A cubemap channel's faces: six images as a browser uploads them (square,
// one size), or an equirectangular image resampled onto faces of a quarter
// of its width. InputError naming the file.
std::array<Image, 6> cubemapFaces(const ShadertoyChannel& ch) {
    constexpr int kMaxFace = 4096;
    std::array<Image, 6> faces;
    const auto readChannelImage = [](const std::filesystem::path& path) {
        const Image img = readImage(path.string());
        if (img.channels() < 1 || img.channels() > 4)
            throw InputError(path.string() + ": a channel image has 1 to 4 channels, got " +
                             std::to_string(img.channels()));
        return asBrowserUploads(img);
    };
    if (!ch.image.empty()) {
        const Image pano = readChannelImage(ch.image);
        const int size = std::clamp(pano.width() / 4, 1, kMaxFace / 2);
        for (int f = 0; f < 6; ++f) faces[size_t(f)] = equirectangularFace(pano, f, size);
        return faces;
    }
    for (size_t f = 0; f < 6; ++f) {
        faces[f] = readChannelImage(ch.faces[f]);
        if (faces[f].width() != faces[f].height() || faces[f].width() > kMaxFace ||
            faces[f].width() != faces[0].width() || faces[f].channels() != faces[0].channels())
            throw InputError(ch.faces[f].string() +
                             ": a cube face is square, at most 4096 pixels, and of the first "
                             "face's size and channels (" +
                             std::to_string(faces[0].width()) + "x" + std::to_string(faces[0].width()) + "), got " +
                             std::to_string(faces[f].width()) + "x" + std::to_string(faces[f].height()));
    }
    return faces;
}

// A compiler's log, after ShaderError's first line, as one short message:
// its first error with its location ("file:line", mapped to the user's
// files by compileProgram), the source line it names, and how many more
// errors there are. Mesa follows an error with indented lines of the same
// location (the 60 candidate overloads of `texture`); they are part of the
// first error, not errors of their own, and are left out.
std::string firstCompilerError(const std::string& what,
                               const std::vector<std::pair<std::string, std::string>>& userFiles) {
    // Mesa: "file:12(3): error: …"; NVIDIA: "file:12 : error C1008: …".
    static const std::regex errorLine(R"(^(.+?):(\d+)(?:\((\d+)\))?\s*:\s*error\b[^:]*:(.*)$)");
    std::vector<std::smatch> errors;
    std::vector<std::string> lines;
    for (size_t pos = what.find('\n'); pos != std::string::npos && pos + 1 < what.size();) {
        const size_t end = what.find('\n', pos + 1);
        lines.push_back(what.substr(pos + 1, end == std::string::npos ? std::string::npos : end - pos - 1));
        pos = end;
    }
    std::string first, location, file;
    int line = 0, more = 0;
    for (const std::string& text : lines) {
        std::smatch m;
        if (!std::regex_match(text, m, errorLine)) continue;
        std::string message = m[4].str();
        if (message.empty() ||
            (message.size() > 1 && std::isspace((unsigned char)message[0]) && std::isspace((unsigned char)message[1])))
            continue;  // a continuation (indented twice or more): a candidate, a note
        if (!first.empty()) {
            ++more;
            continue;
        }
        while (!message.empty() && std::isspace((unsigned char)message.front())) message.erase(0, 1);
        while (!message.empty() && std::isspace((unsigned char)message.back())) message.pop_back();
        if (message.ends_with("candidates are:")) message.resize(message.size() - 16);
        while (!message.empty() && (message.back() == ';' || message.back() == ' ')) message.pop_back();
        file = m[1].str();
        line = logLineNumber(m[2].str());  // 0 (past an int): no source line is quoted
        location = file + ":" + m[2].str() + (m[3].matched ? ":" + m[3].str() : "");
        first = message;
    }
    if (first.empty()) {  // no line in a known form: the log as it is, on one line, cut short
        std::string out;
        for (const std::string& text : lines) out += (out.empty() ? "" : "; ") + text;
        return out.size() > 600 ? out.substr(0, 600) + " …" : out.empty() ? what : out;
    }
    std::string out = location + ": " + first;
    // A channel sampled with a 3D coordinate is a cubemap or volume channel on ShaderToy.
    if (std::regex_search(first, std::regex(R"(texture\w*\(sampler2D, [iu]?vec3)")))
        out +=
            " (a channel read with a 3D coordinate is a volume or cubemap channel on ShaderToy: give a volume as "
            "{\"type\": \"volume\"}, a cubemap as {\"type\": \"cubemap\"} in the manifest; docs/SHADERTOY.md)";
    if (more > 0) out += " (and " + std::to_string(more) + " more error" + (more > 1 ? "s" : "") + ")";
    // The line itself, from the user's file, so the message is read without opening it.
    for (const auto& [path, text] : userFiles) {
        if (path != file || line == 0) continue;
        size_t begin = 0;
        for (int k = 1; k < line && begin != std::string::npos; ++k) {
            begin = text.find('\n', begin);
            if (begin != std::string::npos) ++begin;
        }
        if (begin == std::string::npos || begin >= text.size()) break;
        std::string source = text.substr(begin, text.find('\n', begin) - begin);
        while (!source.empty() && std::isspace((unsigned char)source.front())) source.erase(0, 1);
        if (source.size() > 120) source = source.substr(0, 120) + " …";
        if (!source.empty()) out += "\n    " + std::to_string(line) + " | " + source;
    }
    return out;
}

// What a pass uses that ShaderToy has and this host does not (a sound,
// cubemap or VR entry point instead of mainImage), named as such: the
// compiler would only say that mainImage is missing. Empty when nothing is.
// `common`: the Common file's text, which may define mainImage for every pass.
std::string unsupportedFeature(const std::string& path, const std::string& text, const std::string& common) {
    static const std::regex mainImage(R"(\bvoid\s+mainImage\s*\()");
    static const std::pair<const char*, const char*> kEntryPoints[] = {
        {R"(\bmainSound\s*\()",
         "a sound pass's code (mainSound), which belongs in sound.glsl or the manifest's "
         "\"sound\" pass, not"},
        {R"(\bmainCubemap\s*\()",
         "a cubemap pass's code (mainCubemap), which belongs in cube_a.glsl or the "
         "manifest's \"cube_a\" pass, not"},
        {R"(\bmainVR\s*\()", "a VR entry point (mainVR) alone"}};
    if (!std::regex_search(text, mainImage) && !std::regex_search(common, mainImage)) {
        for (int k = 0; k < 2; ++k)  // a sound or cube pass's code in a picture pass
            if (std::regex_search(text, std::regex(kEntryPoints[k].first)))
                return path + ": " + kEntryPoints[k].second +
                       " a picture pass: a picture pass defines mainImage(out vec4, in vec2)";
        for (const auto& [pattern, what] : kEntryPoints)
            if (std::regex_search(text, std::regex(pattern)))
                return path + ": " + what +
                       " is a ShaderToy feature this host does not run (docs/SHADERTOY.md lists "
                       "what it does); a pass defines mainImage(out vec4, in vec2)";
        return path + ": defines no mainImage(out vec4 fragColor, in vec2 fragCoord), ShaderToy's entry point";
    }
    return {};
}

}  // namespace

std::vector<float> shadertoyNoiseVolume(int size, bool rgba, uint32_t seed) {
    if (size < 1 || size > 256) throw std::invalid_argument("shadertoyNoiseVolume: size must be in [1, 256]");
    const uint32_t key = deriveSeed(seed, 0x766f6cu);
    std::vector<float> out(size_t(size) * size * size * 4);
    for (int z = 0; z < size; ++z) {
        const uint32_t slice = deriveSeed(key, uint32_t(z));
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const UInt3 h = pcg3d({uint32_t(x), uint32_t(y), slice});
                float* v = &out[((size_t(z) * size + y) * size + x) * 4];
                if (!rgba) {
                    v[0] = v[1] = v[2] = v[3] = unitFloat(h.x);
                    continue;
                }
                v[0] = unitFloat(h.x);
                v[1] = unitFloat(h.y);
                v[2] = unitFloat(h.z);
                v[3] = unitFloat(pcg3d({h.x, h.y, h.z}).x);
            }
    }
    return out;
}

struct ShadertoyHost::Impl {
    ShadertoySpec spec;
    ShadertoySettings settings;
    gl::VertexArray vao;
    // Per pass: its program, its uniform locations, two targets (a buffer
    // writes one while it may read the other), which holds the last output.
    struct Pass {
        gl::Program program;
        std::vector<RenderTarget> targets;  // two for a buffer, one for the image
        int latest = 0;
        bool renderedThisFrame = false;
        bool mipmaps = false;  // some channel reads it with mipmaps
        std::array<Sampler, 4> samplers;
        std::array<gl::Texture, 4> inputs;  // image, keyboard and noise channels' textures
        std::array<std::array<int, 3>, 4> inputSize{};
        std::array<std::unique_ptr<VideoReader>, 4> videos;  // video channels' files, the frame shown decoded
        std::array<int, 4> videoFrame{-1, -1, -1, -1};       // the frame each video channel's texture holds
        // Cube A: two cube maps (RGBA32F faces), drawn face by face through one framebuffer.
        bool cube = false;
        std::array<gl::Texture, 2> cubeTargets;
        gl::Framebuffer cubeFramebuffer;
    };
    std::vector<Pass> passes;
    gl::Program sound;                 // the Sound pass's program (0: none)
    std::unique_ptr<GpuView> pattern;  // the stochtex_sample include's textures and parameters
    int channelUnit = 0;               // iChannel0's texture unit
    gl::Texture keyboard;
    ShadertoyInputState input;  // the keyboard texture's rows and iMouse
    size_t nextInput = 0;       // the settings' next event of the timeline
    int frame = 0;
    int instance = 0;

    // Waits for the passes' fences in order: a pass still running when the
    // frame's time budget is spent cannot be stopped (a loop that never ends;
    // a real driver would hang or reset), so the process ends naming it.
    void awaitFrame(const std::vector<GLsync>& passDone, std::chrono::steady_clock::time_point start) const {
        const double budget = budgetedSeconds(kFrameSeconds);
        const auto deadline = start + std::chrono::duration<double>(budget);
        for (size_t p = 0; p < passDone.size(); ++p) {
            const auto left =
                std::chrono::duration_cast<std::chrono::nanoseconds>(deadline - std::chrono::steady_clock::now());
            const GLenum r = glClientWaitSync(passDone[p], GL_SYNC_FLUSH_COMMANDS_BIT,
                                              GLuint64(std::max<long long>(left.count(), 0)));
            if (r == GL_TIMEOUT_EXPIRED)
                overrun(spec.name + ": pass " + spec.passes[p].name + " of frame " + std::to_string(frame) +
                        " ran past the frame's time budget of " + formatValue(budget) + " s");
        }
        for (GLsync fence : passDone) glDeleteSync(fence);
    }

    RenderTarget newTarget(bool mipmaps) const {
        while (glGetError() != GL_NO_ERROR) {}
        RenderTarget t(settings.width, settings.height, false);
        if (mipmaps) withMipmaps(t.texture());
        glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer());
        if (glGetError() == GL_OUT_OF_MEMORY || glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw InputError::parameter("width", "the " + std::to_string(settings.width) + "x" +
                                                     std::to_string(settings.height) +
                                                     " frame's buffers do not fit in this GL's memory");
        return t;
    }

    // Every target at 0, its mip levels too (a mipmapped read of a buffer
    // that has not run yet sees zeros, not a previous run's levels).
    void clearTargets() {
        const float zero[4] = {0, 0, 0, 0};
        for (Pass& p : passes)
            if (p.cube)
                for (const gl::Texture& t : p.cubeTargets) {
                    const std::vector<float> zeros(size_t(spec.cubeSize) * spec.cubeSize * 4, 0.0f);
                    glBindTexture(GL_TEXTURE_CUBE_MAP, t.id());
                    for (int f = 0; f < 6; ++f)
                        glTexSubImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, 0, 0, spec.cubeSize,
                                        spec.cubeSize, GL_RGBA, GL_FLOAT, zeros.data());
                    if (p.mipmaps) glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
                }
        for (Pass& p : passes)
            for (const RenderTarget& t : p.targets) {
                glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer());
                glClearBufferfv(GL_COLOR, 0, zero);
                if (p.mipmaps) {
                    glBindTexture(GL_TEXTURE_2D, t.texture());
                    glGenerateMipmap(GL_TEXTURE_2D);
                }
            }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    void uploadKeyboard() {
        glBindTexture(GL_TEXTURE_2D, keyboard.id());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, kKeys, 3, 0, GL_RED, GL_FLOAT, input.keyboard().data());
    }

    // The texture channel i of pass p reads now, its target and its size
    // (iChannelResolution: width, height, depth; 0 for none).
    struct ChannelTexture {
        GLuint id = 0;
        GLenum target = GL_TEXTURE_2D;
        std::array<int, 3> size{};
    };
    ChannelTexture channelTexture(size_t p, size_t i) const {
        const ShadertoyChannel& ch = spec.passes[p].channels[i];
        const Pass& pass = passes[p];
        switch (ch.kind) {
            case ShadertoyChannel::Kind::None: return {};
            case ShadertoyChannel::Kind::Buffer: {
                const Pass& b = passes[size_t(spec.bufferPass(ch.buffer))];
                // Previous: the other target once the buffer has run this frame.
                const bool other = ch.frame == ShadertoyChannel::Frame::Previous && b.renderedThisFrame;
                return {b.targets[size_t(other ? 1 - b.latest : b.latest)].texture(),
                        GL_TEXTURE_2D,
                        {settings.width, settings.height, 1}};
            }
            case ShadertoyChannel::Kind::Keyboard: return {keyboard.id(), GL_TEXTURE_2D, {kKeys, 3, 1}};
            case ShadertoyChannel::Kind::Image:
            case ShadertoyChannel::Kind::Video:
            case ShadertoyChannel::Kind::Noise: return {pass.inputs[i].id(), GL_TEXTURE_2D, pass.inputSize[i]};
            case ShadertoyChannel::Kind::Volume: return {pass.inputs[i].id(), GL_TEXTURE_3D, pass.inputSize[i]};
            case ShadertoyChannel::Kind::Cubemap: return {pass.inputs[i].id(), GL_TEXTURE_CUBE_MAP, pass.inputSize[i]};
            case ShadertoyChannel::Kind::CubePass: {
                const Pass& c = passes[size_t(spec.bufferPass(4))];
                const bool other = ch.frame == ShadertoyChannel::Frame::Previous && c.renderedThisFrame;
                return {c.cubeTargets[size_t(other ? 1 - c.latest : c.latest)].id(),
                        GL_TEXTURE_CUBE_MAP,
                        {spec.cubeSize, spec.cubeSize, 1}};
            }
        }
        return {};
    }

    double time() const { return settings.startTime + frame / settings.fps; }

    // Puts the frame of video channel i of pass p at this frame's time in
    // its texture (decoding on as needed); the video's time shown.
    double showVideoFrame(size_t p, size_t i) {
        Pass& pass = passes[p];
        const ShadertoyChannel& ch = spec.passes[p].channels[i];
        VideoReader& video = *pass.videos[i];
        const Image& img = video.frameAt(time(), ch.loop);
        if (video.frameIndex() != pass.videoFrame[i]) {
            pass.inputs[i] = imageTexture(img, ch.vflip, ch.filter == ChannelFilter::Mipmap);
            pass.videoFrame[i] = video.frameIndex();
        }
        return video.frameIndex() / video.fps();
    }

    void run(size_t p) {
        Pass& pass = passes[p];
        const bool buffer = spec.passes[p].name != "image";
        const int write = buffer ? 1 - pass.latest : 0;
        if (pass.cube) {
            glBindFramebuffer(GL_FRAMEBUFFER, pass.cubeFramebuffer.id());
            glViewport(0, 0, spec.cubeSize, spec.cubeSize);
        } else {
            pass.targets[size_t(write)].bind();
        }
        const GLuint prog = pass.program.id();
        if (pattern) pattern->bind(prog);  // units 0–15 and the parameter block
        glUseProgram(prog);
        const auto loc = [&](const char* name) { return glGetUniformLocation(prog, name); };
        const float t = float(time());
        if (pass.cube)
            glUniform3f(loc("iResolution"), float(spec.cubeSize), float(spec.cubeSize), 1.0f);
        else
            glUniform3f(loc("iResolution"), float(settings.width), float(settings.height), 1.0f);
        glUniform1f(loc("iTime"), t);
        glUniform1f(loc("iTimeDelta"), float(1.0 / settings.fps));
        glUniform1i(loc("iFrame"), frame);
        glUniform1f(loc("iFrameRate"), float(settings.fps));
        const std::array<float, 4>& mouse = input.mouse();
        glUniform4f(loc("iMouse"), mouse[0], mouse[1], mouse[2], mouse[3]);
        const auto& d = settings.date;
        const double seconds = d[3] * 3600.0 + d[4] * 60.0 + d[5] + time();
        glUniform4f(loc("iDate"), float(d[0]), float(d[1] - 1), float(d[2]), float(seconds));
        glUniform1f(loc("iSampleRate"), float(settings.sampleRate));
        for (const ShadertoyUniform& u : spec.uniforms) {
            const GLint l = loc(u.name.c_str());
            const auto& v = u.value;
            const double value = u.name == spec.instanceUniform ? double(instance) : v[0];
            switch (u.type) {
                case ShadertoyUniform::Type::Float: glUniform1f(l, float(value)); break;
                case ShadertoyUniform::Type::Int: glUniform1i(l, int(value)); break;
                case ShadertoyUniform::Type::Vec2: glUniform2f(l, float(v[0]), float(v[1])); break;
                case ShadertoyUniform::Type::Vec3: glUniform3f(l, float(v[0]), float(v[1]), float(v[2])); break;
                case ShadertoyUniform::Type::Vec4:
                    glUniform4f(l, float(v[0]), float(v[1]), float(v[2]), float(v[3]));
                    break;
            }
        }
        float resolutions[12] = {}, times[4] = {t, t, t, t};
        for (size_t i = 0; i < 4; ++i)
            if (pass.videos[i]) times[i] = float(showVideoFrame(p, i));
        for (size_t i = 0; i < 4; ++i) {
            const ChannelTexture tex = channelTexture(p, i);
            const GLuint unit = GLuint(channelUnit) + GLuint(i);
            glActiveTexture(GL_TEXTURE0 + unit);
            glBindTexture(tex.target, tex.id);
            glBindSampler(unit, pass.samplers[i].id());
            const std::string name = "iChannel" + std::to_string(i);
            glUniform1i(loc(name.c_str()), GLint(unit));
            for (size_t k = 0; k < 3; ++k) resolutions[3 * i + k] = float(tex.size[k]);
        }
        glUniform3fv(loc("iChannelResolution"), 4, resolutions);
        glUniform1fv(loc("iChannelTime"), 4, times);
        glBindVertexArray(vao.id());
        if (pass.cube) {
            for (int face = 0; face < 6; ++face) {
                glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                       GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face),
                                       pass.cubeTargets[size_t(write)].id(), 0);
                glUniform1i(loc("stochtexCubeFace"), face);
                glDrawArrays(GL_TRIANGLES, 0, 3);
            }
        } else {
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        for (GLuint i = 0; i < 4; ++i) glBindSampler(GLuint(channelUnit) + i, 0);
        if (pass.mipmaps && pass.cube) {
            glBindTexture(GL_TEXTURE_CUBE_MAP, pass.cubeTargets[size_t(write)].id());
            glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
        } else if (pass.mipmaps) {
            glBindTexture(GL_TEXTURE_2D, pass.targets[size_t(write)].texture());
            glGenerateMipmap(GL_TEXTURE_2D);
        }
        pass.latest = write;
        pass.renderedThisFrame = true;
    }
};

ShadertoyHost::ShadertoyHost(const ShadertoySpec& spec, GlContext& context, const ShadertoySettings& settings)
    : impl_(std::make_unique<Impl>()) {
    validateShadertoySettings(settings);
    checkShadertoyMemory(spec, settings);
    for (const ShadertoyPass& pass : spec.passes)  // a spec built in code, not by loadShadertoy
        for (const ShadertoyChannel& ch : pass.channels)
            if (ch.kind == ShadertoyChannel::Kind::Buffer &&
                (ch.buffer < 0 || ch.buffer > 3 || spec.bufferPass(ch.buffer) < 0))
                throw std::invalid_argument("ShadertoyHost: pass " + pass.name + " reads a buffer the program lacks");
    if (spec.passes.empty() || spec.passes.back().name != "image")
        throw std::invalid_argument("ShadertoyHost: the program's last pass must be the image pass");
    Impl& m = *impl_;
    m.spec = spec;
    m.settings = settings;
    context.makeCurrent();
    // The pattern's include and its textures: the channels then take the units after the pattern's 16.
    std::string include;
    if (spec.pattern) {
        GLint units = 0;
        glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
        if (units < kPatternUnits + 4)
            throw InputError(spec.name + ": a program with a pattern needs " + std::to_string(kPatternUnits + 4) +
                             " texture units; this GL has " + std::to_string(units));
        m.channelUnit = kPatternUnits;
        // One program for the view's textures and the include's code.
        const GraphPattern program = GraphPattern::build(*spec.pattern, spec.patternFilter.response);
        m.pattern = std::make_unique<GpuGraph>(program, context, spec.patternFilter);
        include = exportedGraphInclude(program);
    }
    m.vao = gl::newVertexArray();
    m.keyboard = gl::newTexture();
    m.uploadKeyboard();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    // The user's files, read once.
    std::vector<std::pair<std::string, std::string>> userFiles;
    const auto userFile = [](const std::filesystem::path& path, const std::string& embedded) {
        return embedded.empty() ? readShaderFile(path.string())
                                : std::pair{path.string(), shaderText(embedded, path.string())};
    };
    if (!spec.common.empty()) userFiles.push_back(userFile(spec.common, spec.commonSource));
    for (const ShadertoyPass& pass : spec.passes) userFiles.push_back(userFile(pass.code, pass.source));
    std::vector<std::string> texts;
    for (const auto& f : userFiles) texts.push_back(f.second);
    std::vector<std::pair<std::string, std::string>> sources{
        {"shadertoy_prelude", prelude(spec, settings, legacyAliases(texts))},
        {"shadertoy_main", kMain},
        {"shadertoy_cube_main", kCubeMain},
        {"stochtex_pattern", include}};
    if (!spec.common.empty()) sources.push_back(userFiles.front());
    // Which buffers some channel reads with mipmaps.
    std::array<bool, 5> mipmapped{};  // buffers A–D, Cube A
    for (const ShadertoyPass& pass : spec.passes)
        for (const ShadertoyChannel& ch : pass.channels)
            if ((ch.kind == ShadertoyChannel::Kind::Buffer || ch.kind == ShadertoyChannel::Kind::CubePass) &&
                ch.filter == ChannelFilter::Mipmap)
                mipmapped[size_t(ch.buffer)] = true;
    checkChannelBudget(spec);
    for (size_t k = 0; k < spec.passes.size(); ++k) {
        const ShadertoyPass& pass = spec.passes[k];
        Impl::Pass p;
        std::vector<std::pair<std::string, std::string>> overrides = sources;
        overrides.push_back(userFiles[k + (spec.common.empty() ? 0 : 1)]);
        overrides.push_back({"shadertoy_channels", channelDeclarations(pass)});
        std::vector<std::string> files{"shadertoy_prelude", "shadertoy_channels"};
        if (spec.pattern) files.insert(files.end(), {"colour", "stochtex_pattern"});
        if (!spec.common.empty()) files.push_back(spec.common.string());
        files.push_back(pass.code.string());
        if (pass.name == "cube_a")
            files.insert(files.end(), {"cube_map", "shadertoy_cube_main"});
        else
            files.push_back("shadertoy_main");
        try {
            p.program = gl::Program(compileProgram({"fullscreen"}, files, overrides));
        } catch (const ShaderError& e) {
            // A feature the host lacks is named as such; otherwise the compiler's first error.
            const std::string& code = userFiles[k + (spec.common.empty() ? 0 : 1)].second;
            if (pass.name == "cube_a" && !std::regex_search(code, std::regex(R"(\bmainCubemap\s*\()")))
                throw InputError(spec.name + ": pass cube_a: " + pass.code.string() +
                                 ": defines no mainCubemap(out vec4 fragColor, in vec2 fragCoord, in vec3 rayOri, in "
                                 "vec3 rayDir), Cube A's entry point");
            if (const std::string why = pass.name == "cube_a"
                                            ? ""
                                            : unsupportedFeature(pass.code.string(), code,
                                                                 spec.common.empty() ? "" : userFiles.front().second);
                !why.empty())
                throw InputError(spec.name + ": pass " + pass.name + ": " + why);
            throw InputError(spec.name + ": pass " + pass.name +
                             " does not compile: " + firstCompilerError(e.what(), userFiles));
        }
        const int buffer = pass.name == "image" ? -1 : pass.name == "cube_a" ? 4 : pass.name.back() - 'a';
        p.mipmaps = buffer >= 0 && mipmapped[size_t(buffer)];
        p.cube = buffer == 4;
        if (p.cube) {
            for (gl::Texture& t : p.cubeTargets) t = cubeTarget(spec.cubeSize, p.mipmaps);
            p.cubeFramebuffer = gl::newFramebuffer();
        } else {
            for (int t = 0; t < (buffer >= 0 ? 2 : 1); ++t) p.targets.push_back(m.newTarget(p.mipmaps));
        }
        for (size_t i = 0; i < 4; ++i) {
            const ShadertoyChannel& ch = pass.channels[i];
            GLuint id = 0;
            glGenSamplers(1, &id);
            p.samplers[i] = Sampler(id);
            // Mipmaps on a texture without them (keyboard) read level 0 only.
            glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, minFilter(ch.filter));
            glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER,
                                ch.filter == ChannelFilter::Nearest ? GL_NEAREST : GL_LINEAR);
            const GLint wrap = ch.wrap == ChannelWrap::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
            glSamplerParameteri(id, GL_TEXTURE_WRAP_S, wrap);
            glSamplerParameteri(id, GL_TEXTURE_WRAP_T, wrap);
            glSamplerParameteri(id, GL_TEXTURE_WRAP_R, wrap);
            if (ch.kind == ShadertoyChannel::Kind::Image) {
                const Image img = readImage(ch.image.string());
                if (img.channels() < 1 || img.channels() > 4)
                    throw InputError(ch.image.string() + ": a channel image has 1 to 4 channels, got " +
                                     std::to_string(img.channels()));
                p.inputs[i] = imageTexture(asBrowserUploads(img), ch.vflip, ch.filter == ChannelFilter::Mipmap);
                p.inputSize[i] = {img.width(), img.height(), 1};
            } else if (ch.kind == ShadertoyChannel::Kind::Noise) {
                p.inputs[i] = imageTexture(noiseImage(ch.noiseSize, ch.rgbaNoise, ch.noiseSeed), false,
                                           ch.filter == ChannelFilter::Mipmap);
                p.inputSize[i] = {ch.noiseSize, ch.noiseSize, 1};
            } else if (ch.kind == ShadertoyChannel::Kind::Volume) {
                p.inputs[i] = volumeTexture(shadertoyNoiseVolume(ch.noiseSize, ch.rgbaNoise, ch.noiseSeed),
                                            ch.noiseSize, ch.filter == ChannelFilter::Mipmap);
                p.inputSize[i] = {ch.noiseSize, ch.noiseSize, ch.noiseSize};
            } else if (ch.kind == ShadertoyChannel::Kind::Video) {
                p.videos[i] = std::make_unique<VideoReader>(ch.image.string());
                p.inputSize[i] = {p.videos[i]->width(), p.videos[i]->height(), 1};
            } else if (ch.kind == ShadertoyChannel::Kind::Cubemap) {
                const std::array<Image, 6> faces = cubemapFaces(ch);
                p.inputs[i] = cubeTexture(faces, ch.filter == ChannelFilter::Mipmap);
                p.inputSize[i] = {faces[0].width(), faces[0].height(), 1};
            }
        }
        m.passes.push_back(std::move(p));
    }
    if (spec.sound) {
        const auto code = userFile(spec.sound->code, spec.sound->source);
        const bool withIndex = std::regex_search(code.second, std::regex(R"(\bmainSound\s*\(\s*(in\s+)?int\b)"));
        std::vector<std::pair<std::string, std::string>> overrides = sources;
        overrides.push_back(code);
        overrides.push_back({"shadertoy_channels", channelDeclarations(*spec.sound)});
        overrides.push_back({"shadertoy_sound_main", soundMain(withIndex)});
        std::vector<std::string> files{"shadertoy_prelude", "shadertoy_channels"};
        if (spec.pattern) files.insert(files.end(), {"colour", "stochtex_pattern"});
        if (!spec.common.empty()) files.push_back(spec.common.string());
        files.push_back(code.first);
        files.push_back("shadertoy_sound_main");
        try {
            m.sound = gl::Program(compileProgram({"fullscreen"}, files, overrides));
        } catch (const ShaderError& e) {
            throw InputError(spec.name + ": the sound pass does not compile: " + firstCompilerError(e.what(), {code}));
        }
    }
    reset(0);
}

std::vector<float> ShadertoyHost::renderSound(double seconds, const Progress& progress) const {
    const Impl& m = *impl_;
    if (!m.spec.sound) throw InputError::parameter("sound", m.spec.name + " has no sound pass (sound.glsl)");
    if (!(std::isfinite(seconds) && seconds > 0 && seconds <= kMaxSoundSeconds))
        throw InputError::parameter(
            "soundSeconds", "must be in (0, " + formatValue(kMaxSoundSeconds) + "] s, got " + formatValue(seconds));
    const long long samples = std::llround(seconds * m.settings.sampleRate);
    const long long perBlock = kSoundBlock * kSoundBlock;
    std::vector<float> out(size_t(std::max(samples, 1ll)) * 2);
    RenderTarget target(kSoundBlock, kSoundBlock, false);
    const GLuint prog = m.sound.id();
    glUseProgram(prog);
    glUniform1f(glGetUniformLocation(prog, "iSampleRate"), float(m.settings.sampleRate));
    glUniform3f(glGetUniformLocation(prog, "iResolution"), float(kSoundBlock), float(kSoundBlock), 1.0f);
    for (long long start = 0; start < samples; start += perBlock) {
        // A block is one draw and its read-back: the frame's budget applies to it.
        const Watchdog watchdog(m.spec.name + ": pass sound, samples from " + std::to_string(start),
                                budgetedSeconds(kFrameSeconds), budgeted(kMaxShadertoyBytes));
        target.bind();
        glUseProgram(prog);
        glUniform1i(glGetUniformLocation(prog, "stochtexSoundStart"), GLint(start));
        glBindVertexArray(m.vao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        const Image block = target.readRgb(RenderTarget::Rows::AsDrawn);  // row y: samples start + 512 y …
        const long long n = std::min(perBlock, samples - start);
        for (long long k = 0; k < n; ++k)
            for (int c = 0; c < 2; ++c)  // played as a browser plays it: clamped to [−1, 1]
                out[size_t(start + k) * 2 + size_t(c)] =
                    std::clamp(block.data()[size_t(k) * 3 + size_t(c)], -1.0f, 1.0f);
        if (progress) progress(double(start + n) / double(samples), "sound");
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return out;
}

ShadertoyHost::~ShadertoyHost() = default;

const ShadertoySpec& ShadertoyHost::spec() const { return impl_->spec; }
const ShadertoySettings& ShadertoyHost::settings() const { return impl_->settings; }
int ShadertoyHost::frame() const { return impl_->frame; }
int ShadertoyHost::instance() const { return impl_->instance; }

void ShadertoyHost::reset(int instance) {
    Impl& m = *impl_;
    m.frame = 0;
    m.instance = instance;
    m.input.reset(m.settings.keys, m.settings.mouse);  // held from frame 0: down and toggled, pressed on frame 0
    m.nextInput = 0;
    m.uploadKeyboard();
    for (Impl::Pass& p : m.passes) p.latest = 0;
    m.clearTargets();
}

void ShadertoyHost::resize(int width, int height) {
    Impl& m = *impl_;
    if (width == m.settings.width && height == m.settings.height) return;
    ShadertoySettings next = m.settings;
    next.width = width;
    next.height = height;
    validateShadertoySettings(next);
    checkShadertoyMemory(m.spec, next);
    const ShadertoySettings before = m.settings;
    std::vector<std::vector<RenderTarget>> resized;
    m.settings = next;  // newTarget's size
    try {
        for (const Impl::Pass& p : m.passes) {
            resized.emplace_back();
            for (size_t t = 0; t < p.targets.size(); ++t) resized.back().push_back(m.newTarget(p.mipmaps));
        }
    } catch (...) {
        m.settings = before;
        throw;
    }
    for (size_t i = 0; i < m.passes.size(); ++i) {
        Impl::Pass& p = m.passes[i];
        for (size_t t = 0; t < p.targets.size(); ++t) {
            glBindFramebuffer(GL_READ_FRAMEBUFFER, p.targets[t].framebuffer());
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resized[i][t].framebuffer());
            glBlitFramebuffer(0, 0, before.width, before.height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
            if (p.mipmaps) {
                glBindTexture(GL_TEXTURE_2D, resized[i][t].texture());
                glGenerateMipmap(GL_TEXTURE_2D);
            }
        }
        p.targets = std::move(resized[i]);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    m.input.scaleMouse(float(width) / float(before.width),
                       float(height) / float(before.height));  // iMouse in the new pixels
}

void ShadertoyHost::renderFrame() {
    Impl& m = *impl_;
    for (; m.nextInput < m.settings.inputs.size() && m.settings.inputs[m.nextInput].frame <= m.frame; ++m.nextInput)
        m.input.apply(m.settings.inputs[m.nextInput]);
    if (m.input.takeKeyboardChange()) m.uploadKeyboard();
    for (Impl::Pass& p : m.passes) p.renderedThisFrame = false;
    const auto start = std::chrono::steady_clock::now();
    std::vector<GLsync> passDone(m.passes.size());
    for (size_t p = 0; p < m.passes.size(); ++p) {
        {
            // A CPU's GL (llvmpipe) generates a pass's code at its first draw,
            // inside the call: an array of 10⁸ elements took 18 GB there.
            const Watchdog watchdog(m.spec.name + ": pass " + m.spec.passes[p].name + " of frame " +
                                        std::to_string(m.frame) + ", in the GL driver's draw",
                                    budgetedSeconds(kFrameSeconds), budgeted(kMaxShadertoyBytes));
            m.run(p);
        }
        passDone[p] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    m.awaitFrame(passDone, start);
    ++m.frame;
    m.input.endFrame();  // "pressed" and "just clicked" last one frame
}

namespace {

// The RGBA of one pixel of a framebuffer (GL's rows: y up).
std::array<float, 4> readPixelRgba(GLuint framebuffer, int x, int y) {
    std::array<float, 4> rgba{};
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_FLOAT, rgba.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return rgba;
}

}  // namespace

Image ShadertoyHost::image() const {
    const Impl::Pass& p = impl_->passes.back();
    return p.targets[size_t(p.latest)].readRgb(RenderTarget::Rows::TopDown);
}

unsigned ShadertoyHost::frameTexture() const {
    const Impl::Pass& p = impl_->passes.back();
    return p.targets[size_t(p.latest)].texture();
}

std::array<float, 4> ShadertoyHost::pixel(const std::string& pass, int x, int y) const {
    checkPixel(pass, x, y);
    const Impl& m = *impl_;
    const auto it = std::find_if(m.spec.passes.begin(), m.spec.passes.end(),
                                 [&](const ShadertoyPass& p) { return p.name == pass; });
    const Impl::Pass& p = m.passes[size_t(it - m.spec.passes.begin())];
    return readPixelRgba(p.targets[size_t(p.latest)].framebuffer(), x, y);
}

void ShadertoyHost::checkPixel(const std::string& pass, int x, int y) const {
    const Impl& m = *impl_;
    const auto it = std::find_if(m.spec.passes.begin(), m.spec.passes.end(),
                                 [&](const ShadertoyPass& p) { return p.name == pass; });
    if (it == m.spec.passes.end()) {
        std::string names;
        for (const ShadertoyPass& p : m.spec.passes) names += (names.empty() ? "" : ", ") + p.name;
        throw InputError::parameter("pass",
                                    "\"" + pass + "\" names no pass of " + m.spec.name + " (it has " + names + ")");
    }
    if (pass == "cube_a")
        throw InputError::parameter("pass", "\"cube_a\" is a cube map, not a frame: inspect a pass that reads it");
    if (x < 0 || y < 0 || x >= m.settings.width || y >= m.settings.height)
        throw InputError::parameter("pixel", "(" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                                                 std::to_string(m.settings.width) + "x" +
                                                 std::to_string(m.settings.height) + " frame");
}

void ShadertoyHost::setKey(int keyCode, bool down) { impl_->input.setKey(keyCode, down); }
void ShadertoyHost::setMouse(const std::array<float, 4>& mouse) { impl_->input.setMouse(mouse); }
void ShadertoyHost::apply(const ShadertoyInput& input) {
    validateShadertoyInput({0, input.kind, input.key, input.x, input.y});
    impl_->input.apply(input);
}
std::array<float, 4> ShadertoyHost::mouse() const { return impl_->input.mouse(); }

void renderShadertoyFrames(ShadertoyHost& host, int frames, const ShadertoyFrameSink& sink, const Progress& progress,
                           FrameReadBack readBack) {
    if (frames < 1 || frames > 1000000)
        throw InputError::parameter("frames", "must be in [1, 1000000], got " + std::to_string(frames));
    for (int k = 0; k < frames; ++k) {
        const int frame = host.frame();
        host.renderFrame();
        const bool wanted = readBack == FrameReadBack::Every || (readBack == FrameReadBack::Last && k + 1 == frames);
        if (sink && wanted) sink(frame, host.image());
        if (progress) progress(double(k + 1) / frames, "frame " + std::to_string(frame));
    }
}

int ShadertoySource::frameAt(double time) const {
    const ShadertoySettings& s = host_.settings();
    return int(std::lround((time - s.startTime) * s.fps));
}

void ShadertoySource::checkWindow(const SourceRegion& region, double time) const {
    const ShadertoySettings& s = host_.settings();
    // Windows start on whole pixels (an odd centred window's half-pixel start rounds down).
    const double x0 = std::floor(region.x0) + s.width / 2, y0 = std::floor(region.y0) + s.height / 2;
    if (x0 < 0 || y0 < 0 || x0 + region.width > s.width || y0 + region.height > s.height)
        throw InputError::parameter("size", "of the window, " + std::to_string(region.width) + "x" +
                                                std::to_string(region.height) + " at (" + formatValue(region.x0) +
                                                ", " + formatValue(region.y0) + ") from the centre, exceeds the " +
                                                std::to_string(s.width) + "x" + std::to_string(s.height) + " frame");
    if (!(std::isfinite(time) && frameAt(time) >= 0 && frameAt(time) <= 1000000))
        throw InputError::parameter("time", "must be at or after the program's start (" + formatValue(s.startTime) +
                                                " s) and within 10⁶ frames, got " + formatValue(time));
}

void ShadertoySource::checkInstances(int count) const {
    if (count > 1 && host_.spec().instanceUniform.empty())
        throw InputError::parameter("instances", "must be 1: " + host_.spec().name +
                                                     " has no instance uniform (the manifest's \"instance\"), so its "
                                                     "instances would all be one, got " +
                                                     std::to_string(count));
}

Image ShadertoySource::render(const SourceRegion& region, double time, int instance) const {
    checkWindow(region, time);
    checkInstances(instance + 1);
    const int n = frameAt(time);
    if (instance != host_.instance() || n < host_.frame() - 1 || host_.frame() == 0) host_.reset(instance);
    while (host_.frame() <= n) host_.renderFrame();
    const Image frame = host_.image();
    Image out(region.width, region.height, 3, Image::Uninitialized{});
    const int x0 = int(std::floor(region.x0)) + host_.settings().width / 2;
    const int y0 = int(std::floor(region.y0)) + host_.settings().height / 2;
    for (int y = 0; y < region.height; ++y)
        std::copy(frame.row(y0 + y) + size_t(x0) * 3, frame.row(y0 + y) + size_t(x0 + region.width) * 3, out.row(y));
    return out;
}

}  // namespace stochtex
