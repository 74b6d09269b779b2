#pragma once
// What differs between the kernel's two hosts, named once.
//
// Texture coordinates in the host's precision: double on the CPU, where an
// offset may be 1e9 texels and a pixel's uv must still resolve a texel, and
// float on the GPU (kernel/coords.glsl), which has no double in GLSL ES.
// Kernel functions that place pixels in texture space (kernel/camera.glsl:
// the zoom mapping, the plane's centre, a graph's uv transform) are written
// once over these names and run at each host's precision.
#include <glm/vec2.hpp>

namespace stochtex::kernel {

using coord = double;
using coord2 = glm::dvec2;

// Marks a kernel function as generic over a type its host supplies (a
// texel source): a template in C++, and in GLSL, where the host declares
// one struct of that name before the kernel file, nothing.
#define STOCHTEX_HOST_TYPE(T) template <class T>

}  // namespace stochtex::kernel
