// Response: the prefiltered colormap H̄(μ, σ_x, σ_y) of paper eq. 5–6 (§5),
// PrefilteredColormapResponse on the CPU. It reads the table layers of
// uTable through the kernel's σ-level lookup
// (kernel/sigma_levels.glsl); an axis-aligned Gaussian, so the covariance
// is not read (Response::needsCovariance() is false, so is
// uPattern.hasCovariance).
#include "stochtex/kernel/sigma_levels.glsl"
uniform sampler2DArray uTable;  // RGB32F, layer kx·levels + ky

vec3 tableLayer(sampler2DArray table, int kx, int ky, vec2 mu) {
    return tableLookup(table, kx * uPattern.tableLevels + ky, mu);
}

// [T ∗ G_σ](μ) of any prefiltered table laid out as uTable (the σ levels of
// uPattern; a texture graph's tables too, gpu/gpu_graph.cpp).
vec3 prefilteredLookup(sampler2DArray table, vec2 mu, vec2 sigma) {
    LayerBlend b = layerBlend(sigma, uPattern.smoothTable == 0, uPattern.tableLevels);
    if (b.f.x == 0.0 && b.f.y == 0.0) return tableLayer(table, b.k0.x, b.k0.y, mu);
    return layerMix(tableLayer(table, b.k0.x, b.k0.y, mu), tableLayer(table, b.k1.x, b.k0.y, mu),
                    tableLayer(table, b.k0.x, b.k1.y, mu), tableLayer(table, b.k1.x, b.k1.y, mu), b.f);
}

vec3 prefiltered(vec2 mu, vec2 sigma) { return prefilteredLookup(uTable, mu, sigma); }

vec3 footprintResponse(vec2 mean, vec2 var, float cov) { return prefiltered(mean, sqrt(var)); }

// Unfiltered (unfiltered.glsl): H at the point's N (T⁻¹ applied already),
// the colormap itself. Unused by the filtered programs and the export, whose
// compilers drop it with uColormap.
uniform sampler2DArray uColormap;  // H: RGB32F table, one layer
vec3 pointResponse(vec2 n) { return tableLookup(uColormap, 0, n); }
