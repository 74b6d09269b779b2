#pragma once
// Frames of a texture for the studies: a source renders a window of its
// plane at a time t and for an instance i (a realisation of its random
// process), and tells its closed-form statistics where it knows them.
//
// Adapters: the stationary zoom texture (instance i = white-noise lattice i,
// analytic statistics from ZoomStatistics), the procedural phasor noise
// (unfiltered) and any ViewRenderer (a file's program under any statistics
// source and response, on the CPU or the GPU, through its Camera). Patterns are static (t is ignored); their instance i
// ≠ 0 is the same texture seen through a window moved by a hashed offset of up to 1024 example periods, which for the
// tiled-and-blended noise (tiles hashed per grid cell) is another draw of the random tile offsets. Instance 0 is the
// plain render.
#include <functional>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "stochtex/image/image.h"
#include "stochtex/noise/phasor_noise.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/pattern/view.h"
#include "stochtex/pattern/view_renderer.h"
#include "stochtex/textures/zoom_statistics.h"
#include "stochtex/textures/zoom_texture.h"

namespace stochtex {

// A window of a source's pixel grid: image pixel (px, py) shows the
// source's pixel (x0 + px, y0 + py). For the zoom texture the source's
// pixels are the plane's points relative to the zoom centre; for patterns,
// pixel (0, 0) is the pixel (0, 0) of the pattern's view or camera.
struct SourceRegion {
    int width = 256, height = 256;
    double x0 = 0, y0 = 0;
    static SourceRegion centred(int width, int height) { return {width, height, -0.5 * width, -0.5 * height}; }
};

// Moments over instances of a 1-channel source at one time, in closed form.
class AnalyticStatistics {
public:
    virtual ~AnalyticStatistics() = default;
    virtual double mean(double x, double y) const = 0;
    virtual double variance(double x, double y) const = 0;
    virtual double correlation(double x1, double y1, double x2, double y2) const = 0;
};

class TextureSource {
public:
    virtual ~TextureSource() = default;
    virtual int channels() const = 0;
    virtual Image render(const SourceRegion& region, double time, int instance) const = 0;
    // nullptr where the source has no closed form.
    virtual std::unique_ptr<const AnalyticStatistics> statistics(double /*time*/) const { return nullptr; }
    // InputError where render(region, time, ·) cannot be done (a window or a
    // time outside the source's range), so that a study checks every frame
    // before it writes anything; render throws the same error.
    virtual void checkWindow(const SourceRegion& /*region*/, double /*time*/) const {}
    // InputError (parameter "instances") where instances 0…count−1 are not
    // distinct draws of the source (a program without an instance uniform),
    // so that a study does not average one frame with itself and call it a
    // mean over instances.
    virtual void checkInstances(int /*count*/) const {}
};

// The zoom texture over a white-noise lattice (size × size, instance i uses
// the seed deriveSeed(seed, i)) or over one gray image (instance i ≠ 0: the
// image moved periodically by imageInstanceOffset(i), so that statistics over
// instances are those of the image's translations, thesis §2.7.1).
struct ZoomBase {
    int size = 512;  // the white-noise lattice's period
    uint32_t seed = 1;
    Image image;  // empty: white noise
};
// The entry of its lattice's period ("baseSize": it sits beside the frame's
// size wherever both are set), the check of a white-noise base and the CLI's flag.
std::span<const OptionMember<ZoomBase>> zoomBaseMembers();
// InputError for a white-noise base whose period is out of its range.
void validateZoomBase(const ZoomBase& base);

class ZoomSource : public TextureSource {
public:
    // InputError for unusable parameters (validateZoomParams) or base.
    ZoomSource(const ZoomParams& params, ZoomBase base);
    const ZoomParams& params() const { return params_; }
    const ZoomBase& base() const { return base_; }
    // The lattice of one instance (the first one is kept).
    LatticeTexture lattice(int instance) const;
    const LatticeTexture& firstLattice() const { return first_; }

    int channels() const override { return 1; }
    Image render(const SourceRegion& region, double time, int instance) const override;
    std::unique_ptr<const AnalyticStatistics> statistics(double time) const override;

private:
    ZoomParams params_;
    ZoomBase base_;
    LatticeTexture first_;
};

// The analytic statistics of the zoom texture (μ_f; σ_f² α(x, x); eq. 2.11).
class ZoomAnalyticStatistics : public AnalyticStatistics {
public:
    ZoomAnalyticStatistics(const ZoomParams& params, const LatticeTexture& lattice)
        : stats_(params, lattice.width(), lattice.height()), mean_(lattice.mean()), variance_(lattice.variance()) {}
    const ZoomStatistics& zoom() const { return stats_; }
    double mean(double, double) const override { return mean_; }
    double variance(double x, double y) const override { return variance_ * stats_.varianceFactor(x, y); }
    double correlation(double x1, double y1, double x2, double y2) const override {
        return stats_.correlation(x1, y1, x2, y2);
    }

private:
    ZoomStatistics stats_;
    double mean_, variance_;
};

// The periodic shift of an image texture's instance i: (0, 0) for i = 0,
// else hashed in [0, width) × [0, height).
std::array<int, 2> imageInstanceOffset(int instance, int width, int height);

// A gray image as a periodic texture (thesis §2.7.1, Figure 2.15): source
// pixel (x, y) is texel (x mod W, y mod H) of the image moved by
// imageInstanceOffset(i); static in t. Its correlation over instances is the
// image's own (spatial) autocorrelation.
class ImageTextureSource : public TextureSource {
public:
    // InputError unless gray is 1-channel and at least 2×2.
    explicit ImageTextureSource(Image gray);
    int channels() const override { return 1; }
    Image render(const SourceRegion& region, double time, int instance) const override;

private:
    Image image_;
};

// The window offset (in texels) of pattern instance i: (0, 0) for i = 0.
std::array<double, 2> instanceOffset(int instance, int exampleSize);

// Any renderer of a camera's view (pattern/view_renderer.h: the CPU
// evaluators, the GPU's GpuView) as a source: the region is a window of the
// camera's view (a plane camera renders whole frames only: its region offset
// must be 0), instance i ≠ 0 moves the view by instanceOffset(i). The
// renderer must outlive the source.
class CameraSource : public TextureSource {
public:
    CameraSource(const ViewRenderer& renderer, const Camera& camera)
        : renderer_(renderer), exampleSize_(renderer.exampleSize()), camera_(camera) {}
    int channels() const override { return 3; }
    Image render(const SourceRegion& region, double time, int instance) const override;
    // InputError for a region offset under a plane camera.
    void checkWindow(const SourceRegion& region, double time) const override;
    const Camera& camera() const { return camera_; }

private:
    const ViewRenderer& renderer_;
    int exampleSize_;
    Camera camera_;
};

// Procedural phasor noise (noise/phasor_noise.h) under a phasor colormap H:
// S = H(½ + ¼ cos φ, ½ + ¼ sin φ), the profile P(φ) through the same table as
// a pattern's, unfiltered, one sample per pixel centre. Pixels map to uv as
// a pattern's do: `view` in texels of an example of `exampleSize` (its size
// is ignored: the region's is used). Instance i ≠ 0 draws the impulses with
// the seed deriveSeed(seed, i). Static in t.
class PhasorNoiseSource : public TextureSource {
public:
    PhasorNoiseSource(const PhasorNoiseParams& params, ColormapTable colormap, const View& view, int exampleSize);
    int channels() const override { return 3; }
    Image render(const SourceRegion& region, double time, int instance) const override;

private:
    PhasorNoise noise_;
    ColormapTable colormap_;
    View view_;
    int exampleSize_;
};

// Images as a source, so that files (frames of a video, photographs,
// renders of another tool) feed the same studies: frame k = floor(time)
// (one frame per time unit), instance i ≠ 0 reads frame i instead, so a set
// of images can also stand for instances. Regions are windows of the frame
// in its pixels (x0, y0 ≥ 0 from the top-left corner) and must lie inside.
// All frames have one size and channel count (InputError otherwise).
class ImageSequenceSource : public TextureSource {
public:
    explicit ImageSequenceSource(std::vector<Image> frames);
    int frames() const { return int(frames_.size()); }
    int width() const { return frames_.front().width(); }
    int height() const { return frames_.front().height(); }
    int channels() const override { return frames_.front().channels(); }
    Image render(const SourceRegion& region, double time, int instance) const override;
    // InputError for a window not inside the frames or a time with no frame.
    void checkWindow(const SourceRegion& region, double time) const override;
    // Instance i reads frame i: at most frames() instances.
    void checkInstances(int count) const override;

private:
    std::vector<Image> frames_;
};

}  // namespace stochtex
