#include "stochtex/pattern/fields/fields.h"

#include "stochtex/pattern/fields/field_node.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/pattern_members.h"
#include "stochtex/pattern/pattern_parts.h"

namespace stochtex {

NodeInfo spectralNoiseNode() {
    using json = nlohmann::json;
    NodeInfo n{"spectral_noise",
               "source",
               "A periodic Gaussian example synthesised from a power spectrum (paper §3), tiled and blended",
               {},
               PortType::Field,
               {patternMembers().noiseSize,
                {"seed", ParamType::Seed, "Seed of the white noise (default: from the graph seed and the node id)", json()},
                patternMembers().noiseMean,
                patternMembers().noiseStddev,
                {"quadrature", ParamType::Boolean, "The Hilbert partner of the same white noise (a phase shift of π/2)",
                 false},
                {"components", ParamType::Components, "Spectrum components: lowpass, ring or bilobe (docs/PATTERNS.md)",
                 json(), 0, 0, json::parse(R"([{"shape": "lowpass", "cutoff": 8}])")}}};
    n.parsed = [](GraphNode& g, const JsonReader& r) {
        SpectrumSpec& s = g.noise.spectrum;
        g.noise.source = NoiseSpec::Source::Spectrum;
        s.size = int(g.numbers["size"]);
        s.mean = g.numbers["mean"];
        s.stddev = g.numbers["stddev"];
        s.quadrature = g.numbers["quadrature"] != 0;
        g.noise.explicitSeed = g.seed.has_value();
        checkSpectrumSpec(r, s);
    };
    n.fold = [](const FieldFold& f) {
        NoiseSpec ns = f.node.noise;
        ns.spectrum.seed = f.node.seed ? *f.node.seed : f.defaultSeed();
        return buildNoiseExample(ns, f.where);
    };
    return n;
}

}  // namespace stochtex
