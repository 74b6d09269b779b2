// Response: the prefiltered colormap H̄(μ, σ_x, σ_y) of paper eq. 5–6 (§5),
// PrefilteredColormapResponse on the CPU. It reads the table layers of
// uTable through the kernel's σ-level lookup
// (kernel/sigma_levels.glsl); an axis-aligned Gaussian, so the covariance
// is not read (Response::needsCovariance() is false, so is
// uPattern.hasCovariance).
uniform sampler2DArray uTable;  // RGB32F, layer kx·levels + ky

vec3 tableLayer(int kx, int ky, vec2 mu) { return tableLookup(uTable, kx * uPattern.tableLevels + ky, mu); }

vec3 prefiltered(vec2 mu, vec2 sigma) {
    LayerBlend b = layerBlend(sigma, uPattern.smoothTable == 0, uPattern.tableLevels);
    if (b.f.x == 0.0 && b.f.y == 0.0) return tableLayer(b.k0.x, b.k0.y, mu);
    return layerMix(tableLayer(b.k0.x, b.k0.y, mu), tableLayer(b.k1.x, b.k0.y, mu), tableLayer(b.k0.x, b.k1.y, mu),
                    tableLayer(b.k1.x, b.k1.y, mu), b.f);
}

vec3 footprintResponse(vec2 mean, vec2 var, float cov) { return prefiltered(mean, sqrt(var)); }

// Unfiltered (unfiltered.glsl): H at the point's N (T⁻¹ applied already),
// the colormap itself. Unused by the filtered programs and the export, whose
// compilers drop it with uColormap.
uniform sampler2DArray uColormap;  // H: RGB32F table, one layer
vec3 pointResponse(vec2 n) { return tableLookup(uColormap, 0, n); }
