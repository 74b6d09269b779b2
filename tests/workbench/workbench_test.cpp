// The workbench's parts that need no window: the document (edits, refusals,
// saving, live reload), the script, and the live analyses.
#include <gtest/gtest.h>
#include <imgui.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <sstream>

#include "stochtex/core/hash.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/graph_nodes.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/presets.h"
#include "stochtex/workbench/document.h"
#include "stochtex/workbench/editors.h"
#include "stochtex/workbench/json_layout.h"
#include "stochtex/workbench/live_analysis.h"
#include "stochtex/workbench/previews.h"
#include "stochtex/workbench/script.h"
#include "test_util.h"

namespace stochtex {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct TempDir {
    fs::path path =
        fs::temp_directory_path() / ("stochtex-wb-" + std::to_string(::getpid()) + "-" +
                                     std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    TempDir() { fs::create_directories(path); }
    ~TempDir() { fs::remove_all(path); }
};

// A hashed value in [0, 1): fixed noise without a random engine.
double hashToUnit(uint32_t a, uint32_t b, uint32_t c) { return pcg3d({a, b, c}).x * 0x1p-32; }

void writeText(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

TEST(WorkbenchDocument, EditsAreKeptOnlyWhenThePatternStillParses) {
    WorkbenchDocument d = WorkbenchDocument::preset("camouflage");
    EXPECT_FALSE(d.edited());
    d.set("/colormap/shapes/0/colour", "#d02020");
    EXPECT_TRUE(d.edited());
    EXPECT_EQ(d.json()["colormap"]["shapes"][0]["colour"], "#d02020");
    const PatternSpec spec = d.patternSpec();
    EXPECT_NEAR(spec.colormap.painted.shapes[0].colour[0], float(0xd0) / 255.0f, 1e-6);  // codes, decoded in the table

    // A refused edit names the pointer as the parser words it, and changes nothing.
    const json before = d.json();
    const InputError e = test::inputErrorOf([&] { d.set("/colormap/shapes/0/colour", "red"); });
    EXPECT_NE(std::string(e.what()).find("preset camouflage: /colormap/shapes/0/colour: invalid colour \"red\""),
              std::string::npos)
        << e.what();
    EXPECT_EQ(d.json(), before);
    EXPECT_NE(std::string(test::inputErrorOf([&] { d.set("/noise_x/components/0/cutoff", -3); }).what())
                  .find("/noise_x/components/0/cutoff"),
              std::string::npos);
    EXPECT_NE(std::string(test::inputErrorOf([&] { d.set("/nothing/here", 1); }).what()).find("no such place"),
              std::string::npos);
    EXPECT_EQ(d.json(), before);

    // Appending a shape (an index one past the end) and removing it again.
    const size_t shapes = d.json()["colormap"]["shapes"].size();
    d.set("/colormap/shapes/" + std::to_string(shapes),
          json{{"shape", "disc"}, {"center", {0.5, 0.5}}, {"radius", 0.1}, {"colour", "#ffffff"}});
    EXPECT_EQ(d.json()["colormap"]["shapes"].size(), shapes + 1);
    EXPECT_EQ(d.patternSpec().colormap.painted.shapes.size(), shapes + 1);
    d.remove("/colormap/shapes/" + std::to_string(shapes));
    EXPECT_EQ(d.json(), before);
    // An index past the end would fill the gap with nulls (400000000 of them
    // took 14 GB): refused, naming the array's size.
    EXPECT_EQ(std::string(test::inputErrorOf([&] { d.set("/colormap/shapes/400000000", 1); }).what()),
              "preset camouflage: /colormap/shapes/400000000: the array holds " + std::to_string(shapes) +
                  " elements; set one of them, or append at " + std::to_string(shapes) + " (or -)");
    EXPECT_EQ(d.json(), before);
    // The last component of a noise cannot go: a noise needs one.
    EXPECT_THROW(d.remove("/noise_x/components/0"), InputError);
    EXPECT_EQ(d.json(), before);
}

// Issue 31 item 1: the parse that checked a change is the one patternSpec()
// gives (the workbench builds from it, no second parse), and the revision
// counts accepted changes only: a refused edit moves neither.
TEST(WorkbenchDocument, TheKeptParseAndTheRevisionFollowAcceptedChangesOnly) {
    WorkbenchDocument d = WorkbenchDocument::preset("camouflage");
    const uint64_t r0 = d.revision();
    d.set("/colormap/shapes/0/colour", "#d02020");
    EXPECT_EQ(d.revision(), r0 + 1);
    EXPECT_NEAR(d.patternSpec().colormap.painted.shapes[0].colour[0], float(0xd0) / 255.0f, 1e-6);
    const PatternSpec edited = d.patternSpec();
    EXPECT_THROW(d.set("/colormap/shapes/0/colour", "red"), InputError);
    EXPECT_EQ(d.revision(), r0 + 1);  // refused: neither the revision nor the parse moved
    EXPECT_TRUE(d.patternSpec().colormap == edited.colormap);
    d.checkpoint();
    d.set("/noise_x/components/0/cutoff", 5);
    EXPECT_EQ(d.revision(), r0 + 2);
    ASSERT_TRUE(d.undo());
    EXPECT_EQ(d.revision(), r0 + 3);
    EXPECT_TRUE(d.patternSpec().noise[0] == edited.noise[0]);  // the undone state's parse
    d.reload();
    EXPECT_EQ(d.revision(), r0 + 4);
    EXPECT_TRUE(d.patternSpec().colormap == WorkbenchDocument::preset("camouflage").patternSpec().colormap);
}

// Issue 31 item 1: a colormap edit does not synthesise the noises again and
// a noise edit does not rasterise the colormap; the previews are those of a
// fresh build either way.
TEST(PreviewCache, AnEditRebuildsOnlyThePartItChanged) {
    WorkbenchDocument d = WorkbenchDocument::preset("camouflage");
    PreviewCache cache;
    cache.update(d.patternSpec());
    EXPECT_EQ(cache.colormapBuilds(), 1);
    EXPECT_EQ(cache.exampleBuilds(), 2);
    cache.update(d.patternSpec());  // nothing changed: nothing built
    EXPECT_EQ(cache.colormapBuilds(), 1);
    EXPECT_EQ(cache.exampleBuilds(), 2);

    d.set("/colormap/shapes/0/colour", "#d02020");
    const PatternPreviews& afterColormap = cache.update(d.patternSpec());
    EXPECT_EQ(cache.colormapBuilds(), 2);
    EXPECT_EQ(cache.exampleBuilds(), 2);
    PreviewCache fresh;
    EXPECT_EQ(afterColormap.colormap.data(), fresh.update(d.patternSpec()).colormap.data());

    d.set("/noise_y/components/0/cutoff", 5);
    const PatternPreviews& afterNoise = cache.update(d.patternSpec());
    EXPECT_EQ(cache.colormapBuilds(), 2);
    EXPECT_EQ(cache.exampleBuilds(), 3);  // N_y only
    PreviewCache fresh2;
    const PatternPreviews& rebuilt = fresh2.update(d.patternSpec());
    const GraphPattern program = GraphPattern::build(d.patternSpec());
    for (size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(afterNoise.examples[k].data(), rebuilt.examples[k].data()) << k;
        EXPECT_EQ(afterNoise.spectra[k].data(), rebuilt.spectra[k].data()) << k;
        // The example the program renders with (its seed from the pattern's).
        EXPECT_EQ(afterNoise.examples[k].data(), program.leafPairs()[0].channel(int(k)).example().values().data()) << k;
    }
    // The pattern seed reaches the noises without a seed of their own.
    d.set("/seed", 99);
    cache.update(d.patternSpec());
    EXPECT_EQ(cache.exampleBuilds(), 5);
    EXPECT_EQ(cache.colormapBuilds(), 2);
    cache.clear();  // a reload: everything again
    cache.update(d.patternSpec());
    EXPECT_EQ(cache.exampleBuilds(), 7);
    EXPECT_EQ(cache.colormapBuilds(), 3);

    // A graph's examples are its nodes' (none shown); a quadrature pair shows N_x alone.
    const PatternPreviews& graph = cache.update(WorkbenchDocument::preset("figure14").patternSpec());
    EXPECT_TRUE(graph.examples[0].empty() && graph.examples[1].empty());
    EXPECT_FALSE(graph.colormap.empty());
    const PatternPreviews& phasor = cache.update(WorkbenchDocument::preset("phasor-colour").patternSpec());
    EXPECT_FALSE(phasor.examples[0].empty());
    EXPECT_TRUE(phasor.examples[1].empty());
}

// Undo and redo move between the marked states; a new edit forgets what
// was undone; the history is capped; a reload is one more step.
TEST(WorkbenchDocument, UndoAndRedoMoveBetweenCheckpoints) {
    WorkbenchDocument doc = WorkbenchDocument::preset("camouflage");
    const json original = doc.json();
    const std::string colour = "/colormap/shapes/0/colour";
    EXPECT_FALSE(doc.canUndo());
    EXPECT_FALSE(doc.undo());
    doc.checkpoint();
    EXPECT_FALSE(doc.canUndo());  // the marked state is the current one: nothing to go back to
    doc.set(colour, "#d02020");
    doc.checkpoint();
    doc.set(colour, "#2020d0");
    doc.set("/seed", 99);  // the same gesture: one step with the colour
    EXPECT_TRUE(doc.canUndo());
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.json()[json::json_pointer(colour)], "#d02020");
    EXPECT_EQ(doc.json()["seed"], original["seed"]);
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.json(), original);
    EXPECT_FALSE(doc.undo());
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.json()[json::json_pointer(colour)], "#d02020");
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.json()["seed"], 99);
    EXPECT_FALSE(doc.redo());
    // A refused edit touches no history; a new edit after an undo forgets the undone one.
    ASSERT_TRUE(doc.undo());
    doc.checkpoint();
    EXPECT_THROW(doc.set(colour, "red"), InputError);
    EXPECT_TRUE(doc.canRedo());
    doc.checkpoint();
    doc.set(colour, "#20d020");
    EXPECT_FALSE(doc.canRedo());
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.json()[json::json_pointer(colour)], "#d02020");

    // At most kUndoDepth states.
    for (size_t k = 0; k < WorkbenchDocument::kUndoDepth + 10; ++k) {
        doc.checkpoint();
        doc.set("/seed", int(k));
    }
    size_t undone = 0;
    while (doc.undo()) ++undone;
    EXPECT_EQ(undone, WorkbenchDocument::kUndoDepth);

    // A reload keeps the history, and what was on screen is one undo away.
    TempDir dir;
    const fs::path file = dir.path / "p.json";
    writeText(file, presetText("camouflage"));
    WorkbenchDocument onDisk = WorkbenchDocument::patternFile(file.string());
    onDisk.checkpoint();
    onDisk.set(colour, "#d02020");
    onDisk.reload();
    EXPECT_EQ(onDisk.json()[json::json_pointer(colour)], original[json::json_pointer(colour)]);
    ASSERT_TRUE(onDisk.undo());
    EXPECT_EQ(onDisk.json()[json::json_pointer(colour)], "#d02020");
    ASSERT_TRUE(onDisk.undo());
    EXPECT_EQ(onDisk.json(), original);
}

TEST(WorkbenchDocument, SavingKeepsImagePathsValidAndReloadFollowsTheFile) {
    TempDir dir;
    fs::create_directories(dir.path / "a");
    fs::create_directories(dir.path / "b");
    // A pattern whose noise is an image beside it.
    Image noise(16, 16, 1);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) noise.at(x, y) = float(hashToUnit(uint32_t(x), uint32_t(y), 5));
    writeImage((dir.path / "a" / "n.png").string(), noise, kNoTransfer);
    const json pattern = {{"size", 32},
                          {"noise_x", {{"type", "image"}, {"path", "n.png"}}},
                          {"noise_y", {{"type", "image"}, {"path", "n.png"}}},
                          {"colormap", {{"type", "gaussian"}}}};
    const fs::path file = dir.path / "a" / "p.json";
    writeText(file, pattern.dump());
    WorkbenchDocument d = WorkbenchDocument::patternFile(file.string());
    ASSERT_EQ(d.watchedFiles().size(), 3u);  // the file and its image, named twice
    EXPECT_FALSE(d.changedOnDisk());

    d.set("/seed", 9);
    d.save((dir.path / "b" / "q.json").string());  // another folder: the image path is made absolute
    const json saved = readJsonFile((dir.path / "b" / "q.json").string());
    EXPECT_EQ(saved["seed"], 9);
    EXPECT_EQ(fs::path(saved["noise_x"]["path"].get<std::string>()), fs::absolute(dir.path / "a" / "n.png"));
    EXPECT_NO_THROW(WorkbenchDocument::patternFile((dir.path / "b" / "q.json").string()).patternSpec());
    EXPECT_TRUE(d.edited());  // saved elsewhere: the source file is still behind
    d.save(file.string());
    EXPECT_FALSE(d.edited());
    EXPECT_EQ(readJsonFile(file.string())["noise_x"]["path"], "n.png");  // beside it: left relative
    EXPECT_FALSE(d.changedOnDisk()) << "our own save is not a change on disk";

    // Another program writes the file: seen once, then reloaded.
    json changed = pattern;
    changed["seed"] = 42;
    writeText(file, changed.dump());
    fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
    EXPECT_TRUE(d.changedOnDisk());
    EXPECT_FALSE(d.changedOnDisk());
    d.reload();
    EXPECT_EQ(d.json()["seed"], 42);
    EXPECT_FALSE(d.edited());

    // A broken file on reload: the error names the file, the document stays.
    writeText(file, "{\"size\": ");
    EXPECT_THROW(d.reload(), InputError);
    EXPECT_EQ(d.json()["seed"], 42);
}

// Saving an edit changes the edited line alone: the file's key order,
// spacing, one-line objects and wrapped lines stay (issue: Save JSON sorted
// every key, so one number diffed the whole file).
TEST(WorkbenchDocument, SavingAnEditChangesOnlyItsLine) {
    TempDir dir;
    const std::string text = R"({
  "size": 64,
  "seed": 7,
  "colormap": {"type": "painted", "background": "#102030",
               "shapes": [{"shape": "rectangle", "min": [0.3, -1], "max": [2, 2], "colour": "#c04020"}]},
  "noise_y": {"type": "spectrum", "components": [{"shape": "lowpass", "cutoff": 12}]},
  "noise_x": {"type": "spectrum", "components": [{"shape": "lowpass", "cutoff": 8}]}
}
)";
    const fs::path file = dir.path / "p.json";
    writeText(file, text);
    WorkbenchDocument d = WorkbenchDocument::patternFile(file.string());
    auto lines = [](const std::string& t) {
        std::vector<std::string> out;
        std::istringstream in(t);
        for (std::string line; std::getline(in, line);) out.push_back(line);
        return out;
    };
    auto savedText = [&] {
        std::ifstream in(file);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    d.save(file.string());
    EXPECT_EQ(savedText(), text) << "an unedited document is written back byte for byte";

    d.set("/noise_x/components/0/cutoff", 9);
    d.save(file.string());
    const std::vector<std::string> before = lines(text), after = lines(savedText());
    ASSERT_EQ(after.size(), before.size());
    for (size_t k = 0; k < before.size(); ++k)
        if (k == 6)
            EXPECT_EQ(after[k],
                      R"(  "noise_x": {"type": "spectrum", "components": [{"shape": "lowpass", "cutoff": 9}]})");
        else
            EXPECT_EQ(after[k], before[k]) << "line " << k + 1;

    // A new member goes after the ones the object had, in its layout.
    d.set("/noise_y/components/0/weight", 2);
    d.save(file.string());
    EXPECT_EQ(lines(savedText())[5],
              R"(  "noise_y": {"type": "spectrum", "components": [{"shape": "lowpass", "cutoff": 12, "weight": 2}]},)");
    EXPECT_EQ(json::parse(savedText()), d.json());
}

// Every shipped pattern and graph file is written back byte for byte, and
// an edit anywhere in it parses back to the edited document.
TEST(JsonLayout, ShippedFilesRoundTripAndEditsParseBack) {
    int files = 0;
    for (const char* folder : {"presets", "graphs"})
        for (const auto& e : fs::directory_iterator(fs::path(STOCHTEX_DATA_DIR) / folder)) {
            if (e.path().extension() != ".json") continue;
            std::ifstream in(e.path());
            const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            json value = json::parse(text);
            EXPECT_EQ(layoutLike(value, text), text) << e.path();
            value["seed"] = 12345;
            value["added"] = {{"a", {1, 2}}, {"b", "c"}};
            const std::string edited = layoutLike(value, text);
            EXPECT_EQ(json::parse(edited), value) << e.path();
            ++files;
        }
    EXPECT_GE(files, 10);
}

TEST(WorkbenchDocument, AProgramWatchesItsPassFiles) {
    TempDir dir;
    writeText(dir.path / "image.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n");
    writeText(dir.path / "common.glsl", "float f(float x) { return x; }\n");
    const WorkbenchDocument d = WorkbenchDocument::shadertoy(dir.path.string());
    EXPECT_EQ(d.kind(), WorkbenchDocument::Kind::Shadertoy);
    ASSERT_EQ(d.watchedFiles().size(), 2u);
    EXPECT_THROW(WorkbenchDocument::shadertoy((dir.path / "missing").string()), InputError);
}

// A panel driven as a person would: the mouse placed and pressed frame by
// frame (headless ImGui, no backend), the canvas found where it was drawn.
class DrivenPanel {
public:
    DrivenPanel() {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(400, 2000);
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    }
    ~DrivenPanel() { ImGui::DestroyContext(); }

    // One frame with the mouse at `at`, its left button held or not.
    std::vector<JsonEdit> frame(const json& pattern, const EditorPreviews& previews, EditorState& state, ImVec2 at,
                                bool down) {
        ImGuiIO& io = ImGui::GetIO();
        io.DeltaTime = 1.0f / 60;
        io.MousePos = at;
        io.MouseDown[0] = down;
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(400, 2000));
        ImGui::Begin("panel");
        std::vector<JsonEdit> edits = patternEditor(pattern, previews, state);
        ImGui::End();
        ImGui::Render();
        return edits;
    }

    // Where the last frame drew the image of `texture`: its bounding box.
    static std::pair<ImVec2, ImVec2> imageRect(void* texture) {
        ImVec2 lo(1e9f, 1e9f), hi(-1e9f, -1e9f);
        const ImDrawData* data = ImGui::GetDrawData();
        for (int n = 0; n < data->CmdListsCount; ++n) {
            const ImDrawList* list = data->CmdLists[n];
            for (const ImDrawCmd& cmd : list->CmdBuffer) {
                if (cmd.TextureId != texture) continue;
                for (unsigned k = 0; k < cmd.ElemCount; ++k) {
                    const ImVec2 p = list->VtxBuffer[int(cmd.VtxOffset + list->IdxBuffer[int(cmd.IdxOffset + k)])].pos;
                    lo = ImVec2(std::min(lo.x, p.x), std::min(lo.y, p.y));
                    hi = ImVec2(std::max(hi.x, p.x), std::max(hi.y, p.y));
                }
            }
        }
        return {lo, hi};
    }
};

// The panels drawn (headless ImGui, no backend) over every preset and the
// sample graph of every node: no exception from a member's type, balanced
// ImGui stacks, and no edit made by merely drawing.
TEST(WorkbenchEditors, EveryPresetAndNodeDrawsWithoutEdits) {
    DrivenPanel panel;
    std::vector<json> patterns;
    for (const std::string& name : presetNames()) patterns.push_back(JsonReader::parse(presetText(name), name));
    for (const NodeInfo& node : graphNodes()) patterns.push_back(sampleNodeGraph(node, "exemplar.png"));
    EditorPreviews previews;
    int dummy = 1;
    previews.colormap = &dummy;  // any id: nothing is rendered
    EditorState state;
    for (const json& pattern : patterns) {
        int vertices[2] = {0, 0};
        for (int frame = 0; frame < 4; ++frame) {
            previews.expandAll = frame >= 2;  // two frames as opened, then everything unfolded
            std::vector<JsonEdit> edits;
            EXPECT_NO_THROW(edits = panel.frame(pattern, previews, state, ImVec2(-10, -10), false))
                << pattern.value("name", "?");
            EXPECT_TRUE(edits.empty()) << pattern.value("name", "?") << ": " << (edits.empty() ? "" : edits[0].pointer);
            if (frame % 2 == 1) vertices[frame / 2] = ImGui::GetDrawData()->TotalVtxCount;
        }
        // Unfolded, every section drew its widgets.
        EXPECT_GT(vertices[1], vertices[0] + 200) << pattern.value("name", "?");
        // Fold everything again for the next pattern.
        ImGui::NewFrame();
        ImGui::Begin("panel");
        ImGui::GetStateStorage()->SetAllInt(0);
        ImGui::End();
        ImGui::Render();
    }
}

// Clicking the painted colormap's canvas adds the brush's shape where the
// click was (x right, y up), and the document takes the edit; the move tool
// drags the shape under the cursor by the mouse's motion.
TEST(WorkbenchEditors, ClickingTheCanvasPaintsAndDraggingMovesAShape) {
    DrivenPanel panel;
    WorkbenchDocument doc = WorkbenchDocument::preset("camouflage");
    const size_t shapes = doc.json()["colormap"]["shapes"].size();
    ASSERT_EQ(shapes, 4u);
    EditorPreviews previews;
    int canvasTexture = 1;
    previews.colormap = &canvasTexture;
    EditorState state;
    PaintBrush& brush = state.brush;

    EXPECT_TRUE(panel.frame(doc.json(), previews, state, ImVec2(-10, -10), false).empty());
    const auto [lo, hi] = DrivenPanel::imageRect(&canvasTexture);
    ASSERT_NEAR(hi.x - lo.x, previews.canvasSize, 0.5f);
    ASSERT_NEAR(hi.y - lo.y, previews.canvasSize, 0.5f);
    // The canvas point (0.25, 0.75): a quarter from the left, a quarter from the top.
    const ImVec2 at(lo.x + 0.25f * previews.canvasSize, lo.y + 0.25f * previews.canvasSize);
    EXPECT_TRUE(panel.frame(doc.json(), previews, state, at, false).empty());  // hovering alone edits nothing
    const std::vector<JsonEdit> painted = panel.frame(doc.json(), previews, state, at, true);
    ASSERT_EQ(painted.size(), 1u);
    EXPECT_EQ(painted[0].pointer, "/colormap/shapes/4");
    EXPECT_EQ(painted[0].value["shape"], "disc");
    EXPECT_EQ(painted[0].value["colour"], colourHex(brush.colour));
    EXPECT_NEAR(painted[0].value["radius"].get<double>(), brush.radius, 1e-6);
    EXPECT_NEAR(painted[0].value["center"][0].get<double>(), 0.25, 0.5 / previews.canvasSize);
    EXPECT_NEAR(painted[0].value["center"][1].get<double>(), 0.75, 0.5 / previews.canvasSize);
    EXPECT_TRUE(panel.frame(doc.json(), previews, state, at, true).empty());  // held: one shape per click
    doc.set(painted[0].pointer, painted[0].value);
    const PatternSpec withDisc = doc.patternSpec();
    ASSERT_EQ(withDisc.colormap.painted.shapes.size(), 5u);
    EXPECT_NEAR(withDisc.colormap.painted.shapes[4].a[0], 0.25, 0.5 / previews.canvasSize);
    panel.frame(doc.json(), previews, state, at, false);  // released

    // The move tool: press on the disc at (0.9, 0.1) (shape 3, not the new one), drag by (−20, −10) pixels.
    brush.shape = 3;
    previews.painted = &withDisc.colormap.painted;
    const ImVec2 on(lo.x + 0.9f * previews.canvasSize, lo.y + 0.9f * previews.canvasSize);
    EXPECT_TRUE(panel.frame(doc.json(), previews, state, on, false).empty());
    EXPECT_TRUE(panel.frame(doc.json(), previews, state, on, true).empty());
    EXPECT_EQ(brush.moving, 3);
    const std::vector<JsonEdit> moved = panel.frame(doc.json(), previews, state, ImVec2(on.x - 20, on.y - 10), true);
    ASSERT_EQ(moved.size(), 1u);
    EXPECT_EQ(moved[0].pointer, "/colormap/shapes/3");
    EXPECT_NEAR(moved[0].value["center"][0].get<double>(), 0.9 - 20 / previews.canvasSize, 1e-4);
    EXPECT_NEAR(moved[0].value["center"][1].get<double>(), 0.1 + 10 / previews.canvasSize, 1e-4);
    EXPECT_NEAR(moved[0].value["radius"].get<double>(), 0.28, 1e-9);
    panel.frame(doc.json(), previews, state, on, false);
    EXPECT_EQ(brush.moving, -1);  // released: nothing held
}

// The graph panel's structure edits: a node of every type added to a graph
// (its inputs fed by the first node that fits), taken by the document; the
// output moved to a new colour node; a node another reads is kept.
TEST(WorkbenchEditors, EveryNodeTypeCanBeAddedToAGraph) {
    TempDir dir;
    const fs::path image = dir.path / "exemplar.png";
    Image texture(32, 32, 3);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            for (int c = 0; c < 3; ++c) texture.at(x, y, c) = float(hashToUnit(uint32_t(x), uint32_t(y), uint32_t(c)));
    writeImage(image.string(), texture);
    WorkbenchDocument doc = WorkbenchDocument::preset("figure14");
    const size_t before = doc.json()["nodes"].size();
    for (const NodeInfo& node : graphNodes()) {  // tiled_field comes before channel, which reads one
        SCOPED_TRACE(node.name);
        const JsonEdit e = addGraphNode(doc.json(), node, image.string());
        EXPECT_EQ(e.pointer, "/nodes/" + node.name + "_1");
        EXPECT_EQ(e.value["type"], node.name);
        for (const PortInfo& port : node.inputs) {
            ASSERT_TRUE(e.value.contains(port.name)) << port.name;
            const std::vector<std::string> fit = nodesFitting(doc.json(), port.type);
            const std::string source = e.value[port.name];
            EXPECT_NE(std::find(fit.begin(), fit.end(), source), fit.end()) << port.name;
            // A field input is fed by a spectral noise (figure14's height is one).
            if (port.type == PortType::Field) {
                EXPECT_EQ(doc.json()["nodes"][source]["type"], "spectral_noise");
            }
        }
        EXPECT_NO_THROW(doc.set(e.pointer, e.value));
    }
    EXPECT_EQ(doc.json()["nodes"].size(), before + graphNodes().size());
    // A second node of a type takes the next id.
    EXPECT_EQ(addGraphNode(doc.json(), *findGraphNode("curve"), "").pointer, "/nodes/curve_2");
    // The output: any colour node; the panel lists them.
    const std::vector<std::string> colours = nodesFitting(doc.json(), PortType::Colour);
    EXPECT_NE(std::find(colours.begin(), colours.end(), "mix_1"), colours.end());
    EXPECT_EQ(std::find(colours.begin(), colours.end(), "height"), colours.end());
    doc.set("/output", "mix_1");
    EXPECT_NO_THROW(GraphPattern::build(doc.patternSpec()));  // and it builds, every node wired
    // A node another reads stays (the parser's message); an unread one goes.
    EXPECT_THROW(doc.remove("/nodes/height"), InputError);
    EXPECT_TRUE(doc.json()["nodes"].contains("height"));
    doc.remove("/nodes/lean_1");
    EXPECT_FALSE(doc.json()["nodes"].contains("lean_1"));
}

TEST(WorkbenchScript, StepsKeepTheirFrameAndNameOneAction) {
    const json script = json::parse(R"([
        {"frame": 2, "zoom": 2, "at": [10, 20]}, {"filter": "paper"},
        {"frame": 5, "set": "/seed", "value": 3}, {"mode": "split"}, {"analysis": "flow"},
        {"view": "torus"}, {"pick": [4, 5]}, {"screenshot": "a.png"}, {"quit": true},
        {"estimator": "sub-probes"}])");
    const std::vector<WorkbenchStep> steps = parseWorkbenchScript(script, "s.json");
    ASSERT_EQ(steps.size(), 10u);
    using A = WorkbenchStep::Action;
    EXPECT_EQ(steps[0].action, A::Zoom);
    EXPECT_EQ(steps[0].amount, 2);
    EXPECT_EQ(steps[0].x, 10);
    EXPECT_EQ(steps[0].y, 20);
    EXPECT_EQ(steps[1].frame, 2);  // no frame: the step before's
    EXPECT_EQ(steps[1].text, "paper");
    EXPECT_EQ(steps[2].frame, 5);
    EXPECT_EQ(steps[2].value, 3);
    EXPECT_EQ(steps[3].text, "split");
    EXPECT_EQ(steps[5].action, A::View);
    EXPECT_EQ(steps[8].action, A::Quit);
    EXPECT_EQ(steps[9].action, A::Estimator);
    EXPECT_EQ(steps[9].text, "sub-probes");

    auto message = [](const char* text) {
        return std::string(test::inputErrorOf([&] { parseWorkbenchScript(json::parse(text), "s.json"); }).what());
    };
    EXPECT_EQ(message(R"([{"frame": 3, "pause": true}, {"frame": 1, "quit": true}])"),
              "s.json: /1/frame: frames never go back (the step before runs at frame 3)");
    EXPECT_EQ(message(R"([{"filter": "paper", "mode": "split"}])"), "s.json: /0: one action per step");
    EXPECT_EQ(message(R"([{"frame": 1}])"),
              "s.json: /0: a step needs one action (zoom, pan, filter, set, screenshot, …)");
    EXPECT_NE(message(R"([{"zom": 2}])").find("/0"), std::string::npos);
    EXPECT_NE(message(R"([{"mode": "quad"}])").find("/0/mode: unknown value \"quad\""), std::string::npos);
    EXPECT_NE(message(R"([{"filter": "reference"}])").find("/0/filter"), std::string::npos);
    EXPECT_NE(message(R"([{"estimator": "dh"}])").find("/0/estimator"), std::string::npos);
    EXPECT_NE(message(R"({"zoom": 2})").find("expected an array"), std::string::npos);
}

// A key step names a key as the help does; it becomes GLFW's key and modifiers.
TEST(WorkbenchScript, KeysAreNamedAsOnTheKeyboard) {
    const std::vector<WorkbenchStep> steps = parseWorkbenchScript(
        json::parse(R"([{"key": "V"}, {"key": "f12"}, {"key": "Ctrl+Shift+Z"}, {"key": "]"}, {"key": "7"}])"),
        "s.json");
    ASSERT_EQ(steps.size(), 5u);
    EXPECT_EQ(steps[0].action, WorkbenchStep::Action::Key);
    EXPECT_EQ(steps[0].key, 86);    // GLFW_KEY_V
    EXPECT_EQ(steps[1].key, 301);   // GLFW_KEY_F12
    EXPECT_EQ(steps[2].key, 90);    // GLFW_KEY_Z
    EXPECT_EQ(steps[2].mods, 0x3);  // GLFW_MOD_SHIFT | GLFW_MOD_CONTROL
    EXPECT_EQ(steps[3].key, 93);    // GLFW_KEY_RIGHT_BRACKET
    EXPECT_EQ(steps[4].key, 55);    // GLFW_KEY_7
    EXPECT_EQ(steps[0].mods, 0);
    for (const char* bad : {"f13", "f01", "alt+v", "vv", ""}) EXPECT_THROW(parseKeyChord(bad), InputError) << bad;
}

// Mouse steps drive a program's iMouse: a point in its pixels, or a release.
TEST(WorkbenchScript, MouseStepsTakeAPointOrARelease) {
    const std::vector<WorkbenchStep> steps = parseWorkbenchScript(
        json::parse(R"([{"frame": 2, "mousedown": [3, 4]}, {"mousemove": [5, 6]}, {"frame": 4, "mouseup": true}])"),
        "s.json");
    ASSERT_EQ(steps.size(), 3u);
    using A = WorkbenchStep::Action;
    EXPECT_EQ(steps[0].action, A::MouseDown);
    EXPECT_EQ(steps[0].x, 3);
    EXPECT_EQ(steps[0].y, 4);
    EXPECT_EQ(steps[1].action, A::MouseMove);
    EXPECT_EQ(steps[1].frame, 2);
    EXPECT_EQ(steps[2].action, A::MouseUp);
    EXPECT_EQ(steps[2].frame, 4);
    auto message = [](const char* text) {
        return std::string(test::inputErrorOf([&] { parseWorkbenchScript(json::parse(text), "s.json"); }).what());
    };
    EXPECT_EQ(message(R"([{"mousedown": [1]}])"), "s.json: /0/mousedown: needs [x, y] in pixels");
    EXPECT_EQ(message(R"([{"mouseup": false}])"), "s.json: /0/mouseup: is written true");
}

// Stripes of a known frequency: the spectrum's brightest pixels sit at ±f
// from the centre, and the summary reads that frequency.
TEST(LiveAnalysis, SpectrumIsTheStudysFigureOfTheFrame) {
    const int w = 64, h = 64;
    Image frame(w, h, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                frame.at(x, y, c) = float(0.5 + 0.4 * std::cos(2 * std::numbers::pi * 8.0 * x / w));
    const LiveAnalysisResult r = liveSpectrum(frame);
    ASSERT_EQ(r.image.width(), w);
    ASSERT_EQ(r.image.channels(), 3);
    float best = -1;
    int bx = -1, by = -1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (x != w / 2 && r.image.at(x, y, 0) > best) best = r.image.at(x, y, 0), bx = x, by = y;
    EXPECT_EQ(std::abs(bx - w / 2), 8);
    EXPECT_EQ(by, h / 2);
    EXPECT_NE(r.summary.find("peak |f| 0.1250"), std::string::npos) << r.summary;
    EXPECT_GE(r.profile.size(), 32u);
}

TEST(LiveAnalysis, FlowReadsAShiftBetweenFrames) {
    const int w = 96, h = 80;
    auto frame = [&](double shift) {
        Image f(w, h, 3);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double v = 0.5 + 0.25 * std::sin(0.31 * (x - shift)) * std::cos(0.23 * y) +
                                 0.15 * std::sin(0.11 * (x - shift) + 0.17 * y);
                for (int c = 0; c < 3; ++c) f.at(x, y, c) = float(v);
            }
        return f;
    };
    const LiveAnalysisResult r = liveFlow(frame(0), frame(2));
    double u = 0, v = 0;
    ASSERT_EQ(std::sscanf(r.summary.c_str(), "mean vector (%lf, %lf)", &u, &v), 2) << r.summary;
    EXPECT_NEAR(u, 2.0, 0.3);
    EXPECT_NEAR(v, 0.0, 0.3);
    EXPECT_EQ(r.image.width(), w);
}

// The live flicker is the flicker measure's: a still frame reads none, an
// inverted one reads much.
TEST(LiveAnalysis, FlickerOfAStillAndOfABlinkingFrame) {
    const int w = 64, h = 48;
    Image a(w, h, 3), b(w, h, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                a.at(x, y, c) = float(hashToUnit(uint32_t(x / 4), uint32_t(y / 4), 9));
                b.at(x, y, c) = 1.0f - a.at(x, y, c);
            }
    double residual = -1, contrast = -1, relative = -1;
    const LiveAnalysisResult still = liveFlicker(a, a);
    ASSERT_EQ(std::sscanf(still.summary.c_str(), "residual %lf (codes)\ncontrast %lf\nresidual / contrast %lf",
                          &residual, &contrast, &relative),
              3)
        << still.summary;
    EXPECT_LT(relative, 0.01);
    const LiveAnalysisResult blink = liveFlicker(a, b);
    ASSERT_EQ(std::sscanf(blink.summary.c_str(), "residual %lf (codes)\ncontrast %lf\nresidual / contrast %lf",
                          &residual, &contrast, &relative),
              3)
        << blink.summary;
    EXPECT_GT(relative, 0.5);
    EXPECT_EQ(blink.image.width(), w);
    // The map's alpha: see-through where nothing flickers (an overlay of a
    // still pattern shows the pattern, not the colour map's zero), opaque
    // where the frame blinks.
    auto meanAlpha = [](const Image& im) {
        double sum = 0;
        for (int y = 0; y < im.height(); ++y)
            for (int x = 0; x < im.width(); ++x) sum += im.at(x, y, 3);
        return sum / double(im.pixelCount());
    };
    ASSERT_EQ(still.image.channels(), 4);
    EXPECT_LT(meanAlpha(still.image), 0.02);
    EXPECT_GT(meanAlpha(blink.image), 0.2);
}

// Samples of independent white noise plus a part shared by the left half:
// the left half correlates with a point in it by ~½, the right half by ~0.
TEST(LiveAnalysis, CorrelationWithAPointOverSamples) {
    const int w = 32, h = 16, n = 2000;
    LiveCorrelation corr(w, h, 4, 8);
    EXPECT_EQ(corr.result().summary, "collecting samples…");
    for (int k = 0; k < n; ++k) {
        Image s(w, h, 1);
        const float shared = float(hashToUnit(uint32_t(k), 0, 1)) - 0.5f;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const float own = float(hashToUnit(uint32_t(k), uint32_t(y * w + x), 2)) - 0.5f;
                s.at(x, y) = x < w / 2 ? shared + own : own;
            }
        corr.add(s);
    }
    EXPECT_EQ(corr.count(), n);
    const LiveAnalysisResult r = corr.result();
    // Diverging palette: red for +, white for 0. Mean red-minus-blue per half.
    auto warmth = [&](int x0, int x1) {
        double sum = 0;
        for (int y = 0; y < h; ++y)
            for (int x = x0; x < x1; ++x)
                if (!(x == 4 && y == 8)) sum += r.image.at(x, y, 0) - r.image.at(x, y, 2);
        return sum / (double(x1 - x0) * h);
    };
    EXPECT_GT(warmth(0, w / 2), 0.2);
    EXPECT_LT(std::abs(warmth(w / 2, w)), 0.05);
    // Alpha follows |correlation|: the correlated half shows, the other is nearly see-through.
    auto alpha = [&](int x0, int x1) {
        double sum = 0;
        for (int y = 0; y < h; ++y)
            for (int x = x0; x < x1; ++x) sum += r.image.at(x, y, 3);
        return sum / (double(x1 - x0) * h);
    };
    EXPECT_GT(alpha(0, w / 2), 0.3);
    EXPECT_LT(alpha(w / 2, w), 0.1);
    EXPECT_NE(r.summary.find("2000 samples"), std::string::npos) << r.summary;
    // The same accumulator's mean and variance: flat for these stationary samples
    // (the left half's variance is twice the right's: shared plus own noise).
    const LiveAnalysisResult variance = corr.result(LiveStatistic::Variance);
    double varianceValue = 0, spread = 0;
    const size_t at = variance.summary.find("variance ");
    ASSERT_NE(at, std::string::npos) << variance.summary;
    ASSERT_EQ(std::sscanf(variance.summary.c_str() + at, "variance %lf (spread %lf)", &varianceValue, &spread), 2);
    EXPECT_NEAR(varianceValue, 1.5 / 12.0, 0.01);  // uniform noise: 1/12 per part, two parts on half the picture
    EXPECT_NE(corr.result(LiveStatistic::Mean).image.data(), variance.image.data());
}

}  // namespace
}  // namespace stochtex
