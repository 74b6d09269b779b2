// Integer hashing (kernel file: GLSL and C++, see kernel/glsl.h).
//
// pcg3d (Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 2020):
// 32-bit unsigned arithmetic only, which GLSL ES 3.00 has, so the CPU and
// the GPU draw the same random numbers bit for bit.

inline uvec3 pcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

// 32 random bits to [0, 1) through the top 24 bits: exactly representable as
// a float, so the same value comes out on both sides.
inline float unitFloat(uint bits) {
    return float(bits >> 8u) * (1.0f / 16777216.0f);
}

// An independent stream seed from a seed and a stream index.
inline uint deriveSeed(uint seed, uint stream) {
    return pcg3d(uvec3(seed, stream, 0x5bd1e995u)).x;
}
