#pragma once
// GLSL programs assembled from the embedded shader files (gpu/shaders/*.glsl,
// *.vert, *.frag). The same sources compile as GLSL 3.30 core (desktop) and
// GLSL ES 3.00 (WebGL 2): only the header differs.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace stochtex {

enum class GlslTarget { Core330, Es300, Core430 };

// A shader failed to compile or link; what() holds the compiler log with
// every location rewritten as the shader file's stem and line ("pattern:12").
class ShaderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A line number in a driver's log (its digits), or 0 when an int does not
// hold it: after a `#line` near 2³¹ drivers print numbers past it.
int logLineNumber(const std::string& digits);

// The embedded shader file with this stem ("common", "pattern", ...).
const std::string& shaderSource(const std::string& stem);
std::vector<std::string> shaderNames();

// The files with the files they need put before them, once each, in
// dependency order. What a file needs is read from the file itself: its
// `#include "…"` lines (GLSL-only chunks, and generated text passed in
// `overrides`), and for a kernel file (kernel/*.glsl, pattern/ops/*.glsl)
// the includes of its C++ header, which are what the C++ side compiles
// against too. A cycle is std::invalid_argument.
std::vector<std::string> shaderChunks(const std::vector<std::string>& files,
                                      const std::vector<std::pair<std::string, std::string>>& overrides = {});
// A file's text as GLSL: kernel files lose their C++ `inline` marks and
// include lines become comments (their files are assembled before).
std::string shaderText(const std::string& stem);
// The same for text that is not embedded (generated chunks).
std::string generatedShaderText(const std::string& text);

// A user's GLSL file, as (path, text) to pass in `overrides` with its path
// among the stems: its compile errors then read "path:line". InputError if
// it cannot be read or is not text. A UTF-8 byte-order mark is dropped and
// CR LF (or a lone CR) line ends become LF, as GL compilers need.
std::pair<std::string, std::string> readShaderFile(const std::string& path);
// The same for a source already in memory (a pass embedded in a ShaderToy
// export); `name` names it in the error.
std::string shaderText(const std::string& text, const std::string& name);

// The version header, then the files in order (what the driver compiles);
// `overrides` as for compileProgram.
std::string assembleShader(GlslTarget target, const std::vector<std::string>& files,
                           const std::vector<std::pair<std::string, std::string>>& overrides = {});

// Compiles and links a program (needs a current context); returns its id.
// Sources are given by stems; `overrides` maps stems to replacement text
// (tests use it to feed a broken shader) or to the text of a file of the
// caller's that is not embedded (its stem names it in error messages).
unsigned compileProgram(const std::vector<std::string>& vertexFiles, const std::vector<std::string>& fragmentFiles,
                        const std::vector<std::pair<std::string, std::string>>& overrides = {});
// A compute program (GLSL 4.30 core; needs a 4.3 context).
unsigned compileComputeProgram(const std::vector<std::string>& files,
                               const std::vector<std::pair<std::string, std::string>>& overrides = {});

}  // namespace stochtex
