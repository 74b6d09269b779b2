#pragma once
// The workbench's picture area (issue 31 item 1): what the model shows, drawn
// on the window's GL context — a pattern's GPU view (one per filter,
// response and anisotropy, built from the model's kept parts on first use),
// on a 3D object or through the zoom or plane camera, or a ShaderToy
// program's frame — with the live analysis beside, split or over it (the
// view modes of thesis Figure 3.2). It also holds the previews' textures the
// panels show. It reads the model and changes only what it shows: a failure
// is put in the model's error line.
#include <array>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "stochtex/gpu/gl_context.h"
#include "stochtex/gpu/gpu_view.h"
#include "stochtex/gpu/render_target.h"
#include "stochtex/gpu/scene_render.h"
#include "stochtex/gpu/shadertoy.h"
#include "stochtex/gpu/texture_display.h"
#include "stochtex/workbench/analysis_runner.h"
#include "stochtex/workbench/model.h"

namespace stochtex {

class WorkbenchPicture {
public:
    WorkbenchPicture(GlContext& context, WorkbenchModel& model, const ShadertoySettings& settings);
    ~WorkbenchPicture();

    // Builds what a first frame of `texture`'s size needs: a program that
    // does not compile or a pattern the GPU cannot draw throws here.
    void prepare(const DisplayRect& texture);
    // Draws the picture area into the default framebuffer: the texture in
    // `texture`, the analysis per the model's mode over `picture`.
    // `capture`: this frame is saved, so its analysis waits for itself.
    void draw(const DisplayRect& texture, const DisplayRect& picture, bool capture);
    // The picture area of the default framebuffer as shown (display codes), row 0 at the top.
    Image codes(const DisplayRect& picture, int windowWidth, int windowHeight) const;

    // For the panels: the program's host (null: none yet), the previews'
    // textures (0: none) and the analysis's numbers.
    const ShadertoyHost* host() const { return host_.get(); }
    unsigned colormapTexture() const { return canvas_.empty() ? 0 : canvas_.texture(); }
    unsigned exampleTexture(int k) const;
    unsigned spectrumTexture(int k) const;
    const std::string& analysisSummary() const { return summary_; }
    const std::vector<float>& analysisProfile() const { return profile_; }
    const std::string& analysisProfileLabel() const { return profileLabel_; }

private:
    void followBuilds();
    GpuView& renderer();
    unsigned drawPattern(int width, int height);
    unsigned drawProgram(int width, int height);
    void buildHost(int width, int height);
    void analyse(const DisplayRect& texture, bool capture);
    LiveAnalysisResult correlationStep(const Image& frame, bool changed, bool restart);
    void show(const LiveAnalysisResult& result);
    void showAnalysis(const DisplayRect& rect, float opacity, bool overlay = false);

    GlContext& context_;
    WorkbenchModel& model_;
    ShadertoySettings settings_;
    TextureDisplay display_;
    long long seenBuild_ = -1;

    // The pattern's views (one per filter, response and anisotropy: the
    // probes are compiled in), its scene and the target they draw into.
    std::map<std::tuple<std::string, ResponseKind, int, VarianceEstimator>, std::unique_ptr<GpuView>> renderers_;
    std::unique_ptr<SceneRenderer> scene_;
    const GpuView* sceneView_ = nullptr;
    std::string sceneObject_;
    std::unique_ptr<RenderTarget> target_;
    std::string failedKey_;  // what a pattern's frame failed for: not tried again until it changes
    // A program's host; stale: rebuilt at the next frame; failed: not until a restart or reload.
    std::unique_ptr<ShadertoyHost> host_;
    bool hostFailed_ = false, hostStale_ = false;

    DisplayImage canvas_, example_[2], exampleSpectrum_[2];

    // The live analysis: again when the picture changes (the model's view
    // version, a program's frame) and for every correlation frame.
    LiveAnalysisRunner analyses_;
    long long analysedVersion_ = -1;
    const ShadertoyHost* analysedHost_ = nullptr;
    std::array<int, 2> lastTextureSize_{0, 0};
    DisplayImage analysisImage_;
    std::string summary_, profileLabel_;
    std::vector<float> profile_;
    static constexpr int kMaxCorrelationSamples = 4096;
};

}  // namespace stochtex
