// The pattern on a lit object (paper Fig. 15): the mesh's uv scaled by
// uTiling (example periods across the uv square), filtered with the
// footprint of the rasterizer's derivatives, under one directional light.
in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;
uniform float uTiling;
uniform bool uFiltered;
uniform vec3 uLight;  // direction towards the light, normalised
uniform vec3 uEye;
layout(location = 0) out vec4 fragColour;

void main() {
    vec2 uv = vUv * uTiling;
    vec2 jx = dFdx(uv), jy = dFdy(uv);
    vec3 albedo = uFiltered ? filteredColour(uv, jx, jy) : unfilteredColour(uv);
    vec3 n = normalize(vNormal);
    vec3 v = normalize(uEye - vWorld);
    if (dot(n, v) < 0.0) n = -n;  // two-sided: whatever the mesh's winding
    vec3 h = normalize(uLight + v);
    float diffuse = max(dot(n, uLight), 0.0);
    float specular = pow(max(dot(n, h), 0.0), 48.0) * 0.15;
    fragColour = vec4(albedo * (0.25 + 0.75 * diffuse) + vec3(specular), 1.0);
}
