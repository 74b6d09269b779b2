// sum op: w_a·a + w_b·b of fields that ops give (over fields that fold, sum
// is linear and folds into the example). The moments' variance takes the
// two inputs as uncorrelated over the footprint, which holds for fields
// from different sources; where a sum of two functions of one source (or
// a node after it) is what the filtered program reads, that node is
// filtered as one function of its sources instead, when moment matching
// (GraphPattern::planSourceFunctions).
// Kernel file (ops/op_host.h).
struct SumParams {
    float weightA;
    float weightB;
};
inline vec3 opPoint(SumParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    return vec3(p.weightA * a.x + p.weightB * b.x, 0.0f, 0.0f);
}
inline vec3 opFiltered(SumParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    return vec3(p.weightA * a.x + p.weightB * b.x, p.weightA * p.weightA * a.y + p.weightB * p.weightB * b.y, 0.0f);
}
