#pragma once
// The pattern on a lit mesh (paper Fig. 15): drawn with depth and one
// directional light by the view's scene program (mesh.vert + scene.frag),
// the pattern's (or graph's) textures and uniforms bound by GpuView::bind.
#include "stochtex/gpu/gpu_view.h"
#include "stochtex/gpu/render_target.h"
#include "stochtex/gpu/scene.h"
#include "stochtex/image/image.h"

namespace stochtex {

// The pattern on one mesh: the view's scene program and the mesh's buffers,
// built once (needs the context current), so a window draws it every frame
// without compiling. The view must outlive it.
class SceneRenderer {
public:
    SceneRenderer(const GpuView& pattern, const Mesh& mesh);
    // Draws the mesh, uv × tiling example periods, seen by a perspective
    // camera, into `target` (which needs a depth buffer), over the slate
    // background; rows as drawn (GL row 0 at the bottom). tiling in (0, 1e4]
    // (triplanar: example periods across 2 units of the object, its size).
    void draw(const SceneCamera& camera, const RenderTarget& target, float tiling,
              SurfaceMapping mapping = SurfaceMapping::Uv) const;

private:
    const GpuView& pattern_;
    gl::Program program_;
    gl::VertexArray vao_;
    gl::Buffer vertices_, indices_;
    GLsizei indexCount_;
};

// A SceneRenderer's draw into a new target, read back: 3 channels, row 0 at the top.
// width, height in [1, 8192].
Image renderScene(const GpuView& pattern, const Mesh& mesh, const SceneCamera& camera, int width, int height,
                  float tiling, SurfaceMapping mapping = SurfaceMapping::Uv);

}  // namespace stochtex
