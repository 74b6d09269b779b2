// Shared by every stochtex shader: texture lookups of the examples, T⁻¹ and
// the colormap, and eq. 7 over them. The hash, the triangle grid, the tile
// offsets and the lookups' addressing and blends are the kernel's
// (kernel/hash.glsl, grid.glsl, lookup.glsl: the same source the CPU
// compiles); this file only fetches the texels.
#include "stochtex/kernel/grid.glsl"
#include "stochtex/kernel/lookup.glsl"
#include "stochtex/kernel/pattern_params.glsl"

// The unit directions from the shaded point towards the eye and the light
// in the texture frame (x along u, y along v, z up), read by responses that
// shade (the lean response). The eye: set per pixel by the view (view.glsl,
// the kernel's planeViewDirection) or the scene (the surface's tangent
// frame); straight down where nothing sets it. The light: set by the scene
// (w = 1); w = 0 leaves the response's own.
vec3 gEyeDirection = vec3(0.0, 0.0, 1.0);
vec4 gLightDirection = vec4(0.0);

// Bilinear lookup of a periodic W×W grid (texel centres at (i + ½)/W) at
// fu + offset, fu ∈ [0, 1)² a point of one period and offset ∈ [0, 1)² a
// tile's offset: the kernel's addressing and blend (kernel/lookup.glsl), as
// the CPU's grids do it. Any channel count: the caller picks the channels.
vec4 periodicBilinearLod(sampler2D grid, vec2 fu, vec2 offset, int lod) {
    // Mip l of a W-texel level 0 is max(W >> l, 1) wide. Not textureSize(grid,
    // lod): llvmpipe answers that size query with one lane's lod for the
    // whole SIMD vector, wrong where neighbouring pixels read other levels.
    int w = max(textureSize(grid, 0).x >> lod, 1);
    float fw = float(w);
    vec2 t = vec2(periodicTexel(texelOfPoint(fu.x, fw), offset.x * fw, fw),
                  periodicTexel(texelOfPoint(fu.y, fw), offset.y * fw, fw));
    PeriodicTaps k = periodicTaps(t, w);
    return blendColumnsFirst(texelFetch(grid, k.left, lod), texelFetch(grid, ivec2(k.right.x, k.left.y), lod),
                             texelFetch(grid, ivec2(k.left.x, k.right.y), lod), texelFetch(grid, k.right, lod), k.f);
}

// Tile i's value of the example at fu (uv reduced to one period).
float tileValue(sampler2D example, uint seed, Stencil s, int i, vec2 fu) {
    return periodicBilinearLod(example, fu, tileOffset(stencilVertex(s, i), seed), 0).r;
}

// Eq. 7: N(u) = μ + Σ w_i (E(u + o_i) − μ). The three tiles are written out
// (no loop writing a vector by index: llvmpipe spills such vectors).
float tilingBlending(sampler2D example, float mean, uint seed, Stencil s, vec2 fu) {
    vec3 e = vec3(tileValue(example, seed, s, 0, fu), tileValue(example, seed, s, 1, fu), tileValue(example, seed, s, 2, fu));
    return blendMean(mean, s.w, e);
}

// T⁻¹ through its LUT (n × 1 texture), clamped to [0, 1] as on the CPU.
float inverseTransform(sampler2D lut, float g) {
    TableTap tap = tableTap(g, textureSize(lut, 0).x);
    return blendEntries(texelFetch(lut, ivec2(tap.i, 0), 0).r, texelFetch(lut, ivec2(tap.i + 1, 0), 0).r, tap.t);
}

// Layer `layer` of a table texture (the colormap H, a layer of H̄): entry
// (i, j) at (i/(Rx − 1), j/(Ry − 1)), bilinear, clamp-to-edge, by the
// kernel's taps and blend as on the CPU (pattern/colormap.h).
vec3 tableLookup(sampler2DArray table, int layer, vec2 xy) {
    ivec2 r = textureSize(table, 0).xy;
    TableTap tx = tableTap(xy.x, r.x), ty = tableTap(xy.y, r.y);
    vec4 e00 = texelFetch(table, ivec3(tx.i, ty.i, layer), 0), e10 = texelFetch(table, ivec3(tx.i + 1, ty.i, layer), 0);
    vec4 e01 = texelFetch(table, ivec3(tx.i, ty.i + 1, layer), 0);
    vec4 e11 = texelFetch(table, ivec3(tx.i + 1, ty.i + 1, layer), 0);
    return blendRowsFirst(e00, e10, e01, e11, vec2(tx.t, ty.t)).rgb;
}

// The pattern's parameters (kernel/pattern_params.glsl): one std140 block,
// filled on the CPU from the same struct (GpuGraph::bind, an engine from
// the export's README). STOCHTEX_BINDING(n): nothing for OpenGL (the host's
// header), a Vulkan set and binding in the export's include.
STOCHTEX_BINDING(0) layout(std140) uniform PatternParameters { PatternParams uPattern; };
