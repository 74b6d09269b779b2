// colormap op: the 2D transfer function H, colour = H(x, y) (paper eq. 1);
// filtered, the prefiltered table at the inputs' means and deviations,
// H̄(μ, σ) (paper eq. 5-6). Kernel file (ops/op_host.h).
struct ColormapParams {
    float unused;  // GLSL has no empty struct: H is the op's table
};
inline vec3 opPoint(ColormapParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) { return opTable(ctx, vec2(a.x, b.x)); }
inline vec3 opFiltered(ColormapParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    return opPrefiltered(ctx, vec2(a.x, b.x), vec2(momentSigma(vec2(a.x, a.y)), momentSigma(vec2(b.x, b.y))));
}
