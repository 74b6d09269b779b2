// The pattern's parameter block (kernel/pattern_params.glsl) is filled in C++
// and read by GLSL under std140: both must put every member at the same
// offset. GL's own introspection of each linked program (whatever OpenGL the
// machine has; Mesa llvmpipe in CI) is compared with offsetof and the table
// kPatternParamFields that writes the exported README.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "gl_test_context.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/gpu/programs.h"
#include "stochtex/gpu/shader.h"
#include "stochtex/kernel/pattern_params.h"
#include "stochtex/pattern/presets.h"

namespace stochtex {
namespace {

// A member of the block as GL lays it out.
struct GlMember {
    GLint offset = -1, type = 0, size = 0, arrayStride = 0;
};

GLenum glType(const std::string& glsl) {
    const std::map<std::string, GLenum> types = {
        {"float", GL_FLOAT}, {"int", GL_INT}, {"uint", GL_UNSIGNED_INT}, {"vec4", GL_FLOAT_VEC4}};
    return types.at(glsl);
}

// The block's members by GL name ("uPattern.aniso")
// and its data size, in a linked program.
std::map<std::string, GlMember> blockMembers(GLuint program, GLint& dataSize) {
    const GLuint block = glGetUniformBlockIndex(program, kPatternBlockName);
    EXPECT_NE(block, GL_INVALID_INDEX) << "no " << kPatternBlockName << " block";
    if (block == GL_INVALID_INDEX) return {};
    glGetActiveUniformBlockiv(program, block, GL_UNIFORM_BLOCK_DATA_SIZE, &dataSize);
    GLint count = 0;
    glGetActiveUniformBlockiv(program, block, GL_UNIFORM_BLOCK_ACTIVE_UNIFORMS, &count);
    std::vector<GLint> indices(static_cast<size_t>(count));
    glGetActiveUniformBlockiv(program, block, GL_UNIFORM_BLOCK_ACTIVE_UNIFORM_INDICES, indices.data());
    const std::vector<GLuint> ids(indices.begin(), indices.end());
    const auto query = [&](GLenum what) {
        std::vector<GLint> v(static_cast<size_t>(count));
        glGetActiveUniformsiv(program, count, ids.data(), what, v.data());
        return v;
    };
    const std::vector<GLint> offsets = query(GL_UNIFORM_OFFSET), types = query(GL_UNIFORM_TYPE),
                             sizes = query(GL_UNIFORM_SIZE), strides = query(GL_UNIFORM_ARRAY_STRIDE);
    std::map<std::string, GlMember> members;
    for (size_t k = 0; k < ids.size(); ++k) {
        char name[256];
        glGetActiveUniformName(program, ids[k], sizeof name, nullptr, name);
        members[name] = {offsets[k], types[k], sizes[k], strides[k]};
    }
    return members;
}

TEST(KernelPatternParams, CppOffsetsMatchTheStd140LayoutOfEveryProgram) {
    test::glContext().makeCurrent();
    int programs = 0;
    for (const ProgramRecipe& r : programRecipes()) {
        if (r.kind == ProgramRecipe::Kind::Include) continue;
        if (r.kind == ProgramRecipe::Kind::Compute && !test::glContext().hasCompute()) continue;
        // Programs without the pattern (the window's "display") declare no block.
        const std::vector<std::string> chunks = shaderChunks(r.main);
        if (std::find(chunks.begin(), chunks.end(), "pattern_params") == chunks.end()) continue;
        // A texture graph's recipe reads a generated chunk: Figure 14's.
        std::vector<std::pair<std::string, std::string>> generated;
        if (r.name.starts_with("graph"))
            generated = {{kGraphProgramStem, graphProgramSource(GraphPattern::build(loadPreset("figure14")))}};
        const gl::Program program = buildProgram(r.name, generated);
        GLint dataSize = 0;
        const std::map<std::string, GlMember> members = blockMembers(program.id(), dataSize);
        EXPECT_EQ(size_t(dataSize), sizeof(kernel::PatternParams)) << r.name;
        // std140 keeps every member of the block, used or not, so GL lists
        // exactly the table's members.
        EXPECT_EQ(members.size(), std::size(kernel::kPatternParamFields)) << r.name;
        for (const kernel::PatternParamField& f : kernel::kPatternParamFields) {
            const std::string name = std::string("uPattern.") + f.name + (f.count > 1 ? "[0]" : "");
            const auto it = members.find(name);
            if (it == members.end()) {
                ADD_FAILURE() << r.name << ": GL has no member " << name;
                continue;
            }
            const GlMember& m = it->second;
            EXPECT_EQ(size_t(m.offset), f.offset) << r.name << ": " << name;
            EXPECT_EQ(GLenum(m.type), glType(f.type)) << r.name << ": " << name;
            EXPECT_EQ(m.size, f.count) << r.name << ": " << name;
            if (f.count > 1) {
                EXPECT_EQ(size_t(m.arrayStride) * size_t(f.count), f.size) << r.name << ": " << name;
            }
        }
        ++programs;
    }
    EXPECT_GE(programs, 3);  // unfiltered, filtered, scene at least
}

}  // namespace
}  // namespace stochtex
