// Value noise from the noise channel (a 256² RGBA texture with mipmaps) and its fractal sum.
float noise2(sampler2D tex, vec2 p) { return textureLod(tex, p / 256.0, 0.0).x; }
float fbm(sampler2D tex, vec2 p) {
    float sum = 0.0, amplitude = 0.5;
    for (int k = 0; k < 5; ++k) {
        sum += amplitude * noise2(tex, p);
        p = mat2(1.6, 1.2, -1.2, 1.6) * p;
        amplitude *= 0.5;
    }
    return sum;
}
