// A texture graph at each pixel of the view: graphColour is the graph's
// program, generated per graph (gpu/gpu_graph.cpp) and assembled before this
// file; footprints are the camera's exact Jacobian, as on the CPU.
vec3 graphColour(vec2 uv, vec2 jx, vec2 jy);
layout(location = 0) out vec4 fragColour;

void main() {
    bool sky;
    vec2 jx, jy;
    vec2 uv = viewUv(gl_FragCoord.xy, jx, jy, sky);
    fragColour = vec4(sky ? uSky : graphColour(uv, jx, jy), 1.0);
}
