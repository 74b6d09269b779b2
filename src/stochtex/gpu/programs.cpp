#include "stochtex/gpu/programs.h"

#include <stdexcept>

#include "stochtex/gpu/shader.h"

namespace stochtex {

const std::vector<ProgramRecipe>& programRecipes() {
    using K = ProgramRecipe::Kind;
    static const std::vector<ProgramRecipe> recipes = {
        {"unfiltered", K::Graphics, {"fullscreen"}, {"common", "unfiltered", "view", "pattern"}},
        {"filtered", K::Graphics, {"fullscreen"}, {"common", "filtering", "view", "filtered"}},
        {"unfiltered-compute", K::Compute, {}, {"common", "unfiltered", "view", "kernel_unfiltered", "view_kernel"}},
        {"filtered-compute", K::Compute, {}, {"common", "filtering", "view", "kernel_filtered", "view_kernel"}},
        {"scene", K::Graphics, {"mesh"}, {"common", "unfiltered", "filtering", "scene"}},
        {"export-include", K::Include, {}, {"common", "filtering"}},
    };
    return recipes;
}

const ProgramRecipe& programRecipe(const std::string& name) {
    for (const auto& r : programRecipes())
        if (r.name == name) return r;
    throw std::invalid_argument("no program recipe \"" + name + "\"");
}

gl::Program buildProgram(const std::string& name) {
    const ProgramRecipe& r = programRecipe(name);
    switch (r.kind) {
        case ProgramRecipe::Kind::Graphics: return gl::Program(compileProgram(r.vertex, r.main));
        case ProgramRecipe::Kind::Compute: return gl::Program(compileComputeProgram(r.main));
        case ProgramRecipe::Kind::Include: break;
    }
    throw std::invalid_argument("program recipe \"" + name + "\" is an include, not a program");
}

}  // namespace stochtex
