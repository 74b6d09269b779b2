// Fuzz target: texture graphs deep enough to matter. The JSON targets
// mutate text, and a mutated file rarely stays a graph of more than a few
// valid nodes; here the input's bytes choose the graph instead, from the
// node table (graph_nodes.h) alone: each byte-driven step appends a node of
// some type, wires each input port to an earlier node of that port's type
// (or a new source), and sets each parameter to its minimum, its maximum,
// its default or a value in between, so chains of 40 transforms or affines,
// sums of sums and ops over ops are a few bytes away. The graph is written
// as a pattern file and goes the user's way: parse, build, render through
// every filter (fuzz_pipeline.h), and generate its GLSL program.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "fuzz_pipeline.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/pattern/graph_nodes.h"

namespace {

using nlohmann::json;
using namespace stochtex;

constexpr int kMaxNodes = 64;

// The input, read a byte at a time; zeros once it is used up.
class Bytes {
public:
    Bytes(const uint8_t* data, size_t size) : data_(data), size_(size) {}
    bool done() const { return size_ == 0; }
    unsigned byte() {
        if (size_ == 0) return 0;
        --size_;
        return *data_++;
    }
    double unit() { return byte() / 255.0; }
    size_t pick(size_t count) { return count == 0 ? 0 : byte() % count; }

private:
    const uint8_t* data_;
    size_t size_;
};

// A number parameter: its ends and default most of the time (where the
// bugs are), else a point between them, linear or geometric.
double numberValue(const ParamInfo& p, Bytes& in) {
    switch (in.byte() % 6) {
        case 0: return p.min;
        case 1: return p.max;
        case 2: return p.typical();
        case 3: return p.min + in.unit() * (p.max - p.min);
        case 4: {  // geometric, towards whichever end is farther from 0
            const double end = std::abs(p.max) >= std::abs(p.min) ? p.max : p.min;
            return std::clamp(end * std::pow(2.0, -double(in.byte() % 40)), p.min, p.max);
        }
        default: return p.typical() * (in.byte() % 2 ? 2 : 0.5);  // may leave the range: refused
    }
}

// An integer parameter: mostly a power of two in range (sizes must be;
// resolutions and indices take it too), else any value numberValue gives.
long long integerValue(const ParamInfo& p, Bytes& in) {
    const double x = numberValue(p, in);
    if (in.byte() % 4 == 0 || !(x >= 1)) return std::llround(x);
    return std::llround(std::clamp(std::exp2(std::round(std::log2(x))), p.min, p.max));
}

class GraphWriter {
public:
    explicit GraphWriter(Bytes& in) : in_(in) {}

    json write() {
        int steps = 0;
        while (!in_.done() && steps++ < kMaxNodes) {
            const std::vector<NodeInfo>& table = graphNodes();
            add(table[in_.pick(table.size())]);
        }
        // The output: a colour, whatever the last node gives.
        std::string last = ids_.empty() ? source(PortType::Colour) : ids_.back();
        if (typeOf(last) == PortType::Channels) last = add(*findGraphNode("channel"), {{"field", last}});
        if (typeOf(last) == PortType::Field) last = add(*findGraphNode("colormap"), {{"x", last}, {"y", last}});
        json file = {{"name", "fuzz"}, {"seed", in_.byte()}, {"size", 8}, {"nodes", nodes_}, {"output", last}};
        if (in_.byte() % 2) file["offsets"] = "shared";
        if (in_.byte() % 4 == 0) file["scale"] = std::pow(2.0, double(in_.byte() % 24) - 8);
        return file;
    }

private:
    // Appends a node of type `info`: the given inputs, the others from the
    // input's bytes; returns its id.
    std::string add(const NodeInfo& info, const std::map<std::string, std::string>& given = {}) {
        json node = nodeWithSampleParams(info, imageFor(info));
        for (const PortInfo& port : info.inputs) {
            const auto it = given.find(port.name);
            node[port.name] = it != given.end() ? it->second : inputOf(port.type);
        }
        for (const ParamInfo& p : info.params) {
            if (in_.byte() % 3 == 0) continue;  // the default (or sample)
            if (p.type == ParamType::Number)
                node[p.name] = numberValue(p, in_);
            else if (p.type == ParamType::Integer)
                node[p.name] = integerValue(p, in_);
            else if (p.type == ParamType::Boolean)
                node[p.name] = in_.byte() % 2 == 1;
            else if (p.type == ParamType::Seed)
                node[p.name] = in_.byte() * 16777619u;
            else if (p.type == ParamType::Choice)
                node[p.name] = p.choices[in_.pick(p.choices.size())];
        }
        std::string id = "n";  // not "n" + to_string(…), on which GCC 12 warns falsely (-Wrestrict)
        id += std::to_string(ids_.size());
        nodes_[id] = node;
        ids_.push_back(id);
        types_.push_back(info.output);
        return id;
    }

    PortType typeOf(const std::string& id) const {
        return types_[size_t(std::find(ids_.begin(), ids_.end(), id) - ids_.begin())];
    }

    // An earlier node of type t, mostly the latest (chains), else any, else
    // a new source.
    std::string inputOf(PortType t) {
        std::vector<std::string> candidates;
        for (size_t i = 0; i < ids_.size(); ++i)
            if (types_[i] == t) candidates.push_back(ids_[i]);
        if (candidates.empty() || in_.byte() % 8 == 0) return source(t);
        return in_.byte() % 2 ? candidates.back() : candidates[in_.pick(candidates.size())];
    }

    std::string source(PortType t) {
        if (t == PortType::Field) return add(*findGraphNode("spectral_noise"));
        if (t == PortType::Channels) return add(*findGraphNode("tiled_field"));
        return add(*findGraphNode("colour"));
    }

    // An image of the fuzz folder for a node that reads one: a gray one for
    // an exemplar, any for a tiled field.
    std::string imageFor(const NodeInfo& info) {
        static const std::vector<std::string> gray{"gray8.png", "gray16.png", "gray.exr"};
        static const std::vector<std::string> any{"gray8.png", "colormap8.png", "colormap.exr", "gray.exr"};
        const std::vector<std::string>& from = info.output == PortType::Channels ? any : gray;
        return from[in_.pick(from.size())];
    }

    Bytes& in_;
    json nodes_ = json::object();
    std::vector<std::string> ids_;
    std::vector<PortType> types_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace stochtex;
    return fuzz::run([&] {
        Bytes in(data, size);
        const json file = GraphWriter(in).write();
        // STOCHTEX_FUZZ_DUMP=1 prints the graph: a finding as a pattern file to reproduce with the CLI.
        static const bool dump = std::getenv("STOCHTEX_FUZZ_DUMP") != nullptr;
        if (dump) std::fprintf(stderr, "%s\n", file.dump(1).c_str());
        PatternSpec spec = parsePatternSpec(JsonReader(file, "fuzz.json"), fuzz::imagesDir());
        if (!fuzz::shrinkSpec(spec)) return;
        const GraphPattern program = GraphPattern::build(spec);
        fuzz::renderEveryFilter(program, View{spec.width, spec.height, spec.scale});
        (void)graphProgramSource(program);  // a non-finite literal would throw a logic_error (a finding)
    });
}
