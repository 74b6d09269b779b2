#include "stochtex/workbench/workbench.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <numbers>
#include <optional>

#include "stochtex/core/error.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/gpu/render_target.h"
#include "stochtex/gpu/scene.h"
#include "stochtex/gpu/scene_render.h"
#include "stochtex/gpu/texture_display.h"
#include "stochtex/image/image_io.h"
#include "stochtex/noise/spectrum.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/pattern/part_cache.h"
#include "stochtex/report/frame_sequence.h"
#include "stochtex/textures/texture_source.h"
#include "stochtex/workbench/editors.h"
#include "stochtex/workbench/previews.h"

namespace stochtex {

void validateWorkbenchOptions(const WorkbenchOptions& o) {
    const View& v = o.camera.view;
    if (std::min(v.width, v.height) < 16 || std::max(v.width, v.height) > 8192)
        throw InputError::parameter(
            "size", "must be in [16, 8192] per side, got " + std::to_string(v.width) + "x" + std::to_string(v.height));
    if (o.filter.source != StatisticsSource::Point && o.filter.source != StatisticsSource::Estimators)
        throw InputError::parameter("filter", "the window draws none, paper or smooth, got " + filterName(o.filter));
    checkInteger(anisoParam(), o.filter.aniso);
    checkNumber(cameraTiltParam(), o.camera.tiltDeg, " degrees");
    if (!(o.camera.view.scale > 0) || !std::isfinite(o.camera.view.scale))
        throw InputError::parameter("scale", "must be a finite number > 0, got " + formatValue(o.camera.view.scale));
    if (o.frames < 0) throw InputError::parameter("frames", "must be ≥ 0, got " + std::to_string(o.frames));
    if (!o.screenshot.empty() && o.frames == 0)
        throw InputError::parameter("frames", "must be given with a screenshot (it is of the last frame)");
    validateShadertoySettings(o.shadertoy);
}

namespace {

// The keys, as the help window lists them.
struct KeyHelp {
    const char* keys;
    const char* what;
};
constexpr KeyHelp kPatternKeys[] = {
    {"wheel", "zoom about the cursor (3D: distance)"},
    {"left drag", "pan (3D: orbit)"},
    {"right click", "pick the correlation point"},
    {"Ctrl + drag", "move the split line"},
    {"1 / 2 / 3", "filter none / paper / smooth"},
    {"[ / ]", "anisotropy down / up"},
    {"L", "colours or LEAN normals (a pattern with a normal map)"},
    {"V", "view: zoom, plane, sphere, torus"},
    {"Up / Down", "tilt of the plane"},
    {"D", "footprints from the camera or the rasterizer"},
    {"M", "mode: texture, analysis, side by side, split, overlay"},
    {"A", "analysis: spectrum, flow, flicker, correlation"},
    {"Ctrl + Z / Ctrl + Y", "undo / redo an edit (a drag is one step)"},
};
constexpr KeyHelp kCommonKeys[] = {
    {"Tab", "show or hide the panel"},
    {"F1", "this help"},
    {"F2", "screenshot of the picture (PNG, current folder)"},
    {"F3", "start or stop recording (MP4, current folder)"},
    {"F4", "pause or run (ShaderToy)"},
    {"F5", "reload from disk"},
    {"Ctrl + S", "save the pattern (its file; a preset to NAME.json)"},
    {"Esc", "quit"},
};

// ShaderToy's keyboard texture is indexed by JavaScript key codes: GLFW's
// letters, digits and space are the same; a few others differ.
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

// A file name in the current folder that does not exist yet: stem-N.ext.
std::string freshName(const std::string& stem, const std::string& ext) {
    for (int i = 1;; ++i) {
        const std::string name = stem + "-" + std::to_string(i) + ext;
        if (!std::filesystem::exists(name)) return name;
    }
}

class Workbench {
public:
    Workbench(WorkbenchDocument document, const WorkbenchOptions& options)
        : doc_(std::move(document)),
          options_(options),
          camera_(options.camera),
          filter_(options.filter),
          view_(options.view),
          mode_(options.mode),
          analysis_(options.analysis),
          showPanel_(options.panel) {
        filterName_ = filter_.source == StatisticsSource::Point
                          ? "none"
                          : filterName(FilterOptions{}.use(
                                {filter_.source, {ResponseKind::PrefilteredColormap, filter_.response.prefilter}}));
        response_ = filter_.response.kind;
        const int panel = showPanel_ ? kWorkbenchPanelWidth : 0;
        context_ = GlContext::window(camera_.view.width + panel, camera_.view.height, "stochtex workbench");
        window_ = static_cast<GLFWwindow*>(context_->nativeWindow());
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's files
        ImGui::StyleColorsDark();
        loadFont();
        // Every key event is queued before ImGui sees it (its backend chains
        // to this callback): ImGui 1.86 keeps only whether a key is down at
        // each frame, so a tap shorter than a frame was lost at low frame rates.
        glfwSetWindowUserPointer(window_, this);
        glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
            static_cast<Workbench*>(glfwGetWindowUserPointer(w))->keyEvents_.push_back({key, action, mods});
        });
        ImGui_ImplGlfw_InitForOpenGL(window_, true);
        ImGui_ImplOpenGL3_Init("#version 330");
        display_ = std::make_unique<TextureDisplay>();
        loadDocument();
        // What the first frame needs, built now: a program that does not
        // compile or a pattern the GPU cannot draw fails the run here.
        context_->framebufferSize(windowWidth_, windowHeight_);
        int coordinatesWide = 0, coordinatesHigh = 0;
        glfwGetWindowSize(window_, &coordinatesWide, &coordinatesHigh);
        pixelScale_ = coordinatesWide > 0 ? float(windowWidth_) / float(coordinatesWide) : 1.0f;
        if (isShadertoy())
            buildHost(textureRect().width, textureRect().height);
        else
            renderer();
    }

    ~Workbench() {
        try {
            stopRecording();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "stochtex: the recording could not be finished: %s\n", e.what());
        }
        scene_.reset();
        renderers_.clear();
        host_.reset();
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }

    // DejaVu Sans (fonts-dejavu-core) with the Greek letters, sub- and
    // superscripts and arrows the studies' numbers use; ImGui's own font
    // (ASCII) when it is missing.
    static void loadFont() {
        const char* path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
        if (!std::filesystem::exists(path)) return;
        static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x2027, 0x2070,
                                         0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};
        ImGui::GetIO().Fonts->AddFontFromFileTTF(path, 15.0f, nullptr, ranges);
    }

    int run() {
        size_t nextStep = 0;
        auto lastPoll = std::chrono::steady_clock::now();
        bool screenshotWritten = false;
        while (!context_->shouldClose() && !quit_ && (options_.frames == 0 || frame_ < options_.frames)) {
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            const float scale = ImGui::GetIO().DisplayFramebufferScale.x;
            pixelScale_ = scale > 0 && std::isfinite(scale) ? scale : 1.0f;
            ImGui::NewFrame();
            while (nextStep < options_.script.size() && options_.script[nextStep].frame <= frame_)
                runStep(options_.script[nextStep++]);
            guarded([&] { handleInput(); });
            const auto now = std::chrono::steady_clock::now();
            if (now - lastPoll > std::chrono::milliseconds(500)) {
                lastPoll = now;
                if (doc_.changedOnDisk()) reloadDocument();
            }
            // While a widget or the canvas is dragged, at most one rebuild every 0.3 s.
            const bool dragging = ImGui::IsAnyItemActive() || ImGui::IsMouseDown(ImGuiMouseButton_Left);
            if (needsRebuild_ && (!dragging || now - lastBuild_ > std::chrono::milliseconds(300))) rebuild();
            drawPicture();
            // The picture area as it stands, before the panels are drawn over
            // the window; the run's screenshot is its last frame.
            const bool last = isLastFrame() || quit_ || context_->shouldClose();
            const bool runShot = !options_.screenshot.empty() && last;
            if (!pendingScreenshots_.empty() || !scriptScreenshots_.empty() || recorder_ || runShot) {
                const Image shot = pictureCodes();
                for (const std::string& f : pendingScreenshots_) guarded([&] { writeScreenshot(f, shot); });
                pendingScreenshots_.clear();
                // A script's screenshot that cannot be written fails the run
                // (exit 2); a key's is reported in the panel.
                for (const std::string& f : scriptScreenshots_) writeScreenshot(f, shot);
                scriptScreenshots_.clear();
                guarded([&] { record(shot); });
                if (runShot) writeScreenshot(options_.screenshot, shot), screenshotWritten = true;
            }
            drawPanels();
            ImGui::Render();
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, windowWidth_, windowHeight_);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            ++frame_;
            updateTitle();
            context_->swapAndPoll();
        }
        if (!options_.screenshot.empty() && !screenshotWritten)
            throw InputError("screenshot: the window closed before a frame was drawn");
        return frame_;
    }

private:
    bool isLastFrame() const { return options_.frames > 0 && frame_ + 1 == options_.frames; }
    bool isShadertoy() const { return doc_.kind() == WorkbenchDocument::Kind::Shadertoy; }
    bool isScene() const { return view_ == WorkbenchView::Sphere || view_ == WorkbenchView::Torus; }
    // The panel's width in framebuffer pixels: ImGui lays it out in window
    // coordinates, which a HiDPI screen scales by pixelScale_ (GLFW's
    // framebuffer / window size) into pixels, where the picture is drawn.
    int panelWidth() const { return showPanel_ ? int(std::lround(kWorkbenchPanelWidth * pixelScale_)) : 0; }
    bool analysing() const { return mode_ != WorkbenchMode::Texture; }

    // An interactive action: a failure is shown in the panel, the session goes on.
    template <class F>
    void guarded(F&& action) {
        try {
            action();
        } catch (const std::exception& e) {
            error_ = e.what();
        }
    }

    // Another statistic of the same samples: shown from the accumulator at once, the samples kept.
    void showStatisticChanged() {
        if (correlation_) showAnalysisResult(correlation_->result(statistic_));
    }

    // Something the picture shows changed: analyses of the old picture are stale.
    void viewChanged() { ++viewVersion_; }

    // --- the document ---

    void loadDocument() {
        failedKey_.clear();
        hostFailed_ = false;
        scene_.reset();
        renderers_.clear();
        exampleSize_ = 0;
        viewChanged();
        if (isShadertoy()) {
            // Rebuilt at the picture's size on the next frame; the old one
            // stays on screen if the program no longer compiles.
            hostStale_ = true;
            return;
        }
        host_.reset();
        parts_.beginGeneration();  // the parts of the last two revisions stay: an undo rebuilds nothing
        spec_ = doc_.patternSpec();
        hasNormalMap_ = spec_.normalMap.has_value() && !spec_.graph;
        if (!hasNormalMap_) response_ = ResponseKind::PrefilteredColormap;
        // The colormap canvas and the examples, rebuilt where their specs changed.
        const PatternPreviews& previews = previews_.update(spec_, &parts_);
        canvas_.upload(previews.colormap);
        for (size_t k = 0; k < 2; ++k) {
            example_[k] = {};
            exampleSpectrum_[k] = {};
            if (previews.examples[k].empty()) continue;
            example_[k].upload(previews.examples[k]);
            exampleSpectrum_[k].upload(previews.spectra[k]);
        }
    }

    // W of the pattern's example, for the instance offsets (built once per document, when needed).
    int exampleSize() {
        if (exampleSize_ == 0) exampleSize_ = GraphPattern::build(spec_, {}, &parts_).exampleSize();
        return exampleSize_;
    }

    void rebuild() {
        needsRebuild_ = false;
        lastBuild_ = std::chrono::steady_clock::now();
        try {
            loadDocument();
            error_.clear();
        } catch (const std::exception& e) {
            error_ = e.what();
        }
    }

    void reloadDocument() {
        try {
            doc_.reload();
            previews_.clear();
            parts_.clear();
            loadDocument();
            error_.clear();
            notice_ = "reloaded " + doc_.source();
        } catch (const std::exception& e) {
            error_ = std::string("reload: ") + e.what();
        }
    }

    // The panel's edits; the script's too, which then fail the run if refused.
    void applyEdit(const JsonEdit& e) {
        try {
            if (e.remove)
                doc_.remove(e.pointer);
            else
                doc_.set(e.pointer, e.value);
            error_.clear();
            needsRebuild_ = true;
        } catch (const InputError& x) {
            error_ = x.what();
        }
    }

    // The panel's edits of one frame. A gesture — a slider or a shape
    // dragged over many frames, or one click — is one undo step: the state
    // before it is marked when its first edit comes.
    void applyGesture(const std::vector<JsonEdit>& edits) {
        if (!edits.empty() && !gestureOpen_) {
            doc_.checkpoint();
            gestureOpen_ = true;
        }
        for (const JsonEdit& e : edits) applyEdit(e);
        gestureOpen_ = gestureOpen_ && (ImGui::IsAnyItemActive() || ImGui::IsMouseDown(ImGuiMouseButton_Left));
    }
    void undo() {
        gestureOpen_ = false;  // an edit after it is a step of its own
        guarded([&] {
            if (doc_.undo()) needsRebuild_ = true, notice_ = "undone";
        });
    }
    void redo() {
        gestureOpen_ = false;
        guarded([&] {
            if (doc_.redo()) needsRebuild_ = true, notice_ = "redone";
        });
    }

    void save(const std::string& path) {
        doc_.save(path);
        notice_ = "saved " + path;
    }

    void saveDefault() {
        if (isShadertoy()) return;
        const bool preset = doc_.source().rfind("preset ", 0) == 0;
        save(preset ? doc_.source().substr(7) + ".json" : doc_.source());
    }

    // --- drawing ---

    GpuView& renderer() {
        auto& r = renderers_[{filterName_, response_}];
        if (!r) {
            FilterOptions o = filter_;
            const bool covariance = o.response.covariance;
            o.use(parseFilter(filterName_));
            o.response.kind = response_;
            o.response.covariance = covariance;
            r = makeGpuView(spec_, *context_, o, &parts_);
        }
        return *r;
    }

    // The texture's part of the picture area: all of it, or the left half side by side.
    DisplayRect textureRect() const {
        const int w = windowWidth_ - panelWidth(), h = windowHeight_;
        const int tw = mode_ == WorkbenchMode::SideBySide ? w / 2 : w;
        return {panelWidth(), 0, std::max(1, tw), std::max(1, h)};
    }
    DisplayRect pictureRect() const {
        return {panelWidth(), 0, std::max(1, windowWidth_ - panelWidth()), std::max(1, windowHeight_)};
    }

    void drawPicture() {
        context_->framebufferSize(windowWidth_, windowHeight_);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, windowWidth_, windowHeight_);
        glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        const DisplayRect tr = textureRect();
        if (tr.width != lastTextureSize_[0] || tr.height != lastTextureSize_[1]) {
            lastTextureSize_ = {tr.width, tr.height};
            viewChanged();
        }
        GLuint texture = 0;
        TextureDisplay::Look look = TextureDisplay::kRenderTarget;
        if (isShadertoy()) {
            texture = drawProgramFrame(tr.width, tr.height);
            look = TextureDisplay::kGlCodes;
        } else if (drawKey() != failedKey_) {
            try {
                texture = drawPatternFrame(tr.width, tr.height);
            } catch (const std::exception& e) {
                // Shown in the panel; tried again when the view or the document changes, not every frame.
                error_ = e.what();
                failedKey_ = drawKey();
            }
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (!texture) return;
        if (isScene()) look = TextureDisplay::kGlLinear;  // a mesh is drawn the GL way up
        if (analysing()) guarded([&] { updateAnalysis(); });
        glBindFramebuffer(GL_FRAMEBUFFER, 0);  // the analysis read back from the frame's own framebuffer
        const DisplayRect pr = pictureRect();
        switch (mode_) {
            case WorkbenchMode::Texture: display_->show(texture, tr, look); break;
            case WorkbenchMode::Analysis: showAnalysis(pr, 1); break;
            case WorkbenchMode::SideBySide:
                display_->show(texture, tr, look);
                showAnalysis({tr.x + tr.width, 0, pr.width - tr.width, pr.height}, 1);
                break;
            case WorkbenchMode::Split: {
                display_->show(texture, tr, look);
                const int cut = int(std::lround(split_ * pr.width));
                glEnable(GL_SCISSOR_TEST);
                glScissor(pr.x + cut, 0, pr.width - cut, pr.height);
                showAnalysis(pr, 1);
                // The split line, part of the picture (screenshots and
                // recordings show where the halves meet): two pixels of white.
                glScissor(pr.x + std::clamp(cut - 1, 0, std::max(0, pr.width - 2)), 0, std::min(2, pr.width),
                          pr.height);
                glClearColor(1, 1, 1, 1);
                glClear(GL_COLOR_BUFFER_BIT);
                glDisable(GL_SCISSOR_TEST);
                break;
            }
            case WorkbenchMode::Overlay:
                display_->show(texture, tr, look);
                showAnalysis(pr, overlayOpacity_, true);
                break;
        }
    }

    // What a pattern's frame depends on besides the document: a failed build is not retried until it changes.
    std::string drawKey() const {
        return filterName_ + "|" + std::to_string(int(response_)) + "|" + std::to_string(filter_.aniso) + "|" +
               std::to_string(int(view_));
    }

    // overlay: a map's own alpha (LiveAnalysisResult) scales the opacity, so the frame shows where it is zero.
    void showAnalysis(const DisplayRect& rect, float opacity, bool overlay = false) {
        if (analysisImage_.empty()) return;
        TextureDisplay::Look look = TextureDisplay::kImageCodes;
        look.opacity = opacity;
        look.alpha = overlay;
        display_->show(analysisImage_.texture(), rect, look);
    }

    GLuint drawPatternFrame(int w, int h) {
        if (!target_ || target_->width() != w || target_->height() != h)
            target_ = std::make_unique<RenderTarget>(w, h, true);
        GpuView& r = renderer();
        if (isScene()) {
            const std::string object = view_ == WorkbenchView::Sphere ? "sphere" : "torus";
            if (!scene_ || sceneView_ != &r || sceneObject_ != object) {
                scene_ = std::make_unique<SceneRenderer>(r, makeObject(object));
                sceneView_ = &r;
                sceneObject_ = object;
            }
            scene_->draw(orbit_.camera(), *target_, 4.0f);
        } else {
            camera_.kind = view_ == WorkbenchView::Plane ? Camera::Kind::Plane : Camera::Kind::Zoom;
            camera_.view.width = w;
            camera_.view.height = h;
            target_->bind();
            r.setDerivatives(derivatives_);
            r.drawView(camera_);
        }
        return target_->texture();
    }

    // A new host at the picture's size, swapped in only once it compiled.
    void buildHost(int w, int h) {
        ShadertoySettings s = options_.shadertoy;
        s.width = w;
        s.height = h;
        auto next = std::make_unique<ShadertoyHost>(doc_.shadertoySpec(), *context_, s);
        host_ = std::move(next);
        hostStale_ = false;
        viewChanged();
    }

    GLuint drawProgramFrame(int w, int h) {
        // A new picture size (Tab, side by side, the window resized): the program runs on at it.
        if (host_ && !hostStale_ && !hostFailed_ && (host_->settings().width != w || host_->settings().height != h)) {
            try {
                host_->resize(w, h);  // iMouse too, in the new pixels
                viewChanged();
            } catch (const std::exception& e) {
                error_ = e.what();
                hostFailed_ = true;
            }
        }
        if (!host_ || hostStale_ || host_->settings().width != w || host_->settings().height != h) {
            if (hostFailed_ && host_) return host_->frameTexture();  // the last good one, until the next reload
            if (hostFailed_) return 0;
            try {
                buildHost(w, h);
            } catch (const std::exception& e) {
                error_ = e.what();
                hostFailed_ = true;
                return host_ ? host_->frameTexture() : 0;
            }
        }
        for (const ShadertoyInput& e : std::exchange(pendingInputs_, {})) host_->apply(e);  // paused too: state only
        if (!paused_ || host_->frame() == 0) {
            host_->renderFrame();
        }
        return host_->frameTexture();
    }

    // The live analysis of the frame shown: spectrum and flow of the frames
    // shown, recomputed when the picture changed; the correlation over a
    // pattern's instances (a program's frames).
    //
    // The spectrum, flow and flicker run beside the window, since a flow of a
    // large picture takes longer than a frame: the frame read when the
    // picture changes (and, for flow and flicker, the frame before it) is
    // queued, the newest replacing an older one still waiting, and the panel
    // shows the last analysis finished. A frame that is captured (a
    // screenshot, a recording, a run's last frame) waits for the analysis of
    // itself, so what is saved is the picture's own.
    void updateAnalysis() {
        const DisplayRect tr = textureRect();
        if (std::min(tr.width, tr.height) < 16) {
            analysisSummary_ = "the picture is too small to analyse (16 pixels a side at least)";
            analysisImage_ = {};
            return;
        }
        const long long version = isShadertoy() ? host_->frame() : viewVersion_;
        const bool changed = version != analysedVersion_ || host_.get() != analysedHost_;
        if (changed || analysisDirty_ || analysis_ == LiveAnalysisKind::Correlation) {
            // Pattern targets hold image row 0 in GL row 0; a mesh and a program's frame the GL way up.
            const Image frame = isShadertoy() ? host_->image()
                                : isScene()   ? target_->readRgb(RenderTarget::Rows::TopDown)
                                              : target_->readRgb(RenderTarget::Rows::AsDrawn);
            if (analysis_ == LiveAnalysisKind::Correlation) {
                const LiveAnalysisResult r = correlationStep(frame, changed);
                analysisDirty_ = false;
                showAnalysisResult(r);
            } else {
                Image previous;
                if (analysis_ != LiveAnalysisKind::Spectrum) {
                    if (previousFrame_.width() != frame.width() || previousFrame_.height() != frame.height())
                        previousFrame_ = frame;
                    previous = previousFrame_;
                    previousFrame_ = frame;
                }
                queuedAnalysis_ = AnalysisRequest{analysis_, frame, std::move(previous)};
                analysisDirty_ = false;
            }
            analysedVersion_ = version;
            analysedHost_ = host_.get();
        }
        const bool capture = isLastFrame() || quit_ || context_->shouldClose() || !pendingScreenshots_.empty() ||
                             !scriptScreenshots_.empty() || recorder_;
        collectAnalysis(capture);
        if (!analysisJob_.valid() && queuedAnalysis_) {
            AnalysisRequest request = std::move(*queuedAnalysis_);
            queuedAnalysis_.reset();
            runningAnalysis_ = request.kind;
            analysisJob_ = std::async(std::launch::async, [request = std::move(request)] {
                switch (request.kind) {
                    case LiveAnalysisKind::Spectrum: return liveSpectrum(request.frame);
                    case LiveAnalysisKind::Flow: return liveFlow(request.previous, request.frame);
                    default: return liveFlicker(request.previous, request.frame);
                }
            });
        }
        if (capture) collectAnalysis(true);
    }

    // Shows the running analysis when it is done (or, `wait`, once it is);
    // one of an analysis since switched away from is dropped.
    void collectAnalysis(bool wait) {
        if (!analysisJob_.valid()) return;
        if (!wait && analysisJob_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
        const LiveAnalysisResult r = analysisJob_.get();  // rethrows the analysis's error
        if (runningAnalysis_ == analysis_) showAnalysisResult(r);
    }

    void showAnalysisResult(const LiveAnalysisResult& result) {
        analysisImage_.upload(result.image);
        analysisSummary_ = result.summary;
        analysisProfile_ = result.profile;
        analysisProfileLabel_ = result.profileLabel;
    }

    LiveAnalysisResult correlationStep(const Image& frame, bool changed) {
        const int w = frame.width(), h = frame.height();
        const int px = std::clamp(pickX_ < 0 ? w / 2 : pickX_, 0, w - 1);
        const int py = std::clamp(pickY_ < 0 ? h / 2 : pickY_, 0, h - 1);
        // A program's samples are its frames; a pattern's are its instances
        // of one view, so a new view starts them again.
        const bool restart = analysisDirty_ || (changed && !isShadertoy());
        if (!correlation_ || restart || correlation_->width() != w || correlation_->height() != h ||
            correlation_->pointX() != px || correlation_->pointY() != py)
            correlation_ = std::make_unique<LiveCorrelation>(w, h, px, py);
        if (isShadertoy()) {
            if (changed) correlation_->add(frame);
        } else if (isScene()) {
            LiveAnalysisResult r;
            r.image = Image(w, h, 3, 0.5f);
            r.summary = "correlation over instances: in the zoom and plane views";
            return r;
        } else if (correlation_->count() < kMaxCorrelationSamples) {
            // Instances through the GPU: the view moved by a hashed whole-texel offset (CameraSource).
            const CameraSource source(renderer(), camera_);
            for (int k = 0; k < 4; ++k) correlation_->add(source.render({w, h, 0, 0}, 0, correlation_->count()));
        }
        return correlation_->result(statistic_);
    }
    static constexpr int kMaxCorrelationSamples = 4096;

    // The picture area as shown (display codes), row 0 at the top.
    Image pictureCodes() const {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glReadBuffer(GL_BACK);
        const Image all = readBoundFramebufferRgb(windowWidth_, windowHeight_, RenderTarget::Rows::TopDown);
        const DisplayRect pr = pictureRect();
        return crop(all, pr.x, 0, std::min(pr.width, all.width() - pr.x), std::min(pr.height, all.height()));
    }

    void writeScreenshot(const std::string& path, const Image& shot) {
        writeImage(path, shot, kNoTransfer);  // sRGB codes already
        notice_ = "wrote " + path;
    }

    void startRecording(const std::string& path) {
        stopRecording();
        const DisplayRect pr = pictureRect();
        recorder_ = std::make_unique<FrameSequenceWriter>(path, pr.width, pr.height, options_.shadertoy.fps, "",
                                                          Transfer::Linear);
        recordingSize_ = {pr.width, pr.height};
        recordingClock_.emplace(options_.shadertoy.fps);
        heldShot_ = {};
        recordedProgramFrame_ = -1;
        recordingPath_ = path;
        notice_ = "recording " + path;
    }
    void record(const Image& shot) {
        if (!recorder_) return;
        if (shot.width() != recordingSize_[0] || shot.height() != recordingSize_[1]) {
            stopRecording();  // a video keeps one size: the picture area changed
            notice_ += " (stopped: the picture changed size)";
            return;
        }
        // A program's frame is one frame of its own time (iTimeDelta = 1/fps),
        // so its video plays at the program's speed. A pattern has no clock:
        // its frames go on the wall clock, so the video plays what the person
        // saw, at their pace.
        if (isShadertoy()) {
            // A paused program adds no frame to its video: one per program frame.
            const long long programFrame = host_ ? host_->frame() : -1;
            if (programFrame != recordedProgramFrame_) recorder_->write(shot);
            recordedProgramFrame_ = programFrame;
            return;
        }
        // A pattern's picture is held until the next one: the frames whose
        // times fell while it was on screen are written with it. The clock
        // starts at the first picture (the first frame may take a build).
        if (heldShot_.empty()) {
            recordingStart_ = std::chrono::steady_clock::now();
            heldShot_ = shot;
            return;
        }
        const int held = recordingClock_->framesBefore(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - recordingStart_).count());
        for (int k = 0; k < held; ++k) recorder_->write(heldShot_);
        heldShot_ = shot;
    }
    void stopRecording() {
        if (!recorder_) return;
        const std::unique_ptr<FrameSequenceWriter> r = std::move(recorder_);
        if (!heldShot_.empty()) r->write(heldShot_);  // the last picture, one frame
        heldShot_ = {};
        const std::string written = r->finish();
        notice_ = "wrote " + (written.empty() ? recordingPath_ : written);
    }

    // --- controls: the mouse, the keys and the script act through these ---

    void zoomAt(double factor, double px, double py) {
        if (isScene()) {
            orbit_.distance = std::clamp(orbit_.distance / factor, 1.3, 20.0);
        } else {
            View& v = camera_.view;
            const double next = std::clamp(v.scale / factor, 1.0 / 64.0, 4096.0);
            v.offsetU += px * (v.scale - next);
            v.offsetV += py * (v.scale - next);
            v.scale = next;
        }
        viewChanged();
    }
    void pan(double dx, double dy) {
        if (isScene()) {
            orbit_.yawDeg -= dx * 0.4;
            orbit_.pitchDeg = std::clamp(orbit_.pitchDeg + dy * 0.4, -80.0, 80.0);
        } else {
            camera_.view.offsetU -= dx * camera_.view.scale;
            camera_.view.offsetV -= dy * camera_.view.scale;
        }
        viewChanged();
    }
    void setFilter(const std::string& name) {
        filterName_ = name;
        viewChanged();
    }
    void setAniso(int k) {
        k = std::clamp(k, 1, int(kMaxAnisotropy));
        if (k == filter_.aniso) return;
        filter_.aniso = k;
        scene_.reset();
        renderers_.clear();  // the probes are compiled in
        viewChanged();
    }
    void setResponse(ResponseKind kind) {
        response_ = kind;
        viewChanged();
    }
    void setDerivatives(GpuView::Derivatives d) {
        derivatives_ = d;
        viewChanged();
    }
    void setTilt(double degrees) {
        camera_.tiltDeg = std::clamp(degrees, 0.0, 89.0);
        viewChanged();
    }
    void setView(WorkbenchView v) {
        view_ = v;
        viewChanged();
    }
    void setPick(double x, double y) {
        pickX_ = int(x);
        pickY_ = int(y);
        analysisDirty_ = true;
    }

    void runStep(const WorkbenchStep& s) {
        using A = WorkbenchStep::Action;
        if ((s.action == A::Set || s.action == A::Save || s.action == A::Undo || s.action == A::Redo) && isShadertoy())
            throw InputError(
                "script: a ShaderToy program is edited in its files, not by \"set\", \"undo\", "
                "\"redo\" or \"save\"");
        switch (s.action) {
            case A::Zoom: zoomAt(s.amount, s.x, s.y); break;
            case A::Pan: pan(s.x, s.y); break;
            case A::Filter: setFilter(s.text); break;
            case A::Aniso: setAniso(int(s.amount)); break;
            case A::Tilt: setTilt(s.amount); break;
            case A::Set:
                // The panel's path: the edit, then the rebuild. A script has no
                // one to read the panel: a refused edit fails the run.
                doc_.checkpoint();
                applyEdit({s.text, s.value});
                if (!error_.empty()) throw InputError(error_);
                rebuild();
                if (!error_.empty()) throw InputError(error_);
                break;
            case A::Mode: mode_ = parseEnum(kWorkbenchModeNames, s.text, "mode"), analysisDirty_ = true; break;
            case A::Analysis:
                analysis_ = parseEnum(kLiveAnalysisNames, s.text, "analysis"), analysisDirty_ = true;
                break;
            case A::View: setView(parseEnum(kWorkbenchViewNames, s.text, "view")); break;
            case A::Pick: setPick(s.x, s.y); break;
            case A::Pause: paused_ = s.amount != 0; break;
            case A::Screenshot: scriptScreenshots_.push_back(s.text); break;
            case A::Save: save(s.text); break;
            case A::Record: startRecording(s.text); break;
            case A::StopRecording: stopRecording(); break;
            case A::Undo:
            case A::Redo:
                if (!(s.action == A::Undo ? doc_.undo() : doc_.redo()))
                    throw InputError(std::string("script: nothing to ") + (s.action == A::Undo ? "undo" : "redo"));
                rebuild();
                if (!error_.empty()) throw InputError(error_);
                break;
            case A::Key:  // a tap within one frame, as the window's callback queues it
                keyEvents_.push_back({s.key, GLFW_PRESS, s.mods});
                keyEvents_.push_back({s.key, GLFW_RELEASE, s.mods});
                break;
            case A::MouseDown:
            case A::MouseMove:
            case A::MouseUp:
                if (!isShadertoy())
                    throw InputError("script: a mouse step drives a ShaderToy program's iMouse; this is a pattern");
                // Applied before the program's next frame (its host may not be built yet).
                pendingInputs_.push_back({0,
                                          s.action == A::MouseDown   ? ShadertoyInput::Kind::MouseDown
                                          : s.action == A::MouseMove ? ShadertoyInput::Kind::MouseMove
                                                                     : ShadertoyInput::Kind::MouseUp,
                                          0, float(s.x), float(s.y)});
                break;
            case A::Quit: quit_ = true; break;
        }
    }

    void handleInput() {
        ImGuiIO& io = ImGui::GetIO();
        const DisplayRect pr = pictureRect(), tr = textureRect();
        // Picture pixels, rows down (ImGui's mouse is in window coordinates).
        const double px = io.MousePos.x * pixelScale_ - pr.x, py = io.MousePos.y * pixelScale_;
        const bool overPicture = px >= 0 && py >= 0 && px < pr.width && py < pr.height;
        // A point of the texture: side by side, the analysis half maps onto it.
        const double tx = px >= tr.width ? px - tr.width : px;
        if (!io.WantCaptureMouse && overPicture) {
            if (io.MouseWheel != 0) zoomAt(std::pow(1.15, io.MouseWheel), tx, py);
            if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
                if (io.KeyCtrl)
                    split_ = float(std::clamp(px / pr.width, 0.0, 1.0));
                else if (!isShadertoy())
                    pan(io.MouseDelta.x * pixelScale_, io.MouseDelta.y * pixelScale_);
            }
            if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) setPick(tx, py);
            if (isShadertoy()) {
                // iMouse with ShaderToy's click semantics (gpu/shadertoy_input.h), in the program's pixels, y up.
                const float mx = float(std::min(tx, double(tr.width - 1))), my = float(tr.height - 1 - py);
                using K = ShadertoyInput::Kind;
                if (ImGui::IsMouseClicked(ImGuiMouseButton_Left))
                    pendingInputs_.push_back({0, K::MouseDown, 0, mx, my});
                else if (ImGui::IsMouseDown(ImGuiMouseButton_Left))
                    pendingInputs_.push_back({0, K::MouseMove, 0, mx, my});
                else if (ImGui::IsMouseReleased(ImGuiMouseButton_Left))
                    pendingInputs_.push_back({0, K::MouseUp, 0, 0, 0});
            }
        }
        // The key events since the last frame, each applied in order (a
        // text field being edited takes them all).
        const std::vector<KeyEvent> events = std::exchange(keyEvents_, {});
        if (io.WantCaptureKeyboard) return;
        for (const KeyEvent& e : events) applyKey(e);
    }

    struct KeyEvent {
        int key, action, mods;  // GLFW's
    };

    void applyKey(const KeyEvent& e) {
        const bool press = e.action == GLFW_PRESS, ctrl = (e.mods & GLFW_MOD_CONTROL) != 0;
        auto pressed = [&](int key) { return press && e.key == key; };
        if (pressed(GLFW_KEY_ESCAPE)) quit_ = true;
        if (pressed(GLFW_KEY_TAB)) showPanel_ = !showPanel_;
        if (pressed(GLFW_KEY_F1)) showHelp_ = !showHelp_;
        if (pressed(GLFW_KEY_F2)) pendingScreenshots_.push_back(freshName("stochtex-screenshot", ".png"));
        if (pressed(GLFW_KEY_F3)) recorder_ ? stopRecording() : startRecording(freshName("stochtex-recording", ".mp4"));
        if (pressed(GLFW_KEY_F4)) paused_ = !paused_;
        if (pressed(GLFW_KEY_F5)) reloadDocument();
        if (ctrl && pressed(GLFW_KEY_S)) saveDefault();
        if (ctrl && !isShadertoy()) {
            if (pressed(GLFW_KEY_Z)) (e.mods & GLFW_MOD_SHIFT) ? redo() : undo();
            if (pressed(GLFW_KEY_Y)) redo();
        }
        if (isShadertoy()) {
            // Every other key goes to the program's keyboard texture (a
            // tap: pressed for the next frame, no longer held).
            const int code = javascriptKeyCode(e.key);
            if (host_ && code >= 0 && e.action != GLFW_REPEAT) host_->setKey(code, press);
            return;
        }
        if (ctrl) return;
        if (pressed(GLFW_KEY_1)) setFilter("none");
        if (pressed(GLFW_KEY_2)) setFilter("paper");
        if (pressed(GLFW_KEY_3)) setFilter("smooth");
        if (pressed(GLFW_KEY_LEFT_BRACKET)) setAniso(filter_.aniso / 2);
        if (pressed(GLFW_KEY_RIGHT_BRACKET)) setAniso(filter_.aniso * 2);
        if (pressed(GLFW_KEY_L) && hasNormalMap_)
            setResponse(response_ == ResponseKind::Lean ? ResponseKind::PrefilteredColormap : ResponseKind::Lean);
        if (pressed(GLFW_KEY_V)) setView(WorkbenchView((int(view_) + 1) % 4));
        if (pressed(GLFW_KEY_D))
            setDerivatives(derivatives_ == GpuView::Derivatives::Camera ? GpuView::Derivatives::Rasterizer
                                                                        : GpuView::Derivatives::Camera);
        // Held arrows repeat.
        const bool pressOrRepeat = e.action == GLFW_PRESS || e.action == GLFW_REPEAT;
        if (pressOrRepeat && e.key == GLFW_KEY_UP) setTilt(camera_.tiltDeg + 2.0);
        if (pressOrRepeat && e.key == GLFW_KEY_DOWN) setTilt(camera_.tiltDeg - 2.0);
        if (pressed(GLFW_KEY_M)) mode_ = WorkbenchMode((int(mode_) + 1) % 5), analysisDirty_ = true;
        if (pressed(GLFW_KEY_A)) analysis_ = LiveAnalysisKind((int(analysis_) + 1) % 4), analysisDirty_ = true;
    }

    // --- the panels ---

    template <class E>
    bool enumCombo(const char* label, E& value, const EnumNames<E>& names) {
        bool changed = false;
        if (ImGui::BeginCombo(label, enumName(names, value).c_str())) {
            for (const auto& [name, v] : names)
                if (ImGui::Selectable(name.c_str(), v == value)) value = v, changed = true;
            ImGui::EndCombo();
        }
        return changed;
    }

    void drawPanels() {
        if (showHelp_) drawHelp();
        if (!showPanel_) return;
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(float(kWorkbenchPanelWidth), float(windowHeight_) / pixelScale_));
        ImGui::Begin("stochtex", nullptr,
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                         ImGuiWindowFlags_NoTitleBar);
        ImGui::TextWrapped("%s", doc_.source().c_str());
        ImGui::TextDisabled("F1: keys   Tab: hide panel");
        auto message = [](const std::string& text, const ImVec4& colour) {
            if (text.empty()) return;
            ImGui::PushStyleColor(ImGuiCol_Text, colour);
            ImGui::TextWrapped("%s", text.c_str());
            ImGui::PopStyleColor();
        };
        message(error_, ImVec4(1, 0.45f, 0.4f, 1));
        message(notice_, ImVec4(0.6f, 0.9f, 0.6f, 1));
        ImGui::PushID("view");  // the view's controls apart from the pattern's members of the same names
        if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) drawViewControls();
        if (analysing() && ImGui::CollapsingHeader("Analysis", ImGuiTreeNodeFlags_DefaultOpen)) drawAnalysisPanel();
        ImGui::PopID();
        if (!isShadertoy()) {
            auto id = [](const DisplayImage& i) {
                return i.empty() ? nullptr : reinterpret_cast<void*>(uintptr_t(i.texture()));
            };
            EditorPreviews previews;
            previews.colormap = id(canvas_);
            previews.colormapPointer = outputColormapPointer();
            if (!spec_.graph && spec_.colormap.source == ColormapSpec::Source::Painted)
                previews.painted = &spec_.colormap.painted;
            for (int k = 0; k < 2; ++k)
                previews.example[k] = id(example_[k]), previews.spectrum[k] = id(exampleSpectrum_[k]);
            ImGui::Checkbox("unfold every section", &expandAll_);
            previews.expandAll = expandAll_;
            applyGesture(patternEditor(doc_.json(), previews, editorState_));
            ImGui::BeginDisabled(!doc_.canUndo());
            if (ImGui::Button("Undo (Ctrl+Z)")) undo();
            ImGui::EndDisabled();
            ImGui::SameLine();
            ImGui::BeginDisabled(!doc_.canRedo());
            if (ImGui::Button("Redo (Ctrl+Y)")) redo();
            ImGui::EndDisabled();
            if (ImGui::Button("Save JSON (Ctrl+S)")) guarded([&] { saveDefault(); });
            ImGui::SameLine();
            ImGui::SetNextItemWidth(160);
            ImGui::InputText("##saveas", saveAs_, sizeof saveAs_);
            ImGui::SameLine();
            if (ImGui::Button("Save as")) guarded([&] { save(saveAs_); });
        }
        ImGui::End();
    }

    // Where the colormap the canvas shows lives in the JSON: the pattern's,
    // or the output node's of a graph.
    std::string outputColormapPointer() const {
        const nlohmann::json& j = doc_.json();
        if (j.contains("nodes") && j.contains("output") && j["output"].is_string())
            return "/nodes/" + j["output"].get<std::string>() + "/colormap";
        return "/colormap";
    }

    void drawViewControls() {
        enumCombo("mode", mode_, kWorkbenchModeNames);
        if (mode_ == WorkbenchMode::Split) ImGui::SliderFloat("split", &split_, 0, 1);
        if (mode_ == WorkbenchMode::Overlay) ImGui::SliderFloat("opacity", &overlayOpacity_, 0, 1);
        if (analysing() && enumCombo("analysis", analysis_, kLiveAnalysisNames)) analysisDirty_ = true;
        if (isShadertoy()) {
            const int frame = host_ ? host_->frame() : 0;
            ImGui::Text("frame %d, iTime %.2f s", frame, options_.shadertoy.startTime + frame / options_.shadertoy.fps);
            ImGui::Checkbox("pause (F4)", &paused_);
            ImGui::SameLine();
            if (ImGui::Button("restart")) hostFailed_ = false, hostStale_ = true;
            return;
        }
        static const std::vector<std::string> filters{"none", "paper", "smooth"};
        if (ImGui::BeginCombo("filter", filterName_.c_str())) {
            for (const std::string& f : filters)
                if (ImGui::Selectable(f.c_str(), f == filterName_)) setFilter(f);
            ImGui::EndCombo();
        }
        int aniso = filter_.aniso;
        if (ImGui::SliderInt("aniso", &aniso, int(anisoParam().min), int(anisoParam().max))) setAniso(aniso);
        if (hasNormalMap_) {
            bool lean = response_ == ResponseKind::Lean;
            if (ImGui::Checkbox("LEAN normals (L)", &lean))
                setResponse(lean ? ResponseKind::Lean : ResponseKind::PrefilteredColormap);
        }
        WorkbenchView v = view_;
        if (enumCombo("view", v, kWorkbenchViewNames)) setView(v);
        if (view_ == WorkbenchView::Plane) {
            float tilt = float(camera_.tiltDeg);
            if (ImGui::SliderFloat("tilt", &tilt, float(cameraTiltParam().min), float(cameraTiltParam().max), "%.1f°"))
                setTilt(tilt);
        }
        if (!isScene()) {
            float scale = float(camera_.view.scale);
            if (ImGui::SliderFloat("zoom", &scale, 1.0f / 64, 4096, "%.4g texels/px", ImGuiSliderFlags_Logarithmic))
                zoomAt(camera_.view.scale / scale, textureRect().width / 2.0, textureRect().height / 2.0);
            bool rasterizer = derivatives_ == GpuView::Derivatives::Rasterizer;
            if (ImGui::Checkbox("rasterizer derivatives (D)", &rasterizer))
                setDerivatives(rasterizer ? GpuView::Derivatives::Rasterizer : GpuView::Derivatives::Camera);
        }
    }

    void drawAnalysisPanel() {
        ImGui::TextUnformatted(analysisSummary_.c_str());
        if (!analysisProfile_.empty())
            ImGui::PlotLines("##profile", analysisProfile_.data(), int(analysisProfile_.size()), 0,
                             analysisProfileLabel_.c_str(), FLT_MAX, FLT_MAX,
                             ImVec2(float(kWorkbenchPanelWidth - 30), 80));
        if (analysis_ == LiveAnalysisKind::Correlation) {
            if (enumCombo("show", statistic_, kLiveStatisticNames)) showStatisticChanged();
            ImGui::TextDisabled("right click: pick the point");
            if (ImGui::Button("restart the samples")) analysisDirty_ = true;
        }
    }

    void drawHelp() {
        ImGui::SetNextWindowPos(ImVec2(float(panelWidth()) / pixelScale_ + 20, 20), ImGuiCond_Appearing);
        ImGui::Begin("Keys (F1)", &showHelp_, ImGuiWindowFlags_AlwaysAutoResize);
        if (ImGui::BeginTable("keys", 2)) {
            auto rows = [](const auto& table) {
                for (const KeyHelp& k : table) {
                    ImGui::TableNextRow();
                    ImGui::TableNextColumn();
                    ImGui::TextUnformatted(k.keys);
                    ImGui::TableNextColumn();
                    ImGui::TextUnformatted(k.what);
                }
            };
            if (!isShadertoy()) rows(kPatternKeys);
            rows(kCommonKeys);
            ImGui::EndTable();
        }
        if (isShadertoy())
            ImGui::TextWrapped("Other keys and the left button go to the program (keyboard texture, iMouse).");
        ImGui::End();
    }

    void updateTitle() {
        const auto now = std::chrono::steady_clock::now();
        const double dt = std::chrono::duration<double>(now - lastFrameTime_).count();
        lastFrameTime_ = now;
        fps_ = fps_ == 0 ? 1.0 / std::max(dt, 1e-6) : 0.9 * fps_ + 0.1 / std::max(dt, 1e-6);
        char title[400];
        if (isShadertoy())
            std::snprintf(title, sizeof title, "stochtex workbench - %s - %s - %.0f fps", doc_.source().c_str(),
                          enumName(kWorkbenchModeNames, mode_).c_str(), fps_);
        else
            std::snprintf(title, sizeof title, "stochtex workbench - %s%s - %s - %s view - scale %.3g - %s - %.0f fps",
                          doc_.source().c_str(), doc_.edited() ? " (edited)" : "",
                          filterName_ == "none" ? "unfiltered" : filterName_.c_str(),
                          enumName(kWorkbenchViewNames, view_).c_str(), camera_.view.scale,
                          enumName(kWorkbenchModeNames, mode_).c_str(), fps_);
        context_->setTitle(title);
    }

    // The eye of the 3D views orbits the object's centre; it starts where
    // `scene` puts it (SceneCamera's default eye and target).
    struct Orbit {
        std::array<float, 3> target = SceneCamera{}.target;
        double distance = length(SceneCamera{}), yawDeg = 0, pitchDeg = pitch(SceneCamera{});
        static double length(const SceneCamera& c) {
            const double x = c.eye[0] - c.target[0], y = c.eye[1] - c.target[1], z = c.eye[2] - c.target[2];
            return std::sqrt(x * x + y * y + z * z);
        }
        static double pitch(const SceneCamera& c) {
            return std::asin((c.eye[1] - c.target[1]) / length(c)) * 180.0 / std::numbers::pi;
        }
        SceneCamera camera() const {
            SceneCamera c;
            const double yaw = yawDeg * std::numbers::pi / 180.0, p = pitchDeg * std::numbers::pi / 180.0;
            c.target = target;
            c.eye = {float(target[0] + distance * std::cos(p) * std::sin(yaw)),
                     float(target[1] + distance * std::sin(p)),
                     float(target[2] + distance * std::cos(p) * std::cos(yaw))};
            return c;
        }
    };

    WorkbenchDocument doc_;
    WorkbenchOptions options_;
    std::unique_ptr<GlContext> context_;
    GLFWwindow* window_ = nullptr;
    std::unique_ptr<TextureDisplay> display_;

    // The pattern and its renderers (one per filter and response, built on first use).
    PatternSpec spec_;
    PreviewCache previews_;  // the canvas's and the examples' images, kept across edits of other parts
    PartCache parts_;        // the program's parts, kept across edits of other parts
    int exampleSize_ = 0;
    bool hasNormalMap_ = false;
    std::map<std::pair<std::string, ResponseKind>, std::unique_ptr<GpuView>> renderers_;
    std::unique_ptr<SceneRenderer> scene_;
    const GpuView* sceneView_ = nullptr;
    std::string sceneObject_;
    std::unique_ptr<RenderTarget> target_;
    std::unique_ptr<ShadertoyHost> host_;
    bool hostFailed_ = false, hostStale_ = false;
    std::string failedKey_;
    DisplayImage canvas_, example_[2], exampleSpectrum_[2];
    EditorState editorState_;
    bool needsRebuild_ = false;
    bool gestureOpen_ = false;  // the panel's edits since the mouse or a widget was taken up
    std::chrono::steady_clock::time_point lastBuild_{};

    // What is shown.
    Camera camera_;
    FilterOptions filter_;
    std::string filterName_;
    ResponseKind response_ = ResponseKind::PrefilteredColormap;
    GpuView::Derivatives derivatives_ = GpuView::Derivatives::Camera;
    WorkbenchView view_;
    WorkbenchMode mode_;
    LiveAnalysisKind analysis_;
    LiveStatistic statistic_ = LiveStatistic::Correlation;
    Orbit orbit_;
    float split_ = 0.5f, overlayOpacity_ = 0.5f;
    bool showPanel_ = true, showHelp_ = false, paused_ = false, quit_ = false, expandAll_ = false;
    std::chrono::steady_clock::time_point recordingStart_;
    std::optional<WallClockFrames> recordingClock_;
    long long recordedProgramFrame_ = -1;
    Image heldShot_;                          // a pattern recording's last picture, written when the next comes
    int windowWidth_ = 1, windowHeight_ = 1;  // the framebuffer's pixels
    float pixelScale_ = 1;                    // framebuffer pixels per window coordinate (HiDPI: 2)
    std::array<int, 2> lastTextureSize_{0, 0};
    char saveAs_[256] = "edited.json";

    // The live analysis: recomputed when the picture changes (viewVersion_) or a program draws a frame.
    long long viewVersion_ = 0, analysedVersion_ = -1;
    const ShadertoyHost* analysedHost_ = nullptr;
    bool analysisDirty_ = true;
    Image previousFrame_;
    // The spectrum, flow or flicker running beside the window, and the newest frame waiting for it.
    struct AnalysisRequest {
        LiveAnalysisKind kind;
        Image frame, previous;
    };
    std::future<LiveAnalysisResult> analysisJob_;
    LiveAnalysisKind runningAnalysis_ = LiveAnalysisKind::Spectrum;
    std::optional<AnalysisRequest> queuedAnalysis_;
    DisplayImage analysisImage_;
    std::string analysisSummary_, analysisProfileLabel_;
    std::vector<float> analysisProfile_;
    std::unique_ptr<LiveCorrelation> correlation_;
    int pickX_ = -1, pickY_ = -1;

    // Output.
    std::vector<std::string> pendingScreenshots_;  // F2's
    std::vector<std::string> scriptScreenshots_;   // the script's
    std::unique_ptr<FrameSequenceWriter> recorder_;
    std::vector<ShadertoyInput>
        pendingInputs_;                // a program's mouse since its last frame: the window's and "mouse" steps
    std::vector<KeyEvent> keyEvents_;  // since the last frame: the window's callback and "key" steps
    std::array<int, 2> recordingSize_{0, 0};
    std::string recordingPath_;
    std::string error_, notice_;

    int frame_ = 0;
    double fps_ = 0;
    std::chrono::steady_clock::time_point lastFrameTime_ = std::chrono::steady_clock::now();
};

}  // namespace

int runWorkbench(WorkbenchDocument document, const WorkbenchOptions& options) {
    validateWorkbenchOptions(options);
    Workbench bench(std::move(document), options);
    return bench.run();
}

}  // namespace stochtex
