// A swirling velocity field: two counter-rotating vortices drifting in time.
vec2 velocity(vec2 uv, float t) {
    vec2 c1 = vec2(0.35 + 0.1 * sin(0.7 * t), 0.5), c2 = vec2(0.65, 0.5 + 0.1 * cos(0.5 * t));
    vec2 d1 = uv - c1, d2 = uv - c2;
    vec2 v1 = vec2(-d1.y, d1.x) / (dot(d1, d1) + 0.02);
    vec2 v2 = vec2(d2.y, -d2.x) / (dot(d2, d2) + 0.02);
    return 0.004 * (v1 + v2);
}
