#pragma once
// The GLSL subset the kernel files (kernel/*.glsl) are written in, for C++.
//
// A kernel file is GLSL 3.30 core / ES 3.00 source that also compiles as
// C++20 inside namespace stochtex::kernel: glm supplies the vector types
// and the built-in functions under their GLSL names, and each function is
// marked `inline`, which the shader assembler (gpu/shader.cpp) removes.
// Rules for kernel files (docs/CODE_STYLE.md has the long form):
//   * float literals carry the `f` suffix (an unsuffixed literal is a double
//     in C++ and would change the rounding);
//   * no swizzles (glm has none without extensions), no `out`/`inout`
//     parameters (return a struct), no implicit int↔float conversions;
//   * no preprocessor lines: the C++ wrapper header includes the kernel
//     files a file needs, and the shader assembler reads those includes to
//     put the same files first in GLSL (gpu/shader.cpp, shaderChunks);
//   * texture coordinates that the CPU needs in double are `coord` /
//     `coord2` (kernel/coords.h), float in GLSL;
//   * sums are written out term by term (dot() may associate differently
//     on a GPU).
// Only the names below are visible to kernel code, so nothing of
// namespace stochtex or <cmath> can silently replace a GLSL built-in.
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace stochtex::kernel {

using uint = glm::uint;
using glm::bvec2;
using glm::ivec2;
using glm::ivec3;
using glm::ivec4;
using glm::uvec2;
using glm::uvec3;
using glm::uvec4;
using glm::vec2;
using glm::vec3;
using glm::vec4;

using glm::abs;
using glm::ceil;
using glm::clamp;
using glm::cos;
using glm::exp2;
using glm::floatBitsToUint;
using glm::floor;
using glm::fract;
using glm::length;
using glm::log2;
using glm::max;
using glm::min;
using glm::mix;
using glm::pow;
using glm::sin;
using glm::sqrt;
using glm::uintBitsToFloat;

}  // namespace stochtex::kernel
