// The tiling-and-blending triangle grid (paper eq. 7; Heitz & Neyret 2018,
// Deliot & Heitz 2019). Kernel file: GLSL and C++, see kernel/glsl.h.
//
// The grid lives on uv·density (density 2√3 by default), skewed by
// (u − kGridSkewX·v, kGridSkewY·v): the GLSL `mat2(1, 0, −0.57735027,
// 1.15470054) * uv` convention. Each vertex owns a tile, a copy of the
// example shifted by o = hash(vertex, seed) ∈ [0, 1)²; a point mixes the
// three tiles of its triangle with barycentric weights normalised to
// Σ w² = 1 (variance preserving).

const float kGridSkewX = 0.57735026918962573f;  // 1/√3
const float kGridSkewY = 1.1547005383792515f;   // 2/√3
const float kDefaultGridDensity = 3.4641016151377544f;  // 2√3

// A grid's shape: its cells per example period along u and v (2√3 both by
// default: equilateral triangles) and its period in cells, for tileable
// bakes. With period (n, m), n > 0, the vertices (i, j), (i + n, j) and
// (i − m, j + 2m) are one vertex, with one tile offset: the grid and its
// tiles repeat every n / density.x along u and every √3·m / density.y along
// v (a period of the skewed lattice). (0, 0): no period, the whole plane.
struct GridShape {
    vec2 density;
    ivec2 period;
};

inline GridShape planeGrid(float density) {
    GridShape g;
    g.density = vec2(density, density);
    g.period = ivec2(0, 0);
    return g;
}

// The three tiles seen at a point: the lattice cell (ids wrap modulo 2³², as
// uints do), which triangle of the cell (upper: (1,1), (1,0), (0,1); lower:
// (0,0), (0,1), (1,0)), the normalised weights of its vertices and the
// grid's period (GridShape; its vertices are reduced by it).
struct Stencil {
    uvec2 cell;
    bool upper;
    vec3 w;
    ivec2 period;
};

// The stencil from the skewed coordinate split into its integer cell and its
// fractional part (fx, fy) ∈ [0, 1)², on the plane (no period). The CPU's
// scanline path computes the split in double precision; triangleGrid()
// below computes it in float.
inline Stencil blendStencil(uvec2 cell, float fx, float fy) {
    Stencil s;
    s.cell = cell;
    float fz = 1.0f - fx - fy;
    s.upper = !(fz > 0.0f);
    s.w = s.upper ? vec3(-fz, 1.0f - fy, 1.0f - fx) : vec3(fz, fy, fx);
    float norm = 1.0f / sqrt(s.w.x * s.w.x + s.w.y * s.w.y + s.w.z * s.w.z);
    s.w = s.w * norm;
    s.period = ivec2(0, 0);
    return s;
}

// The stencil at uv (any real uv) on the grid g.
inline Stencil triangleGrid(vec2 uv, GridShape g) {
    float sv = uv.y * g.density.y;
    float y = kGridSkewY * sv;
    float x = uv.x * g.density.x - kGridSkewX * sv;
    float bx = floor(x);
    float by = floor(y);
    Stencil s = blendStencil(uvec2(ivec2(int(bx), int(by))), x - bx, y - by);
    s.period = g.period;
    return s;
}

// floor(a / b) for b > 0, dividing non-negative numbers only (GLSL leaves
// the division of negative integers to the implementation).
inline int floorDivision(int a, int b) {
    return a >= 0 ? a / b : -((b - 1 - a) / b);
}

// The representative of vertex v modulo the grid's period (n, m): the one
// with 0 ≤ j < 2m and 0 ≤ i < n, the same for every copy of the vertex.
inline uvec2 periodicVertex(uvec2 v, ivec2 period) {
    int i = int(v.x);
    int j = int(v.y);
    int k = floorDivision(j, 2 * period.y);
    j -= 2 * period.y * k;
    i += period.y * k;
    i -= period.x * floorDivision(i, period.x);
    return uvec2(ivec2(i, j));
}

// Vertex i ∈ {0, 1, 2} of the stencil's triangle (its representative on a
// periodic grid).
inline uvec2 stencilVertex(Stencil s, int i) {
    uint dx = s.upper ? uint(i < 2) : uint(i == 2);
    uint dy = s.upper ? uint(i != 1) : uint(i == 1);
    uvec2 v = s.cell + uvec2(dx, dy);
    return s.period.x > 0 ? periodicVertex(v, s.period) : v;
}

// The random offset of a vertex's tile, in [0, 1)² (one example period).
inline vec2 tileOffset(uvec2 vertex, uint seed) {
    uvec3 h = pcg3d(uvec3(vertex.x, vertex.y, seed));
    return vec2(unitFloat(h.x), unitFloat(h.y));
}

// One texel footprint at level l (level 0: one point), weights w_i of the
// stencil at its centre:
//   N̂_l = μ + Σ w_i (E_{l,i} − μ)   (eq. 8, mean-centred as eq. 7)
//   σ̂²_l = Σ w_i² V_{l,i}            (eq. 12; covariances Σ w_i² C_{l,i}, eq. 17)
// Eq. 8 (and eq. 7 at level 0): terms added in vertex order.
inline float blendMean(float mean, vec3 w, vec3 e) {
    float n = mean;
    n += w.x * (e.x - mean);
    n += w.y * (e.y - mean);
    n += w.z * (e.z - mean);
    return n;
}

// Eq. 12 and 17: the tiles are taken as uncorrelated, weights constant over P.
inline float blendVariance(vec3 w, vec3 v) {
    return w.x * w.x * v.x + w.y * w.y * v.y + w.z * w.z * v.z;
}
