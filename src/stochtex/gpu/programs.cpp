#include "stochtex/gpu/programs.h"

#include <stdexcept>
#include <string>

#include "stochtex/gpu/shader.h"

namespace stochtex {

const std::vector<ProgramRecipe>& programRecipes() {
    using K = ProgramRecipe::Kind;
    // A file's program: the chunk generated per program (gpu/gpu_graph.h)
    // defines unfilteredColour and filteredColour by wiring the kernel
    // functions; the main files draw it (a view, a compute kernel, a mesh)
    // or make it an include (the export).
    const std::string& G = kPrefilteredLookupChunk;
    static const std::vector<ProgramRecipe> recipes = {
        {"display", K::Graphics, {"fullscreen"}, {"display"}},  // a render target in a window, sRGB-encoded
        {"graph",
         K::Graphics,
         {"fullscreen"},
         {"common", "filtering", G, "graph_ops", kGraphProgramStem, "view", "pattern"}},
        {"graph-filtered",
         K::Graphics,
         {"fullscreen"},
         {"common", "filtering", G, "graph_ops", kGraphProgramStem, "view", "filtered"}},
        {"graph-compute",
         K::Compute,
         {},
         {"common", "filtering", G, "graph_ops", kGraphProgramStem, "view", "kernel_unfiltered", "view_kernel"}},
        {"graph-filtered-compute",
         K::Compute,
         {},
         {"common", "filtering", G, "graph_ops", kGraphProgramStem, "view", "kernel_filtered", "view_kernel"}},
        {"graph-scene",
         K::Graphics,
         {"mesh"},
         {"common", "filtering", G, "graph_ops", kGraphProgramStem, "triplanar", "scene"}},
        {"graph-web",  // the web page's program (gpu/web_page.h), GLSL ES 3.00: both paths, a uniform picks one
         K::Graphics,
         {"fullscreen"},
         {"common", "filtering", G, "graph_ops", kGraphProgramStem, "view", "web"}},
        {"export-graph-include",
         K::Include,
         {},
         {"common", "filtering", G, "graph_ops", kGraphProgramStem, "triplanar"}},
    };
    return recipes;
}

const ProgramRecipe& programRecipe(const std::string& name) {
    for (const auto& r : programRecipes())
        if (r.name == name) return r;
    throw std::invalid_argument("no program recipe \"" + name + "\"");
}

gl::Program buildProgram(const std::string& name, const std::vector<std::pair<std::string, std::string>>& generated) {
    const ProgramRecipe& r = programRecipe(name);
    switch (r.kind) {
        case ProgramRecipe::Kind::Graphics: return gl::Program(compileProgram(r.vertex, r.main, generated));
        case ProgramRecipe::Kind::Compute: return gl::Program(compileComputeProgram(r.main, generated));
        case ProgramRecipe::Kind::Include: break;
    }
    throw std::invalid_argument("program recipe \"" + name + "\" is an include, not a program");
}

}  // namespace stochtex
