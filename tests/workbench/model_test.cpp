// The workbench's model, commands, recorder and analysis runner, driven
// without a window (issue 31 item 1).
#include "stochtex/workbench/model.h"

#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>  // key codes only

#include <chrono>
#include <filesystem>
#include <fstream>

#include "stochtex/core/error.h"
#include "stochtex/pattern/presets.h"
#include "stochtex/workbench/analysis_runner.h"
#include "stochtex/workbench/recorder.h"
#include "test_util.h"

namespace stochtex {
namespace {

using A = WorkbenchCommand::Action;

WorkbenchCommand set(const std::string& pointer, const nlohmann::json& value) {
    WorkbenchCommand c = WorkbenchCommand::of(A::Set, 1, pointer);
    c.value = value;
    return c;
}

void tap(WorkbenchModel& m, int key, int mods = 0) {
    m.applyKeyEvent({key, GLFW_PRESS, mods});
    m.applyKeyEvent({key, GLFW_RELEASE, mods});
}

WorkbenchOptions options() {
    WorkbenchOptions o;
    o.camera.view.width = 96;
    o.camera.view.height = 64;
    return o;
}

const char* kColour = "/colormap/shapes/0/colour";

TEST(WorkbenchModel, AnEditIsOneRevisionAndOneBuildOfTheChangedPartsOnly) {
    WorkbenchModel m(WorkbenchDocument::preset("camouflage"), options());
    EXPECT_EQ(m.buildCount(), 1);  // the first revision, built by the constructor
    EXPECT_EQ(m.previewCache().colormapBuilds(), 1);
    EXPECT_EQ(m.previewCache().exampleBuilds(), 2);
    const uint64_t revision = m.document().revision();
    const long long view = m.viewVersion();
    m.apply(set(kColour, "#d02020"), true);
    EXPECT_EQ(m.document().revision(), revision + 1);  // one parse
    EXPECT_EQ(m.buildCount(), 2);                      // one build
    EXPECT_GT(m.viewVersion(), view);                  // the picture is stale
    EXPECT_EQ(m.previewCache().colormapBuilds(), 2);   // the colormap again,
    EXPECT_EQ(m.previewCache().exampleBuilds(), 2);    // not the noises
    EXPECT_EQ(m.parts().builds().colormaps, 2);        // kept in the parts the GPU views are built from
    m.apply(set("/noise_y/components/0/cutoff", 5), true);
    EXPECT_EQ(m.previewCache().colormapBuilds(), 2);
    EXPECT_EQ(m.previewCache().exampleBuilds(), 3);
}

TEST(WorkbenchModel, UndoRedoAndAGestureThatIsOneStep) {
    WorkbenchModel m(WorkbenchDocument::preset("camouflage"), options());
    const nlohmann::json original = m.document().json();
    // A slider dragged over three frames: one undo step.
    for (const char* c : {"#101010", "#202020", "#303030"}) m.applyGesture({{kColour, c}}, true);
    m.applyGesture({}, false);
    const auto now = std::chrono::steady_clock::now();
    EXPECT_FALSE(m.rebuildDue(now, true));  // dragged, and built just now (the constructor)
    EXPECT_TRUE(m.rebuildDue(now, false));
    m.rebuild();
    EXPECT_FALSE(m.rebuildDue(now, false));
    EXPECT_EQ(m.document().json().at(nlohmann::json::json_pointer(kColour)), "#303030");
    m.apply(WorkbenchCommand::of(A::Undo), true);
    EXPECT_EQ(m.document().json(), original);
    EXPECT_EQ(m.notice(), "undone");
    m.apply(WorkbenchCommand::of(A::Redo), true);
    EXPECT_EQ(m.document().json().at(nlohmann::json::json_pointer(kColour)), "#303030");
    // Ctrl+Z is the same command.
    tap(m, GLFW_KEY_Z, GLFW_MOD_CONTROL);
    EXPECT_EQ(m.document().json(), original);
    EXPECT_THROW(m.apply(WorkbenchCommand::of(A::Undo), true), InputError);  // nothing left: a script's step fails
    m.apply(WorkbenchCommand::of(A::Undo));                                  // the window's is a no-op
    EXPECT_TRUE(m.error().empty());
}

TEST(WorkbenchModel, AScriptsRefusalFailsTheRunAndTheWindowsIsShown) {
    WorkbenchModel m(WorkbenchDocument::preset("camouflage"), options());
    const nlohmann::json original = m.document().json();
    try {
        m.apply(set("/colormap/shapes/0/colour", "not a colour"), true);
        FAIL() << "a scripted edit the pattern refuses must throw";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("colour"), std::string::npos) << e.what();
    }
    EXPECT_EQ(m.document().json(), original);
    m.applyGesture({{kColour, "not a colour"}}, false);
    EXPECT_NE(m.error().find("colour"), std::string::npos) << m.error();
    EXPECT_EQ(m.document().json(), original);
    WorkbenchCommand mouse = WorkbenchCommand::of(A::MouseDown);
    EXPECT_THROW(m.apply(mouse, true), InputError);  // a pattern has no iMouse
}

TEST(WorkbenchModel, KeysAreTheCommandsTheHelpLists) {
    WorkbenchOptions o = options();
    o.filter.aniso = 4;
    WorkbenchModel m(WorkbenchDocument::preset("camouflage"), o);
    tap(m, GLFW_KEY_1);
    EXPECT_EQ(m.shown().filterName, "none");
    tap(m, GLFW_KEY_2);
    EXPECT_EQ(m.shown().filterName, "paper");
    tap(m, GLFW_KEY_3);
    EXPECT_EQ(m.shown().filterName, "smooth");
    tap(m, GLFW_KEY_LEFT_BRACKET);
    EXPECT_EQ(m.shown().filter.aniso, 2);
    for (int k = 0; k < 3; ++k) tap(m, GLFW_KEY_LEFT_BRACKET);
    EXPECT_EQ(m.shown().filter.aniso, 1);  // at least 1
    tap(m, GLFW_KEY_V);
    EXPECT_EQ(m.shown().view, WorkbenchView::Plane);
    tap(m, GLFW_KEY_UP);
    EXPECT_DOUBLE_EQ(m.shown().camera.tiltDeg, o.camera.tiltDeg + 2.0);
    for (int k = 0; k < 3; ++k) tap(m, GLFW_KEY_V);
    EXPECT_EQ(m.shown().view, WorkbenchView::Zoom);  // round
    m.takeAnalysisRestart();
    tap(m, GLFW_KEY_M);
    EXPECT_EQ(m.shown().mode, WorkbenchMode::Analysis);
    EXPECT_TRUE(m.takeAnalysisRestart());
    EXPECT_FALSE(m.takeAnalysisRestart());  // read once
    tap(m, GLFW_KEY_A);
    EXPECT_EQ(m.shown().analysis, LiveAnalysisKind::Flow);
    tap(m, GLFW_KEY_L);  // no normal map: the response stays
    EXPECT_EQ(m.shown().response, ResponseKind::PrefilteredColormap);
    tap(m, GLFW_KEY_TAB);
    EXPECT_FALSE(m.shown().panel);
    tap(m, GLFW_KEY_F1);
    EXPECT_TRUE(m.shown().help);
    tap(m, GLFW_KEY_D);
    EXPECT_EQ(m.shown().derivatives, GpuView::Derivatives::Rasterizer);
    EXPECT_FALSE(m.screenshotsPending());
    tap(m, GLFW_KEY_F2);
    EXPECT_TRUE(m.screenshotsPending());
    ASSERT_EQ(m.takeScreenshots().size(), 1u);
    EXPECT_FALSE(m.shown().quit);
    tap(m, GLFW_KEY_ESCAPE);
    EXPECT_TRUE(m.shown().quit);
    // A script's key step is the same tap.
    WorkbenchCommand key = WorkbenchCommand::of(A::Key);
    key.key = GLFW_KEY_2;
    m.apply(key, true);
    EXPECT_EQ(m.shown().filterName, "paper");
}

// The estimator control changes the filter the picture's view is built
// with, and asks for a new view (a new program: its loop's sub-probes).
// The mesh view is offered only with a mesh: V skips it without one (torus
// → zoom) and goes to it with one (torus → mesh → zoom); a script's step
// to it without one is refused naming the view.
TEST(WorkbenchModel, TheMeshViewIsOfferedOnlyWithAMesh) {
    WorkbenchOptions o = options();
    o.view = WorkbenchView::Torus;
    WorkbenchModel bare(WorkbenchDocument::preset("camouflage"), o);
    tap(bare, GLFW_KEY_V);
    EXPECT_EQ(bare.shown().view, WorkbenchView::Zoom);
    EXPECT_EQ(test::inputErrorOf([&] { bare.apply(WorkbenchCommand::of(A::View, 0, "mesh"), true); }).parameter(),
              "view");
    auto mesh = std::make_shared<LoadedMesh>();
    mesh->mesh = makeSphere(16);
    mesh->hasUv = true;
    o.mesh = mesh;
    o.mapping = SurfaceMapping::Triplanar;
    WorkbenchModel withMesh(WorkbenchDocument::preset("camouflage"), o);
    tap(withMesh, GLFW_KEY_V);
    EXPECT_EQ(withMesh.shown().view, WorkbenchView::Mesh);
    EXPECT_TRUE(withMesh.isScene());
    EXPECT_EQ(withMesh.mesh(), mesh.get());
    EXPECT_EQ(withMesh.mapping(), SurfaceMapping::Triplanar);
    tap(withMesh, GLFW_KEY_V);
    EXPECT_EQ(withMesh.shown().view, WorkbenchView::Zoom);
    o.mesh = nullptr;
    o.view = WorkbenchView::Mesh;
    EXPECT_EQ(test::inputErrorOf([&] { validateWorkbenchOptions(o); }).parameter(), "view");
}

TEST(WorkbenchModel, TheEstimatorStepSetsTheFiltersEstimator) {
    WorkbenchModel m(WorkbenchDocument::preset("camouflage"), options());
    EXPECT_EQ(m.shown().filter.estimator, VarianceEstimator::Paper);
    const long long before = m.viewVersion();
    m.apply(WorkbenchCommand::of(A::Estimator, 0, "sub-probes"), true);
    EXPECT_EQ(m.shown().filter.estimator, VarianceEstimator::SubProbes);
    EXPECT_GT(m.viewVersion(), before);
    EXPECT_THROW(m.apply(WorkbenchCommand::of(A::Estimator, 0, "dh"), true), InputError);
}

TEST(WorkbenchModel, ZoomKeepsThePointUnderTheCursorAndPanMovesByPixels) {
    WorkbenchModel m(WorkbenchDocument::preset("camouflage"), options());
    const View before = m.shown().camera.view;
    m.apply(WorkbenchCommand::at(A::Zoom, 30, 20, 2.0));
    const View& after = m.shown().camera.view;
    EXPECT_DOUBLE_EQ(after.scale, before.scale / 2);
    EXPECT_NEAR(after.offsetU + 30 * after.scale, before.offsetU + 30 * before.scale, 1e-12);
    EXPECT_NEAR(after.offsetV + 20 * after.scale, before.offsetV + 20 * before.scale, 1e-12);
    const double u = after.offsetU, v = after.offsetV;
    m.apply(WorkbenchCommand::at(A::Pan, 4, -2));
    EXPECT_NEAR(m.shown().camera.view.offsetU, u - 4 * after.scale, 1e-12);
    EXPECT_NEAR(m.shown().camera.view.offsetV, v + 2 * after.scale, 1e-12);
}

TEST(WorkbenchModel, AProgramTakesItsKeysAndMouseAndRefusesEdits) {
    WorkbenchModel m(WorkbenchDocument::shadertoy(std::string(STOCHTEX_SHADERTOY_EXAMPLES) + "/swirl"), options());
    EXPECT_TRUE(m.takeProgramRestart());  // built by the picture at its size
    tap(m, GLFW_KEY_W);
    const auto keys = m.takeProgramKeys();
    ASSERT_EQ(keys.size(), 2u);
    EXPECT_EQ(keys[0], std::make_pair(int('W'), true));
    EXPECT_EQ(keys[1], std::make_pair(int('W'), false));
    m.apply(WorkbenchCommand::at(A::MouseDown, 10, 5), true);
    const auto inputs = m.takeProgramInputs();
    ASSERT_EQ(inputs.size(), 1u);
    EXPECT_EQ(inputs[0].kind, ShadertoyInput::Kind::MouseDown);
    EXPECT_EQ(inputs[0].x, 10.0f);
    EXPECT_THROW(m.apply(set("/x", 1), true), InputError);
    tap(m, GLFW_KEY_F4);
    EXPECT_TRUE(m.shown().paused);
}

class WorkbenchModelFiles : public test::ScratchFolder {};

// A pattern file that names its estimator opens with it.
TEST_F(WorkbenchModelFiles, APatternFilesEstimatorIsTheOneShownFirst) {
    const std::filesystem::path file = dir_ / "e.json";
    nlohmann::json j = nlohmann::json::parse(presetText("camouflage"));
    j["size"] = 64;
    j["estimator"] = "sub-probes-4x4";
    std::ofstream(file) << j.dump();
    const WorkbenchModel m(WorkbenchDocument::patternFile(file.string()), options());
    EXPECT_EQ(m.shown().filter.estimator, VarianceEstimator::SubProbes4x4);
}

TEST_F(WorkbenchModelFiles, AFileChangedOnDiskIsReloadedAndItsPartsBuiltAgain) {
    const std::filesystem::path file = dir_ / "p.json";
    nlohmann::json j = nlohmann::json::parse(presetText("camouflage"));
    j["size"] = 64;
    std::ofstream(file) << j.dump();
    WorkbenchModel m(WorkbenchDocument::patternFile(file.string()), options());
    const auto start = std::chrono::steady_clock::now();
    m.watchFiles(start);
    EXPECT_EQ(m.buildCount(), 1);  // nothing changed
    const int colormaps = m.parts().builds().colormaps;
    // A noise edited on disk: the colormap's spec is the same, but what the
    // old files gave is not kept (an image it names may have changed).
    j["noise_y"]["components"][0]["cutoff"] = 5;
    std::ofstream(file) << j.dump();
    std::filesystem::last_write_time(file, std::filesystem::last_write_time(file) + std::chrono::seconds(2));
    m.watchFiles(start + std::chrono::milliseconds(100));  // looked at twice a second: not yet
    EXPECT_EQ(m.buildCount(), 1);
    m.watchFiles(start + std::chrono::seconds(1));
    EXPECT_EQ(m.buildCount(), 2);
    EXPECT_EQ(m.notice(), "reloaded " + m.document().source());
    EXPECT_EQ(m.document().json()["noise_y"]["components"][0]["cutoff"], 5);
    EXPECT_EQ(m.parts().builds().colormaps, colormaps + 1);
    EXPECT_EQ(m.previewCache().exampleBuilds(), 4);
    // A file that no longer parses: the error is shown, the last build stays.
    std::ofstream(file) << "{ not json";
    std::filesystem::last_write_time(file, std::filesystem::last_write_time(file) + std::chrono::seconds(4));
    m.watchFiles(start + std::chrono::seconds(2));
    EXPECT_EQ(m.error().rfind("reload: ", 0), 0u) << m.error();
    EXPECT_EQ(m.buildCount(), 2);
}

class WorkbenchRecorderTest : public test::ScratchFolder {};

TEST_F(WorkbenchRecorderTest, APatternsPicturesGoOnTheWallClockAndAProgramsOnItsFrames) {
    const Image grey(16, 8, 3, 0.5f), white(16, 8, 3, 1.0f);
    WorkbenchRecorder r;
    r.start((dir_ / "pattern").string() + "/", 16, 8, 10.0);
    EXPECT_TRUE(r.recording());
    EXPECT_TRUE(r.addPicture(grey, 100.0));  // the clock starts here
    EXPECT_EQ(r.framesWritten(), 0);
    EXPECT_TRUE(r.addPicture(white, 100.05));  // frame 0 (t = 0) showed grey
    EXPECT_EQ(r.framesWritten(), 1);
    EXPECT_TRUE(r.addPicture(grey, 100.35));  // frames 1–3 (0.1, 0.2, 0.3 s) showed white
    EXPECT_EQ(r.framesWritten(), 4);
    EXPECT_EQ(r.stop(), (dir_ / "pattern").string() + "/");  // the held picture: one frame
    EXPECT_EQ(r.framesWritten(), 5);
    EXPECT_FALSE(r.recording());
    EXPECT_TRUE(std::filesystem::exists(dir_ / "pattern" / "frame_0004.png"));
    EXPECT_FALSE(std::filesystem::exists(dir_ / "pattern" / "frame_0005.png"));

    r.start((dir_ / "program").string() + "/", 16, 8, 10.0);
    for (long long f : {0, 0, 1, 2, 2, 3}) EXPECT_TRUE(r.addProgramFrame(grey, f));  // a paused frame adds none
    EXPECT_EQ(r.framesWritten(), 4);
    EXPECT_FALSE(r.addProgramFrame(Image(8, 8, 3, 0.5f), 4));  // another size: stopped
    EXPECT_FALSE(r.recording());
}

TEST(LiveAnalysisRunner, TheNewestFrameReplacesOneWaitingAndACaptureWaitsForItsOwn) {
    LiveAnalysisRunner runner;
    runner.queue(LiveAnalysisKind::Spectrum, Image(32, 32, 3, 0.5f));
    runner.collect(LiveAnalysisKind::Spectrum, false);
    EXPECT_TRUE(runner.running());  // started beside the window (its result is held until collected)
    runner.queue(LiveAnalysisKind::Spectrum, Image(48, 48, 3, 0.5f));
    runner.queue(LiveAnalysisKind::Spectrum, Image(64, 64, 3, 0.5f));  // replaces the 48² one, still waiting
    const std::optional<LiveAnalysisResult> r = runner.collect(LiveAnalysisKind::Spectrum, true);
    ASSERT_TRUE(r.has_value());
    EXPECT_EQ(r->image.width(), 64);  // the newest frame's own analysis
    EXPECT_FALSE(runner.running());
    // One of an analysis since switched away from is dropped.
    runner.queue(LiveAnalysisKind::Flicker, Image(32, 32, 3, 0.5f));
    EXPECT_FALSE(runner.collect(LiveAnalysisKind::Spectrum, true).has_value());
    // The correlation starts again when its point moves.
    LiveCorrelation& c = runner.correlation(16, 16, 4, 4, false);
    c.add(Image(16, 16, 3, 0.25f));
    EXPECT_EQ(runner.correlationSamples(), 1);
    runner.correlation(16, 16, 4, 4, false);
    EXPECT_EQ(runner.correlationSamples(), 1);
    runner.correlation(16, 16, 5, 4, false);
    EXPECT_EQ(runner.correlationSamples(), 0);
}

}  // namespace
}  // namespace stochtex
