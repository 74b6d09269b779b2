// surface op: the maps an engine's PBR material takes for a height field
// (LEAN mapping's slope lobe, kernel/lean.glsl; paper §6.5): its
// tangent-space normal, its roughness or its height. Its inputs are the
// height's slopes along u and v (a, b: two leaves on the height's tiles,
// which the graph builds) and the height itself (c, a leaf on the same
// tiles). Filtered, each map is what the footprint's statistics say: the
// normal of its mean slope, the roughness of its slope lobe (the base
// roughness's spread plus the slopes' footprint variances — what makes a
// distant normal map look rougher), the height's mean. Kernel file
// (ops/op_host.h).
struct SurfaceParams {
    float map;        // 0: normal, 1: roughness, 2: height
    float roughness;  // base Beckmann roughness m of each micro-facet
};

// The unit normal of slope s (x along u, y along v, z up) as a normal map's
// RGB in the OpenGL convention: x to the right, y up the image (v runs down
// it, so y = −v), each component c stored as 0.5 + 0.5·c.
inline vec3 surfaceNormalRgb(vec2 slope) {
    vec3 n = normalize(vec3(-slope.x, -slope.y, 1.0f));
    return vec3(0.5f + 0.5f * n.x, 0.5f - 0.5f * n.y, 0.5f + 0.5f * n.z);
}

// The roughness r of a GGX material (α = r², as glTF and the common engines
// take it) for a slope lobe: Beckmann's m of the lobe's isotropic spread,
// m² = Σxx + Σyy (each axis holds m²/2), matched to α.
inline float surfaceRoughness(LeanLobe l) {
    return sqrt(sqrt(l.sigma.x + l.sigma.y));
}

inline vec3 surfaceMap(SurfaceParams p, LeanLobe lobe, float height) {
    if (p.map == 0.0f) return surfaceNormalRgb(lobe.mean);
    if (p.map == 1.0f) return vec3(surfaceRoughness(lobe));
    return vec3(height);
}
inline vec3 opPoint(SurfaceParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    return surfaceMap(p, leanLobe(vec2(a.x, b.x), vec2(0.0f), 0.0f, p.roughness), c.x);
}
inline vec3 opFiltered(SurfaceParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) {
    return surfaceMap(p, leanLobe(vec2(a.x, b.x), vec2(a.y, b.y), ctx.slopeCov, p.roughness), c.x);
}
