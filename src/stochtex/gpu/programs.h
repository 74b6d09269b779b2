#pragma once
// The shader programs stochtex builds, as one table: a name, its stages and
// the shader files (stems) each stage is assembled from. The kernel files a
// stage needs are added by the assembler (shaderChunks), so a recipe names
// only what it uses directly. GpuGraph (every file's program), the scene,
// the export and the tests (compilation, glslangValidator) all read this
// table.
#include <string>
#include <vector>

#include "stochtex/gpu/gl_objects.h"

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
// point GpuGraph::bind attaches it to.
inline constexpr const char* kPatternBlockName = "PatternParameters";
inline constexpr unsigned kPatternBlockBinding = 0;

// The stem the texture-graph recipes read for the chunk generated per graph
// (gpu/gpu_graph.h, graphProgramSource); its text is passed as an override.
inline const std::string kGraphProgramStem = "graph_program";
// The chunk (stem) of the prefiltered tables' lookup, prefilteredLookup.
inline const std::string kPrefilteredLookupChunk = "prefiltered_lookup";

const std::vector<ProgramRecipe>& programRecipes();
// InputError-free: an unknown name is a programming error (std::invalid_argument).
const ProgramRecipe& programRecipe(const std::string& name);
// Compiles and links a Graphics or Compute recipe (needs a current context;
// ShaderError with file:line locations on failure).
// `generated`: the text of generated chunks by stem (a graph recipe's kGraphProgramStem).
gl::Program buildProgram(const std::string& name, const std::vector<std::pair<std::string, std::string>>& generated = {});

}  // namespace stochtex
