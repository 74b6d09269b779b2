#pragma once
// The ops: every node type evaluated per pixel (ops/op_host.h says what an
// op is). This file is their one list — OpList below — from which the node
// table (graph_nodes.h: `stochtex nodes`, the parser, the workbench's
// widgets, the per-node benchmarks), the CPU dispatch (opPoint,
// opFiltered) and the GLSL emitter (opGlslCall, opKernelStem) are derived.
// A new op is its kernel file (<name>_op.glsl), its header (<name>_op.h:
// node description and `bind`, the typed parameters from a node) and its
// line here, with its include.
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "stochtex/pattern/ops/affine_op.h"
#include "stochtex/pattern/ops/colormap_field_op.h"
#include "stochtex/pattern/ops/colormap_op.h"
#include "stochtex/pattern/ops/colour_op.h"
#include "stochtex/pattern/ops/compose_op.h"
#include "stochtex/pattern/ops/curve_op.h"
#include "stochtex/pattern/ops/lean_op.h"
#include "stochtex/pattern/ops/mix_op.h"
#include "stochtex/pattern/ops/op_host.h"
#include "stochtex/pattern/ops/product_op.h"
#include "stochtex/pattern/ops/square_op.h"
#include "stochtex/pattern/ops/sum_op.h"
#include "stochtex/pattern/ops/surface_op.h"
#include "stochtex/pattern/ops/threshold_op.h"

namespace stochtex {

template <class... Ops>
struct OpTypes {
    using Tuple = std::tuple<Ops...>;
    using Params = std::variant<typename Ops::Params...>;
};
// The list, in the order `stochtex nodes` shows them after the sources and linear nodes.
using OpList = OpTypes<AffineOp, SumOp, ProductOp, SquareOp, ColormapOp, ColormapFieldOp, CurveOp, ThresholdOp,
                       ColourOp, MixOp, ComposeOp, LeanOp, SurfaceOp>;

// One op's typed parameters; the alternative's index is the op (NodeInfo::op).
using OpParams = OpList::Params;

// The index of an op in the list (NodeInfo::op).
template <class Op, size_t I = 0>
constexpr int opIndex() {
    static_assert(I < std::tuple_size_v<OpList::Tuple>, "not a listed op");
    if constexpr (std::is_same_v<std::tuple_element_t<I, OpList::Tuple>, Op>)
        return int(I);
    else
        return opIndex<Op, I + 1>();
}

// Each op's node description, its `op` set to its index in the list.
std::vector<NodeInfo> opNodeInfos();
// The parameters of op `op` for a node of its type; its table, if it has
// one, added to build.tables. InputError naming the parameter when they are
// unusable.
OpParams bindOp(int op, OpBuild& build);

// The op on its inputs' values, and on their footprint moments (op_host.h).
kernel::vec3 opPoint(const OpParams& op, kernel::vec3 a, kernel::vec3 b, kernel::vec3 c, const kernel::OpContext& ctx);
kernel::vec3 opFiltered(const OpParams& op, kernel::vec3 a, kernel::vec3 b, kernel::vec3 c,
                        const kernel::OpContext& ctx);
// opPoint at n pixels, the op chosen once: out[i] = opPoint(op, a[i], b[i], c[i], ctx)
// (a plain lookup's row, its table's sampleRow: taps in SIMD lanes).
void opPointRow(const OpParams& op, const kernel::vec3* a, const kernel::vec3* b, const kernel::vec3* c,
                kernel::vec3* out, int n, const kernel::OpContext& ctx);

// Whether the op lights its colour: it reads OpContext's eye and light (an
// op declares `static constexpr bool kShadesLight = true`; false otherwise).
bool opShadesLight(const OpParams& op);
// Whether the op's point value is its table at its two inputs (x, y), and
// its filtered value the prefiltered table at their moments: over one pair
// of leaves, the program is a plain pattern's H ∘ N, which the evaluators
// run through one lookup (GraphPattern::plainColormap; an op declares
// `static constexpr bool kPlainLookup = true`).
bool opIsPlainLookup(const OpParams& op);
// Whether the op's point value is its table at its two inputs (x, y), so
// that a row of them is one row of table lookups (opPointRow): every plain
// lookup, and an op that declares `static constexpr bool kPointLookup =
// true` (a colormap read as a field, whose filtered value is not a lookup).
bool opPointIsLookup(const OpParams& op);
// What an engine reads of the op beside the generated GLSL, for an export's
// manifest.json (an op declares `static nlohmann::json manifest(const
// Params&)`, e.g. a lean op's light; null otherwise).
nlohmann::json opManifest(const OpParams& op);
// The node types of the ops that declare a manifest entry ("lean"): the
// export's manifest has a list under each, empty or not.
std::vector<std::string> opManifestTypes();
// The embedded kernel file that defines the op (the GPU program includes it).
const char* opKernelStem(const OpParams& op);
// The GLSL call of the op: "opPoint(AffineParams(2.0, 0.5), a, b, c, ctx)"
// (opFiltered when filtered), the arguments being GLSL expressions.
std::string opGlslCall(const OpParams& op, bool filtered, const std::string& a, const std::string& b,
                       const std::string& c, const std::string& ctx);
// The GLSL name of the Params of the op whose kernel file is `stem`:
// "colormap_field_op" → "ColormapFieldParams" (an op's header names only its file).
std::string paramsStructName(std::string_view stem);
// A float as a GLSL literal that reads back as the same float.
std::string glslFloat(float v);

}  // namespace stochtex
