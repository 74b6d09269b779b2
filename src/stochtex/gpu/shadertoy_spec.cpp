#include "stochtex/gpu/shadertoy_spec.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "stochtex/core/error.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/pattern/presets.h"

namespace stochtex {

namespace fs = std::filesystem;

const std::array<const char*, 6>& shadertoyPassNames() {
    static const std::array<const char*, 6> names{"buffer_a", "buffer_b", "buffer_c", "buffer_d", "cube_a", "image"};
    return names;
}

int ShadertoySpec::bufferPass(int buffer) const {
    for (size_t k = 0; k < passes.size(); ++k)
        if (passes[k].name == shadertoyPassNames()[size_t(buffer)]) return int(k);
    return -1;
}

namespace {

// The order of a pass in a frame (0–3 buffers, 4 Cube A, 5 the image).
int passOrder(const std::string& name) {
    const auto& names = shadertoyPassNames();
    return int(std::find(names.begin(), names.end(), name) - names.begin());
}

// The names the host declares itself (the ShaderToy uniforms) and GLSL's own.
bool reservedName(const std::string& name) {
    static const std::set<std::string> reserved{
        "iResolution", "iTime",    "iTimeDelta", "iFrame",    "iFrameRate", "iMouse",    "iDate",
        "iSampleRate", "iChannel0", "iChannel1", "iChannel2", "iChannel3", "iChannelResolution", "iChannelTime",
        "mainImage",   "main"};
    return reserved.count(name) > 0 || name.starts_with("gl_") || name.starts_with("stochtex");
}

bool validIdentifier(const std::string& name) {
    if (name.empty() || name.size() > 64 || std::isdigit((unsigned char)name[0])) return false;
    return std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum((unsigned char)c) || c == '_'; });
}

void requireFile(const fs::path& path, const std::string& what) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw InputError(path.string() + ": " + what + " not found");
}

ShadertoyChannel parseChannel(const JsonReader& c, const fs::path& baseDir) {
    ShadertoyChannel ch;
    if (!c.value().is_object()) c.fail("expected a channel object with a \"type\", or null");
    // ShaderToy's other inputs, named as such rather than as an unknown value.
    static const std::set<std::string> unsupported{"webcam", "music", "musicstream", "mic", "sound"};
    if (c.has("type") && c.at("type").value().is_string() && unsupported.count(c.at("type").value().get<std::string>()))
        c.at("type").fail("a " + c.at("type").value().get<std::string>() +
                          " channel is a ShaderToy input this host does not support yet (it reads buffer, image, "
                          "keyboard, noise, volume, cubemap and video channels; docs/SHADERTOY.md)");
    const std::string type =
        c.at("type").choice({"buffer", "cube_a", "image", "keyboard", "noise", "volume", "cubemap", "video"});
    if (type == "buffer" || type == "cube_a") {
        c.expectObject({"type", "buffer", "frame", "filter", "wrap"});
        ch.kind = type == "buffer" ? ShadertoyChannel::Kind::Buffer : ShadertoyChannel::Kind::CubePass;
        if (type == "buffer") ch.buffer = c.at("buffer").choice({"a", "b", "c", "d"})[0] - 'a';
        else if (c.has("buffer")) c.at("buffer").fail("a cube_a channel reads Cube A; it names no buffer");
        else ch.buffer = 4;
        const std::string frame = c.choice("frame", std::string("latest"), {"latest", "previous", "current"});
        ch.frame = frame == "latest" ? ShadertoyChannel::Frame::Latest
                   : frame == "previous" ? ShadertoyChannel::Frame::Previous : ShadertoyChannel::Frame::Current;
    } else if (type == "image") {
        c.expectObject({"type", "path", "vflip", "filter", "wrap"});
        ch.kind = ShadertoyChannel::Kind::Image;
        ch.image = resolveInputPath(c.at("path"), baseDir);
        ch.vflip = c.boolean("vflip", true);
        ch.filter = ChannelFilter::Mipmap;
        ch.wrap = ChannelWrap::Repeat;
    } else if (type == "video") {
        c.expectObject({"type", "path", "loop", "vflip", "filter", "wrap"});
        ch.kind = ShadertoyChannel::Kind::Video;
        ch.image = resolveInputPath(c.at("path"), baseDir);
        ch.loop = c.boolean("loop", true);
        ch.vflip = c.boolean("vflip", true);
    } else if (type == "cubemap") {
        c.expectObject({"type", "faces", "equirect", "filter", "wrap"});
        ch.kind = ShadertoyChannel::Kind::Cubemap;
        if (c.has("faces") == c.has("equirect")) c.fail("a cubemap needs \"faces\" (six images) or \"equirect\" (one)");
        if (c.has("equirect")) {
            ch.image = resolveInputPath(c.at("equirect"), baseDir);
        } else {
            const JsonReader faces = c.at("faces");
            if (faces.arraySize() != 6) faces.fail("needs six images: +x, -x, +y, -y, +z, -z");
            for (size_t k = 0; k < 6; ++k) ch.faces.push_back(resolveInputPath(faces.at(k), baseDir));
        }
        ch.filter = ChannelFilter::Mipmap;
    } else if (type == "keyboard") {
        c.expectObject({"type", "filter", "wrap"});
        ch.kind = ShadertoyChannel::Kind::Keyboard;
        ch.filter = ChannelFilter::Nearest;
    } else {
        c.expectObject({"type", "kind", "size", "seed", "filter", "wrap"});
        const bool volume = type == "volume";
        ch.kind = volume ? ShadertoyChannel::Kind::Volume : ShadertoyChannel::Kind::Noise;
        ch.rgbaNoise = c.choice("kind", std::string("rgba"), {"gray", "rgba"}) == "rgba";
        // ShaderToy's volumes are 32³; its noise images 64² (small) and 256² (medium).
        ch.noiseSize = volume ? c.integer("size", 32, 4, 128) : c.integer("size", 64, 8, 1024);
        if ((ch.noiseSize & (ch.noiseSize - 1)) != 0) c.at("size").fail("must be a power of two");
        ch.noiseSeed = c.uint32("seed", 0);
        ch.filter = ChannelFilter::Mipmap;
        ch.wrap = ChannelWrap::Repeat;
    }
    ch.filter = c.choice("filter", ch.filter, kChannelFilterNames);
    ch.wrap = c.choice("wrap", ch.wrap, kChannelWrapNames);
    return ch;
}

ShadertoySpec parseManifest(const JsonReader& r, const fs::path& baseDir) {
    r.expectObject({"name", "description", "common", "passes", "uniforms", "instance", "pattern"});
    ShadertoySpec spec;
    spec.name = r.string("name", "shadertoy");
    if (r.has("common")) {
        spec.common = resolveInputPath(r.at("common"), baseDir);
        requireFile(spec.common, "common file");
    }
    const JsonReader passes = r.at("passes");
    passes.expectObject({"buffer_a", "buffer_b", "buffer_c", "buffer_d", "cube_a", "image", "sound"});
    if (!passes.has("image")) passes.fail("needs an \"image\" pass");
    for (const char* name : shadertoyPassNames()) {
        const auto p = passes.find(name);
        if (!p) continue;
        p->expectObject({"code", "channels", "size"});
        if (p->has("size") && std::string(name) != "cube_a") p->at("size").fail("only Cube A has a size (its faces')");
        if (p->has("size")) {
            spec.cubeSize = p->integer("size", 1024, 8, 2048);
            if ((spec.cubeSize & (spec.cubeSize - 1)) != 0) p->at("size").fail("must be a power of two");
        }
        ShadertoyPass pass;
        pass.name = name;
        pass.code = resolveInputPath(p->at("code"), baseDir);
        requireFile(pass.code, "pass file");
        if (const auto channels = p->find("channels")) {
            const size_t n = channels->arraySize();
            if (n > 4) channels->fail("a pass has at most 4 channels (iChannel0–3), got " + std::to_string(n));
            for (size_t i = 0; i < n; ++i)
                if (!channels->at(i).value().is_null()) pass.channels[i] = parseChannel(channels->at(i), baseDir);
        }
        spec.passes.push_back(std::move(pass));
    }
    if (const auto p = passes.find("sound")) {
        p->expectObject({"code", "channels"});
        if (p->has("channels")) p->at("channels").fail("a sound pass reads no channels here (ShaderToy's may)");
        ShadertoyPass pass;
        pass.name = "sound";
        pass.code = resolveInputPath(p->at("code"), baseDir);
        requireFile(pass.code, "pass file");
        spec.sound = std::move(pass);
    }
    // Buffers read must exist; a "current" read must run before its reader.
    for (const ShadertoyPass& pass : spec.passes)
        for (size_t i = 0; i < 4; ++i) {
            const ShadertoyChannel& ch = pass.channels[i];
            if (ch.kind != ShadertoyChannel::Kind::Buffer && ch.kind != ShadertoyChannel::Kind::CubePass) continue;
            const JsonReader at = passes.at(pass.name).at("channels").at(i);
            const std::string buffer = shadertoyPassNames()[size_t(ch.buffer)];
            if (spec.bufferPass(ch.buffer) < 0)
                (at.has("buffer") ? at.at("buffer") : at.at("type")).fail("the program has no pass \"" + buffer + "\"");
            if (ch.frame == ShadertoyChannel::Frame::Current && passOrder(buffer) >= passOrder(pass.name))
                at.at("frame").fail("a pass cycle: \"" + pass.name + "\" reads the current frame of \"" + buffer +
                                    "\", which runs " + (buffer == pass.name ? "as this pass" : "after it") +
                                    " (passes run buffer_a to buffer_d, then image); read its \"previous\" frame");
        }
    if (const auto uniforms = r.find("uniforms")) {
        if (!uniforms->value().is_object()) uniforms->fail("expected an object of uniforms by name");
        for (const auto& item : uniforms->value().items()) {
            const std::string name = item.key();
            const JsonReader u = uniforms->at(name);
            if (!validIdentifier(name) || reservedName(name))
                u.fail("not a usable uniform name (a GLSL identifier other than the iXxx uniforms, main, mainImage, "
                       "gl_* and stochtex*)");
            u.expectObject({"type", "value"});
            ShadertoyUniform su;
            su.name = name;
            su.type = u.at("type").choice(kShadertoyUniformTypeNames);
            const int count = su.type == ShadertoyUniform::Type::Vec2   ? 2
                              : su.type == ShadertoyUniform::Type::Vec3 ? 3
                              : su.type == ShadertoyUniform::Type::Vec4 ? 4 : 1;
            if (u.has("value")) {
                const JsonReader v = u.at("value");
                if (count == 1) {
                    su.value[0] = su.type == ShadertoyUniform::Type::Int ? double(v.integer(-(1 << 30), 1 << 30))
                                                                         : v.number(-1e30, 1e30);
                } else {
                    if (v.arraySize() != size_t(count)) v.fail("a " + std::to_string(count) + "-vector needs " +
                                                               std::to_string(count) + " numbers");
                    for (int k = 0; k < count; ++k) su.value[size_t(k)] = v.at(size_t(k)).number(-1e30, 1e30);
                }
            }
            spec.uniforms.push_back(su);
        }
    }
    if (r.has("instance")) {
        spec.instanceUniform = r.at("instance").string();
        const auto it = std::find_if(spec.uniforms.begin(), spec.uniforms.end(),
                                     [&](const ShadertoyUniform& u) { return u.name == spec.instanceUniform; });
        if (it == spec.uniforms.end() || it->type != ShadertoyUniform::Type::Int)
            r.at("instance").fail("must name an int uniform of \"uniforms\"");
    }
    if (const auto pattern = r.find("pattern")) {
        pattern->expectObject({"preset", "file", "filter"});
        if (pattern->has("preset") == pattern->has("file")) pattern->fail("needs one of \"preset\" or \"file\"");
        if (pattern->has("preset")) {
            const JsonReader preset = pattern->at("preset");
            try {
                spec.pattern = loadPreset(preset.string());
            } catch (const InputError& e) {
                preset.fail(e.what());
            }
        } else {
            spec.pattern = loadPatternFile(resolveInputPath(pattern->at("file"), baseDir).string());
        }
        const std::string filter = pattern->choice("filter", std::string("smooth"), {"paper", "smooth"});
        spec.patternFilter.use(parseFilter(filter));
    }
    return spec;
}

}  // namespace

ShadertoySpec loadShadertoy(const std::string& path, const std::string& mediaDir) {
    std::error_code ec;
    const fs::path p(path);
    if (fs::is_directory(p, ec)) {
        if (fs::is_regular_file(p / "shadertoy.json", ec)) return loadShadertoy((p / "shadertoy.json").string(), mediaDir);
        ShadertoySpec spec;
        spec.name = p.filename().empty() ? p.parent_path().filename().string() : p.filename().string();
        // Our names, or ShaderToy's tab names (as a program copied tab by tab is saved).
        const auto file = [&](const std::string& ours, const std::string& tab) {
            for (const std::string& name : {ours, tab})
                if (fs::is_regular_file(p / (name + ".glsl"), ec)) return p / (name + ".glsl");
            return fs::path();
        };
        spec.common = file("common", "Common");
        static const char* kTabs[] = {"Buffer A", "Buffer B", "Buffer C", "Buffer D", "Cube A", "Image"};
        for (size_t k = 0; k < 6; ++k) {
            const fs::path code = file(shadertoyPassNames()[k], kTabs[k]);
            if (code.empty()) continue;
            spec.passes.push_back({shadertoyPassNames()[k], code, "", {}});
        }
        if (const fs::path sound = file("sound", "Sound"); !sound.empty()) spec.sound = ShadertoyPass{"sound", sound, "", {}};
        if (spec.passes.empty() || spec.passes.back().name != "image")
            throw InputError(path + ": a ShaderToy folder needs image.glsl (and optionally common.glsl, "
                                    "buffer_a.glsl … buffer_d.glsl, shadertoy.json; or ShaderToy's tab names, "
                                    "Image.glsl, Common.glsl, \"Buffer A.glsl\" …)");
        return spec;
    }
    if (!fs::is_regular_file(p, ec)) throw InputError(path + ": no such ShaderToy folder or manifest");
    const nlohmann::json j = readJsonFile(path);
    if (isShadertoyExport(j)) return parseShadertoyExport(JsonReader(j, path), p, mediaDir);
    return parseManifest(JsonReader(j, path), p.parent_path());
}

ShadertoySpec parseShadertoyManifest(const JsonReader& r, const fs::path& baseDir) { return parseManifest(r, baseDir); }

}  // namespace stochtex
