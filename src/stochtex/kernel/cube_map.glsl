// A cube map's texel directions. Kernel file: GLSL and C++, see kernel/glsl.h.
//
// The direction along which texel centre (s, t) ∈ (0, 1)² of face `face`
// (0–5: +x, −x, +y, −y, +z, −z) is sampled: GL's cube map selection
// (OpenGL 4.5 §8.13) inverted, t going down each face as a face image's rows
// do. Not normalised: its major axis is ±1. Cube A's fragments are given it
// as their ray (gpu/shadertoy.cpp), and an equirectangular image is resampled
// onto faces along it.
inline vec3 cubeFaceDirection(int face, float s, float t) {
    float a = 2.0f * s - 1.0f;
    float b = 2.0f * t - 1.0f;
    if (face == 0) return vec3(1.0f, -b, -a);
    if (face == 1) return vec3(-1.0f, -b, a);
    if (face == 2) return vec3(a, 1.0f, b);
    if (face == 3) return vec3(a, -1.0f, -b);
    if (face == 4) return vec3(a, -b, 1.0f);
    return vec3(-a, -b, -1.0f);
}
