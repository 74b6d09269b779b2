#pragma once
// The same-run gather floor (gather_floor.cpp).
namespace stochtex::bench {

// Seconds to gather `pairs` 64-bit texel pairs from a 256² example's grid,
// in the widest vectors of the machine, and do nothing else.
double gatherFloorSeconds(long long pairs);

}  // namespace stochtex::bench
