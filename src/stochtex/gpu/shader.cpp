#include "stochtex/gpu/shader.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <regex>
#include <string_view>

#include "stochtex/core/budget.h"
#include "stochtex/core/embedded_file.h"
#include "stochtex/core/error.h"
#include "stochtex/core/watchdog.h"

namespace stochtex {

extern const EmbeddedFile kEmbeddedShaders[];
extern const std::size_t kEmbeddedShadersCount;
extern const EmbeddedFile kEmbeddedShaderHeaders[];
extern const std::size_t kEmbeddedShaderHeadersCount;

namespace {

std::map<std::string, std::string> embeddedTexts(const EmbeddedFile* files, std::size_t count) {
    std::map<std::string, std::string> m;
    for (std::size_t i = 0; i < count; ++i) m[files[i].name] = files[i].contents;
    return m;
}

const std::map<std::string, std::string>& embeddedShaders() {
    static const std::map<std::string, std::string> shaders = embeddedTexts(kEmbeddedShaders, kEmbeddedShadersCount);
    return shaders;
}

}  // namespace

int logLineNumber(const std::string& digits) {
    int line = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), line);
    return error == std::errc() && end == digits.data() + digits.size() && line > 0 ? line : 0;
}

const std::string& shaderSource(const std::string& stem) {
    const auto it = embeddedShaders().find(stem);
    if (it == embeddedShaders().end()) throw std::invalid_argument("no embedded shader \"" + stem + "\"");
    return it->second;
}

std::vector<std::string> shaderNames() {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < kEmbeddedShadersCount; ++i) names.emplace_back(kEmbeddedShaders[i].name);
    return names;
}

namespace {

std::string header(GlslTarget target) {
    // A resource's binding (the export's Vulkan layout): OpenGL binds by name.
    const std::string bindings = "#define STOCHTEX_BINDING(n)\n";
    switch (target) {
        case GlslTarget::Core330: return "#version 330 core\n" + bindings;
        case GlslTarget::Core430: return "#version 430 core\n" + bindings;
        case GlslTarget::Es300: break;
    }
    return "#version 300 es\nprecision highp float;\nprecision highp int;\n"
           "precision highp sampler2D;\nprecision highp sampler2DArray;\n" +
           bindings;
}

// A line `#include "path"`: GLSL has no includes, so the line names a file
// this one needs (its stem: "stochtex/kernel/grid.h" and "grid.glsl" both
// name the kernel file grid), and the assembler puts that file first.
std::string includedStem(std::string_view line) {
    constexpr std::string_view kInclude = "#include \"";
    if (!line.starts_with(kInclude)) return {};
    line.remove_prefix(kInclude.size());
    const std::size_t close = line.find('"');
    if (close == std::string_view::npos) return {};
    std::string_view path = line.substr(0, close);
    if (const std::size_t slash = path.rfind('/'); slash != std::string_view::npos) path.remove_prefix(slash + 1);
    return std::string(path.substr(0, path.find('.')));
}

std::vector<std::string> includedStems(const std::string& text) {
    std::vector<std::string> stems;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        if (std::string stem = includedStem(std::string_view(text).substr(pos, end - pos)); !stem.empty())
            stems.push_back(std::move(stem));
        pos = end + 1;
    }
    return stems;
}

// The C++ header of a kernel file (kernel/*.h, pattern/ops/*.h), or null.
const std::string* kernelHeader(const std::string& stem) {
    static const std::map<std::string, std::string> headers =
        embeddedTexts(kEmbeddedShaderHeaders, kEmbeddedShaderHeadersCount);
    const auto it = headers.find(stem);
    return it == headers.end() ? nullptr : &it->second;
}

bool isShader(const std::string& stem) { return embeddedShaders().count(stem) != 0; }

using Overrides = std::vector<std::pair<std::string, std::string>>;

const std::string* overrideText(const std::string& stem, const Overrides& overrides) {
    const auto own = std::find_if(overrides.begin(), overrides.end(), [&](const auto& o) { return o.first == stem; });
    return own != overrides.end() ? &own->second : nullptr;
}

const std::string& chunkText(const std::string& stem, const Overrides& overrides) {
    const std::string* own = overrideText(stem, overrides);
    return own ? *own : shaderSource(stem);
}

// The files `stem` needs, from its own `#include` lines (GLSL-only chunks,
// generated text) and from its C++ header's includes (a kernel file's are
// in its .h, which includes it inside the kernel's namespace): an included
// header that is a kernel file's is that file; one without a kernel file
// (kernel/glsl.h, ops/op_host.h's C++ side) stands for what it includes in
// turn. Includes of anything else (a system header) are not GLSL's concern.
void addNeeds(const std::string& text, const std::string& self, const Overrides& overrides,
              std::vector<std::string>& needs, std::vector<std::string>& seen) {
    for (const std::string& inc : includedStems(text)) {
        if (inc == self || std::find(seen.begin(), seen.end(), inc) != seen.end()) continue;
        seen.push_back(inc);
        if (isShader(inc) || overrideText(inc, overrides))
            needs.push_back(inc);
        else if (const std::string* header = kernelHeader(inc))
            addNeeds(*header, self, overrides, needs, seen);
    }
}

std::vector<std::string> chunkNeeds(const std::string& stem, const Overrides& overrides) {
    std::vector<std::string> needs, seen;
    // A file not given yet (a recipe's generated chunk, listed without its
    // text) needs nothing that can be known; assembling it will ask for it.
    if (isShader(stem) || overrideText(stem, overrides))
        addNeeds(chunkText(stem, overrides), stem, overrides, needs, seen);
    if (const std::string* header = kernelHeader(stem)) addNeeds(*header, stem, overrides, needs, seen);
    return needs;
}

void expandChunk(const std::string& stem, const Overrides& overrides, std::vector<std::string>& out,
                 std::vector<std::string>& open) {
    if (std::find(out.begin(), out.end(), stem) != out.end()) return;
    if (std::find(open.begin(), open.end(), stem) != open.end())
        throw std::invalid_argument("shader files include each other in a cycle through \"" + stem + "\"");
    open.push_back(stem);
    for (const auto& dep : chunkNeeds(stem, overrides)) expandChunk(dep, overrides, out, open);
    open.pop_back();
    out.push_back(stem);
}

// Kernel files mark each function `inline` for C++ (kernel/glsl.h); GLSL
// has no such word, so it is dropped from the start of lines. An include
// line becomes a comment (the file it names is already assembled before).
std::string glslText(const std::string& text, const Overrides& overrides = {}) {
    std::string out;
    out.reserve(text.size());
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        end = end == std::string::npos ? text.size() : end + 1;
        std::string_view line(text.data() + pos, end - pos);
        if (line.starts_with("inline ")) line.remove_prefix(7);
        if (const std::string stem = includedStem(line);
            isShader(stem) || kernelHeader(stem) || overrideText(stem, overrides))
            out += "// ";
        out += line;
        pos = end;
    }
    return out;
}

}  // namespace

std::vector<std::string> shaderChunks(const std::vector<std::string>& files,
                                      const std::vector<std::pair<std::string, std::string>>& overrides) {
    std::vector<std::string> out, open;
    for (const auto& f : files) expandChunk(f, overrides, out, open);
    return out;
}

std::string shaderText(const std::string& stem) { return glslText(shaderSource(stem)); }

std::string generatedShaderText(const std::string& text) { return glslText(text); }

namespace {

// The header, then the files (with the kernel files they need) one after
// the other. `starts[k]` is the line (1-based, in the whole text) where
// file k of `*expanded` begins.
std::string assemble(GlslTarget target, const std::vector<std::string>& requested,
                     const std::vector<std::pair<std::string, std::string>>& overrides,
                     std::vector<int>* starts = nullptr, std::vector<std::string>* expanded = nullptr) {
    const std::vector<std::string> files = shaderChunks(requested, overrides);
    std::string out = header(target);
    for (const auto& f : files) {
        // An override replaces an embedded file or adds one of the caller's.
        const std::string text = glslText(chunkText(f, overrides), overrides);
        if (starts) starts->push_back(int(std::count(out.begin(), out.end(), '\n')) + 1);
        out += text;
        if (out.back() != '\n') out += '\n';
    }
    if (expanded) *expanded = files;
    return out;
}

// Driver logs locate errors as "0:12(3)" (Mesa) or "0(12)" (NVIDIA): the
// line is in the assembled text. Rewrite each as "file:line".
std::string mapLocations(const std::string& log, const std::vector<std::string>& files,
                         const std::vector<int>& starts) {
    std::string out;
    const std::regex loc(R"(\b0[:(](\d+))");
    std::sregex_iterator it(log.begin(), log.end(), loc), end;
    std::size_t last = 0;
    for (; it != end; ++it) {
        const int line = logLineNumber((*it)[1]);
        out += log.substr(last, std::size_t(it->position()) - last);
        if (line == 0) {  // no line of the text: the location as the driver wrote it
            out += it->str();
            last = std::size_t(it->position() + it->length());
            continue;
        }
        std::size_t k = 0;
        while (k + 1 < starts.size() && starts[k + 1] <= line) ++k;
        out += line >= starts.front() ? files[k] + ":" + std::to_string(line - starts[k] + 1)
                                      : "header:" + std::to_string(line);
        last = std::size_t(it->position() + it->length());
    }
    return out + log.substr(last);
}

// The GL driver's compiler runs inside one call that cannot be interrupted:
// a shader whose macros expand exponentially or that declares an array of
// 10⁸ elements takes minutes and gigabytes there (Mesa: 38 s and 7 GB, then
// a crash). Our own shaders compile in well under a second and 100 MB.
constexpr double kCompileSeconds = 60;
constexpr long long kCompileBytes = 2LL << 30;
Watchdog compileWatchdog(const std::string& what) {
    return Watchdog(what, budgetedSeconds(kCompileSeconds), budgeted(kCompileBytes));
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

// "a.glsl + b": a stage's files as messages name them.
std::string fileNames(const std::vector<std::string>& files) {
    std::string names;
    for (const auto& f : files) names += (names.empty() ? "" : " + ") + f;
    return names;
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
    const std::string names = fileNames(files);
    {
        const Watchdog watchdog = compileWatchdog("shader " + names + ": the GL driver's compile");
        glCompileShader(s);
    }
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        const std::string log = infoLog(s, glGetShaderiv, glGetShaderInfoLog);
        glDeleteShader(s);
        throw ShaderError("shader " + names + " does not compile:\n" + mapLocations(log, expanded, starts));
    }
    return s;
}

// Links the stages (deleting them); ShaderError with the log on failure.
// `names`: the program's own files (its fragment or compute stage), as the
// watchdog names them.
unsigned link(const std::string& names, std::initializer_list<unsigned> shaders) {
    const GLuint prog = glCreateProgram();
    for (unsigned s : shaders) glAttachShader(prog, s);
    {
        // Drivers optimise and generate code here (llvmpipe on some CPUs;
        // others at the first draw): most of the work of a large program.
        const Watchdog watchdog = compileWatchdog("shader " + names + ": the GL driver's link");
        glLinkProgram(prog);
    }
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
    return {path, shaderText(text, path)};
}

std::string shaderText(const std::string& text, const std::string& name) {
    if (text.find('\0') != std::string::npos) throw InputError(name + ": not a text file");
    // As editors save them: a UTF-8 byte-order mark (Windows editors, exported
    // shaders) is no GLSL token, and CR line ends would split a line
    // continuation; the text GL compiles has neither.
    const size_t start = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
    std::string lf;
    lf.reserve(text.size());
    for (size_t i = start; i < text.size(); ++i)
        if (text[i] != '\r')
            lf += text[i];
        else if (i + 1 >= text.size() || text[i + 1] != '\n')
            lf += '\n';  // a lone CR (old Mac) ends a line too
    return lf;
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
    return link(fileNames(fragmentFiles), {vs, fs});
}

unsigned compileComputeProgram(const std::vector<std::string>& files,
                               const std::vector<std::pair<std::string, std::string>>& overrides) {
    return link(fileNames(files), {compileStage(GL_COMPUTE_SHADER, files, overrides, GlslTarget::Core430)});
}

}  // namespace stochtex
