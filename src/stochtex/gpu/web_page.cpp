#include "stochtex/gpu/web_page.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "stochtex/core/atomic_file.h"
#include "stochtex/core/base64.h"
#include "stochtex/core/embedded_file.h"
#include "stochtex/core/error.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/gpu/packed_stats.h"
#include "stochtex/gpu/programs.h"
#include "stochtex/gpu/scene.h"
#include "stochtex/gpu/shader.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/part_cache.h"

namespace stochtex {

extern const EmbeddedFile kEmbeddedWeb[];
extern const std::size_t kEmbeddedWebCount;

namespace fs = std::filesystem;

namespace {

// WebGL 2's guaranteed fragment texture units.
constexpr int kWebTextureUnits = 16;

const char* webFile(const std::string& stem) {
    for (std::size_t i = 0; i < kEmbeddedWebCount; ++i)
        if (stem == kEmbeddedWeb[i].name) return kEmbeddedWeb[i].contents;
    throw std::invalid_argument("no embedded web file \"" + stem + "\"");
}

std::string base64Of(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    return base64(std::vector<unsigned char>(p, p + bytes));
}

// One level of a texture: raw little-endian float32 values (the point
// path's data, as GpuGraph uploads it) or a PNG (8-bit codes, or 16-bit
// for a field table) that page.js decodes.
nlohmann::json floatLevel(int width, int height, const float* values, int channels) {
    return {
        {"width", width},
        {"height", height},
        {"encoding", "f32"},
        {"data", base64Of(values, sizeof(float) * std::size_t(width) * std::size_t(height) * std::size_t(channels))}};
}
nlohmann::json pngLevel(const Image& image, const WriteOptions& w) {
    return {{"width", image.width()},
            {"height", image.height()},
            {"encoding", "png"},
            {"data", base64(encodeImage("level.png", image, w))}};
}

nlohmann::json texture(const std::string& uniform, const char* target, const char* format, nlohmann::json levels,
                       int layers = 1) {
    return {{"uniform", uniform}, {"target", target}, {"format", format}, {"layers", layers}, {"levels", levels}};
}

// The pattern's parameter block under `options`, as bytes.
std::string blockOf(const GraphPattern& graph, const FilterOptions& options) {
    const kernel::PatternParams p = patternParams(graph, options);
    return base64Of(&p, sizeof p);
}

}  // namespace

void writeWebPage(const PatternSpec& spec, const WebPageOptions& web, const std::string& dir) {
    const FilterOptions& start = web.options;
    if (!gpuHasSource(start.source))
        throw InputError::parameter("source", "must be point or estimators on the web page, got " +
                                                  enumName(kStatisticsSourceNames, start.source));
    validateCamera(web.camera);
    // Both tables' filters, on one set of parts (the pyramids are built once).
    FilterOptions paper = start, smooth = start;
    paper.source = smooth.source = StatisticsSource::Estimators;
    paper.response.prefilter = PrefilterMode::Paper;
    smooth.response.prefilter = PrefilterMode::Smooth;
    PartCache parts;
    const GraphPattern graph = GraphPattern::build(spec, start.response, &parts);
    const FilteredGraph paperGraph(graph, paper, GraphMoments::Matched, &parts);
    const FilteredGraph smoothGraph(graph, smooth, GraphMoments::Matched, &parts);
    // Both paths' samplers in one program: the point set and the filtered set (pyramids per pair).
    const int units = graphTextureUnits(graph, true, true, GraphMoments::Matched);
    if (units > kWebTextureUnits)
        throw InputError("the graph's web program reads " + std::to_string(units) + " textures, more than the " +
                         std::to_string(kWebTextureUnits) + " units WebGL 2 guarantees; use fewer leaves or tables");

    nlohmann::json textures = nlohmann::json::array();
    for (int k = 0; k < graph.leafCount(); ++k) {
        const std::string leaf = std::to_string(k);
        const NoiseExample& e = graph.leaf(k).example();
        const Image& values = e.grid().values();
        textures.push_back(texture("uGraphExample" + leaf, "2d", "R32F",
                                   {floatLevel(values.width(), values.height(), values.data().data(), 1)}));
        if (e.gaussianized()) {
            const std::vector<float>& lut = e.transform()->inverseLut();
            textures.push_back(
                texture("uGraphInverse" + leaf, "2d", "R32F", {floatLevel(int(lut.size()), 1, lut.data(), 1)}));
        }
    }
    // The 8-bit pyramids (the export's layout), their codes into the program.
    GraphEstimator estimator = graphEstimator(paperGraph, paper);
    estimator.packedPairs = true;
    for (std::size_t p = 0; p < graph.leafPairs().size(); ++p) {
        const auto [x, y] = pairPyramids(graph, paperGraph, int(p));
        std::vector<GraphEstimator::LevelCoding>& coding = estimator.pyramidCoding.emplace_back();
        nlohmann::json levels = nlohmann::json::array();
        for (int l = 0; l < x->levels(); ++l)
            levels.push_back(pngLevel(packedPairLevel(*x, *y, l, coding.emplace_back()), kNoTransfer));
        textures.push_back(texture("uGraphPairStats" + std::to_string(p), "2d", "RGBA8", std::move(levels)));
        if (!graph.pairCovariance(int(p))) continue;
        const StatsPyramid& covariance = *paperGraph.estimator(int(p)).covariancePyramid();
        nlohmann::json covarianceLevels = nlohmann::json::array();
        for (int l = 0; l < covariance.levels(); ++l)
            covarianceLevels.push_back(
                pngLevel(codedCovarianceLevel(covariance, l, coding[std::size_t(l)]), kNoTransfer));
        textures.push_back(texture("uGraphCov" + std::to_string(p), "2d", "RGBA8", std::move(covarianceLevels)));
    }
    for (std::size_t t = 0; t < graph.tables().size(); ++t) {
        const std::string table = std::to_string(t);
        if (graph.readsTable(int(t), false, false)) {
            const Image point = graph.tables()[t].point.table();
            textures.push_back(texture("uGraphTable" + table, "array", "RGB32F",
                                       {floatLevel(point.width(), point.height(), point.data().data(), 3)}));
        }
        if (!graph.readsTable(int(t), true, true)) continue;  // an op's table its function of sources replaces
        // Each filter's prefiltered table, as the 8-bit export stores it:
        // colours as 8-bit sRGB codes, a field's (g, g²) as 16-bit codes
        // where it lies in [0, 1] (page.js turns them into floats), else floats.
        const ColormapTable& h = graph.tables()[t].blended;
        const bool field = graph.tables()[t].field;
        for (const FilteredGraph* f : {&paperGraph, &smoothGraph}) {
            const int n = int(f->table(int(t)).sigmas().size());
            const Image atlas = f->table(int(t)).atlas(h.resolutionX(), h.resolutionY());
            const nlohmann::json level =
                !field               ? pngLevel(atlas, WriteOptions{})  // 8-bit sRGB codes of the linear values
                : fitsUnorm16(atlas) ? pngLevel(atlas, {.bitDepth = 16, .transfer = Transfer::Linear})
                                     : floatLevel(atlas.width(), atlas.height(), atlas.data().data(), 3);
            nlohmann::json entry =
                texture("uGraphPrefiltered" + table, "array", field ? "RGB32F" : "SRGB8", {level}, n * n);
            entry["filter"] = f == &paperGraph ? "paper" : "smooth";
            textures.push_back(std::move(entry));
        }
    }

    const ProgramRecipe& recipe = programRecipe("graph-web");
    const ProgramRecipe& scene = programRecipe("graph-scene");
    const std::vector<std::pair<std::string, std::string>> program = {
        {kGraphProgramStem, graphProgramSource(graph, GraphMoments::Matched, estimator)}};
    const Camera& camera = web.camera;
    nlohmann::json data;
    data["name"] = spec.name;
    data["vertex"] = assembleShader(GlslTarget::Es300, recipe.vertex, program);
    data["fragment"] = assembleShader(GlslTarget::Es300, recipe.main, program);
    // The lit objects: `scene`'s program and meshes, its camera's defaults.
    data["sceneVertex"] = assembleShader(GlslTarget::Es300, scene.vertex, program);
    data["sceneFragment"] = assembleShader(GlslTarget::Es300, scene.main, program);
    data["shadesLight"] = graph.shadesLight();
    for (const char* object : {"sphere", "torus"}) {
        const Mesh mesh = makeObject(object);
        data["meshes"][object] = {
            {"vertices", base64Of(mesh.vertices.data(), mesh.vertices.size() * sizeof(float))},
            {"indices", base64Of(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t))},
            {"count", mesh.indices.size()}};
    }
    const SceneCamera sceneCamera;
    data["sceneCamera"] = {{"eye", sceneCamera.eye},
                           {"target", sceneCamera.target},
                           {"fov", sceneCamera.fovDeg},
                           {"tiling", kDefaultSceneTiling}};
    data["exampleSize"] = graph.exampleSize();
    data["sky"] = {paperGraph.skyColour()[0], paperGraph.skyColour()[1], paperGraph.skyColour()[2]};
    data["blocks"] = {
        {"none", blockOf(graph, start)}, {"paper", blockOf(graph, paper)}, {"smooth", blockOf(graph, smooth)}};
    data["anisoOffset"] = offsetof(kernel::PatternParams, aniso);
    data["textures"] = std::move(textures);
    data["start"] = {
        {"view", enumName(Camera::kKindNames, camera.kind)},
        {"size", {camera.view.width, camera.view.height}},
        {"scale", camera.view.scale},
        {"x", camera.view.offsetU},
        {"y", camera.view.offsetV},
        {"tilt", camera.tiltDeg},
        {"fov", camera.fovDeg},
        {"filter",
         start.source == StatisticsSource::Point ? "none" : enumName(kPrefilterModeNames, start.response.prefilter)},
        {"aniso", start.aniso}};
    // What the page shows of the pattern: its file and its program.
    nlohmann::json leaves = nlohmann::json::array(), ops = nlohmann::json::array();
    for (const std::string& id : graph.leafIds()) leaves.push_back(id);
    for (const GraphPattern::Operation& op : graph.operations())
        ops.push_back({{"id", op.id}, {"type", op.info->name}});
    data["pattern"] = {{"source", web.sourceText},
                       {"gridDensity", graph.grid().densityV},
                       {"leaves", leaves},
                       {"operations", ops},
                       {"response", enumName(kResponseKindNames, start.response.kind)},
                       {"estimator", enumName(kVarianceEstimatorNames, start.estimator)}};

    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) throw InputError(dir + ": cannot create output folder");
    writeFileAtomic(
        (fs::path(dir) / "data.js").string(),
        "// stochtex web: the pattern's program and data (generated).\nwindow.STOCHTEX_DATA = " + data.dump() + ";\n");
    writeFileAtomic((fs::path(dir) / "page.js").string(), webFile("page"));
    writeFileAtomic((fs::path(dir) / "index.html").string(), webFile("index"));
}

}  // namespace stochtex
