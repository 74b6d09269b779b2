// The parameters of a pattern as its shaders read them: one std140 uniform
// block (`PatternParameters { PatternParams uPattern; }`, declared in
// gpu/shaders/common.glsl), filled on the CPU from this same struct and
// uploaded as one buffer. Kernel file: GLSL and C++, see kernel/glsl.h.
//
// Layout rule, so that C++ (glm) and std140 place every member at the same
// offset: 4-byte scalars (float, int, uint; never bool, which is 1 byte in
// C++) in rows of four, then vec4s and vec4 arrays (std140 pads each element
// of a scalar array to 16 bytes and aligns a vec2 to 8, C++ does neither).
// kernel/pattern_params.h checks the rows at compile time, and a test
// compares every offset with the one GL reports. The members' meanings are
// the table kPatternParamFields (kernel/pattern_params.h), which also writes
// the exported README. A new member fills a spare slot or adds a row of four,
// and gets a row in that table.

// What the generated program does not hold as constants: the triangle
// grid's shape and the examples' size, the estimators' probe count and
// the prefiltered tables' mode and σ levels. A
// program's seeds, means, Gaussianization and pyramid depths are constants
// of its generated GLSL (gpu/gpu_graph.cpp).
struct PatternParams {
    float gridDensity;     // triangle-grid cells per example period along v (and u, unless tileable)
    float invExampleSize;  // 1 / W
    int aniso;             // K
    int smoothTable;       // 1: smooth prefiltered table, 0: paper
    int tableLevels;       // σ levels per axis
    int gridPeriodU;       // the grid's period in cells (GridShape), 0: none
    int gridPeriodV;
    float gridDensityU;    // cells per example period along u
};

// The triangle grid the parameters describe.
inline GridShape patternGrid(PatternParams p) {
    GridShape g;
    g.density = vec2(p.gridDensityU, p.gridDensity);
    g.period = ivec2(p.gridPeriodU, p.gridPeriodV);
    return g;
}
