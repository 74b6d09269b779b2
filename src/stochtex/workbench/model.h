#pragma once
// The workbench's model (issue 31 item 1): the document and what is built
// from it (the spec, the previews, the program's kept parts), what is shown
// and how (camera, filter, view, mode, analysis), the session's recording
// and the requests the window carries out (screenshots, a program's keys and
// mouse). Everything that changes it is a WorkbenchCommand — a key, the
// mouse, a panel's control or a script step — applied by one function,
// apply(); the panels and the picture only read it. It holds no window, GL
// context or ImGui state, so the tests drive it without a display.
#include <array>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "stochtex/gpu/gpu_view.h"
#include "stochtex/gpu/scene.h"
#include "stochtex/gpu/shadertoy_input.h"
#include "stochtex/gpu/texture_display.h"
#include "stochtex/pattern/part_cache.h"
#include "stochtex/workbench/document.h"
#include "stochtex/workbench/editors.h"
#include "stochtex/workbench/options.h"
#include "stochtex/workbench/previews.h"
#include "stochtex/workbench/recorder.h"

namespace stochtex {

// The eye of the 3D views orbits the object's centre; it starts where
// `scene` puts it (SceneCamera's default eye and target).
struct Orbit {
    std::array<float, 3> target = SceneCamera{}.target;
    double distance = 0, yawDeg = 0, pitchDeg = 0;
    Orbit();
    SceneCamera camera() const;
};

// What is shown and how: changed by commands only.
struct WorkbenchShown {
    Camera camera;
    FilterOptions filter;    // its aniso and covariance; the filter itself is `filterName`
    std::string filterName;  // none, paper or smooth
    ResponseKind response = ResponseKind::PrefilteredColormap;
    GpuView::Derivatives derivatives = GpuView::Derivatives::Camera;
    WorkbenchView view = WorkbenchView::Zoom;
    WorkbenchMode mode = WorkbenchMode::Texture;
    LiveAnalysisKind analysis = LiveAnalysisKind::Spectrum;
    LiveStatistic statistic = LiveStatistic::Correlation;
    Orbit orbit;
    float split = 0.5f;           // split mode: where the analysis starts, a fraction of the picture's width
    float overlayOpacity = 0.5f;  // overlay mode: the analysis's opacity
    int pickX = -1, pickY = -1;   // the correlation's point, picture pixels (−1: the centre)
    bool panel = true, help = false, paused = false, quit = false;

    // The camera of the flat (zoom) or plane view drawn at width × height
    // pixels: the picture's, and the correlation's instances of it.
    Camera viewCamera(int width, int height) const;
};

// A key as GLFW reports it.
struct KeyEvent {
    int key = 0, action = 0, mods = 0;
};

class WorkbenchModel {
public:
    WorkbenchModel(WorkbenchDocument document, const WorkbenchOptions& options);
    ~WorkbenchModel();

    // --- the document and what is built from it ---
    const WorkbenchDocument& document() const { return doc_; }
    bool isShadertoy() const { return doc_.kind() == WorkbenchDocument::Kind::Shadertoy; }
    // The revision built last (a pattern's): its spec, previews and kept
    // parts (the document may be ahead of it while an edit waits).
    const PatternSpec& spec() const { return spec_; }
    const PatternPreviews& previews() const { return previews_.previews(); }
    const PreviewCache& previewCache() const { return previews_; }
    PartCache& parts() { return parts_; }
    bool hasNormalMap() const { return hasNormalMap_; }
    // Counts builds: the picture drops what it made of an older one.
    long long buildCount() const { return builds_; }
    // Builds what the document's revision needs (a pattern's previews, a
    // new generation of parts; a program's host is rebuilt by the picture).
    // A failure is shown (error()) and the last build stays.
    void rebuild();
    // Whether a rebuild is due: an edit is waiting, and no control is being
    // dragged or 0.3 s passed since the last build.
    bool rebuildDue(std::chrono::steady_clock::time_point now, bool dragging) const;
    // The files on disk, looked at twice a second: a change reloads them.
    void watchFiles(std::chrono::steady_clock::time_point now);
    // The panel's edits of one frame. A gesture — a slider or a shape
    // dragged over many frames, or one click — is one undo step: the state
    // before it is marked when its first edit comes; `held`: the mouse or a
    // widget is still held, so the gesture goes on.
    void applyGesture(const std::vector<JsonEdit>& edits, bool held);

    // --- commands ---
    // Applies one command. A scripted command that is refused throws
    // InputError (the run fails); the window's are shown in the panel.
    void apply(const WorkbenchCommand& command, bool scripted = false);
    // A key pressed, held or released, as the commands the help window lists for it.
    void applyKeyEvent(const KeyEvent& e);
    // The window's framebuffer in pixels and its pixels per window
    // coordinate (HiDPI: 2), set by the window each frame; with the panel
    // shown (kWorkbenchPanelWidth coordinates at the left) and the mode,
    // they give the picture area and the texture's part of it (all of it,
    // or the left half side by side), as now — a recording's size.
    void setWindow(int width, int height, float pixelScale);
    int panelWidth() const;
    DisplayRect pictureRect() const;
    DisplayRect textureRect() const;
    float pixelScale() const { return pixelScale_; }

    // --- what is shown ---
    const WorkbenchShown& shown() const { return shown_; }
    bool isScene() const {
        return shown_.view == WorkbenchView::Sphere || shown_.view == WorkbenchView::Torus ||
               shown_.view == WorkbenchView::Mesh;
    }
    // The user's mesh of the mesh view (nullptr: none loaded, the view is not offered) and its mapping.
    const LoadedMesh* mesh() const { return mesh_.get(); }
    SurfaceMapping mapping() const { return mapping_; }
    bool analysing() const { return shown_.mode != WorkbenchMode::Texture; }
    // Changes whenever something the picture shows does: analyses of the old picture are stale.
    long long viewVersion() const { return viewVersion_; }
    void viewChanged() { ++viewVersion_; }
    // The analysis must start again (its kind, mode, point or samples changed); read once.
    bool takeAnalysisRestart() { return std::exchange(analysisRestart_, false); }
    // What failed last and what was done last, for the panel.
    const std::string& error() const { return error_; }
    const std::string& notice() const { return notice_; }
    void showError(const std::string& message) { error_ = message; }
    void showNotice(const std::string& message) { notice_ = message; }

    // --- what the window carries out ---
    // Screenshots asked for since the last call: F2's (a failure is shown)
    // and the script's (a failure fails the run).
    std::vector<std::string> takeScreenshots() { return std::exchange(screenshots_, {}); }
    std::vector<std::string> takeScriptScreenshots() { return std::exchange(scriptScreenshots_, {}); }
    bool screenshotsPending() const { return !screenshots_.empty() || !scriptScreenshots_.empty(); }
    // A program's mouse and keys since its last frame (the window's and a script's).
    std::vector<ShadertoyInput> takeProgramInputs() { return std::exchange(programInputs_, {}); }
    std::vector<std::pair<int, bool>> takeProgramKeys() { return std::exchange(programKeys_, {}); }
    // The program is to be built again (the panel's restart, a reload).
    bool takeProgramRestart() { return std::exchange(programRestart_, false); }
    WorkbenchRecorder& recorder() { return recorder_; }

private:
    void build();  // rebuild()'s work, which throws
    void zoomAt(double factor, double px, double py);
    void pan(double dx, double dy);
    bool applyEdit(const JsonEdit& e);  // false: refused (shown)
    void reload();
    void save(const std::string& path);
    void saveDefault();
    void startRecording(const std::string& path);
    void stopRecording();
    template <class F>
    void guarded(F&& action);

    WorkbenchDocument doc_;
    PatternSpec spec_;
    PreviewCache previews_;
    PartCache parts_;
    bool hasNormalMap_ = false;
    std::shared_ptr<const LoadedMesh> mesh_;
    SurfaceMapping mapping_ = SurfaceMapping::Uv;
    long long builds_ = 0;
    bool needsRebuild_ = false, gestureOpen_ = false;
    std::chrono::steady_clock::time_point lastBuild_{}, lastWatch_{};

    WorkbenchShown shown_;
    std::array<int, 2> window_{1, 1};
    float pixelScale_ = 1;
    long long viewVersion_ = 0;
    bool analysisRestart_ = true;
    std::string error_, notice_;

    std::vector<std::string> screenshots_, scriptScreenshots_;
    std::vector<ShadertoyInput> programInputs_;
    std::vector<std::pair<int, bool>> programKeys_;  // JavaScript key code, pressed
    bool programRestart_ = false;
    WorkbenchRecorder recorder_;
    double fps_ = 60;
};

// ShaderToy's keyboard texture is indexed by JavaScript key codes: GLFW's
// letters, digits and space are the same; a few others differ (−1: none).
int javascriptKeyCode(int glfwKey);

}  // namespace stochtex
