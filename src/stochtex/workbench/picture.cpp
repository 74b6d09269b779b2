#include "stochtex/workbench/picture.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/gpu/scene.h"
#include "stochtex/textures/texture_source.h"

namespace stochtex {

WorkbenchPicture::WorkbenchPicture(GlContext& context, WorkbenchModel& model, const ShadertoySettings& settings)
    : context_(context), model_(model), settings_(settings) {}

WorkbenchPicture::~WorkbenchPicture() = default;

unsigned WorkbenchPicture::exampleTexture(int k) const { return example_[k].empty() ? 0 : example_[k].texture(); }
unsigned WorkbenchPicture::spectrumTexture(int k) const {
    return exampleSpectrum_[k].empty() ? 0 : exampleSpectrum_[k].texture();
}

// A new build of the document: what was made of the old one goes; the
// previews are uploaded (the model rebuilt only the parts that changed).
void WorkbenchPicture::followBuilds() {
    if (model_.buildCount() == seenBuild_) return;
    seenBuild_ = model_.buildCount();
    failedKey_.clear();
    hostFailed_ = false;
    scene_.reset();
    renderers_.clear();
    if (model_.isShadertoy()) return;
    host_.reset();
    const PatternPreviews& previews = model_.previews();
    canvas_.upload(previews.colormap);
    for (size_t k = 0; k < 2; ++k) {
        example_[k] = {};
        exampleSpectrum_[k] = {};
        if (previews.examples[k].empty()) continue;
        example_[k].upload(previews.examples[k]);
        exampleSpectrum_[k].upload(previews.spectra[k]);
    }
}

void WorkbenchPicture::prepare(const DisplayRect& texture) {
    followBuilds();
    model_.takeProgramRestart();  // the host is built here, at the picture's size
    if (model_.isShadertoy())
        buildHost(texture.width, texture.height);
    else
        renderer();
}

GpuView& WorkbenchPicture::renderer() {
    const WorkbenchShown& s = model_.shown();
    auto& r = renderers_[{s.filterName, s.response, s.filter.aniso, s.filter.estimator}];
    if (!r) {
        FilterOptions o = s.filter;
        const bool covariance = o.response.covariance;
        o.use(parseFilter(s.filterName));
        o.response.kind = s.response;
        o.response.covariance = covariance;
        r = makeGpuView(model_.spec(), context_, o, &model_.parts());
    }
    return *r;
}

void WorkbenchPicture::draw(const DisplayRect& tr, const DisplayRect& pr, bool capture) {
    followBuilds();
    if (model_.takeProgramRestart()) hostFailed_ = false, hostStale_ = true;
    if (tr.width != lastTextureSize_[0] || tr.height != lastTextureSize_[1]) {
        lastTextureSize_ = {tr.width, tr.height};
        model_.viewChanged();
    }
    const WorkbenchShown& s = model_.shown();
    GLuint texture = 0;
    TextureDisplay::Look look = TextureDisplay::kRenderTarget;
    // What a pattern's frame depends on besides the document.
    const std::string key = s.filterName + "|" + std::to_string(int(s.response)) + "|" +
                            std::to_string(s.filter.aniso) + "|" + std::to_string(int(s.filter.estimator)) + "|" +
                            std::to_string(int(s.view));
    if (model_.isShadertoy()) {
        texture = drawProgram(tr.width, tr.height);
        look = TextureDisplay::kGlCodes;
    } else if (key != failedKey_) {
        try {
            texture = drawPattern(tr.width, tr.height);
        } catch (const std::exception& e) {
            // Shown in the panel; tried again when the view or the document changes, not every frame.
            model_.showError(e.what());
            failedKey_ = key;
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!texture) return;
    if (model_.isScene()) look = TextureDisplay::kGlLinear;  // a mesh is drawn the GL way up
    if (model_.analysing()) {
        try {
            analyse(tr, capture);
        } catch (const std::exception& e) {
            model_.showError(e.what());
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);  // the analysis read back from the frame's own framebuffer
    switch (s.mode) {
        case WorkbenchMode::Texture: display_.show(texture, tr, look); break;
        case WorkbenchMode::Analysis: showAnalysis(pr, 1); break;
        case WorkbenchMode::SideBySide:
            display_.show(texture, tr, look);
            showAnalysis({tr.x + tr.width, 0, pr.width - tr.width, pr.height}, 1);
            break;
        case WorkbenchMode::Split: {
            display_.show(texture, tr, look);
            const int cut = int(std::lround(s.split * pr.width));
            glEnable(GL_SCISSOR_TEST);
            glScissor(pr.x + cut, 0, pr.width - cut, pr.height);
            showAnalysis(pr, 1);
            // The split line, part of the picture (screenshots and
            // recordings show where the halves meet): two pixels of white.
            glScissor(pr.x + std::clamp(cut - 1, 0, std::max(0, pr.width - 2)), 0, std::min(2, pr.width), pr.height);
            glClearColor(1, 1, 1, 1);
            glClear(GL_COLOR_BUFFER_BIT);
            glDisable(GL_SCISSOR_TEST);
            break;
        }
        case WorkbenchMode::Overlay:
            display_.show(texture, tr, look);
            showAnalysis(pr, s.overlayOpacity, true);
            break;
    }
}

// overlay: a map's own alpha (LiveAnalysisResult) scales the opacity, so the frame shows where it is zero.
void WorkbenchPicture::showAnalysis(const DisplayRect& rect, float opacity, bool overlay) {
    if (analysisImage_.empty()) return;
    TextureDisplay::Look look = TextureDisplay::kImageCodes;
    look.opacity = opacity;
    look.alpha = overlay;
    display_.show(analysisImage_.texture(), rect, look);
}

GLuint WorkbenchPicture::drawPattern(int w, int h) {
    if (!target_ || target_->width() != w || target_->height() != h)
        target_ = std::make_unique<RenderTarget>(w, h, true);
    GpuView& r = renderer();
    const WorkbenchShown& s = model_.shown();
    if (model_.isScene()) {
        const bool mesh = s.view == WorkbenchView::Mesh && model_.mesh();
        const std::string object = mesh ? "mesh" : s.view == WorkbenchView::Sphere ? "sphere" : "torus";
        if (!scene_ || sceneView_ != &r || sceneObject_ != object) {
            scene_ = std::make_unique<SceneRenderer>(r, mesh ? model_.mesh()->mesh : makeObject(object));
            sceneView_ = &r;
            sceneObject_ = object;
        }
        scene_->draw(s.orbit.camera(), *target_, 4.0f, mesh ? model_.mapping() : SurfaceMapping::Uv);
    } else {
        target_->bind();
        r.setDerivatives(s.derivatives);
        r.drawView(s.viewCamera(w, h));
    }
    return target_->texture();
}

// A new host at the picture's size, swapped in only once it compiled.
void WorkbenchPicture::buildHost(int w, int h) {
    ShadertoySettings s = settings_;
    s.width = w;
    s.height = h;
    auto next = std::make_unique<ShadertoyHost>(model_.document().shadertoySpec(), context_, s);
    host_ = std::move(next);
    hostStale_ = false;
    model_.viewChanged();
}

GLuint WorkbenchPicture::drawProgram(int w, int h) {
    // A new picture size (Tab, side by side, the window resized): the program runs on at it.
    if (host_ && !hostStale_ && !hostFailed_ && (host_->settings().width != w || host_->settings().height != h)) {
        try {
            host_->resize(w, h);  // iMouse too, in the new pixels
            model_.viewChanged();
        } catch (const std::exception& e) {
            model_.showError(e.what());
            hostFailed_ = true;
        }
    }
    if (!host_ || hostStale_ || host_->settings().width != w || host_->settings().height != h) {
        if (hostFailed_ && host_) return host_->frameTexture();  // the last good one, until the next reload
        if (hostFailed_) return 0;
        try {
            buildHost(w, h);
        } catch (const std::exception& e) {
            model_.showError(e.what());
            hostFailed_ = true;
            return host_ ? host_->frameTexture() : 0;
        }
    }
    // Paused too: the inputs change the program's state only.
    for (const ShadertoyInput& e : model_.takeProgramInputs()) host_->apply(e);
    for (const auto& [code, pressed] : model_.takeProgramKeys()) host_->setKey(code, pressed);
    if (!model_.shown().paused || host_->frame() == 0) host_->renderFrame();
    return host_->frameTexture();
}

// The live analysis of the frame shown (analysis_runner.h), recomputed when the picture changed.
void WorkbenchPicture::analyse(const DisplayRect& tr, bool capture) {
    if (std::min(tr.width, tr.height) < 16) {
        summary_ = "the picture is too small to analyse (16 pixels a side at least)";
        analysisImage_ = {};
        return;
    }
    const WorkbenchShown& s = model_.shown();
    const bool program = model_.isShadertoy();
    const long long version = program ? host_->frame() : model_.viewVersion();
    const bool changed = version != analysedVersion_ || host_.get() != analysedHost_;
    const bool restart = model_.takeAnalysisRestart();
    if (restart) analyses_.restart();
    if (changed || restart || s.analysis == LiveAnalysisKind::Correlation) {
        // Pattern targets hold image row 0 in GL row 0; a mesh and a program's frame the GL way up.
        const Image frame = program            ? host_->image()
                            : model_.isScene() ? target_->readRgb(RenderTarget::Rows::TopDown)
                                               : target_->readRgb(RenderTarget::Rows::AsDrawn);
        if (s.analysis == LiveAnalysisKind::Correlation)
            show(correlationStep(frame, changed, restart));
        else
            analyses_.queue(s.analysis, frame);
        analysedVersion_ = version;
        analysedHost_ = host_.get();
    }
    if (auto r = analyses_.collect(s.analysis, capture)) show(*r);
}

LiveAnalysisResult WorkbenchPicture::correlationStep(const Image& frame, bool changed, bool restart) {
    const WorkbenchShown& s = model_.shown();
    const bool program = model_.isShadertoy();
    const int w = frame.width(), h = frame.height();
    if (!program && model_.isScene()) {
        LiveAnalysisResult r;
        r.image = Image(w, h, 3, 0.5f);
        r.summary = "correlation over instances: in the zoom and plane views";
        return r;
    }
    const int px = std::clamp(s.pickX < 0 ? w / 2 : s.pickX, 0, w - 1);
    const int py = std::clamp(s.pickY < 0 ? h / 2 : s.pickY, 0, h - 1);
    // A program's samples are its frames; a pattern's are its instances of
    // one view, so a new view starts them again.
    LiveCorrelation& c = analyses_.correlation(w, h, px, py, restart || (changed && !program));
    if (program) {
        if (changed) c.add(frame);
    } else if (c.count() < kMaxCorrelationSamples) {
        // Instances through the GPU: the view moved by a hashed whole-texel offset (CameraSource).
        const CameraSource source(renderer(), s.viewCamera(w, h));
        for (int k = 0; k < 4; ++k) c.add(source.render({w, h, 0, 0}, 0, c.count()));
    }
    return c.result(s.statistic);
}

void WorkbenchPicture::show(const LiveAnalysisResult& result) {
    analysisImage_.upload(result.image);
    summary_ = result.summary;
    profile_ = result.profile;
    profileLabel_ = result.profileLabel;
}

Image WorkbenchPicture::codes(const DisplayRect& pr, int windowWidth, int windowHeight) const {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    const Image all = readBoundFramebufferRgb(windowWidth, windowHeight, RenderTarget::Rows::TopDown);
    return crop(all, pr.x, 0, std::min(pr.width, all.width() - pr.x), std::min(pr.height, all.height()));
}

}  // namespace stochtex
