// The view as a compute kernel, one invocation per pixel: the work of
// pattern.frag / filtered.frag (with the camera's Jacobian) without the
// graphics pipeline. Datacentre GPUs run fragment shaders on a few units
// only (an H100 has 2 graphics-capable TPCs of 66); compute uses them all.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) writeonly uniform image2D uTarget;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(uViewSize)))) return;
    bool sky;
    vec2 jx, jy;
    vec2 uv = viewUv(vec2(pixel) + 0.5, jx, jy, sky);  // pixel centre, as gl_FragCoord
    imageStore(uTarget, pixel, vec4(sky ? uSky : pixelColour(uv, jx, jy), 1.0));
}
