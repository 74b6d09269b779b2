// A height field raymarched under a moving camera: fixed steps along the
// ray until it passes under the terrain, then a bisection; fog and a sky.
float height(vec2 p) { return 2.0 * fbm(iChannel0, p * 0.4); }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 eye = vec3(0.0, 2.6, iTime * 1.5);
    vec3 dir = normalize(vec3(uv.x, uv.y - 0.35, 1.5));
    vec3 sky = mix(vec3(0.75, 0.85, 1.0), vec3(0.3, 0.5, 0.9), clamp(uv.y, 0.0, 1.0));
    float t = 0.0, previous = 0.0;
    bool hit = false;
    for (int k = 0; k < 96 && t < 40.0; ++k) {
        vec3 p = eye + t * dir;
        if (p.y < height(p.xz)) { hit = true; break; }
        previous = t;
        t += 0.05 + 0.02 * t;
    }
    if (!hit) { fragColor = vec4(sky, 1.0); return; }
    for (int k = 0; k < 6; ++k) {  // bisect between the last point above and the first below
        float mid = 0.5 * (previous + t);
        vec3 p = eye + mid * dir;
        if (p.y < height(p.xz)) t = mid; else previous = mid;
    }
    vec3 p = eye + t * dir;
    vec2 e = vec2(0.05, 0.0);
    vec3 n = normalize(vec3(height(p.xz - e.xy) - height(p.xz + e.xy), 2.0 * e.x, height(p.xz - e.yx) - height(p.xz + e.yx)));
    vec3 rock = mix(vec3(0.35, 0.3, 0.25), vec3(0.9), smoothstep(1.3, 1.5, p.y));
    vec3 colour = rock * (0.2 + 0.8 * max(dot(n, normalize(vec3(0.6, 0.7, -0.3))), 0.0));
    fragColor = vec4(mix(colour, sky, 1.0 - exp(-0.06 * t)), 1.0);
}
