// Triplanar mapping, for surfaces without texture coordinates: the pattern
// projected along x, y and z (uv = the point's other two coordinates:
// (z, y), (x, z), (x, y)), each projection filtered with its own footprint
// (the same projection of the point's screen derivatives), blended by the
// normal's components to the fourth power (sharp transitions where a
// projection stretches). The `scene` shader and the export's
// stochtex_sample_triplanar call it; the three lookups run in the caller's
// control flow, so it needs no derivatives of its own.
vec3 triplanarWeights(vec3 n) {
    vec3 w = pow(abs(n), vec3(4.0));
    return w / (w.x + w.y + w.z);
}

// p in example periods, n the surface normal (any length), dpdx and dpdy
// p's change over one pixel along x and y; filtered false: the pattern at
// each projection's point (unfilteredColour).
vec3 triplanarColour(vec3 p, vec3 n, vec3 dpdx, vec3 dpdy, bool filtered) {
    vec3 w = triplanarWeights(n);
    vec3 cx = filtered ? filteredColour(p.zy, dpdx.zy, dpdy.zy) : unfilteredColour(p.zy);
    vec3 cy = filtered ? filteredColour(p.xz, dpdx.xz, dpdy.xz) : unfilteredColour(p.xz);
    vec3 cz = filtered ? filteredColour(p.xy, dpdx.xy, dpdy.xy) : unfilteredColour(p.xy);
    return cx * w.x + cy * w.y + cz * w.z;
}
