// affine op: scale·x + offset of a field that an op gives (over fields that
// fold, affine is linear and folds into the example: texture_graph.h).
// Exact on moments. Kernel file (ops/op_host.h).
struct AffineParams {
    float scale;
    float offset;
};
inline vec3 opPoint(AffineParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    return vec3(p.scale * a.x + p.offset, 0.0f, 0.0f);
}
inline vec3 opFiltered(AffineParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    return vec3(p.scale * a.x + p.offset, p.scale * p.scale * a.y, 0.0f);
}
