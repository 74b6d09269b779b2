#include "stochtex/workbench/model.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>  // the key codes alone: the model opens no window

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "stochtex/core/error.h"
#include "stochtex/pattern/param_info.h"

namespace stochtex {

Camera WorkbenchShown::viewCamera(int width, int height) const {
    Camera c = camera;
    c.kind = view == WorkbenchView::Plane ? Camera::Kind::Plane : Camera::Kind::Zoom;
    c.view.width = width;
    c.view.height = height;
    return c;
}

namespace {

double orbitLength(const SceneCamera& c) {
    const double x = c.eye[0] - c.target[0], y = c.eye[1] - c.target[1], z = c.eye[2] - c.target[2];
    return std::sqrt(x * x + y * y + z * z);
}

// A file name in the current folder that does not exist yet: stem-N.ext.
std::string freshName(const std::string& stem, const std::string& ext) {
    for (int i = 1;; ++i) {
        const std::string name = stem + "-" + std::to_string(i) + ext;
        if (!std::filesystem::exists(name)) return name;
    }
}

}  // namespace

Orbit::Orbit()
    : distance(orbitLength(SceneCamera{})),
      pitchDeg(std::asin((SceneCamera{}.eye[1] - SceneCamera{}.target[1]) / orbitLength(SceneCamera{})) * 180.0 /
               std::numbers::pi) {}

SceneCamera Orbit::camera() const {
    SceneCamera c;
    const double yaw = yawDeg * std::numbers::pi / 180.0, p = pitchDeg * std::numbers::pi / 180.0;
    c.target = target;
    c.eye = {float(target[0] + distance * std::cos(p) * std::sin(yaw)), float(target[1] + distance * std::sin(p)),
             float(target[2] + distance * std::cos(p) * std::cos(yaw))};
    return c;
}

int javascriptKeyCode(int glfwKey) {
    if ((glfwKey >= GLFW_KEY_A && glfwKey <= GLFW_KEY_Z) || (glfwKey >= GLFW_KEY_0 && glfwKey <= GLFW_KEY_9) ||
        glfwKey == GLFW_KEY_SPACE)
        return glfwKey;
    switch (glfwKey) {
        case GLFW_KEY_LEFT: return 37;
        case GLFW_KEY_UP: return 38;
        case GLFW_KEY_RIGHT: return 39;
        case GLFW_KEY_DOWN: return 40;
        case GLFW_KEY_ENTER: return 13;
        case GLFW_KEY_LEFT_SHIFT: return 16;
        case GLFW_KEY_LEFT_CONTROL: return 17;
        default: return -1;
    }
}

WorkbenchModel::WorkbenchModel(WorkbenchDocument document, const WorkbenchOptions& options)
    : doc_(std::move(document)), mesh_(options.mesh), mapping_(options.mapping), fps_(options.shadertoy.fps) {
    shown_.camera = options.camera;
    shown_.filter = options.filter;
    shown_.view = options.view;
    shown_.mode = options.mode;
    shown_.analysis = options.analysis;
    shown_.panel = options.panel;
    const FilterOptions& f = options.filter;
    shown_.filterName =
        f.source == StatisticsSource::Point
            ? "none"
            : filterName(FilterOptions{}.use({f.source, {ResponseKind::PrefilteredColormap, f.response.prefilter}}));
    shown_.response = f.response.kind;
    build();  // a document that does not build fails the run here
    // A pattern file that names its estimator opens with it (the panel changes it).
    if (!isShadertoy() && spec_.estimator) shown_.filter.estimator = *spec_.estimator;
}

WorkbenchModel::~WorkbenchModel() {
    try {
        stopRecording();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "stochtex: the recording could not be finished: %s\n", e.what());
    }
}

template <class F>
void WorkbenchModel::guarded(F&& action) {
    try {
        action();
    } catch (const std::exception& e) {
        error_ = e.what();
    }
}

// --- the document ---

void WorkbenchModel::build() {
    needsRebuild_ = false;
    ++builds_;
    viewChanged();
    if (isShadertoy()) {
        // Rebuilt at the picture's size on the next frame; the old one
        // stays on screen if the program no longer compiles.
        programRestart_ = true;
    } else {
        parts_.beginGeneration();  // the parts of the revisions before stay: an undo rebuilds nothing
        spec_ = doc_.patternSpec();
        hasNormalMap_ = spec_.normalMap.has_value() && !spec_.graph;
        if (!hasNormalMap_) shown_.response = ResponseKind::PrefilteredColormap;
        previews_.update(spec_, &parts_);  // the colormap canvas and the examples, where their specs changed
    }
    lastBuild_ = std::chrono::steady_clock::now();  // a drag's next rebuild waits 0.3 s from here
}

void WorkbenchModel::rebuild() {
    try {
        build();
        error_.clear();
    } catch (const std::exception& e) {
        error_ = e.what();
    }
}

bool WorkbenchModel::rebuildDue(std::chrono::steady_clock::time_point now, bool dragging) const {
    return needsRebuild_ && (!dragging || now - lastBuild_ > std::chrono::milliseconds(300));
}

void WorkbenchModel::watchFiles(std::chrono::steady_clock::time_point now) {
    if (now - lastWatch_ < std::chrono::milliseconds(500)) return;
    lastWatch_ = now;
    if (doc_.changedOnDisk()) reload();
}

void WorkbenchModel::reload() {
    try {
        doc_.reload();
        previews_.clear();
        parts_.clear();  // the files the specs name may have changed
        build();
        error_.clear();
        notice_ = "reloaded " + doc_.source();
    } catch (const std::exception& e) {
        error_ = std::string("reload: ") + e.what();
    }
}

bool WorkbenchModel::applyEdit(const JsonEdit& e) {
    try {
        if (e.remove)
            doc_.remove(e.pointer);
        else
            doc_.set(e.pointer, e.value);
        error_.clear();
        needsRebuild_ = true;
        return true;
    } catch (const InputError& x) {
        error_ = x.what();
        return false;
    }
}

void WorkbenchModel::applyGesture(const std::vector<JsonEdit>& edits, bool held) {
    if (!edits.empty() && !gestureOpen_) {
        doc_.checkpoint();
        gestureOpen_ = true;
    }
    for (const JsonEdit& e : edits) applyEdit(e);
    gestureOpen_ = gestureOpen_ && held;
}

void WorkbenchModel::save(const std::string& path) {
    doc_.save(path);
    notice_ = "saved " + path;
}

void WorkbenchModel::saveDefault() {
    if (isShadertoy()) return;
    const bool preset = doc_.source().rfind("preset ", 0) == 0;
    save(preset ? doc_.source().substr(7) + ".json" : doc_.source());
}

void WorkbenchModel::setWindow(int width, int height, float pixelScale) {
    window_ = {std::max(1, width), std::max(1, height)};
    pixelScale_ = pixelScale > 0 && std::isfinite(pixelScale) ? pixelScale : 1.0f;
}

int WorkbenchModel::panelWidth() const {
    return shown_.panel ? int(std::lround(kWorkbenchPanelWidth * pixelScale_)) : 0;
}

DisplayRect WorkbenchModel::pictureRect() const {
    return {panelWidth(), 0, std::max(1, window_[0] - panelWidth()), window_[1]};
}

DisplayRect WorkbenchModel::textureRect() const {
    const int w = window_[0] - panelWidth();
    const int tw = shown_.mode == WorkbenchMode::SideBySide ? w / 2 : w;
    return {panelWidth(), 0, std::max(1, tw), window_[1]};
}

void WorkbenchModel::startRecording(const std::string& path) {
    stopRecording();
    const DisplayRect picture = pictureRect();  // as the panel and mode are now
    recorder_.start(path, picture.width, picture.height, fps_);
    notice_ = "recording " + path;
}

void WorkbenchModel::stopRecording() {
    if (!recorder_.recording()) return;
    notice_ = "wrote " + recorder_.stop();
}

// --- commands ---

void WorkbenchModel::zoomAt(double factor, double px, double py) {
    if (isScene()) {
        shown_.orbit.distance = std::clamp(shown_.orbit.distance / factor, 1.3, 20.0);
    } else {
        View& v = shown_.camera.view;
        const double next = std::clamp(v.scale / factor, 1.0 / 64.0, 4096.0);
        v.offsetU += px * (v.scale - next);
        v.offsetV += py * (v.scale - next);
        v.scale = next;
    }
    viewChanged();
}

void WorkbenchModel::pan(double dx, double dy) {
    if (isScene()) {
        shown_.orbit.yawDeg -= dx * 0.4;
        shown_.orbit.pitchDeg = std::clamp(shown_.orbit.pitchDeg + dy * 0.4, -80.0, 80.0);
    } else {
        shown_.camera.view.offsetU -= dx * shown_.camera.view.scale;
        shown_.camera.view.offsetV -= dy * shown_.camera.view.scale;
    }
    viewChanged();
}

void WorkbenchModel::apply(const WorkbenchCommand& c, bool scripted) {
    using A = WorkbenchCommand::Action;
    const bool edit = c.action == A::Set || c.action == A::Save || c.action == A::Undo || c.action == A::Redo;
    if (scripted && edit && isShadertoy())
        throw InputError(
            "script: a ShaderToy program is edited in its files, not by \"set\", \"undo\", \"redo\" or \"save\"");
    const bool mouse = c.action == A::MouseDown || c.action == A::MouseMove || c.action == A::MouseUp;
    if (scripted && mouse && !isShadertoy())
        throw InputError("script: a mouse step drives a ShaderToy program's iMouse; this is a pattern");
    // A scripted command has no one to read the panel: what it leaves in
    // error() fails the run, and what it throws passes through.
    const auto checked = [&] {
        if (scripted && !error_.empty()) throw InputError(error_);
    };
    const auto run = [&](auto&& action) {
        if (scripted)
            action();
        else
            guarded(action);
    };
    WorkbenchShown& s = shown_;
    switch (c.action) {
        case A::Zoom: zoomAt(c.amount, c.x, c.y); break;
        case A::Pan: pan(c.x, c.y); break;
        case A::Filter: s.filterName = c.text, viewChanged(); break;
        case A::Aniso: {
            const int k = std::clamp(int(c.amount), 1, int(kMaxAnisotropy));
            if (k != s.filter.aniso) s.filter.aniso = k, viewChanged();
            break;
        }
        case A::Estimator:
            s.filter.estimator = parseEnum(kVarianceEstimatorNames, c.text, "estimator"), viewChanged();
            break;
        case A::Response:
            s.response = parseEnum(kResponseKindNames, c.text, "response");
            if (s.response == ResponseKind::Lean && !hasNormalMap_) s.response = ResponseKind::PrefilteredColormap;
            viewChanged();
            break;
        case A::Derivatives:
            s.derivatives = c.amount != 0 ? GpuView::Derivatives::Rasterizer : GpuView::Derivatives::Camera;
            viewChanged();
            break;
        case A::Tilt: s.camera.tiltDeg = std::clamp(c.amount, 0.0, 89.0), viewChanged(); break;
        case A::View: {
            const WorkbenchView view = parseEnum(kWorkbenchViewNames, c.text, "view");
            if (view == WorkbenchView::Mesh && !mesh_) throw InputError::parameter("view", "mesh needs a mesh file");
            s.view = view;
            viewChanged();
            break;
        }
        case A::Mode: s.mode = parseEnum(kWorkbenchModeNames, c.text, "mode"), analysisRestart_ = true; break;
        case A::Analysis:
            s.analysis = parseEnum(kLiveAnalysisNames, c.text, "analysis"), analysisRestart_ = true;
            break;
        case A::Statistic: s.statistic = parseEnum(kLiveStatisticNames, c.text, "statistic"); break;
        case A::Pick: s.pickX = int(c.x), s.pickY = int(c.y), analysisRestart_ = true; break;
        case A::Split: s.split = float(std::clamp(c.amount, 0.0, 1.0)); break;
        case A::Opacity: s.overlayOpacity = float(std::clamp(c.amount, 0.0, 1.0)); break;
        case A::Pause: s.paused = c.amount != 0; break;
        case A::Panel: s.panel = !s.panel; break;
        case A::Help: s.help = !s.help; break;
        case A::Set:
            // The panel's path: the edit, then the rebuild.
            doc_.checkpoint();
            gestureOpen_ = false;
            if (!applyEdit({c.text, c.value})) {
                checked();
                break;  // refused: shown, nothing to build
            }
            rebuild();
            checked();
            break;
        case A::Undo:
        case A::Redo: {
            gestureOpen_ = false;  // an edit after it is a step of its own
            const bool undo = c.action == A::Undo;
            bool moved = false;
            run([&] { moved = undo ? doc_.undo() : doc_.redo(); });
            if (!moved) {
                if (scripted) throw InputError(std::string("script: nothing to ") + (undo ? "undo" : "redo"));
                break;
            }
            notice_ = undo ? "undone" : "redone";
            if (scripted)
                rebuild();  // before the next step, which may read it
            else
                needsRebuild_ = true;
            checked();
            break;
        }
        case A::Reload: reload(); break;
        case A::Save: run([&] { save(c.text); }); break;
        case A::SaveDefault: run([&] { saveDefault(); }); break;
        case A::Screenshot: (scripted ? scriptScreenshots_ : screenshots_).push_back(c.text); break;
        case A::Record: run([&] { startRecording(c.text); }); break;
        case A::StopRecording: run([&] { stopRecording(); }); break;
        case A::ToggleRecording:
            run([&] {
                recorder_.recording() ? stopRecording() : startRecording(freshName("stochtex-recording", ".mp4"));
            });
            break;
        case A::RestartProgram: programRestart_ = true; break;
        case A::Key:  // a tap within one frame, as the window's callback queues it
            applyKeyEvent({c.key, GLFW_PRESS, c.mods});
            applyKeyEvent({c.key, GLFW_RELEASE, c.mods});
            break;
        case A::MouseDown:
        case A::MouseMove:
        case A::MouseUp:
            // Applied before the program's next frame (its host may not be built yet).
            programInputs_.push_back({0,
                                      c.action == A::MouseDown   ? ShadertoyInput::Kind::MouseDown
                                      : c.action == A::MouseMove ? ShadertoyInput::Kind::MouseMove
                                                                 : ShadertoyInput::Kind::MouseUp,
                                      0, float(c.x), float(c.y)});
            break;
        case A::Quit: s.quit = true; break;
    }
}

// A key's commands: the keys the help window lists (workbench.cpp).
void WorkbenchModel::applyKeyEvent(const KeyEvent& e) {
    using A = WorkbenchCommand::Action;
    const bool press = e.action == GLFW_PRESS, ctrl = (e.mods & GLFW_MOD_CONTROL) != 0;
    const auto pressed = [&](int key) { return press && e.key == key; };
    const auto command = [&](A action, double amount = 0, std::string text = {}) {
        apply(WorkbenchCommand::of(action, amount, std::move(text)));
    };
    const WorkbenchShown& s = shown_;
    if (pressed(GLFW_KEY_ESCAPE)) command(A::Quit);
    if (pressed(GLFW_KEY_TAB)) command(A::Panel);
    if (pressed(GLFW_KEY_F1)) command(A::Help);
    if (pressed(GLFW_KEY_F2)) command(A::Screenshot, 0, freshName("stochtex-screenshot", ".png"));
    if (pressed(GLFW_KEY_F3)) command(A::ToggleRecording);
    if (pressed(GLFW_KEY_F4)) command(A::Pause, !s.paused);
    if (pressed(GLFW_KEY_F5)) command(A::Reload);
    if (ctrl && pressed(GLFW_KEY_S)) command(A::SaveDefault);
    if (ctrl && !isShadertoy()) {
        if (pressed(GLFW_KEY_Z)) command((e.mods & GLFW_MOD_SHIFT) ? A::Redo : A::Undo);
        if (pressed(GLFW_KEY_Y)) command(A::Redo);
    }
    if (isShadertoy()) {
        // Every other key goes to the program's keyboard texture (a tap:
        // pressed for the next frame, no longer held).
        const int code = javascriptKeyCode(e.key);
        if (code >= 0 && e.action != GLFW_REPEAT) programKeys_.push_back({code, press});
        return;
    }
    if (ctrl) return;
    if (pressed(GLFW_KEY_1)) command(A::Filter, 0, "none");
    if (pressed(GLFW_KEY_2)) command(A::Filter, 0, "paper");
    if (pressed(GLFW_KEY_3)) command(A::Filter, 0, "smooth");
    if (pressed(GLFW_KEY_LEFT_BRACKET)) command(A::Aniso, s.filter.aniso / 2);
    if (pressed(GLFW_KEY_RIGHT_BRACKET)) command(A::Aniso, s.filter.aniso * 2);
    if (pressed(GLFW_KEY_L) && hasNormalMap_)
        command(A::Response, 0,
                enumName(kResponseKindNames,
                         s.response == ResponseKind::Lean ? ResponseKind::PrefilteredColormap : ResponseKind::Lean));
    const auto next = [](const auto& names, auto value) {  // the name after the value's, round
        const auto it = std::find_if(names.begin(), names.end(), [&](const auto& n) { return n.second == value; });
        return it == names.end() || std::next(it) == names.end() ? names.front().first : std::next(it)->first;
    };
    if (pressed(GLFW_KEY_V)) {
        const std::string view = next(kWorkbenchViewNames, s.view);  // the mesh view only with a mesh
        command(A::View, 0, view == "mesh" && !mesh_ ? kWorkbenchViewNames.front().first : view);
    }
    if (pressed(GLFW_KEY_D)) command(A::Derivatives, s.derivatives == GpuView::Derivatives::Camera);
    // Held arrows repeat.
    const bool pressOrRepeat = e.action == GLFW_PRESS || e.action == GLFW_REPEAT;
    if (pressOrRepeat && e.key == GLFW_KEY_UP) command(A::Tilt, s.camera.tiltDeg + 2.0);
    if (pressOrRepeat && e.key == GLFW_KEY_DOWN) command(A::Tilt, s.camera.tiltDeg - 2.0);
    if (pressed(GLFW_KEY_M)) command(A::Mode, 0, next(kWorkbenchModeNames, s.mode));
    if (pressed(GLFW_KEY_A)) command(A::Analysis, 0, next(kLiveAnalysisNames, s.analysis));
}

}  // namespace stochtex
