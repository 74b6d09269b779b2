#pragma once
// Integer hashes shared by the CPU and (later) the GLSL code, so both paths
// draw the same random numbers bit for bit. pcg3d is from Jarzynski & Olano,
// "Hash Functions for GPU Rendering", JCGT 2020; it needs only 32-bit
// unsigned arithmetic, which GLSL ES 3.00 has.
#include <cstdint>

namespace stochtex {

struct UInt3 {
    uint32_t x, y, z;
};

inline constexpr UInt3 pcg3d(UInt3 v) {
    v.x = v.x * 1664525u + 1013904223u;
    v.y = v.y * 1664525u + 1013904223u;
    v.z = v.z * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.x ^= v.x >> 16u;
    v.y ^= v.y >> 16u;
    v.z ^= v.z >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

// Maps 32 random bits to [0,1) using the top 24 bits, exactly representable
// as float, so the same value comes out in GLSL.
inline constexpr float unitFloat(uint32_t bits) { return float(bits >> 8u) * (1.0f / 16777216.0f); }

// Derives an independent stream seed from a seed and a stream index.
inline constexpr uint32_t deriveSeed(uint32_t seed, uint32_t stream) {
    return pcg3d({seed, stream, 0x5bd1e995u}).x;
}

}  // namespace stochtex
