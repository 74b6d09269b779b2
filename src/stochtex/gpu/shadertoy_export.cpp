// ShaderToy's own export format (the JSON its API and "export" tools give:
// {"Shader": {"info": {...}, "renderpass": [...]}}, the inner object alone,
// or an array of one) read into a ShadertoySpec, and a spec written back as
// our manifest and its pass files (`shadertoy --convert`).
#include <algorithm>
#include <map>

#include "stochtex/core/atomic_file.h"
#include "stochtex/core/error.h"
#include "stochtex/gpu/shadertoy_spec.h"
#include "stochtex/pattern/json_reader.h"

namespace stochtex {

namespace fs = std::filesystem;

namespace {

// ShaderToy's built-in noise textures, by the file name (a hash) its media
// paths end with, and what the host generates for each (ShadertoyChannel's
// noise: docs/SHADERTOY.md "ShaderToy's media").
struct BuiltinMedia {
    const char* file;
    const char* name;
    bool rgba;
    int size;
};
constexpr BuiltinMedia kBuiltinMedia[] = {
    {"0a40562379b63dfb89227e6d172f39fdce9022cba76623f1054a2c83d6c0ba5d.png", "Gray Noise Small", false, 64},
    {"0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f5.png", "Gray Noise Medium", false, 256},
    {"3083c722c0c738cad0f468383167a0d246f91af2bfa373e9c5c094fb8c8413e0.png", "RGBA Noise Small", true, 64},
    {"f735bee5b64ef98879dc618b016ecf7939a5756040c2cde21ccb15e69a6e1cfb.png", "RGBA Noise Medium", true, 256},
};

// And its two noise volumes (32³).
constexpr BuiltinMedia kBuiltinVolumes[] = {
    {"27012b4eadd0c3ce12498b867058e4f717ce79e5.bin", "Grey Noise3D", false, 32},
    {"aea6b99da1d53055107966b59ac5444fc8bc7b3ce2d0bbb6a4a3cbae1d97f3aa.bin", "RGBA Noise3D", true, 32},
};

// The ids ShaderToy gives the buffers' outputs (numbers in older exports).
const std::map<std::string, int>& knownBufferIds() {
    static const std::map<std::string, int> ids{{"257", 0},    {"258", 1},    {"259", 2},
                                                {"260", 3},    {"4dXGR8", 0}, {"XsXGR8", 1},
                                                {"4sXGR8", 2}, {"XdfGR8", 3}, {"4dX3Rr", 4}};  // Cube A
    return ids;
}

// A value ShaderToy writes as a string or a number ("channel": "0" or 0).
std::string text(const JsonReader& r) {
    if (r.value().is_string()) return r.value().get<std::string>();
    if (r.value().is_number_integer()) return std::to_string(r.value().get<long long>());
    r.fail("expected a string or an integer");
}

// A boolean ShaderToy writes as "true"/"false" or a JSON boolean.
bool flag(const JsonReader& r) {
    if (r.value().is_boolean()) return r.value().get<bool>();
    const std::string t = text(r);
    if (t != "true" && t != "false") r.fail("expected true or false, got \"" + t + "\"");
    return t == "true";
}

// The buffer (0–3) a "Buffer A" … "Buffer D" pass renders, or −1.
int bufferOfName(const std::string& name) {
    if (name.size() == 8 && name.starts_with("Buffer ") && name[7] >= 'A' && name[7] <= 'D') return name[7] - 'A';
    return -1;
}

// ShaderToy's tab name of pass slot k (0–3 buffers, 4 Cube A, 5 Image).
std::string passTitle(int slot) {
    return slot == 5 ? "Image" : slot == 4 ? "Cube A" : "Buffer " + std::string(1, char('A' + slot));
}

std::string fileName(const std::string& src) {
    const size_t slash = src.find_last_of('/');
    return slash == std::string::npos ? src : src.substr(slash + 1);
}

struct ExportContext {
    fs::path json;                         // the export, for messages and embedded passes' names
    fs::path mediaDir;                     // where media that are not built in are looked for
    std::map<std::string, int> bufferIds;  // output id → buffer, from the export's own buffer passes
};

ShadertoyChannel exportChannel(const JsonReader& in, const ExportContext& x) {
    ShadertoyChannel ch;
    const JsonReader typeReader = in.has("ctype") ? in.at("ctype") : in.at("type");
    const std::string type = typeReader.string();
    const std::string src = in.has("src")        ? in.at("src").string()
                            : in.has("filepath") ? in.at("filepath").string()
                                                 : "";
    if (type == "buffer") {
        ch.kind = ShadertoyChannel::Kind::Buffer;
        int buffer = -1;
        if (in.has("id")) {
            const std::string id = text(in.at("id"));
            if (const auto it = x.bufferIds.find(id); it != x.bufferIds.end())
                buffer = it->second;
            else if (const auto k = knownBufferIds().find(id); k != knownBufferIds().end())
                buffer = k->second;
        }
        const std::string file = fileName(src);  // "/media/previz/buffer00.png" is Buffer A's preview
        if (buffer < 0 && file.size() == 12 && file.starts_with("buffer0") && file[7] >= '0' && file[7] <= '3')
            buffer = file[7] - '0';
        if (buffer < 0 || buffer > 3) in.fail("a buffer input whose id names none of the program's buffers");
        ch.buffer = buffer;
    } else if (type == "keyboard") {
        ch.kind = ShadertoyChannel::Kind::Keyboard;
        ch.filter = ChannelFilter::Nearest;
    } else if (type == "texture") {
        const std::string file = fileName(src);
        const auto builtin = std::find_if(std::begin(kBuiltinMedia), std::end(kBuiltinMedia),
                                          [&](const BuiltinMedia& m) { return file == m.file; });
        ch.filter = ChannelFilter::Mipmap;
        ch.wrap = ChannelWrap::Repeat;
        if (builtin != std::end(kBuiltinMedia)) {
            ch.kind = ShadertoyChannel::Kind::Noise;
            ch.rgbaNoise = builtin->rgba;
            ch.noiseSize = builtin->size;
        } else {
            ch.kind = ShadertoyChannel::Kind::Image;
            std::error_code ec;
            ch.image = x.mediaDir / file;
            if (file.empty() || !fs::is_regular_file(ch.image, ec))
                in.fail("the texture \"" + src +
                        "\" is not one of ShaderToy's noise textures the host generates; "
                        "put its file (" +
                        (file.empty() ? "?" : file) + ") in " + x.mediaDir.string() +
                        " (or give the program another media folder)");
        }
    } else if (type == "video") {
        const std::string file = fileName(src);
        ch.kind = ShadertoyChannel::Kind::Video;
        ch.image = x.mediaDir / file;
        std::error_code ec;
        if (file.empty() || !fs::is_regular_file(ch.image, ec))
            in.fail("the video \"" + src + "\" is read from its file; put " + (file.empty() ? "it" : file) + " in " +
                    x.mediaDir.string() + " (or give the program another media folder)");
    } else if (type == "cubemap" && in.has("id") && x.bufferIds.count(text(in.at("id"))) &&
               x.bufferIds.at(text(in.at("id"))) == 4) {
        ch.kind = ShadertoyChannel::Kind::CubePass;  // the Cube A pass's output
        ch.buffer = 4;
        ch.filter = ChannelFilter::Mipmap;
    } else if (type == "cubemap") {
        // ShaderToy stores a cubemap's faces as FILE.ext, FILE_1.ext … FILE_5.ext (+x, −x, +y, −y, +z, −z).
        const std::string file = fileName(src);
        const size_t dot = file.find_last_of('.');
        if (file.empty() || dot == std::string::npos)
            in.fail("a cubemap input needs its \"src\" (the first face's file)");
        ch.kind = ShadertoyChannel::Kind::Cubemap;
        ch.filter = ChannelFilter::Mipmap;
        std::string missing;
        for (int f = 0; f < 6; ++f) {
            const std::string name = f == 0 ? file : file.substr(0, dot) + "_" + std::to_string(f) + file.substr(dot);
            ch.faces.push_back(x.mediaDir / name);
            std::error_code ec;
            if (!fs::is_regular_file(ch.faces.back(), ec)) missing += (missing.empty() ? "" : ", ") + name;
        }
        if (!missing.empty())
            in.fail("the cubemap \"" + src + "\" is read from its six face files; put " + missing + " in " +
                    x.mediaDir.string() + " (or give the program another media folder)");
    } else if (type == "volume") {
        const std::string file = fileName(src);
        const auto builtin = std::find_if(std::begin(kBuiltinVolumes), std::end(kBuiltinVolumes),
                                          [&](const BuiltinMedia& m) { return file == m.file; });
        if (builtin == std::end(kBuiltinVolumes))
            in.fail("the volume \"" + src +
                    "\" is not one of ShaderToy's two noise volumes (Grey and RGBA Noise3D), "
                    "which the host generates; other volumes are not supported");
        ch.kind = ShadertoyChannel::Kind::Volume;
        ch.rgbaNoise = builtin->rgba;
        ch.noiseSize = builtin->size;
        ch.filter = ChannelFilter::Mipmap;
        ch.wrap = ChannelWrap::Repeat;
    } else {
        typeReader.fail("a " + type +
                        " input is a ShaderToy input this host does not support yet (it reads buffer, "
                        "texture, volume, cubemap, video and keyboard inputs; docs/SHADERTOY.md)");
    }
    if (const auto sampler = in.find("sampler")) {
        if (const auto f = sampler->find("filter")) ch.filter = f->choice(kChannelFilterNames);
        if (const auto w = sampler->find("wrap")) ch.wrap = w->choice(kChannelWrapNames);
        if (const auto v = sampler->find("vflip")) ch.vflip = flag(*v);
        if (const auto s = sampler->find("srgb"); s && flag(*s))
            s->fail("sRGB decoding of a texture is not supported: the host reads a texture's codes as they are");
    }
    return ch;
}

// The renderpass array of any of the export's forms.
JsonReader renderPasses(const JsonReader& r) {
    if (r.value().is_array()) {
        if (r.arraySize() != 1) r.fail("an export of " + std::to_string(r.arraySize()) + " shaders; give one");
        return renderPasses(r.at(size_t(0)));
    }
    if (r.has("Shader")) return renderPasses(r.at("Shader"));
    return r.at("renderpass");
}

std::string exportName(const JsonReader& r) {
    if (r.value().is_array()) return exportName(r.at(size_t(0)));
    if (r.has("Shader")) return exportName(r.at("Shader"));
    if (const auto info = r.find("info"); info && info->value().is_object())
        if (const auto name = info->find("name"); name && name->value().is_string()) return name->string();
    return "";
}

}  // namespace

bool isShadertoyExport(const nlohmann::json& j) {
    if (j.is_array()) return j.size() == 1 && isShadertoyExport(j[0]);
    return j.is_object() && (j.contains("Shader") || j.contains("renderpass"));
}

ShadertoySpec parseShadertoyExport(const JsonReader& r, const fs::path& json, const fs::path& mediaDir) {
    const JsonReader passes = renderPasses(r);
    const size_t n = passes.arraySize();
    ExportContext x{json, mediaDir.empty() ? json.parent_path() : mediaDir, {}};
    if (x.mediaDir.empty()) x.mediaDir = ".";
    ShadertoySpec spec;
    spec.name = exportName(r);
    if (spec.name.empty()) spec.name = json.stem().string();
    // The buffers first: their output ids name them in the inputs.
    std::array<std::optional<size_t>, 6> byOrder;  // buffer_a … buffer_d, cube_a, image: the renderpass index
    for (size_t i = 0; i < n; ++i) {
        const JsonReader p = passes.at(i);
        const std::string type = p.at("type").string();
        const std::string name = p.has("name") ? p.at("name").string() : "";
        if (type == "common") {
            if (!spec.common.empty()) p.fail("a second Common pass");
            spec.common = json.string() + " (Common)";
            spec.commonSource = p.at("code").string();
            continue;
        }
        if (type == "sound") {
            if (spec.sound) p.fail("a second Sound pass");
            if (p.has("inputs") && p.at("inputs").arraySize() > 0)
                p.at("inputs").fail("a sound pass reading channels is not supported");
            spec.sound = ShadertoyPass{"sound", json.string() + " (Sound)", p.at("code").string(), {}};
            continue;
        }
        int slot = -1;
        if (type == "image")
            slot = 5;
        else if (type == "cubemap")
            slot = 4;
        else if (type == "buffer") {
            slot = bufferOfName(name);
            if (slot < 0 && p.has("outputs") && p.at("outputs").arraySize() > 0 &&
                p.at("outputs").at(size_t(0)).has("id")) {
                const auto k = knownBufferIds().find(text(p.at("outputs").at(size_t(0)).at("id")));
                if (k != knownBufferIds().end() && k->second < 4) slot = k->second;
            }
            if (slot < 0) p.at("name").fail("a buffer pass is named Buffer A to Buffer D");
        } else {
            p.at("type").fail("a " + type + " pass (" + name +
                              ") is a ShaderToy pass this host does not run yet (it "
                              "runs Common, Buffer A–D, Cube A, Image and Sound; docs/SHADERTOY.md)");
        }
        if (byOrder[size_t(slot)]) p.fail("a second " + passTitle(slot) + " pass");
        byOrder[size_t(slot)] = i;
        if (slot < 5)
            if (const auto outs = p.find("outputs"))
                for (size_t k = 0; k < outs->arraySize(); ++k)
                    if (outs->at(k).has("id")) x.bufferIds[text(outs->at(k).at("id"))] = slot;
    }
    if (!byOrder[5]) passes.fail("needs an Image pass");
    for (size_t slot = 0; slot < 6; ++slot) {
        if (!byOrder[slot]) continue;
        const JsonReader p = passes.at(*byOrder[slot]);
        ShadertoyPass pass;
        pass.name = shadertoyPassNames()[slot];
        const std::string title = passTitle(int(slot));
        pass.code = json.string() + " (" + title + ")";
        pass.source = p.at("code").string();
        if (const auto inputs = p.find("inputs"))
            for (size_t k = 0; k < inputs->arraySize(); ++k) {
                const JsonReader in = inputs->at(k);
                const int channel = in.has("channel") ? [&] {
                    const std::string c = text(in.at("channel"));
                    if (c.size() != 1 || c[0] < '0' || c[0] > '3') in.at("channel").fail("a channel is 0 to 3");
                    return c[0] - '0';
                }()
                                                      : int(k);
                if (pass.channels[size_t(channel)].kind != ShadertoyChannel::Kind::None)
                    in.at("channel").fail("a second input on channel " + std::to_string(channel));
                pass.channels[size_t(channel)] = exportChannel(in, x);
            }
        spec.passes.push_back(std::move(pass));
    }
    for (const ShadertoyPass& pass : spec.passes)
        for (const ShadertoyChannel& ch : pass.channels)
            if ((ch.kind == ShadertoyChannel::Kind::Buffer || ch.kind == ShadertoyChannel::Kind::CubePass) &&
                spec.bufferPass(ch.buffer) < 0)
                throw InputError(json.string() + ": pass " + pass.name + " reads " +
                                 shadertoyPassNames()[size_t(ch.buffer)] + ", which the export lacks");
    return spec;
}

nlohmann::json shadertoyManifest(const ShadertoySpec& spec, const fs::path& dir,
                                 const std::map<std::string, std::string>& codeFiles) {
    using json = nlohmann::json;
    const auto relative = [&](const fs::path& p) {
        std::error_code ec;
        const fs::path r = fs::relative(fs::absolute(p, ec), fs::absolute(dir, ec), ec);
        return (ec || r.empty() ? fs::absolute(p) : r).generic_string();
    };
    json m{{"name", spec.name}};
    if (!spec.common.empty()) m["common"] = codeFiles.count("common") ? codeFiles.at("common") : relative(spec.common);
    json passes = json::object();
    for (const ShadertoyPass& pass : spec.passes) {
        json channels = json::array();
        for (const ShadertoyChannel& ch : pass.channels) {
            json c;
            switch (ch.kind) {
                case ShadertoyChannel::Kind::None: channels.push_back(nullptr); continue;
                case ShadertoyChannel::Kind::Buffer:
                    c = {{"type", "buffer"}, {"buffer", std::string(1, char('a' + ch.buffer))}};
                    if (ch.frame != ShadertoyChannel::Frame::Latest)
                        c["frame"] = ch.frame == ShadertoyChannel::Frame::Previous ? "previous" : "current";
                    break;
                case ShadertoyChannel::Kind::Image:
                    c = {{"type", "image"}, {"path", relative(ch.image)}, {"vflip", ch.vflip}};
                    break;
                case ShadertoyChannel::Kind::Video:
                    c = {{"type", "video"}, {"path", relative(ch.image)}, {"loop", ch.loop}, {"vflip", ch.vflip}};
                    break;
                case ShadertoyChannel::Kind::Keyboard: c = {{"type", "keyboard"}}; break;
                case ShadertoyChannel::Kind::CubePass:
                    c = {{"type", "cube_a"}};
                    if (ch.frame != ShadertoyChannel::Frame::Latest)
                        c["frame"] = ch.frame == ShadertoyChannel::Frame::Previous ? "previous" : "current";
                    break;
                case ShadertoyChannel::Kind::Cubemap:
                    c = {{"type", "cubemap"}};
                    if (!ch.image.empty()) c["equirect"] = relative(ch.image);
                    for (const auto& face : ch.faces) c["faces"].push_back(relative(face));
                    break;
                case ShadertoyChannel::Kind::Noise:
                case ShadertoyChannel::Kind::Volume:
                    c = {{"type", ch.kind == ShadertoyChannel::Kind::Volume ? "volume" : "noise"},
                         {"kind", ch.rgbaNoise ? "rgba" : "gray"},
                         {"size", ch.noiseSize}};
                    if (ch.noiseSeed != 0) c["seed"] = ch.noiseSeed;
                    break;
            }
            c["filter"] = enumName(kChannelFilterNames, ch.filter);
            c["wrap"] = enumName(kChannelWrapNames, ch.wrap);
            channels.push_back(c);
        }
        while (!channels.empty() && channels.back().is_null()) channels.erase(channels.end() - 1);
        json p{{"code", codeFiles.count(pass.name) ? codeFiles.at(pass.name) : relative(pass.code)}};
        if (!channels.empty()) p["channels"] = channels;
        if (pass.name == "cube_a") p["size"] = spec.cubeSize;
        passes[pass.name] = p;
    }
    if (spec.sound)
        passes["sound"] = {{"code", codeFiles.count("sound") ? codeFiles.at("sound") : relative(spec.sound->code)}};
    m["passes"] = passes;
    return m;
}

std::string convertShadertoy(const ShadertoySpec& spec, const std::string& folder) {
    std::error_code ec;
    if (fs::exists(folder, ec) && !fs::is_directory(folder, ec))
        throw InputError::parameter("output",
                                    "\"" + folder + "\" is a file; a converted program is written as a folder");
    // Every file is named before any is written: a pass's code as <pass>.glsl,
    // Common's as common.glsl, and the manifest; none may be there already.
    std::map<std::string, std::string> codeFiles;
    std::vector<std::pair<fs::path, std::string>> writes;
    const auto add = [&](const std::string& key, const std::string& file, const std::string& source) {
        codeFiles[key] = file;
        writes.emplace_back(fs::path(folder) / file, source);
    };
    if (!spec.common.empty() && !spec.commonSource.empty()) add("common", "common.glsl", spec.commonSource);
    for (const ShadertoyPass& pass : spec.passes)
        if (!pass.source.empty()) add(pass.name, pass.name + ".glsl", pass.source);
    if (spec.sound && !spec.sound->source.empty()) add("sound", "sound.glsl", spec.sound->source);
    const fs::path manifest = fs::path(folder) / "shadertoy.json";
    writes.emplace_back(manifest, shadertoyManifest(spec, folder, codeFiles).dump(2) + "\n");
    for (const auto& [path, text] : writes)
        if (fs::exists(path, ec))
            throw InputError::parameter("output",
                                        path.string() +
                                            " exists; a converted program is written into a new folder or one "
                                            "without its files");
    fs::create_directories(folder, ec);
    if (ec) throw InputError::parameter("output", "cannot create the folder " + folder + " (" + ec.message() + ")");
    for (const auto& [path, text] : writes) writeFileAtomic(path.string(), text);
    return manifest.string();
}

}  // namespace stochtex
