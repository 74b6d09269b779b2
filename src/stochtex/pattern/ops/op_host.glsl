// What an op is given on the GPU (GLSL only; op_host.h is the C++ side):
// the context of one call and the two table lookups, declared here and
// defined by the host's program — a graph's generated chunk
// (gpu/gpu_graph.cpp) over its samplers, by the op's table index. Every op's
// kernel file needs this one (its header includes op_host.h).
struct OpContext {
    int table;       // the op's table, −1: none
    vec3 eye;        // unit direction towards the eye, texture frame
    vec4 light;      // w ≠ 0: the host's own light (a scene's), which replaces an op's
    float slopeCov;  // covariance of the pair of leaves the op's first input is in
};
vec3 opTable(OpContext ctx, vec2 xy);
vec3 opPrefiltered(OpContext ctx, vec2 xy, vec2 sigma);
