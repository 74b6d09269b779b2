#pragma once
// A ShaderToy-compatible host (issue "The workbench"; thesis ch. 3, GLcv):
// runs a program (gpu/shadertoy_spec.h) frame by frame on a GL context,
// headless or in a window, with ShaderToy's uniforms:
//   iResolution (vec3: width, height, 1), iTime, iTimeDelta, iFrame,
//   iFrameRate, iMouse (vec4, pixels: xy the position while pressed, zw the
//   click), iDate (vec4: year, month − 1, day, seconds since midnight),
//   iChannel0–3, iChannelResolution[4] (vec3), iChannelTime[4], iSampleRate.
// Buffers are RGBA32F, double-buffered (a pass may read its own previous
// frame), cleared to 0 on reset. Time is the frame's: iTime = start +
// iFrame / fps, so a frame's pixels depend on its number alone and runs are
// deterministic; iDate counts from a fixed date (no wall clock).
//
// A program's frame is its Image pass's output as ShaderToy shows it (row 0
// at the top), values as the shader writes them (ShaderToy's are display
// codes; the host neither encodes nor clamps them).
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "stochtex/core/progress.h"
#include "stochtex/gpu/gl_context.h"
#include "stochtex/gpu/shadertoy_input.h"
#include "stochtex/gpu/shadertoy_spec.h"
#include "stochtex/image/image.h"
#include "stochtex/textures/texture_source.h"

namespace stochtex {

struct ShadertoySettings {
    int width = 640, height = 360;  // iResolution, [1, 8192] each
    double fps = 60;                // iFrameRate; iTimeDelta = 1 / fps
    double startTime = 0;           // iTime of frame 0
    std::array<float, 4> mouse{};   // iMouse from frame 0, as given (ShadertoyInputState::setMouse)
    // iDate at iTime = 0: year, month (1–12), day, hour, minute, second. The
    // seconds then run on with iTime (past midnight without a new day).
    std::array<int, 6> date{2026, 1, 1, 12, 0, 0};
    double sampleRate = 44100;  // iSampleRate
    std::vector<int> keys;      // key codes (0–255) held from frame 0, after every reset
    // Key and mouse events at given frames (gpu/shadertoy_input.h), in order
    // of frame; replayed after every reset.
    std::vector<ShadertoyInput> inputs;
    // HW_PERFORMANCE, which published shaders test to choose their quality:
    // 1 as ShaderToy on a desktop, 0 as on a phone.
    int hwPerformance = 1;
};
// InputError naming the parameter (width, height, fps, startTime, date, key, input, hwPerformance).
void validateShadertoySettings(const ShadertoySettings& s);
// ShaderToy plays at most 180 s of a sound pass.
constexpr double kMaxSoundSeconds = 180;
// A program's targets hold at most this many bytes (RGBA32F, two per buffer),
// times the budget factor (core/budget.h).
constexpr long long kMaxShadertoyBytes = 2ll << 30;
// A frame's passes (or a sound block) may run on the GPU for at most this
// many seconds, times the budget factor; past it the process ends with exit
// status 2 and the pass named (core/watchdog.h): a frame cannot be stopped.
// ShaderToy's heaviest programs take a few seconds a frame on a CPU's GL.
constexpr double kFrameSeconds = 30;
// InputError naming `width` when the program's targets at this size would exceed it.
void checkShadertoyMemory(const ShadertoySpec& spec, const ShadertoySettings& s);

// A volume channel's texels (ShaderToy's "Grey Noise3D" and "RGBA Noise3D"
// are 32³): size³ RGBA values, x fastest, then y, then z, each uniform in
// [0, 1) from the project's hash of (x, y, z, seed); rgba: four independent
// channels, else one value in all four.
std::vector<float> shadertoyNoiseVolume(int size, bool rgba, uint32_t seed);

class ShadertoyHost {
public:
    // Compiles every pass and loads its channels (and the program's pattern)
    // on the context, which must outlive the host. InputError: a pass that
    // does not compile (the compiler's messages as "file:line" of the
    // user's files), an unreadable channel image, bad settings.
    ShadertoyHost(const ShadertoySpec& spec, GlContext& context, const ShadertoySettings& settings);
    ~ShadertoyHost();
    ShadertoyHost(const ShadertoyHost&) = delete;
    ShadertoyHost& operator=(const ShadertoyHost&) = delete;

    const ShadertoySpec& spec() const;
    const ShadertoySettings& settings() const;
    // Back to frame 0: buffers cleared, keys as the settings hold them, the program's instance
    // uniform (ShadertoySpec::instanceUniform) set to `instance`.
    void reset(int instance = 0);
    int instance() const;
    // Goes on at another size, as a browser's canvas resized on ShaderToy:
    // the frame count, time, keys and instance kept, the mouse scaled to the
    // new pixels, every buffer's
    // content stretched onto the new size (linear), iResolution the new one.
    // InputError naming width or height (the settings' checks and the
    // memory cap), and then nothing changed.
    void resize(int width, int height);
    // Renders the next frame (every pass in order); frame() then counts it.
    void renderFrame();
    // Frames rendered since reset; the next one is iFrame = frame().
    int frame() const;
    // The Image pass's last output, RGB, row 0 at the top.
    Image image() const;
    // The texture holding it (RGBA32F, GL rows: row 0 at the bottom), for a
    // window to show without a read-back; valid until the next frame or reset.
    unsigned frameTexture() const;
    // The RGBA of a pass's last output at pixel (x, y), ShaderToy's
    // fragCoord convention (y up from the bottom row). InputError naming the
    // pass or the pixel when there is none.
    std::array<float, 4> pixel(const std::string& pass, int x, int y) const;
    // The same checks, before any frame is rendered.
    void checkPixel(const std::string& pass, int x, int y) const;

    // The Sound pass's samples for `seconds` from time 0 (ShaderToy renders
    // its sound ahead, apart from the frames): stereo, interleaved left and
    // right, iSampleRate (the settings' sampleRate) a second, each clamped
    // to [−1, 1] as a browser plays it. InputError naming `sound` for a
    // program without one, `soundSeconds` outside (0, kMaxSoundSeconds].
    std::vector<float> renderSound(double seconds, const Progress& progress = {}) const;

    // The keyboard texture (256 × 3: down, pressed this frame, toggled) and
    // the mouse for the frames to come: a button pressed, dragged and
    // released with ShaderToy's click semantics (gpu/shadertoy_input.h), or
    // iMouse set as it is. The settings' timeline goes on beside them.
    void setKey(int keyCode, bool down);
    void apply(const ShadertoyInput& input);  // now, whatever its frame
    void setMouse(const std::array<float, 4>& mouse);
    std::array<float, 4> mouse() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Renders `frames` frames (≥ 1) on from the host's state, handing the ones
// `readBack` asks for to `sink` with their number (iFrame) as they come, so
// memory stays one frame. A frame not handed on is not read back from the
// GPU (a read-back waits for the frame and copies it: for a simple program
// at 640×360 on llvmpipe it costs more than rendering).
enum class FrameReadBack { Every, Last, None };
using ShadertoyFrameSink = std::function<void(int frame, const Image& image)>;
void renderShadertoyFrames(ShadertoyHost& host, int frames, const ShadertoyFrameSink& sink,
                           const Progress& progress = {}, FrameReadBack readBack = FrameReadBack::Every);

// A program's frames as a texture source, for the studies (spectrum, flow,
// temporal coherence, statistics over instances): source pixel (0, 0) is the
// frame's centre pixel (width / 2, height / 2), rows going down, as the
// zoom texture's windows are centred; time t is frame round((t −
// startTime) · fps), reached by rendering every frame before it (feedback
// buffers need them); instance i sets the program's instance uniform. The
// host must outlive the source, whose renders move it on.
class ShadertoySource : public TextureSource {
public:
    explicit ShadertoySource(ShadertoyHost& host) : host_(host) {}
    int channels() const override { return 3; }
    Image render(const SourceRegion& region, double time, int instance) const override;
    // InputError for a window outside the frame or a time before the start.
    void checkWindow(const SourceRegion& region, double time) const override;
    // InputError for more than one instance of a program without an instance uniform.
    void checkInstances(int count) const override;

private:
    int frameAt(double time) const;
    ShadertoyHost& host_;
};

}  // namespace stochtex
