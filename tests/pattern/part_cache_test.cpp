// PartCache (pattern/part_cache.h): a build after an edit remakes only the
// parts the edit changed, and renders what a build without the cache does,
// bit for bit.
#include "stochtex/pattern/part_cache.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "stochtex/core/budget.h"
#include "stochtex/core/error.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/presets.h"

namespace stochtex {
namespace {

// A preset at 64² examples (which parts are rebuilt does not depend on the size), edited.
PatternSpec preset(const std::string& name, const std::function<void(nlohmann::json&)>& edit = {}) {
    nlohmann::json j = JsonReader::parse(presetText(name), name);
    j["size"] = 64;
    if (edit) edit(j);
    return parsePatternSpec(JsonReader(j, name), ".");
}

void setColour(nlohmann::json& j) { j["colormap"]["shapes"][0]["colour"] = "#d02020"; }
void setCutoff(nlohmann::json& j) { j["noise_y"]["components"][0]["cutoff"] = 5; }

// A filtered render through the estimators and the prefiltered table, built with `parts` (or none).
Image render(const PatternSpec& spec, PartCache* parts, ResponseKind response = ResponseKind::PrefilteredColormap) {
    FilterOptions o;
    o.use(parseFilter("paper"));
    o.response.kind = response;
    const GraphPattern graph = GraphPattern::build(spec, o.response, parts);
    const FilteredGraph filtered(graph, o, GraphMoments::Matched, parts);
    Camera camera;
    camera.view.width = 40;
    camera.view.height = 32;
    camera.view.scale = 2.7;  // a footprint of several texels: the estimators and the table's blurred layers
    return filtered.render(camera);
}

// The same pixels, bit for bit.
void expectSameImage(const Image& a, const Image& b) {
    ASSERT_EQ(a.width(), b.width());
    ASSERT_EQ(a.height(), b.height());
    EXPECT_TRUE(a.data() == b.data());
}

TEST(PartCache, AColormapEditBuildsNoNoiseAndNoPyramid) {
    PartCache parts;
    expectSameImage(render(preset("camouflage"), &parts), render(preset("camouflage"), nullptr));
    const PartCache::Builds first = parts.builds();
    EXPECT_EQ(first.fields, 2);
    EXPECT_EQ(first.colormaps, 1);
    EXPECT_EQ(first.estimators, 1);
    EXPECT_EQ(first.prefiltered, 1);

    parts.beginGeneration();
    const PatternSpec edited = preset("camouflage", setColour);
    expectSameImage(render(edited, &parts), render(edited, nullptr));
    const PartCache::Builds b = parts.builds();
    EXPECT_EQ(b.fields, first.fields);          // no noise synthesised
    EXPECT_EQ(b.estimators, first.estimators);  // no pyramid
    EXPECT_EQ(b.colormaps, first.colormaps + 1);
    EXPECT_EQ(b.prefiltered, first.prefiltered + 1);
}

TEST(PartCache, ANoiseEditBuildsThatNoiseAlone) {
    PartCache parts;
    render(preset("camouflage"), &parts);
    const PartCache::Builds first = parts.builds();
    parts.beginGeneration();
    const PatternSpec edited = preset("camouflage", setCutoff);
    expectSameImage(render(edited, &parts), render(edited, nullptr));
    const PartCache::Builds b = parts.builds();
    EXPECT_EQ(b.fields, first.fields + 1);  // noise_y; noise_x kept
    EXPECT_EQ(b.estimators, first.estimators + 1);
    EXPECT_EQ(b.colormaps, first.colormaps);      // no table rasterised
    EXPECT_EQ(b.prefiltered, first.prefiltered);  // nor prefiltered
}

TEST(PartCache, AnUndoBuildsNothingAndOldPartsAreDropped) {
    PartCache parts;
    const PatternSpec original = preset("camouflage");
    render(original, &parts);
    parts.beginGeneration();
    render(preset("camouflage", setColour), &parts);
    const PartCache::Builds edited = parts.builds();
    const size_t kept = parts.size();
    // The previous revision's parts are kept: undoing the edit builds nothing.
    parts.beginGeneration();
    expectSameImage(render(original, &parts), render(original, nullptr));
    EXPECT_EQ(parts.builds().colormaps, edited.colormaps);
    EXPECT_EQ(parts.builds().prefiltered, edited.prefiltered);
    EXPECT_EQ(parts.size(), kept);
    // Two generations on without the edited colormap, its table and prefiltered table are gone.
    parts.beginGeneration();
    render(original, &parts);
    parts.beginGeneration();
    EXPECT_EQ(parts.size(), kept - 2);
    render(preset("camouflage", setColour), &parts);
    EXPECT_EQ(parts.builds().colormaps, edited.colormaps + 1);
    parts.clear();
    EXPECT_EQ(parts.size(), 0u);
}

TEST(PartCache, ALeanShadingEditKeepsTheSlopesAndANewAmplitudeRebuildsThem) {
    // lean-ridges under the lean response: its height's slope field is a
    // kept part. The albedo is shading, not slopes; the amplitude scales them.
    PartCache parts;
    render(preset("lean-ridges"), &parts, ResponseKind::Lean);
    const PartCache::Builds first = parts.builds();
    EXPECT_EQ(first.slopes, 1);
    parts.beginGeneration();
    const PatternSpec albedo = preset("lean-ridges", [](nlohmann::json& j) { j["normal_map"]["albedo"] = "#a05050"; });
    expectSameImage(render(albedo, &parts, ResponseKind::Lean), render(albedo, nullptr, ResponseKind::Lean));
    EXPECT_EQ(parts.builds().slopes, first.slopes);
    EXPECT_EQ(parts.builds().fields, first.fields);
    parts.beginGeneration();
    const PatternSpec amplitude = preset("lean-ridges", [](nlohmann::json& j) { j["normal_map"]["amplitude"] = 0.5; });
    expectSameImage(render(amplitude, &parts, ResponseKind::Lean), render(amplitude, nullptr, ResponseKind::Lean));
    EXPECT_EQ(parts.builds().slopes, first.slopes + 1);
    EXPECT_EQ(parts.builds().fields, first.fields);  // the height is the same field
}

TEST(PartCache, AGraphEditRebuildsTheNodeItChangedAndWhatIsDownstreamOnly) {
    // figure14: height → du, dv (derivatives) → direction → colour. Every
    // linear node is a kept part, so an edit of du's angle rebuilds du alone
    // (not the height it reads, nor dv), and an edit of the height's
    // cut-off rebuilds the height and both derivatives.
    const auto graph = [](const std::function<void(nlohmann::json&)>& edit) {
        nlohmann::json j = JsonReader::parse(presetText("figure14"), "figure14");
        j["nodes"]["height"]["size"] = 64;
        if (edit) edit(j);
        return parsePatternSpec(JsonReader(j, "figure14"), ".");
    };
    PartCache parts;
    render(graph({}), &parts);
    const int first = parts.builds().fields;
    EXPECT_EQ(first, 3);  // height, du, dv
    parts.beginGeneration();
    const PatternSpec angle = graph([](nlohmann::json& j) { j["nodes"]["du"]["angle"] = 30; });
    expectSameImage(render(angle, &parts), render(angle, nullptr));
    EXPECT_EQ(parts.builds().fields, first + 1);
    parts.beginGeneration();
    const PatternSpec cutoff = graph([](nlohmann::json& j) { j["nodes"]["height"]["components"][0]["cutoff"] = 9; });
    expectSameImage(render(cutoff, &parts), render(cutoff, nullptr));
    EXPECT_EQ(parts.builds().fields, first + 4);
}

TEST(PartCache, KeptFieldsStillCountAgainstTheExamplesBudget) {
    // figure14 with a 1024² height: three fields of 2^20 texels, within the
    // default budget (2^26) but not a 64th of it. Built with the cache at
    // the default, then again (every field kept) at a 64th: refused as a
    // build without the cache is, naming the budget.
    nlohmann::json j = JsonReader::parse(presetText("figure14"), "figure14");
    j["nodes"]["height"]["size"] = 1024;
    const PatternSpec spec = parsePatternSpec(JsonReader(j, "figure14"), ".");
    struct RestoreBudget {
        ~RestoreBudget() { setBudgetFactor(1); }
    } restore;
    PartCache parts;
    GraphPattern::build(spec, {}, &parts);
    EXPECT_EQ(parts.builds().fields, 3);
    setBudgetFactor(1.0 / 64);
    for (PartCache* cache : {&parts, static_cast<PartCache*>(nullptr)}) {
        try {
            GraphPattern::build(spec, {}, cache);
            ADD_FAILURE() << "a graph over a 64th of the budget was built " << (cache ? "from kept fields" : "");
        } catch (const InputError& e) {
            EXPECT_TRUE(e.isOverBudget()) << e.what();
            EXPECT_NE(std::string(e.what()).find("texels in all"), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(parts.builds().fields, 3);  // the kept ones were found, and refused
}

TEST(PartCache, ABuildThatFailsKeepsNothingOfThePartThatFailed) {
    PartCache parts;
    ColormapSpec missing;
    missing.source = ColormapSpec::Source::Image;
    missing.image = "/nonexistent/colormap.png";
    EXPECT_THROW(parts.colormap(missing), InputError);
    EXPECT_EQ(parts.size(), 0u);
    EXPECT_EQ(parts.builds().colormaps, 0);
    EXPECT_THROW(parts.colormap(missing), InputError);  // tried again, not a kept failure
}

// What a device made of a part (the GPU view's textures) lives as long as the
// part is used: kept while a build of the last two generations asked for it,
// destroyed (its deleter run: glDelete* for a texture) when the next begins
// without it, or on clear().
TEST(PartCache, AnAttachmentIsDestroyedTwoGenerationsAfterItsLastUse) {
    PartCache parts;
    const auto part = std::make_shared<const int>(7);
    int made = 0, destroyed = 0;
    const auto make = [&] {
        ++made;
        return std::shared_ptr<void>(new int(made), [&](void* p) {
            delete static_cast<int*>(p);
            ++destroyed;
        });
    };
    const std::shared_ptr<void> first = parts.attachment(part, "texture", make);
    EXPECT_EQ(parts.attachment(part, "texture", make), first);  // found, not made again
    EXPECT_NE(parts.attachment(part, "pyramid", make), first);  // another thing made of the part
    EXPECT_EQ(made, 2);
    parts.beginGeneration();
    EXPECT_EQ(parts.attachment(part, "texture", make), first);  // used in this generation
    parts.beginGeneration();
    parts.beginGeneration();  // "pyramid": last used three generations ago
    EXPECT_EQ(destroyed, 1);
    EXPECT_EQ(parts.size(), 1u);
    parts.beginGeneration();  // "texture" too, but `first` still holds it
    EXPECT_EQ(parts.size(), 0u);
    EXPECT_EQ(destroyed, 1);
    EXPECT_EQ(made, 2);
    EXPECT_EQ(*static_cast<int*>(first.get()), 1);
}

}  // namespace
}  // namespace stochtex
