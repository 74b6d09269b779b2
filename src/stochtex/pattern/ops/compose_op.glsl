// compose op: a colour from three fields. On means it is the same formula,
// exact (a colour's mean is its channels' means). Kernel file (ops/op_host.h).
struct ComposeParams {
    float unused;  // GLSL has no empty struct
};
inline vec3 opPoint(ComposeParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) { return vec3(a.x, b.x, c.x); }
inline vec3 opFiltered(ComposeParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) { return vec3(a.x, b.x, c.x); }
