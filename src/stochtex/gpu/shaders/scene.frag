// The pattern on a lit object (paper Fig. 15): the mesh's uv scaled by
// uTiling (example periods across the uv square), filtered with the
// footprint of the rasterizer's derivatives, under one directional light.
// A program that lights its own colour (a lean op: the lean response of a
// normal map, paper §6.5) is drawn as it is, lit by the same light.
#include "stochtex/kernel/colour.glsl"
in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;
uniform float uTiling;
uniform bool uFiltered;
uniform vec3 uLight;  // direction towards the light, normalised
uniform vec3 uEye;
layout(location = 0) out vec4 fragColour;

uniform bool uShadesLight;  // the program lights its own colour (GpuView::shadesLight): it is the whole colour
uniform bool uTriplanar;    // three projections along the axes instead of the mesh's uv
// Linear light for a float target (the C++ host encodes the image), sRGB
// codes for an 8-bit surface shown as is (the web page's canvas).
uniform bool uEncodeSrgb;

vec4 sceneColour(vec3 linear) {
    return vec4(uEncodeSrgb ? srgbFromLinear3(linear) : linear, 1.0);
}

// Light and eye in the surface's tangent frame for the lean response: T
// along ∂p/∂u (from the screen derivatives of position and uv), the normal
// n as z, B = n × T, so that the normal map's slopes tilt the surface about
// its own frame. The eye is kept a little above the tangent plane (the
// lobe's reflection divides by its z).
vec3 leanShaded(vec2 uv, vec2 jx, vec2 jy, vec3 n, vec3 v) {
    vec3 dpx = dFdx(vWorld), dpy = dFdy(vWorld);
    vec3 t = cross(dpy, n) * jx.x + cross(n, dpx) * jy.x;
    t = t - n * dot(n, t);
    t = dot(t, t) > 0.0 ? normalize(t) : normalize(cross(n, vec3(0.6, 0.0, 0.8)));  // degenerate uv (a pole)
    vec3 b = cross(n, t);
    vec3 l = vec3(dot(uLight, t), dot(uLight, b), dot(uLight, n));
    vec3 e = vec3(dot(v, t), dot(v, b), max(dot(v, n), 0.05));
    gEyeDirection = normalize(e);
    gLightDirection = vec4(l, 1.0);
    if (l.z <= 0.0) return vec3(0.0);  // the light is behind the surface
    return uFiltered ? filteredColour(uv, jx, jy) : unfilteredColour(uv);
}

void main() {
    vec2 uv = vUv * uTiling;
    vec2 jx = dFdx(uv), jy = dFdy(uv);
    vec3 n = normalize(vNormal);
    vec3 v = normalize(uEye - vWorld);
    if (dot(n, v) < 0.0) n = -n;  // two-sided: whatever the mesh's winding
    if (uShadesLight) {
        fragColour = sceneColour(leanShaded(uv, jx, jy, n, v));
        return;
    }
    // Triplanar (triplanar.glsl): uTiling periods across the object's 2-unit size.
    vec3 p = vWorld * (0.5 * uTiling);
    vec3 albedo = uTriplanar ? triplanarColour(p, vNormal, dFdx(p), dFdy(p), uFiltered)
                             : (uFiltered ? filteredColour(uv, jx, jy) : unfilteredColour(uv));
    vec3 h = normalize(uLight + v);
    float diffuse = max(dot(n, uLight), 0.0);
    float specular = pow(max(dot(n, h), 0.0), 48.0) * 0.15;
    fragColour = sceneColour(albedo * (0.25 + 0.75 * diffuse) + vec3(specular));
}
