// The footprint estimators' loop (paper §4): a footprint's probes, each
// split between two pyramid levels (trilinear), their texel statistics
// (eq. 8, 12, 17) summed by eq. 9, 14–15, 18–19, the Deliot–Heitz
// substitution and the single-texel rule. Kernel file: GLSL and C++, see
// kernel/glsl.h; written once over a texel source that each host provides:
//
//   struct TexelSource;                                   // the host's: what to read
//   ProbeTexels probeTexels(TexelSource s, coord2 uv, ProbeLevels l);
//       // the texel statistics of levels l.l0 and, when l.w1 > 0, l.l1 at uv
//       // (eq. 8, 12, 17 with the stencil and tile offsets of the unfiltered noise)
//   vec3 levelAverages(TexelSource s, int level);
//       // the level's average within-texel variances and covariance [DH19]
//
// (TexelStats, ProbeTexels: kernel/texel_stats.glsl.) On the GPU the source
// is a pair of tiled noises' pyramids (gpu/shaders/filtering.glsl declares
// it and the two functions, before this file; the pattern's chunk and a
// graph's generated chunk define them over their samplers); on
// the CPU it is the FootprintEstimator's pyramids, with its memoised tile
// lookups (filter/footprint_stats.cpp), and the loop is a template over it.

// Where probe k of a footprint centred at uv sits: uv + t_k·axis, t_k the
// probe's place along the major axis (probePosition), in the host's
// coordinate precision.
inline coord2 probeCentre(coord2 uv, ProbeLayout probes, int k) {
    return uv + coord(probePosition(k, probes.count)) * coord2(probes.axis);
}

// The sub-probes of a probe (the sub-probes estimator, docs/MATH.md): an
// s×s grid over the probe's square — |axis|/N along the major axis, as much
// across it — each read one level finer per halving (λ − log2 s, at least
// 0) with 1/s² of the probe's weight. Eq. 14–15 sum them as they sum
// probes, so the spread of the sub-probes' means, which eq. 12 leaves out
// (the tiles' values are coherent over a footprint smaller than their
// wavelength), enters σ̂². A magnified probe (λ = 0) is not split, nor one
// at the top level (λ = L: the footprint covers the example, whose whole
// statistics it reads; split, its sub-probes would sample level L − 1 at
// points periods apart and add noise where the pattern should be flat).
inline int subProbesPerSide(ProbeLayout probes, int subProbes, int maxLod) {
    return probes.lod > 0.0f && probes.lod < float(maxLod) ? max(subProbes, 1) : 1;
}
inline vec2 subProbeOffset(ProbeLayout probes, int side, int i, int j) {
    vec2 along = probes.axis / float(probes.count);
    vec2 across = vec2(-along.y, along.x);
    return (float(i) + 0.5f - 0.5f * float(side)) / float(side) * along +
           (float(j) + 0.5f - 0.5f * float(side)) / float(side) * across;
}

// A probe's two levels as one texel's statistics: the trilinear blend, its
// weights normalised (w0 + w1 is the probe's share of the footprint; the
// upper level is read only when its weight is > 0).
inline TexelStats blendLevels(ProbeTexels t, ProbeLevels l) {
    TexelStats r;
    r.mean = l.w0 * t.lo.mean;
    r.var = l.w0 * t.lo.var;
    r.cov = l.w0 * t.lo.cov;
    if (l.w1 > 0.0f) {
        r.mean = r.mean + l.w1 * t.hi.mean;
        r.var = r.var + l.w1 * t.hi.var;
        r.cov = r.cov + l.w1 * t.hi.cov;
    }
    float w = l.w0 + l.w1;
    r.mean = r.mean / w;
    r.var = r.var / w;
    r.cov = r.cov / w;
    return r;
}

// A probe's reads with their levels' average within-texel statistics in
// place of theirs (Deliot–Heitz).
inline ProbeTexels deliotHeitzProbe(ProbeTexels t, vec3 averageLo, vec3 averageHi, bool hasCovariance) {
    t.lo = deliotHeitzTexel(t.lo, averageLo, hasCovariance);
    t.hi = deliotHeitzTexel(t.hi, averageHi, hasCovariance);
    return t;
}

// A probe's two level reads as two samples of eq. 14–15, each of its
// level's weight (the upper read only where it weighs). The CPU's zoom rows
// (one probe a pixel) call it directly (FilteredGraph::renderZoomInLanes),
// and between two levels through probeMomentsLanes
// (noise/tiling_blending_lanes.cpp), which repeats it, momentsAbout and
// momentsResult in lanes: a change here goes there too
// (TilingBlendingLanes.ProbeMomentsAreTheKernels fails until it does).
inline Moments momentsAddProbe(Moments sums, ProbeTexels t, ProbeLevels levels) {
    sums = momentsAdd(sums, levels.w0, t.lo.mean, t.lo.var, t.lo.cov);
    if (levels.w1 > 0.0f) sums = momentsAdd(sums, levels.w1, t.hi.mean, t.hi.var, t.hi.cov);
    return sums;
}

// Sub-probes with fine means (docs/MATH.md): a sub-probe's mean is the
// average of a 2×2 grid of reads one level finer than its square (the
// sub-probes' grid of twice the side), its variance and covariance its
// square's, which hold all of the variance within the square. A bilinear
// read is a box convolved with a tent, three times the box's second moment:
// read at the square's level, the sub-probes' means are blurred over their
// neighbours' squares, which lowers the spread that σ̂² adds up and
// smooths μ̂. Reads one level finer, spaced by their own texel, make it
// 1.5× the box's, and their tents, as wide as their spacing on a whole level,
// still tile the square (tents of half-width h spaced by h sum to 1): μ̂
// does not alias as reads narrower than their spacing do (a log2 √3 level
// bias, tried first: docs/RESULTS.md).
STOCHTEX_HOST_TYPE(TexelSource)
inline vec2 fineMean(TexelSource src, coord2 centre, ProbeLayout probes, int side, int s, ProbeLevels meanLevels) {
    vec2 sum = vec2(0.0f);
    for (int q = 0; q < 4; ++q) {
        coord2 p = centre + coord2(subProbeOffset(probes, 2 * side, 2 * (s % side) + q % 2, 2 * (s / side) + q / 2));
        sum = sum + blendLevels(probeTexels(src, p, meanLevels), meanLevels).mean;
    }
    return 0.25f * sum;
}

// μ̂, σ̂², ĉov of the source over the footprint centred at uv with these
// probes (kernel/footprint.glsl: probeLayout), each split into subProbes²
// (1: the paper's estimator), their means from finer reads when
// fineMeans (a probe that is not split reads its own level). One loop
// for every footprint, a single texel included (its statistics are then
// taken as they are, after the loop: a branch around it would make GPU
// lanes run both paths).
STOCHTEX_HOST_TYPE(TexelSource)
inline FootprintMoments footprintEstimate(TexelSource src, coord2 uv, ProbeLayout probes, int maxLod, bool deliotHeitz,
                                          bool hasCovariance, int subProbes, bool fineMeans) {
    int side = subProbesPerSide(probes, subProbes, maxLod);
    float lod = side > 1 ? max(probes.lod - log2Split(float(side)), 0.0f) : probes.lod;
    ProbeLevels levels = probeLevels(lod, maxLod, probes.count * side * side);
    // On level 0 there is nothing finer: the square's own read is its mean.
    bool fine = fineMeans && side > 1 && lod > 0.0f;
    ProbeLevels meanLevels = probeLevels(fine ? max(lod - 1.0f, 0.0f) : lod, maxLod, probes.count * side * side);
    vec3 averageLo = vec3(0.0f);
    vec3 averageHi = vec3(0.0f);
    if (deliotHeitz) {
        averageLo = levelAverages(src, levels.l0);
        averageHi = levelAverages(src, levels.l1);
    }
    Moments sums = momentsAbout(vec2(0.0f));
    TexelStats first;
    first.mean = vec2(0.0f);
    first.var = vec2(0.0f);
    first.cov = 0.0f;
    for (int k = 0; k < probes.count; ++k) {
        coord2 centre = probeCentre(uv, probes, k);
        for (int s = 0; s < side * side; ++s) {
            coord2 p = side > 1 ? centre + coord2(subProbeOffset(probes, side, s % side, s / side)) : centre;
            ProbeTexels t = probeTexels(src, p, levels);
            if (deliotHeitz) t = deliotHeitzProbe(t, averageLo, averageHi, hasCovariance);
            if (fine) {
                // The sub-probe's mean from the finer reads, its (co)variance
                // from its square's: one sample of weight w0 + w1 = 1/count.
                vec2 mean = fineMean(src, centre, probes, side, s, meanLevels);
                TexelStats square = blendLevels(t, levels);
                if (k == 0 && s == 0) sums = momentsAbout(mean);
                sums = momentsAdd(sums, levels.w0 + levels.w1, mean, square.var, square.cov);
            } else {
                if (k == 0 && s == 0) {
                    sums = momentsAbout(t.lo.mean);
                    first = t.lo;
                }
                sums = momentsAddProbe(sums, t, levels);
            }
        }
    }
    if (isSingleTexel(probes.count * side * side, levels.frac)) return texelMoments(first);
    return momentsResult(sums);
}

// The same for a pixel's Jacobian columns jx, jy (uv per pixel): the
// kernel's probe layout with at most `aniso` probes for a W = `texels`
// example (the CPU builds the layout once per zoom instead:
// filter/footprint.cpp).
STOCHTEX_HOST_TYPE(TexelSource)
inline FootprintMoments jacobianEstimate(TexelSource src, coord2 uv, vec2 jx, vec2 jy, float texels, int aniso,
                                         int maxLod, bool deliotHeitz, bool hasCovariance, int subProbes,
                                         bool fineMeans) {
    return footprintEstimate(src, uv, probeLayout(jx, jy, texels, aniso, maxLod), maxLod, deliotHeitz, hasCovariance,
                             subProbes, fineMeans);
}
