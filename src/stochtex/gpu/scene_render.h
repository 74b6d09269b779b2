#pragma once
// The pattern on a lit mesh (paper Fig. 15): drawn with depth and one
// directional light by the view's scene program (mesh.vert + scene.frag),
// the pattern's (or graph's) textures and uniforms bound by GpuView::bind.
#include "stochtex/gpu/gpu_view.h"
#include "stochtex/gpu/scene.h"
#include "stochtex/image/image.h"

namespace stochtex {

// uv × tiling example periods, seen by a perspective camera; 3 channels,
// row 0 at the top. width, height in [1, 8192]; tiling in (0, 1e4].
Image renderScene(const GpuView& pattern, const Mesh& mesh, const SceneCamera& camera, int width, int height,
                  float tiling);

}  // namespace stochtex
