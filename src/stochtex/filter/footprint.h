#pragma once
// Pixel footprints in texture space and their discretisation into probes.
//
// A pixel's footprint is given by its centre uv and Jacobian J = [∂uv/∂x,
// ∂uv/∂y] (uv per pixel). Following the OpenGL anisotropic filtering
// description (EXT_texture_filter_anisotropic), with P_x = W‖∂uv/∂x‖ and
// P_y = W‖∂uv/∂y‖ in texels:
//   isotropic (K = 1): one probe at the centre, λ = log2 max(P_x, P_y);
//   anisotropic (K > 1): N = min(⌈P_max/P_min⌉, K) probes spread along the
//   major axis at ((j + ½)/N − ½)·axis, each with λ = log2(P_max / N) and
//   weight 1/N.
// λ is clamped to [0, L] (magnification reads level 0). Each probe is later
// split between levels ⌊λ⌋ and ⌊λ⌋ + 1 (trilinear), so a footprint is a
// weighted union of texel footprints, as in paper eq. 9 and 15.

#include "stochtex/kernel/estimate.h"
#include "stochtex/kernel/footprint.h"

namespace stochtex {

struct Jacobian {
    double dudx = 0, dvdx = 0;  // ∂uv/∂x
    double dudy = 0, dvdy = 0;  // ∂uv/∂y
};

// One probe: where it sits, its level λ and its weight.
struct Probe {
    double u, v;
    float lod;     // λ, clamped to [0, maxLod]
    float weight;  // Σ weights = 1
};

using kernel::kMaxAnisotropy;  // 16

// A footprint: its centre and the kernel's probe layout (count, λ, major
// axis), which places the probes (kernel/estimate.glsl reads it as the
// shaders do).
struct Footprint {
    double u = 0, v = 0;
    kernel::ProbeLayout layout{1, 0.0f, kernel::vec2(0.0f)};

    int count() const { return layout.count; }
    // Probe k (k < count()): where the kernel's loop reads it (probeCentre).
    Probe probe(int k) const {
        const kernel::coord2 p = kernel::probeCentre(kernel::coord2(u, v), layout, k);
        return Probe{p.x, p.y, layout.lod, 1.0f / float(layout.count)};
    }
    // The same footprint centred elsewhere. Probes depend on the centre only
    // through a translation, so where J is constant (a zoom) the footprint is
    // built once and moved to every pixel.
    Footprint translated(double du, double dv) const { return Footprint{u + du, v + dv, layout}; }
};

// maxAniso in [1, 16]; exampleSize = W; maxLod = log2 W.
Footprint makeFootprint(double u, double v, const Jacobian& j, int exampleSize, int maxLod, int maxAniso);

}  // namespace stochtex
