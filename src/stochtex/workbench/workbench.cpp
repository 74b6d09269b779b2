#include "stochtex/workbench/workbench.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "stochtex/core/error.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/workbench/model.h"
#include "stochtex/workbench/panels.h"
#include "stochtex/workbench/picture.h"

namespace stochtex {

namespace {

// The window: GLFW and ImGui set up, and the frame loop — the script's
// steps and the window's input as commands to the model, the picture and
// the panels drawn from it, captures written (model.h, picture.h, panels.h).
class Workbench {
public:
    Workbench(WorkbenchDocument document, const WorkbenchOptions& options) : options_(options) {
        const int panel = options.panel ? kWorkbenchPanelWidth : 0;
        context_ =
            GlContext::window(options.camera.view.width + panel, options.camera.view.height, "stochtex workbench");
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
        model_ = std::make_unique<WorkbenchModel>(std::move(document), options);
        picture_ = std::make_unique<WorkbenchPicture>(*context_, *model_, options.shadertoy);
        // What the first frame needs, built now: a program that does not
        // compile or a pattern the GPU cannot draw fails the run here.
        context_->framebufferSize(windowWidth_, windowHeight_);
        int coordinatesWide = 0, coordinatesHigh = 0;
        glfwGetWindowSize(window_, &coordinatesWide, &coordinatesHigh);
        model_->setWindow(windowWidth_, windowHeight_,
                          coordinatesWide > 0 ? float(windowWidth_) / float(coordinatesWide) : 1.0f);
        picture_->prepare(model_->textureRect());
    }

    ~Workbench() {
        // The model's kept parts and the picture's views are GL objects of this context.
        picture_.reset();
        model_.reset();
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }

    int run() {
        size_t nextStep = 0;
        bool screenshotWritten = false;
        WorkbenchModel& m = *model_;
        while (!context_->shouldClose() && !m.shown().quit && (options_.frames == 0 || frame_ < options_.frames)) {
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            context_->framebufferSize(windowWidth_, windowHeight_);
            m.setWindow(windowWidth_, windowHeight_, ImGui::GetIO().DisplayFramebufferScale.x);
            while (nextStep < options_.script.size() && options_.script[nextStep].frame <= frame_)
                m.apply(options_.script[nextStep++], true);
            guarded([&] { handleInput(); });
            const auto now = std::chrono::steady_clock::now();
            m.watchFiles(now);
            // While a widget or the canvas is dragged, at most one rebuild every 0.3 s.
            if (m.rebuildDue(now, ImGui::IsAnyItemActive() || ImGui::IsMouseDown(ImGuiMouseButton_Left))) m.rebuild();
            // The picture area as it stands, before the panels are drawn over
            // the window; the run's screenshot is its last frame.
            const bool last =
                (options_.frames > 0 && frame_ + 1 == options_.frames) || m.shown().quit || context_->shouldClose();
            const bool runShot = !options_.screenshot.empty() && last;
            const bool capture = runShot || m.screenshotsPending() || m.recorder().recording();
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, windowWidth_, windowHeight_);
            glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            const DisplayRect pr = m.pictureRect();  // as the steps and keys left the panel and mode
            picture_->draw(m.textureRect(), pr, capture || last);
            if (capture) {
                const Image shot = picture_->codes(pr, windowWidth_, windowHeight_);
                for (const std::string& f : m.takeScreenshots()) guarded([&] { writeScreenshot(f, shot); });
                // A script's screenshot that cannot be written fails the run
                // (exit 2); a key's is reported in the panel.
                for (const std::string& f : m.takeScriptScreenshots()) writeScreenshot(f, shot);
                guarded([&] { record(shot); });
                if (runShot) writeScreenshot(options_.screenshot, shot), screenshotWritten = true;
            }
            panels_.draw(m, *picture_, m.pixelScale(), windowHeight_, m.textureRect());
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

    // An interactive action: a failure is shown in the panel, the session goes on.
    template <class F>
    void guarded(F&& action) {
        try {
            action();
        } catch (const std::exception& e) {
            model_->showError(e.what());
        }
    }

    // The mouse and the keys since the last frame, as commands.
    void handleInput() {
        using A = WorkbenchCommand::Action;
        WorkbenchModel& m = *model_;
        ImGuiIO& io = ImGui::GetIO();
        const DisplayRect pr = model_->pictureRect(), tr = model_->textureRect();
        // Picture pixels, rows down (ImGui's mouse is in window coordinates).
        const float pixelScale = m.pixelScale();
        const double px = io.MousePos.x * pixelScale - pr.x, py = io.MousePos.y * pixelScale;
        // A point of the texture: side by side, the analysis half maps onto it.
        const double tx = px >= tr.width ? px - tr.width : px;
        if (!io.WantCaptureMouse && px >= 0 && py >= 0 && px < pr.width && py < pr.height) {
            if (io.MouseWheel != 0) m.apply(WorkbenchCommand::at(A::Zoom, tx, py, std::pow(1.15, io.MouseWheel)));
            if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
                if (io.KeyCtrl)
                    m.apply(WorkbenchCommand::of(A::Split, std::clamp(px / pr.width, 0.0, 1.0)));
                else if (!m.isShadertoy())
                    m.apply(WorkbenchCommand::at(A::Pan, io.MouseDelta.x * pixelScale, io.MouseDelta.y * pixelScale));
            }
            if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) m.apply(WorkbenchCommand::at(A::Pick, tx, py));
            if (m.isShadertoy()) {
                // iMouse with ShaderToy's click semantics (gpu/shadertoy_input.h), in the program's pixels, y up.
                const double mx = std::min(tx, double(tr.width - 1)), my = tr.height - 1 - py;
                if (ImGui::IsMouseClicked(ImGuiMouseButton_Left))
                    m.apply(WorkbenchCommand::at(A::MouseDown, mx, my));
                else if (ImGui::IsMouseDown(ImGuiMouseButton_Left))
                    m.apply(WorkbenchCommand::at(A::MouseMove, mx, my));
                else if (ImGui::IsMouseReleased(ImGuiMouseButton_Left))
                    m.apply(WorkbenchCommand::of(A::MouseUp));
            }
        }
        // The key events since the last frame, each applied in order (a
        // text field being edited takes them all).
        const std::vector<KeyEvent> events = std::exchange(keyEvents_, {});
        if (io.WantCaptureKeyboard) return;
        for (const KeyEvent& e : events) m.applyKeyEvent(e);
    }

    void writeScreenshot(const std::string& path, const Image& shot) {
        writeImage(path, shot, kNoTransfer);  // sRGB codes already
        model_->showNotice("wrote " + path);
    }

    void record(const Image& shot) {
        WorkbenchRecorder& r = model_->recorder();
        if (!r.recording()) return;
        const bool same =
            model_->isShadertoy()
                ? r.addProgramFrame(shot, picture_->host() ? picture_->host()->frame() : -1)
                : r.addPicture(
                      shot, std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count());
        if (!same) model_->showNotice("wrote " + r.written() + " (stopped: the picture changed size)");
    }

    void updateTitle() {
        const auto now = std::chrono::steady_clock::now();
        const double dt = std::max(std::chrono::duration<double>(now - lastFrameTime_).count(), 1e-6);
        lastFrameTime_ = now;
        fps_ = fps_ == 0 ? 1.0 / dt : 0.9 * fps_ + 0.1 / dt;
        const WorkbenchModel& m = *model_;
        const WorkbenchShown& s = m.shown();
        char title[400];
        if (m.isShadertoy())
            std::snprintf(title, sizeof title, "stochtex workbench - %s - %s - %.0f fps", m.document().source().c_str(),
                          enumName(kWorkbenchModeNames, s.mode).c_str(), fps_);
        else
            std::snprintf(title, sizeof title, "stochtex workbench - %s%s - %s - %s view - scale %.3g - %s - %.0f fps",
                          m.document().source().c_str(), m.document().edited() ? " (edited)" : "",
                          s.filterName == "none" ? "unfiltered" : s.filterName.c_str(),
                          enumName(kWorkbenchViewNames, s.view).c_str(), s.camera.view.scale,
                          enumName(kWorkbenchModeNames, s.mode).c_str(), fps_);
        context_->setTitle(title);
    }

    WorkbenchOptions options_;
    std::unique_ptr<GlContext> context_;
    GLFWwindow* window_ = nullptr;
    std::unique_ptr<WorkbenchModel> model_;
    std::unique_ptr<WorkbenchPicture> picture_;
    WorkbenchPanels panels_;
    std::vector<KeyEvent> keyEvents_;         // since the last frame: the window's callback
    int windowWidth_ = 1, windowHeight_ = 1;  // the framebuffer's pixels
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
