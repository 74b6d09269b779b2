#include "stochtex/gpu/programs.h"

#include <stdexcept>
#include <string>

#include "stochtex/gpu/shader.h"

namespace stochtex {

const std::string& responseChunk(ResponseKind kind) {
    static const std::string prefilteredColormap = "response_prefiltered_colormap", lean = "response_lean";
    switch (kind) {
        case ResponseKind::PrefilteredColormap: return prefilteredColormap;
        case ResponseKind::Lean: return lean;
    }
    throw std::invalid_argument("responseChunk: no shader chunk for response kind " + std::to_string(int(kind)));
}

const std::vector<ProgramRecipe>& programRecipes() {
    using K = ProgramRecipe::Kind;
    const std::string& R = kResponseSlot;
    // A graph's tables are prefiltered colormaps: their lookup is that response's chunk.
    const std::string& G = responseChunk(ResponseKind::PrefilteredColormap);
    static const std::vector<ProgramRecipe> recipes = {
        {"unfiltered", K::Graphics, {"fullscreen"}, {"common", "unfiltered", R, "view", "pattern"}},
        {"filtered", K::Graphics, {"fullscreen"}, {"common", "pattern_filtering", R, "view", "filtered"}},
        {"unfiltered-compute", K::Compute, {}, {"common", "unfiltered", R, "view", "kernel_unfiltered", "view_kernel"}},
        {"filtered-compute", K::Compute, {}, {"common", "pattern_filtering", R, "view", "kernel_filtered", "view_kernel"}},
        {"scene", K::Graphics, {"mesh"}, {"common", "unfiltered", "pattern_filtering", R, "scene"}},
        {"export-include", K::Include, {}, {"common", "pattern_filtering", R}},
        {"display", K::Graphics, {"fullscreen"}, {"display"}},  // a render target in a window, sRGB-encoded
        // A texture graph's programs: the chunk generated per graph (gpu/gpu_graph.h) defines
        // unfilteredColour and filteredColour by wiring the kernel functions; the rest is the pattern's.
        {"graph", K::Graphics, {"fullscreen"}, {"common", "filtering", G, "graph_ops", kGraphProgramStem, "view", "pattern"}},
        {"graph-filtered", K::Graphics, {"fullscreen"},
         {"common", "filtering", G, "graph_ops", kGraphProgramStem, "view", "filtered"}},
        {"graph-compute", K::Compute, {},
         {"common", "filtering", G, "graph_ops", kGraphProgramStem, "view", "kernel_unfiltered", "view_kernel"}},
        {"graph-filtered-compute", K::Compute, {},
         {"common", "filtering", G, "graph_ops", kGraphProgramStem, "view", "kernel_filtered", "view_kernel"}},
        {"graph-scene", K::Graphics, {"mesh"}, {"common", "filtering", G, "graph_ops", kGraphProgramStem, "scene"}},
        {"export-graph-include", K::Include, {}, {"common", "filtering", G, "graph_ops", kGraphProgramStem}},
    };
    return recipes;
}

std::vector<std::string> recipeFiles(const ProgramRecipe& recipe, ResponseKind response) {
    std::vector<std::string> files = recipe.main;
    for (auto& f : files)
        if (f == kResponseSlot) f = responseChunk(response);
    return files;
}

const ProgramRecipe& programRecipe(const std::string& name) {
    for (const auto& r : programRecipes())
        if (r.name == name) return r;
    throw std::invalid_argument("no program recipe \"" + name + "\"");
}

gl::Program buildProgram(const std::string& name, ResponseKind response,
                         const std::vector<std::pair<std::string, std::string>>& generated) {
    const ProgramRecipe& r = programRecipe(name);
    switch (r.kind) {
        case ProgramRecipe::Kind::Graphics:
            return gl::Program(compileProgram(r.vertex, recipeFiles(r, response), generated));
        case ProgramRecipe::Kind::Compute: return gl::Program(compileComputeProgram(recipeFiles(r, response), generated));
        case ProgramRecipe::Kind::Include: break;
    }
    throw std::invalid_argument("program recipe \"" + name + "\" is an include, not a program");
}

}  // namespace stochtex
