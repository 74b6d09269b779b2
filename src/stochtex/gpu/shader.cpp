#include "stochtex/gpu/shader.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <regex>
#include <string_view>

#include "stochtex/core/embedded_file.h"
#include "stochtex/core/error.h"

namespace stochtex {

extern const EmbeddedFile kEmbeddedShaders[];
extern const std::size_t kEmbeddedShadersCount;

const std::string& shaderSource(const std::string& stem) {
    static const std::map<std::string, std::string> sources = [] {
        std::map<std::string, std::string> m;
        for (std::size_t i = 0; i < kEmbeddedShadersCount; ++i) m[kEmbeddedShaders[i].name] = kEmbeddedShaders[i].contents;
        return m;
    }();
    const auto it = sources.find(stem);
    if (it == sources.end()) throw std::invalid_argument("no embedded shader \"" + stem + "\"");
    return it->second;
}

std::vector<std::string> shaderNames() {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < kEmbeddedShadersCount; ++i) names.emplace_back(kEmbeddedShaders[i].name);
    return names;
}

namespace {

std::string header(GlslTarget target) {
    switch (target) {
        case GlslTarget::Core330: return "#version 330 core\n";
        case GlslTarget::Core430: return "#version 430 core\n";
        case GlslTarget::Es300: break;
    }
    return "#version 300 es\nprecision highp float;\nprecision highp int;\n"
           "precision highp sampler2D;\nprecision highp sampler2DArray;\n";
}

// The kernel files (kernel/*.glsl) each chunk calls, in dependency order:
// they are assembled before it, once each, so a recipe names only what it
// uses directly.
const std::map<std::string, std::vector<std::string>>& chunkNeeds() {
    static const std::map<std::string, std::vector<std::string>> needs = {
        {"grid", {"hash"}},
        {"marble", {"hash"}},
        {"common", {"hash", "grid", "lookup", "pattern_params"}},
        {"filtering", {"footprint", "moments"}},
        {"pattern_filtering", {"filtering"}},
        {"response_prefiltered_colormap", {"sigma_levels"}},
        {"response_lean", {"lean"}},
        {"graph_ops", {"lean"}},
        {"view", {"camera"}},
        {"display", {"colour"}},
    };
    return needs;
}

void expandChunk(const std::string& stem, std::vector<std::string>& out) {
    if (std::find(out.begin(), out.end(), stem) != out.end()) return;
    const auto it = chunkNeeds().find(stem);
    if (it != chunkNeeds().end())
        for (const auto& dep : it->second) expandChunk(dep, out);
    out.push_back(stem);
}

// Kernel files mark each function `inline` for C++ (kernel/glsl.h); GLSL
// has no such word, so it is dropped from the start of lines.
std::string glslText(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        end = end == std::string::npos ? text.size() : end + 1;
        std::string_view line(text.data() + pos, end - pos);
        if (line.starts_with("inline ")) line.remove_prefix(7);
        out += line;
        pos = end;
    }
    return out;
}

}  // namespace

std::vector<std::string> shaderChunks(const std::vector<std::string>& files) {
    std::vector<std::string> out;
    for (const auto& f : files) expandChunk(f, out);
    return out;
}

std::string shaderText(const std::string& stem) { return glslText(shaderSource(stem)); }

namespace {

// The header, then the files (with the kernel files they need) one after
// the other. `starts[k]` is the line (1-based, in the whole text) where
// file k of `*expanded` begins.
std::string assemble(GlslTarget target, const std::vector<std::string>& requested,
                     const std::vector<std::pair<std::string, std::string>>& overrides,
                     std::vector<int>* starts = nullptr, std::vector<std::string>* expanded = nullptr) {
    const std::vector<std::string> files = shaderChunks(requested);
    std::string out = header(target);
    for (const auto& f : files) {
        // An override replaces an embedded file or adds one of the caller's.
        const auto own = std::find_if(overrides.begin(), overrides.end(), [&](const auto& o) { return o.first == f; });
        const std::string text = own != overrides.end() ? own->second : shaderText(f);
        if (starts) starts->push_back(int(std::count(out.begin(), out.end(), '\n')) + 1);
        out += text;
        if (out.back() != '\n') out += '\n';
    }
    if (expanded) *expanded = files;
    return out;
}

// Driver logs locate errors as "0:12(3)" (Mesa) or "0(12)" (NVIDIA): the
// line is in the assembled text. Rewrite each as "file:line".
std::string mapLocations(const std::string& log, const std::vector<std::string>& files, const std::vector<int>& starts) {
    std::string out;
    const std::regex loc(R"(\b0[:(](\d+))");
    std::sregex_iterator it(log.begin(), log.end(), loc), end;
    std::size_t last = 0;
    for (; it != end; ++it) {
        const int line = std::stoi((*it)[1]);
        out += log.substr(last, std::size_t(it->position()) - last);
        std::size_t k = 0;
        while (k + 1 < starts.size() && starts[k + 1] <= line) ++k;
        out += line >= starts.front() ? files[k] + ":" + std::to_string(line - starts[k] + 1) : "header:" + std::to_string(line);
        last = std::size_t(it->position() + it->length());
    }
    return out + log.substr(last);
}

// A shader's or program's info log: `query` is glGetShaderiv/glGetProgramiv,
// `read` glGetShaderInfoLog/glGetProgramInfoLog.
template <class Query, class Read>
std::string infoLog(GLuint object, Query query, Read read) {
    GLint n = 0;
    query(object, GL_INFO_LOG_LENGTH, &n);
    std::string log(std::size_t(std::max(n, 1)), '\0');
    read(object, n, nullptr, log.data());
    return log.c_str();
}

unsigned compileStage(GLenum stage, const std::vector<std::string>& files,
                      const std::vector<std::pair<std::string, std::string>>& overrides,
                      GlslTarget target = GlslTarget::Core330) {
    std::vector<int> starts;
    std::vector<std::string> expanded;
    const std::string src = assemble(target, files, overrides, &starts, &expanded);
    const GLuint s = glCreateShader(stage);
    const char* p = src.c_str();
    glShaderSource(s, 1, &p, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        const std::string log = infoLog(s, glGetShaderiv, glGetShaderInfoLog);
        glDeleteShader(s);
        std::string names;
        for (const auto& f : files) names += (names.empty() ? "" : " + ") + f;
        throw ShaderError("shader " + names + " does not compile:\n" + mapLocations(log, expanded, starts));
    }
    return s;
}

// Links the stages (deleting them); ShaderError with the log on failure.
unsigned link(std::initializer_list<unsigned> shaders) {
    const GLuint prog = glCreateProgram();
    for (unsigned s : shaders) glAttachShader(prog, s);
    glLinkProgram(prog);
    for (unsigned s : shaders) glDeleteShader(s);
    GLint ok = 0;
    glGetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        const std::string log = infoLog(prog, glGetProgramiv, glGetProgramInfoLog);
        glDeleteProgram(prog);
        throw ShaderError("shader program does not link:\n" + log);
    }
    return prog;
}

}  // namespace

std::pair<std::string, std::string> readShaderFile(const std::string& path) {
    constexpr std::uintmax_t kMaxBytes = 1 << 20;  // GLSL sources are kilobytes; refuse to slurp anything huge
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw InputError(path + ": cannot read shader file (" + ec.message() + ")");
    if (size > kMaxBytes) throw InputError(path + ": shader file larger than 1 MiB");
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) throw InputError(path + ": cannot read shader file");
    if (text.find('\0') != std::string::npos) throw InputError(path + ": not a text file");
    return {path, text};
}

std::string assembleShader(GlslTarget target, const std::vector<std::string>& files,
                           const std::vector<std::pair<std::string, std::string>>& overrides) {
    return assemble(target, files, overrides);
}

unsigned compileProgram(const std::vector<std::string>& vertexFiles, const std::vector<std::string>& fragmentFiles,
                        const std::vector<std::pair<std::string, std::string>>& overrides) {
    const GLuint vs = compileStage(GL_VERTEX_SHADER, vertexFiles, overrides);
    GLuint fs = 0;
    try {
        fs = compileStage(GL_FRAGMENT_SHADER, fragmentFiles, overrides);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    return link({vs, fs});
}

unsigned compileComputeProgram(const std::vector<std::string>& files,
                               const std::vector<std::pair<std::string, std::string>>& overrides) {
    return link({compileStage(GL_COMPUTE_SHADER, files, overrides, GlslTarget::Core430)});
}

}  // namespace stochtex
