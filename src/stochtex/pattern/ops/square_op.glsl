// square op: scale·x², the energy of a field (a band-pass noise squared
// gives its local contrast, rectified). Filtered, exact for a Gaussian x of
// mean μ and variance σ²: E[x²] = μ² + σ², Var[x²] = 4μ²σ² + 2σ⁴ (for an op's
// output, Gaussian by moment matching). The variance is clamped at 0, where
// an estimator's rounding leaves it slightly negative. Kernel file
// (ops/op_host.h).
struct SquareParams {
    float scale;
};
inline vec3 opPoint(SquareParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) { return vec3(p.scale * a.x * a.x, 0.0f, 0.0f); }
inline vec3 opFiltered(SquareParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    float v = max(a.y, 0.0f);
    return vec3(p.scale * (a.x * a.x + v), p.scale * p.scale * (4.0f * a.x * a.x * v + 2.0f * v * v), 0.0f);
}
