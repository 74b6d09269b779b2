// colormap_field op: a 2D transfer function read as a field g (one channel
// or the luminance of H, paper Fig. 14). Its table holds (g, g², 0) per
// entry, so a prefiltered lookup gives E[g] and E[g²], the moments the next
// op reads (moment matching, docs/MATH.md). Kernel file (ops/op_host.h).
struct ColormapFieldParams {
    float unused;  // GLSL has no empty struct: g is the op's table
};
inline vec3 opPoint(ColormapFieldParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    return opTable(ctx, vec2(a.x, b.x));
}
inline vec3 opFiltered(ColormapFieldParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    vec2 sigma = vec2(momentSigma(vec2(a.x, a.y)), momentSigma(vec2(b.x, b.y)));
    return vec3(matchedMoments(opPrefiltered(ctx, vec2(a.x, b.x), sigma)), 0.0f);
}
