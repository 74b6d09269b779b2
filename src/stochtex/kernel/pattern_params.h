#pragma once
// C++ view of kernel/pattern_params.glsl (the pattern's shader parameters,
// one std140 uniform block) and the table of its members: what each means
// and where an engine finds it in an export's manifest.json. The table
// writes the exported README and drives the test that compares every
// member's offset with the one GL reports (tests/kernel/pattern_params_test.cpp).
#include <cstddef>
#include <string_view>

#include "stochtex/kernel/glsl.h"
#include "stochtex/kernel/grid.h"

namespace stochtex::kernel {
#include "stochtex/kernel/pattern_params.glsl"

struct PatternParamField {
    const char* name;    // the member, in PatternParams and in GLSL
    const char* type;    // its GLSL type: float, int, uint or vec4
    int count;           // array length (1: not an array)
    std::size_t offset;  // bytes from the start of the block, in C++ and std140 alike
    std::size_t size;    // bytes in C++
    const char* meaning;
    const char* manifest;  // how an engine computes it from the export's manifest.json
};

#define STOCHTEX_PATTERN_FIELD(member, type, count, meaning, manifest)                                          \
    PatternParamField {                                                                                         \
#member, type, count, offsetof(PatternParams, member), sizeof(PatternParams::member), meaning, manifest \
    }
inline constexpr PatternParamField kPatternParamFields[] = {
    STOCHTEX_PATTERN_FIELD(gridDensity, "float", 1, "triangle-grid cells per example period along v", "`grid_density`"),
    STOCHTEX_PATTERN_FIELD(invExampleSize, "float", 1, "1 / W, W the first leaf's side in texels",
                           "1 / `example_size`"),
    STOCHTEX_PATTERN_FIELD(aniso, "int", 1, "K, the most probes per footprint (1..16)", "`aniso`"),
    STOCHTEX_PATTERN_FIELD(smoothTable, "int", 1, "1: the smooth prefiltered table, 0: the paper's",
                           "1 if `filter` is \"smooth\""),
    STOCHTEX_PATTERN_FIELD(tableLevels, "int", 1, "σ levels of the prefiltered table per axis", "`table.levels`"),
    STOCHTEX_PATTERN_FIELD(gridPeriodU, "int", 1, "the grid's period in cells along its first axis (0: none)",
                           "`grid_period[0]`"),
    STOCHTEX_PATTERN_FIELD(gridPeriodV, "int", 1, "the grid's period in cells along its skewed second axis",
                           "`grid_period[1]`"),
    STOCHTEX_PATTERN_FIELD(gridDensityU, "float", 1, "triangle-grid cells per example period along u",
                           "`grid_density_u`"),
};
#undef STOCHTEX_PATTERN_FIELD

// The layout rule of pattern_params.glsl, checked: the table lists every
// member in order with no gap, 4-byte scalars stay scalars (no arrays of
// them: std140 would pad each element to 16 bytes) and every vec4 starts a
// 16-byte row (std140 aligns it there; glm does not).
constexpr bool patternParamsFollowTheLayoutRule() {
    std::size_t end = 0;
    for (const PatternParamField& f : kPatternParamFields) {
        if (f.offset != end) return false;
        const bool vector = std::string_view(f.type) == "vec4";
        if (vector && (f.offset % 16 != 0 || f.size != 16 * std::size_t(f.count))) return false;
        if (!vector && (f.count != 1 || f.size != 4)) return false;
        end = f.offset + f.size;
    }
    return end == sizeof(PatternParams) && end % 16 == 0;
}
static_assert(sizeof(vec4) == 16 && sizeof(uint) == 4 && sizeof(int) == 4);
static_assert(patternParamsFollowTheLayoutRule(),
              "kernel/pattern_params.glsl breaks its layout rule, or kPatternParamFields does not list its members");

}  // namespace stochtex::kernel
