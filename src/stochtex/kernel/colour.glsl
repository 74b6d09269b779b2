// The sRGB transfer function (IEC 61966-2-1), the one pair every colour
// input and output goes through (docs/MATH.md, "Colour space"): colours in
// pattern files and colormap images are sRGB-encoded, every average and
// blend works on linear values, integer image files and the window hold
// sRGB codes. The exact piecewise curve, not a 2.2 power: a linear segment
// below 0.0031308 (encoded 0.04045), a 2.4 power above. Arguments are
// clamped to [0, 1] (an encoded value outside that has no meaning).

inline float srgbFromLinear(float v) {
    float x = clamp(v, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * pow(x, 1.0f / 2.4f) - 0.055f;
}

inline float linearFromSrgb(float c) {
    float x = clamp(c, 0.0f, 1.0f);
    return x <= 0.04045f ? x / 12.92f : pow((x + 0.055f) / 1.055f, 2.4f);
}

inline vec3 srgbFromLinear3(vec3 v) {
    return vec3(srgbFromLinear(v.x), srgbFromLinear(v.y), srgbFromLinear(v.z));
}
