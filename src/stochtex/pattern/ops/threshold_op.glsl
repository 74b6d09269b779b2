// threshold op: a soft threshold of a field, the smoothstep from 0 at
// edge − width/2 to 1 at edge + width/2. C¹ (no step to alias), so a
// pattern's blots get edges of a chosen softness. Points are the formula;
// filtered, the curve op's moment table of s (curveMoments: E[s] and E[s²]
// from one prefiltered lookup, docs/MATH.md). Kernel file (ops/op_host.h).
struct ThresholdParams {
    float edge;
    float width;  // > 0
};
inline float thresholdValue(ThresholdParams p, float x) {
    float t = clamp((x - (p.edge - 0.5f * p.width)) / p.width, 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}
inline vec3 opPoint(ThresholdParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    return vec3(thresholdValue(p, a.x), 0.0f, 0.0f);
}
inline vec3 opFiltered(ThresholdParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) { return curveMoments(ctx, a); }
