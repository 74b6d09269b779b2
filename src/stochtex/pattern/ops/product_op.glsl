// product op: scale·a·b, one field modulating another (an amplitude
// modulation, a mask). Filtered, exact when a and b are independent over
// the footprint: E[ab] = μ_a μ_b and Var[ab] = σ_a² σ_b² + σ_a² μ_b² + σ_b² μ_a²
// (docs/MATH.md "Filtering a graph by moment matching"); the variances are
// clamped at 0, where an estimator's rounding leaves them slightly negative.
// Kernel file (ops/op_host.h).
struct ProductParams {
    float scale;
};
inline vec3 opPoint(ProductParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    return vec3(p.scale * a.x * b.x, 0.0f, 0.0f);
}
inline vec3 opFiltered(ProductParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    float va = max(a.y, 0.0f), vb = max(b.y, 0.0f);
    float v = va * vb + va * b.x * b.x + vb * a.x * a.x;
    return vec3(p.scale * a.x * b.x, p.scale * p.scale * v, 0.0f);
}
