// Conway's Game of Life in a feedback buffer: each cell reads its eight
// neighbours in the previous frame. Frame 0 (or key R, code 82, held) seeds
// the board from the noise channel; the mouse, pressed, paints live cells.
float cell(ivec2 p) {
    ivec2 size = ivec2(iResolution.xy);
    return texelFetch(iChannel0, (p + size) % size, 0).x;  // a torus
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    ivec2 p = ivec2(fragCoord);
    bool reset = iFrame == 0 || texelFetch(iChannel2, ivec2(82, 0), 0).x > 0.5;
    if (reset) {
        fragColor = vec4(step(0.7, texelFetch(iChannel1, p % 64, 0).x), 0.0, 0.0, 1.0);
        return;
    }
    float n = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            if (x != 0 || y != 0) n += cell(p + ivec2(x, y));
    float alive = cell(p);
    float next = (n == 3.0 || (alive > 0.5 && n == 2.0)) ? 1.0 : 0.0;
    if (iMouse.z > 0.0 && length(fragCoord - iMouse.xy) < 3.0) next = 1.0;
    // g: how long the cell has lived (for the colours), b: its previous state.
    float age = next > 0.5 ? min(texelFetch(iChannel0, p, 0).y + 0.02, 1.0) : 0.0;
    fragColor = vec4(next, age, alive, 1.0);
}
