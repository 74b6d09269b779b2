#include "stochtex/pattern/pattern_spec.h"

#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/pattern/pattern_members.h"
#include "stochtex/pattern/texture_graph.h"
#include "stochtex/pattern/view.h"

namespace stochtex {
namespace fs = std::filesystem;

PatternSpec parsePatternSpec(const JsonReader& r, const fs::path& baseDir) {
    const bool graph = r.value().is_object() && r.has("nodes");
    if (graph)
        r.expectObject({"name", "description", "seed", "size", "scale", "offsets", "grid_density", "estimator", "nodes",
                        "output"});
    else
        r.expectObject({"name", "description", "seed", "size", "scale", "offsets", "grid_density", "estimator",
                        "noise_x", "noise_y", "colormap", "normal_map"});
    PatternSpec spec;
    spec.name = r.string("name", "pattern");
    if (r.has("description")) (void)r.at("description").string();
    spec.seed = r.uint32("seed", 1);
    if (auto size = r.find("size")) {
        if (size->value().is_array()) {
            if (size->arraySize() != 2) size->fail("size is N or [width, height]");
            spec.width = size->at(0).integer(1, kMaxOutputSide);
            spec.height = size->at(1).integer(1, kMaxOutputSide);
        } else {
            spec.width = spec.height = size->integer(1, kMaxOutputSide);
        }
    }
    spec.scale = readNumber(r, patternMembers().scale);
    // The output caps (pixel count) are the renderer's: the pattern's own view must pass them.
    r.check([&] { validateView(View{spec.width, spec.height, spec.scale}); });
    spec.gridDensity = readNumber(r, patternMembers().gridDensity);
    if (auto e = r.find("estimator")) spec.estimator = e->choice(kVarianceEstimatorNames);
    if (graph) {
        auto g = std::make_shared<TextureGraph>(parseTextureGraph(r, baseDir));
        spec.colormap = g->node(g->output).colormap;
        spec.offsets = r.choice("offsets", OffsetMode::Independent, kOffsetModeNames);
        spec.graph = std::move(g);
        return spec;
    }

    spec.noise[0] = parseNoiseSpec(r.at("noise_x"), baseDir);
    const JsonReader ny = r.at("noise_y");
    bool quadrature = false;
    if (ny.value().is_string()) {
        if (ny.string() != "quadrature")
            ny.fail("expected a noise object or \"quadrature\" (the Hilbert pair of noise_x)");
        if (spec.noise[0].source != NoiseSpec::Source::Spectrum) ny.fail("\"quadrature\" needs a spectrum noise_x");
        spec.noise[1] = spec.noise[0];
        spec.noise[1].spectrum.quadrature = !spec.noise[0].spectrum.quadrature;
        quadrature = true;
        spec.quadraturePair = true;
    } else {
        spec.noise[1] = parseNoiseSpec(ny, baseDir);
    }
    // A quadrature pair only stays in quadrature if both share the tiling offsets.
    spec.offsets = r.choice("offsets", quadrature ? OffsetMode::Shared : OffsetMode::Independent, kOffsetModeNames);
    spec.colormap = parseColormapSpec(r.at("colormap"), baseDir);
    if (auto nm = r.find("normal_map")) spec.normalMap = parseNormalMapSpec(*nm, baseDir);
    return spec;
}

PatternSpec loadPatternFile(const std::string& path) {
    const nlohmann::json j = readJsonFile(path);
    const fs::path base = fs::path(path).has_parent_path() ? fs::path(path).parent_path() : fs::path(".");
    return parsePatternSpec(JsonReader(j, path), base);
}

View patternView(const PatternSpec& spec, std::span<const int> size, std::optional<double> scale,
                 std::span<const double> offset, ViewUse use) {
    View v;
    v.width = spec.width;
    v.height = spec.height;
    v.scale = scale.value_or(spec.scale);
    if (!size.empty()) {
        if (size.size() > 2)
            throw InputError::parameter(
                "size", "must be N or (width, height), got " + std::to_string(size.size()) + " numbers");
        v.width = size[0];
        v.height = size.size() > 1 ? size[1] : size[0];
    }
    if (!offset.empty()) {
        if (offset.size() != 2)
            throw InputError::parameter("offset",
                                        "must be (u, v) in texels, got " + std::to_string(offset.size()) + " numbers");
        v.offsetU = offset[0];
        v.offsetV = offset[1];
    }
    validateView(v, use);
    return v;
}

uint32_t noiseSeed(const PatternSpec& spec, int axis) {
    const NoiseSpec& n = spec.noise[axis];
    if (n.explicitSeed) return n.spectrum.seed;
    // A quadrature partner shares its partner's white noise.
    if (axis == 1 && spec.quadraturePair) return noiseSeed(spec, 0);
    return deriveSeed(spec.seed, 100u + uint32_t(axis));
}

}  // namespace stochtex
