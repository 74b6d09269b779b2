#pragma once
// What the GPU programs read, uploaded: float textures read with texelFetch,
// statistics pyramids as mip chains, RGB tables as texture arrays, and the
// view's uniforms (gpu/shaders/view.glsl), for GpuGraph and the scene.
#include "stochtex/filter/pyramid.h"
#include "stochtex/gpu/gl_objects.h"
#include "stochtex/pattern/camera.h"

namespace stochtex {

// A W×H texture of 1 to 4 float channels, nearest, one level.
gl::Texture floatTexture(int width, int height, int channels, const float* data);
// A pyramid's levels as the mip chain of one RG32F texture (mean, moment).
gl::Texture pyramidTexture(const StatsPyramid& p);
// RGB tables (rx × ry entries, `layers` of them stacked in `rgb`) as one
// texture array read with texelFetch: a colormap H (one layer) and a
// prefiltered table's layers (PrefilteredColormap::atlas).
gl::Texture tableTexture(int rx, int ry, int layers, const float* rgb);

// The camera's uniforms of view.glsl (and filtered.frag's
// uRasterizerDerivatives) on the current program.
void setCameraUniforms(unsigned program, const Camera& camera, bool rasterizerDerivatives);

}  // namespace stochtex
