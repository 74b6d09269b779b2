// lean op: the radiance of a height field's micro-facets (kernel/lean.glsl,
// paper §6.5). Its inputs are the height's slopes along u and v (a, b: two
// leaves on the height's tiles, which the graph builds) and the albedo (c).
// The slopes' footprint means, variances and covariance (ctx.slopeCov, when
// the node reads it) make the anisotropic Beckmann lobe; unfiltered, the
// variances and covariance are 0 (the base lobe about the point's slope).
// The albedo is a colour's value, or its footprint mean when filtered:
// exact when it is uncorrelated with the slopes over the footprint. Lit by
// the host's light when it has one (a scene's), else the node's; seen from
// the node's fixed view when it has one, else from the host's eye.
// Kernel file (ops/op_host.h).
struct LeanParams {
    float roughness;
    float specular;
    float lightX;  // unit direction towards the light, texture frame
    float lightY;
    float lightZ;
    float covariance;  // 1: read the slopes' covariance, 0: take it as 0
    float viewX;       // a fixed unit direction towards the viewer, texture frame;
    float viewY;       // viewZ = 0: none (the host's eye)
    float viewZ;
};
inline vec3 leanOpLight(LeanParams p, OpContext ctx) {
    return ctx.light.w != 0.0f ? vec3(ctx.light.x, ctx.light.y, ctx.light.z) : vec3(p.lightX, p.lightY, p.lightZ);
}
inline vec3 leanOpEye(LeanParams p, OpContext ctx) {
    return p.viewZ != 0.0f ? vec3(p.viewX, p.viewY, p.viewZ) : ctx.eye;
}
inline vec3 opPoint(LeanParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    LeanLobe lobe = leanLobe(vec2(a.x, b.x), vec2(0.0f), 0.0f, p.roughness);
    return leanShade(lobe, leanOpLight(p, ctx), leanOpEye(p, ctx), c, p.specular);
}
inline vec3 opFiltered(LeanParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    float cov = p.covariance != 0.0f ? ctx.slopeCov : 0.0f;
    LeanLobe lobe = leanLobe(vec2(a.x, b.x), vec2(a.y, b.y), cov, p.roughness);
    return leanShade(lobe, leanOpLight(p, ctx), leanOpEye(p, ctx), c, p.specular);
}
