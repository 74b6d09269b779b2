// curve op: a 1D transfer function f of a field (piecewise linear through
// the node's points, tabulated). Its table holds (f, f², 0) per entry on
// two identical rows, read at y = 0.5, so a prefiltered lookup with no
// spread along y gives E[f] and E[f²] (moment matching, docs/MATH.md).
// Kernel file (ops/op_host.h).
struct CurveParams {
    float unused;  // GLSL has no empty struct: f is the op's table
};
// The moments of f(a) for a field a with moments (mean, variance) from a
// table of (f, f², 0) as this op's (CurveOp::momentTable): shared by the ops
// whose filtered value is a 1D table's (threshold).
inline vec3 curveMoments(OpContext ctx, vec3 a) {
    return vec3(matchedMoments(opPrefiltered(ctx, vec2(a.x, 0.5f), vec2(momentSigma(vec2(a.x, a.y)), 0.0f))), 0.0f);
}
inline vec3 opPoint(CurveParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) { return opTable(ctx, vec2(a.x, 0.5f)); }
inline vec3 opFiltered(CurveParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) { return curveMoments(ctx, a); }
