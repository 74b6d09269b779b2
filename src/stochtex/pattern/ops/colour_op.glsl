// colour op: a constant colour in linear light (an albedo, an end of a mix).
// Its footprint mean is itself, so the filtered value is the point value.
// Kernel file (ops/op_host.h).
struct ColourParams {
    float red;
    float green;
    float blue;
};
inline vec3 opPoint(ColourParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) { return vec3(p.red, p.green, p.blue); }
inline vec3 opFiltered(ColourParams p, vec3 a, vec3 b, vec3 c, OpContext ctx) { return vec3(p.red, p.green, p.blue); }
