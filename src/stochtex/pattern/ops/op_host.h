#pragma once
// What an op (ops/ops.h) is given and may call, on the C++ side.
//
// An op is one node type evaluated per pixel: its kernel file
// (ops/<name>_op.glsl, GLSL that also compiles as C++ over glm, as the
// kernel's files do) declares its typed parameters, `struct <Name>Params`
// (floats only: the GLSL emitter writes them as the struct's constructor, in
// declaration order), and two overloads of one fixed signature:
//
//   vec3 opPoint(<Name>Params p, vec3 a, vec3 b, vec3 c, OpContext ctx);     // values
//   vec3 opFiltered(<Name>Params p, vec3 a, vec3 b, vec3 c, OpContext ctx);  // footprint moments
//
// a, b, c are the op's inputs in its node's port order (vec3(0) when it has
// fewer); a field is vec3(value, 0, 0) in points and vec3(mean, variance, 0)
// filtered, a colour its value or footprint mean. The shading context (eye,
// light) and the op's table come through OpContext, which each host
// declares with the two table lookups, opTable and opPrefiltered: here over
// the evaluator's tables (OpTableLookup), on the GPU as a generated chunk
// over the graph's samplers (gpu/gpu_graph.cpp).
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "stochtex/image/image.h"
#include "stochtex/kernel/glsl.h"
#include "stochtex/kernel/graph_ops.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/node_info.h"
#include "stochtex/pattern/prefiltered_colormap.h"

// An op's header includes its kernel file between these: inside the
// kernel's namespace, where GLSL's fixed signature names parameters that an
// op may not use.
#define STOCHTEX_OP_KERNEL_BEGIN \
    namespace stochtex::kernel { \
    _Pragma("GCC diagnostic push") _Pragma("GCC diagnostic ignored \"-Wunused-parameter\"")
#define STOCHTEX_OP_KERNEL_END    \
    _Pragma("GCC diagnostic pop") \
    }

namespace stochtex {

class PartCache;  // pattern/part_cache.h

namespace kernel {

// The tables of an evaluator, by index (the op's OpContext::table).
struct OpTableLookup {
    virtual ~OpTableLookup() = default;
    virtual vec3 point(int table, vec2 xy) const = 0;                    // the table at xy
    virtual vec3 prefiltered(int table, vec2 xy, vec2 sigma) const = 0;  // its prefiltered table
};

struct OpContext {
    int table = -1;          // the op's table, −1: none
    vec3 eye{0, 0, 1};       // unit direction towards the eye, texture frame
    vec4 light{0, 0, 0, 0};  // w ≠ 0: the host's own light (a scene's), which replaces an op's; w = 0: none
    float slopeCov = 0;      // covariance of the pair of leaves an op's first input is in (estimated only when read)
    // The op's tables themselves where the host holds them (the CPU
    // evaluators): read inline, without the lookup's virtual call (an
    // unfiltered graph render took 13 % less time without it, in one run of
    // BM_FoldingGraphVsPattern before its one-lookup shortcut). Null: read
    // through `tables` (the kernel parity test's known functions of xy).
    const ColormapTable* pointTable = nullptr;
    const PrefilteredColormap* prefilteredTable = nullptr;
    const OpTableLookup* tables = nullptr;
};
inline vec3 opTable(OpContext c, vec2 xy) {
    if (!c.pointTable) return c.tables->point(c.table, xy);
    const Rgb r = c.pointTable->sample(xy.x, xy.y);
    return vec3(r[0], r[1], r[2]);
}
inline vec3 opPrefiltered(OpContext c, vec2 xy, vec2 sigma) {
    if (!c.prefilteredTable) return c.tables->prefiltered(c.table, xy, sigma);
    const Rgb r = c.prefilteredTable->sample(xy.x, xy.y, sigma.x, sigma.y);
    return vec3(r[0], r[1], r[2]);
}

}  // namespace kernel

// A table an op reads: a colour per entry (a colormap) or, for a field,
// (g, g², 0) per entry (kernel momentEntry), so that one prefiltered lookup
// gives E[g] and E[g²]; a 1D table has two identical rows.
struct OpTable {
    ColormapTable point;    // what the unfiltered evaluation reads
    ColormapTable blended;  // the same with the inverse histogram transforms of Gaussianized leaf inputs folded in
    bool field = false;
    // Its axes whose input is a field bounded in [0, 1], prefiltered as a
    // Beta (set once the program's ranges are known, GraphPattern::build).
    BetaAxes beta{false, false};
};

// A table as an image of its entries, each through `entry(i, j)` (Rx×Ry×3).
template <class EntryFn>
ColormapTable tabulate(int rx, int ry, EntryFn&& entry) {
    Image t(rx, ry, 3, Image::Uninitialized{});
    for (int j = 0; j < ry; ++j)
        for (int i = 0; i < rx; ++i) {
            const kernel::vec3 e = entry(i, j);
            t.at(i, j, 0) = e.x;
            t.at(i, j, 1) = e.y;
            t.at(i, j, 2) = e.z;
        }
    return ColormapTable(t);
}

// What an op's `bind` reads and adds while a graph is built.
struct OpBuild {
    const GraphNode& node;
    // The Gaussianized exemplar that an input port reads directly (as a
    // leaf), or null: only a table op may read one, through its table.
    std::function<const NoiseExample*(const std::string& port)> gaussianizedInput;
    std::vector<OpTable>& tables;
    int table = -1;              // the table the op added
    PartCache* parts = nullptr;  // where the build keeps its parts (GraphPattern::build), or none

    // The table of a colormap spec: the kept one, or built (buildColormap).
    ColormapTable colormap(const ColormapSpec& spec) const;

    void addTable(OpTable t) {
        tables.push_back(std::move(t));
        table = int(tables.size()) - 1;
    }
    float number(const std::string& name) const { return float(node.numbers.at(name)); }
};

// A float as the shortest decimal that reads back as it (0.08, not
// 0.0799999982), for JSON (an op's manifest, ops.h).
double shortestDecimal(float v);

}  // namespace stochtex
