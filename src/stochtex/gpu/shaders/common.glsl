// Shared by every stochtex shader: texture lookups of the examples, T⁻¹ and
// the colormap, and eq. 7 over them. The hash, the triangle grid and the
// tile offsets are the kernel's (kernel/hash.glsl, kernel/grid.glsl: the
// same source the CPU compiles); the lookups mirror noise/periodic_grid.h.

// Bilinear lookup of a periodic W×W grid (texel centres at (i + ½)/W) at
// p ∈ [0, 1)², vertical interpolation first as on the CPU. Any channel count:
// the caller picks the channels.
vec4 periodicBilinearLod(sampler2D grid, vec2 p, int lod) {
    // Mip l of a W-texel level 0 is max(W >> l, 1) wide. Not textureSize(grid,
    // lod): llvmpipe answers that size query with one lane's lod for the
    // whole SIMD vector, wrong where neighbouring pixels read other levels.
    int w = max(textureSize(grid, 0).x >> lod, 1);
    vec2 t = p * float(w) - 0.5;
    vec2 i0 = floor(t);
    vec2 f = t - i0;
    ivec2 a = (ivec2(i0) + w) % w;
    ivec2 b = (a + 1) % w;
    vec4 t00 = texelFetch(grid, ivec2(a.x, a.y), lod), t10 = texelFetch(grid, ivec2(b.x, a.y), lod);
    vec4 t01 = texelFetch(grid, ivec2(a.x, b.y), lod), t11 = texelFetch(grid, ivec2(b.x, b.y), lod);
    vec4 left = t00 + f.y * (t01 - t00), right = t10 + f.y * (t11 - t10);
    return left + f.x * (right - left);
}

vec4 periodicBilinear(sampler2D grid, vec2 p) { return periodicBilinearLod(grid, p, 0); }

// Tile i's value of the example at fu (uv reduced to one period).
float tileValue(sampler2D example, uint seed, Stencil s, int i, vec2 fu) {
    return periodicBilinear(example, fract(fu + tileOffset(stencilVertex(s, i), seed))).r;
}

// Eq. 7: N(u) = μ + Σ w_i (E(u + o_i) − μ). The three tiles are written out
// (no loop writing a vector by index: llvmpipe spills such vectors).
float tilingBlending(sampler2D example, float mean, uint seed, Stencil s, vec2 fu) {
    vec3 e = vec3(tileValue(example, seed, s, 0, fu), tileValue(example, seed, s, 1, fu), tileValue(example, seed, s, 2, fu));
    return blendMean(mean, s.w, e);
}

// T⁻¹ through its LUT (n × 1 texture), clamped to [0, 1] as on the CPU.
float inverseTransform(sampler2D lut, float g) {
    int n = textureSize(lut, 0).x;
    float t = clamp(g, 0.0, 1.0) * float(n - 1);
    int i = min(int(t), n - 2);
    float f = t - float(i);
    float a = texelFetch(lut, ivec2(i, 0), 0).r, b = texelFetch(lut, ivec2(i + 1, 0), 0).r;
    return a + f * (b - a);
}

// The colormap table H: entry (i, j) at (i/(Rx − 1), j/(Ry − 1)), bilinear,
// clamp-to-edge.
vec3 colormapLookup(sampler2D table, vec2 xy) {
    ivec2 r = textureSize(table, 0);
    vec2 fxy = clamp(xy, 0.0, 1.0) * vec2(r - 1);
    ivec2 i0 = min(ivec2(fxy), r - 2);
    vec2 t = fxy - vec2(i0);
    vec3 a0 = texelFetch(table, i0, 0).rgb, a1 = texelFetch(table, i0 + ivec2(1, 0), 0).rgb;
    vec3 b0 = texelFetch(table, i0 + ivec2(0, 1), 0).rgb, b1 = texelFetch(table, i0 + ivec2(1, 1), 0).rgb;
    vec3 top = a0 + t.x * (a1 - a0), bottom = b0 + t.x * (b1 - b0);
    return top + t.y * (bottom - top);
}

// The pattern's parameters (kernel/pattern_params.glsl): one std140 block,
// filled on the CPU from the same struct (GpuPattern::bind, an engine from
// the export's README).
layout(std140) uniform PatternParameters { PatternParams uPattern; };
