#include "stochtex/pattern/ops/ops.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <utility>

#include "stochtex/pattern/part_cache.h"
#include "stochtex/pattern/pattern_parts.h"

namespace stochtex {

namespace {

template <size_t I>
using OpAt = std::tuple_element_t<I, OpList::Tuple>;
constexpr size_t kOpCount = std::tuple_size_v<OpList::Tuple>;

// The op whose Params is P.
template <class P, size_t I = 0>
constexpr size_t indexOfParams() {
    static_assert(I < kOpCount, "not the Params of a listed op");
    if constexpr (std::is_same_v<typename OpAt<I>::Params, P>)
        return I;
    else
        return indexOfParams<P, I + 1>();
}

// The GLSL emitter writes a Params as its struct's constructor from its
// floats in declaration order: each must be floats only.
template <size_t... I>
constexpr bool floatsOnly(std::index_sequence<I...>) {
    return ((std::is_standard_layout_v<typename OpAt<I>::Params> &&
             sizeof(typename OpAt<I>::Params) % sizeof(float) == 0 &&
             alignof(typename OpAt<I>::Params) == alignof(float)) &&
            ...);
}
static_assert(floatsOnly(std::make_index_sequence<kOpCount>{}), "an op's Params holds floats only");

}  // namespace

std::vector<NodeInfo> opNodeInfos() {
    std::vector<NodeInfo> infos;
    [&]<size_t... I>(std::index_sequence<I...>) { (infos.push_back(OpAt<I>::info()), ...); }
    (std::make_index_sequence<kOpCount>{});
    for (size_t k = 0; k < infos.size(); ++k) infos[k].op = int(k);
    return infos;
}

OpParams bindOp(int op, OpBuild& build) {
    OpParams params;
    const bool found = [&]<size_t... I>(std::index_sequence<I...>) {
        return ((size_t(op) == I ? (params.emplace<I>(OpAt<I>::bind(build)), true) : false) || ...);
    }
    (std::make_index_sequence<kOpCount>{});
    if (!found) throw std::invalid_argument("bindOp: no op " + std::to_string(op));
    return params;
}

kernel::vec3 opPoint(const OpParams& op, kernel::vec3 a, kernel::vec3 b, kernel::vec3 c, const kernel::OpContext& ctx) {
    return std::visit([&](const auto& p) { return kernel::opPoint(p, a, b, c, ctx); }, op);
}

kernel::vec3 opFiltered(const OpParams& op, kernel::vec3 a, kernel::vec3 b, kernel::vec3 c,
                        const kernel::OpContext& ctx) {
    return std::visit([&](const auto& p) { return kernel::opFiltered(p, a, b, c, ctx); }, op);
}

void opPointRow(const OpParams& op, const kernel::vec3* a, const kernel::vec3* b, const kernel::vec3* c,
                kernel::vec3* out, int n, const kernel::OpContext& ctx) {
    // A lookup's opPoint is its table at (a.x, b.x): a row of them is one
    // row of table lookups, tapped in lanes.
    if (n > 1 && ctx.pointTable && opPointIsLookup(op)) {
        static_assert(sizeof(kernel::vec3) == 3 * sizeof(float), "rows of vec3 are rows of floats, stride 3");
        ctx.pointTable->sampleRow(&a->x, &b->x, 3, &out->x, size_t(n));
        return;
    }
    std::visit(
        [&](const auto& p) {
            for (int i = 0; i < n; ++i) out[i] = kernel::opPoint(p, a[i], b[i], c[i], ctx);
        },
        op);
}

namespace {

// The ops' yes/no traits, one row per op (the variant's index): each is a
// `static constexpr bool` an op may declare, false where it does not.
struct OpTraits {
    bool shadesLight = false;  // kShadesLight
    bool plainLookup = false;  // kPlainLookup
    bool pointLookup = false;  // kPointLookup, or kPlainLookup
};
template <size_t I>
constexpr OpTraits traitsOf() {
    using Op = OpAt<I>;
    OpTraits t;
    if constexpr (requires { Op::kShadesLight; }) t.shadesLight = Op::kShadesLight;
    if constexpr (requires { Op::kPlainLookup; }) t.plainLookup = Op::kPlainLookup;
    if constexpr (requires { Op::kPointLookup; }) t.pointLookup = Op::kPointLookup;
    t.pointLookup = t.pointLookup || t.plainLookup;
    return t;
}
constexpr auto kOpTraits = []<size_t... I>(std::index_sequence<I...>) {
    return std::array<OpTraits, kOpCount>{traitsOf<I>()...};
}
(std::make_index_sequence<kOpCount>{});

}  // namespace

bool opShadesLight(const OpParams& op) { return kOpTraits[op.index()].shadesLight; }

bool opIsPlainLookup(const OpParams& op) { return kOpTraits[op.index()].plainLookup; }

bool opPointIsLookup(const OpParams& op) { return kOpTraits[op.index()].pointLookup; }

nlohmann::json opManifest(const OpParams& op) {
    return std::visit(
        [](const auto& p) {
            using Op = OpAt<indexOfParams<std::decay_t<decltype(p)>>()>;
            if constexpr (requires { Op::manifest(p); })
                return Op::manifest(p);
            else
                return nlohmann::json();
        },
        op);
}

std::vector<std::string> opManifestTypes() {
    std::vector<std::string> types;
    [&]<size_t... I>(std::index_sequence<I...>) {
        ((requires(const typename OpAt<I>::Params& p) { OpAt<I>::manifest(p); } ? types.push_back(OpAt<I>::info().name)
                                                                                : void()),
         ...);
    }
    (std::make_index_sequence<kOpCount>{});
    return types;
}

ColormapTable OpBuild::colormap(const ColormapSpec& spec) const { return *colormapPart(parts, spec); }

double shortestDecimal(float v) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, v).ptr;
    return std::stod(std::string(text, end));
}

const char* opKernelStem(const OpParams& op) {
    return std::visit([](const auto& p) { return OpAt<indexOfParams<std::decay_t<decltype(p)>>()>::kKernel; }, op);
}

std::string glslFloat(float v) {
    // GLSL has no literal for inf or NaN ("inf.0" fails to compile): every
    // number that reaches the program is bounded where it is parsed, so one
    // here is a bug, not an input.
    if (!std::isfinite(v)) throw std::logic_error("glslFloat: non-finite value " + std::to_string(v));
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", double(v));
    std::string s = buffer;
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

// The GLSL name of an op's Params: "colormap_field_op" → "ColormapFieldParams".
std::string paramsStructName(std::string_view stem) {
    std::string name;
    bool upper = true;
    for (const char c : stem.substr(0, stem.size() - 3)) {  // without "_op"
        if (c == '_') {
            upper = true;
            continue;
        }
        name += upper ? char(std::toupper(static_cast<unsigned char>(c))) : c;
        upper = false;
    }
    return name + "Params";
}

std::string opGlslCall(const OpParams& op, bool filtered, const std::string& a, const std::string& b,
                       const std::string& c, const std::string& ctx) {
    return std::visit(
        [&](const auto& p) {
            using P = std::decay_t<decltype(p)>;
            std::string s = std::string(filtered ? "opFiltered(" : "opPoint(") +
                            paramsStructName(OpAt<indexOfParams<P>()>::kKernel) + "(";
            float f[sizeof(P) / sizeof(float)];
            std::memcpy(f, &p, sizeof(P));
            for (size_t k = 0; k < std::size(f); ++k) s += (k ? ", " : "") + glslFloat(f[k]);
            return s + "), " + a + ", " + b + ", " + c + ", " + ctx + ")";
        },
        op);
}

}  // namespace stochtex
