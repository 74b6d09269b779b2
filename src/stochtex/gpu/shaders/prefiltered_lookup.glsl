// The lookup of a prefiltered table H̄(μ, σ_x, σ_y) (paper eq. 5–6, §5;
// PrefilteredColormap::sample on the CPU): the table's layers through the
// kernel's σ-level rule (kernel/sigma_levels.glsl). The generated program
// of a file reads each of its tables through it (gpu/gpu_graph.cpp).
#include "stochtex/kernel/sigma_levels.glsl"

vec3 tableLayer(sampler2DArray table, int kx, int ky, vec2 mu) {
    return tableLookup(table, kx * uPattern.tableLevels + ky, mu);
}

// [T ∗ G_σ](μ) of a prefiltered table: layer kx·levels + ky holds σ levels
// (kx, ky) of uPattern's mode; an axis with beta ≠ 0 is a Beta axis.
vec3 prefilteredLookup(sampler2DArray table, vec2 mu, vec2 sigma, ivec2 beta) {
    LayerBlend b = tableLayerBlend(mu, sigma, beta, uPattern.smoothTable == 0, uPattern.tableLevels);
    if (b.f.x == 0.0 && b.f.y == 0.0) return tableLayer(table, b.k0.x, b.k0.y, mu);
    return layerMix(tableLayer(table, b.k0.x, b.k0.y, mu), tableLayer(table, b.k1.x, b.k0.y, mu),
                    tableLayer(table, b.k0.x, b.k1.y, mu), tableLayer(table, b.k1.x, b.k1.y, mu), b.f);
}
