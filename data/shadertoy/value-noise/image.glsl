// Value noise: hashed lattice values under a C1 (smoothstep) interpolant, two
// octaves, drifting right. Each instance (the uniform uSeed) hashes another
// lattice, so the frames of instances 0…N−1 are N draws of one stationary
// random field: statistics over them give its mean, variance and
// autocorrelation (a bump a cell wide, squarish from the separable kernel).

// pcg3d (Jarzynski and Olano 2020), first component.
uint pcg(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v.x;
}

float lattice(ivec2 c, int octave) { return float(pcg(uvec3(ivec3(c, 2 * uSeed + octave))) >> 8) / 16777216.0; }

float valueNoise(vec2 p, int octave) {
    vec2 i = floor(p), f = p - i;
    vec2 s = f * f * (3.0 - 2.0 * f);
    ivec2 c = ivec2(i);
    float bottom = mix(lattice(c, octave), lattice(c + ivec2(1, 0), octave), s.x);
    float top = mix(lattice(c + ivec2(0, 1), octave), lattice(c + ivec2(1, 1), octave), s.x);
    return mix(bottom, top, s.y);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = fragCoord / 12.0 + vec2(0.25 * iTime, 0.0);  // 12-pixel cells, a quarter cell per second
    float v = 0.7 * valueNoise(p, 0) + 0.3 * valueNoise(2.0 * p + 0.5, 1);
    fragColor = vec4(vec3(v), 1.0);
}
