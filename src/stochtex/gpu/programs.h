#pragma once
// The shader programs stochtex builds, as one table: a name, its stages and
// the shader files (stems) each stage is assembled from. The kernel files a
// stage needs are added by the assembler (shaderChunks), so a recipe names
// only what it uses directly. GpuPattern, the scene, the export and the
// tests (compilation, glslangValidator) all read this table.
//
// A filtering recipe lists kResponseSlot where the response's chunk goes:
// filtering.glsl declares `vec3 footprintResponse(vec2 mean, vec2 var,
// float cov)` and the chunk of the pattern's response kind (responseChunk)
// defines it. A new response is a new chunk and its line in responseChunk.
#include <string>
#include <vector>

#include "stochtex/gpu/gl_objects.h"
#include "stochtex/pattern/response.h"

namespace stochtex {

struct ProgramRecipe {
    enum class Kind {
        Graphics,  // vertex + fragment, GLSL 3.30 core / ES 3.00
        Compute,   // compute, GLSL 4.30 core
        Include,   // a GLSL library for other programs (the engine export's stochtex.glsl)
    };
    std::string name;
    Kind kind;
    std::vector<std::string> vertex;  // Graphics only
    std::vector<std::string> main;    // fragment, compute or include files
};

// The uniform block of the pattern's parameters (kernel::PatternParams) that
// every recipe's programs declare (gpu/shaders/common.glsl), and the binding
// point GpuPattern::bind attaches it to.
inline constexpr const char* kPatternBlockName = "PatternParameters";
inline constexpr unsigned kPatternBlockBinding = 0;

inline const std::string kResponseSlot = "response";
// The stem the texture-graph recipes read for the chunk generated per graph
// (gpu/gpu_graph.h, graphProgramSource); its text is passed as an override.
inline const std::string kGraphProgramStem = "graph_program";
// The shader chunk (stem) of a response kind.
const std::string& responseChunk(ResponseKind kind);

const std::vector<ProgramRecipe>& programRecipes();
// InputError-free: an unknown name is a programming error (std::invalid_argument).
const ProgramRecipe& programRecipe(const std::string& name);
// A recipe's main files with kResponseSlot replaced by the response's chunk.
std::vector<std::string> recipeFiles(const ProgramRecipe& recipe, ResponseKind response);
// Compiles and links a Graphics or Compute recipe with the response's chunk
// (ignored by recipes without the slot; needs a current context;
// ShaderError with file:line locations on failure).
// `generated`: the text of generated chunks by stem (a graph recipe's kGraphProgramStem).
gl::Program buildProgram(const std::string& name, ResponseKind response = ResponseKind::PrefilteredColormap,
                         const std::vector<std::pair<std::string, std::string>>& generated = {});

}  // namespace stochtex
