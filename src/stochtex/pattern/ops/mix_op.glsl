// mix op: a + t·(b − a), two colours mixed by a field t (not clamped). It is
// linear in each of a, b and t, so on means it is the same formula, exact
// when t is uncorrelated with the colours over the footprint (put a curve
// before t to clamp it). Kernel file (ops/op_host.h).
struct MixParams {
    float unused;  // GLSL has no empty struct
};
inline vec3 opPoint(MixParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) { return a + c.x * (b - a); }
inline vec3 opFiltered(MixParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) { return a + c.x * (b - a); }
