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

// Pyramid levels the shaders take per-level constants for: examples of at
// most 2¹⁵ texels a side.
const int kMaxPyramidLevels = 16;

struct PatternParams {
    float meanX;           // μ of noise x's example
    float meanY;           // μ of noise y's example
    float gridDensity;     // triangle-grid cells per example period
    float invExampleSize;  // 1 / W
    uint seedX;            // tile-offset seeds
    uint seedY;
    int gaussianizedX;     // 1: through T⁻¹ (unfiltered only)
    int gaussianizedY;
    int hasCovariance;     // 1: covariances fetched and used
    int deliotHeitz;       // 1: averageMoments instead of eq. 12
    int maxLod;            // L = log2 W
    int aniso;             // K
    int smoothTable;       // 1: smooth prefiltered table, 0: paper
    int tableLevels;       // σ levels per axis
    int spare0;            // unused: completes the row
    int spare1;
    vec4 averageMoments[kMaxPyramidLevels];  // per level l: (V̄_x, V̄_y, C̄, 0)
};
