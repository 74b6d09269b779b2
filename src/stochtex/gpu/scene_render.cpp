#include "stochtex/gpu/scene_render.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/gpu/programs.h"
#include "stochtex/gpu/render_target.h"
#include "stochtex/image/colour_space.h"

namespace stochtex {

SceneRenderer::SceneRenderer(const GpuView& pattern, const Mesh& mesh)
    : pattern_(pattern), program_(pattern.sceneProgram()), vao_(gl::newVertexArray()), vertices_(gl::newBuffer()),
      indices_(gl::newBuffer()), indexCount_(GLsizei(mesh.indices.size())) {
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(float)), mesh.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(uint32_t)), mesh.indices.data(),
                 GL_STATIC_DRAW);
    const GLsizei stride = Mesh::kStride * sizeof(float);
    const int sizes[3] = {3, 3, 2}, offsets[3] = {0, 3, 6};
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexAttribArray(a);
        glVertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(size_t(offsets[a]) * sizeof(float)));
    }
    glBindVertexArray(0);
}

void SceneRenderer::draw(const SceneCamera& camera, const RenderTarget& target, float tiling,
                         SurfaceMapping mapping) const {
    if (!(tiling > 0) || !std::isfinite(tiling) || tiling > 1e4)
        throw InputError::parameter("tiling", "must be a finite number in (0, 1e4], got " + formatValue(tiling));
    // A lean program shades its slopes in the uv frame of one projection.
    if (mapping == SurfaceMapping::Triplanar && pattern_.shadesLight())
        throw InputError::parameter("mapping", "triplanar does not light a program that shades its own light (lean)");
    for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {}  // earlier callers' errors are not ours
    target.bind();
    // The dark slate background, given as sRGB codes: the target holds linear light.
    glClearColor(linearFromSrgb(0.08f), linearFromSrgb(0.09f), linearFromSrgb(0.11f), 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    const GLuint program = program_.id();
    pattern_.bind(program);
    auto uniform = [&](const char* name) { return glGetUniformLocation(program, name); };
    const Mat4 vp = camera.viewProjection(float(target.width()) / float(target.height()));
    glUniformMatrix4fv(uniform("uViewProjection"), 1, GL_FALSE, vp.data());
    glUniform1f(uniform("uTiling"), tiling);
    glUniform1i(uniform("uFiltered"), pattern_.filtered());
    glUniform1i(uniform("uShadesLight"), pattern_.shadesLight());
    glUniform1i(uniform("uTriplanar"), mapping == SurfaceMapping::Triplanar);
    const float l[3] = {0.45f, 0.8f, 0.4f};
    const float n = std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    glUniform3f(uniform("uLight"), l[0] / n, l[1] / n, l[2] / n);
    glUniform3f(uniform("uEye"), camera.eye[0], camera.eye[1], camera.eye[2]);
    glBindVertexArray(vao_.id());
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    glDisable(GL_DEPTH_TEST);
    // A draw GL refuses leaves only the clear colour: fail rather than
    // show an empty picture as a success.
    if (const GLenum e = glGetError(); e != GL_NO_ERROR)
        throw std::runtime_error("scene: OpenGL error " + std::to_string(e) + " while drawing the mesh");
}

Image renderScene(const GpuView& pattern, const Mesh& mesh, const SceneCamera& camera, int width, int height,
                  float tiling, SurfaceMapping mapping) {
    if (width < 1 || height < 1 || width > 8192 || height > 8192)
        throw InputError::parameter("size", "must be in [1, 8192] per side, got " + std::to_string(width) + "x" +
                                                std::to_string(height));
    const RenderTarget target(width, height, true);
    SceneRenderer(pattern, mesh).draw(camera, target, tiling, mapping);
    // GL's row 0 is the bottom of the picture: flip for an image file.
    Image out = target.readRgb(RenderTarget::Rows::TopDown);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return out;
}

}  // namespace stochtex
