#pragma once
// The paper's 8-bit layout of a program's pyramids (§5): one RGBA8 texture
// per leaf pair holding (E_x, E_y, V_x, V_y), each channel's codes spread
// over its level's range, and the codes the program decodes them with
// (GraphEstimator::LevelCoding, StatsCoding in gpu/shaders/filtering.glsl).
// What the export's 8-bit format writes and the web page embeds.
#include <array>

#include "stochtex/filter/pyramid.h"
#include "stochtex/gpu/gpu_graph.h"

namespace stochtex {

// The two pyramids of leaf pair p, channel x then y (a leaf without a
// partner fills both).
std::array<const StatsPyramid*, 2> pairPyramids(const GraphPattern& graph, const FilteredGraph& filtered, int p);

// Level l of a pair's pyramids as RGBA values q/255 (the codes, no transfer
// function), q = round(255 (v − lo)/(hi − lo)) over each channel's [lo, hi]
// at that level; `coding` gets offset lo and scale hi − lo per channel, so
// that lo + (hi − lo)·texel decodes it (affine: it commutes with the
// bilinear blend of texels). A constant channel is its offset.
Image packedPairLevel(const StatsPyramid& x, const StatsPyramid& y, int level, GraphEstimator::LevelCoding& coding);

// Level l of a covariance pyramid likewise: G = C_l coded (R = the first
// leaf's E_l, coded too; B = 0, A = 1); `coding.covariance` gets its code.
Image codedCovarianceLevel(const StatsPyramid& covariance, int level, GraphEstimator::LevelCoding& coding);

// Whether every value lies in [0, 1], so that 16-bit unorm codes hold it:
// a field table's (g, g²) travels as such codes where it does (the 8-bit
// export, the web page) and as floats otherwise.
bool fitsUnorm16(const Image& image);

}  // namespace stochtex
