// The ShaderToy host for Python: a program's frames as arrays, rendered on
// a headless OpenGL context that lives on a thread of its own (gl_thread.h).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "bindings.h"
#include "gl_thread.h"
#include "stochtex/core/error.h"
#include "stochtex/gpu/gl_context.h"
#include "stochtex/gpu/shadertoy.h"
#include "stochtex/gpu/shadertoy_spec.h"

namespace stochtex::python {

namespace {

// The most one frames() call returns.
constexpr long long kMaxFramesBytes = 4ll << 30;

class Shadertoy : public PySource {
public:
    Shadertoy(const std::string& path, const ShadertoySettings& settings) {
        validateShadertoySettings(settings);
        gl_->run([&] {
            const ShadertoySpec spec = loadShadertoy(path);
            checkShadertoyMemory(spec, settings);
            // Made here and kept only when both are made: a failed compile
            // destroys the context on this thread, where it is current.
            auto context = GlContext::headless();
            auto host = std::make_unique<ShadertoyHost>(spec, *context, settings);
            context_ = std::move(context);
            host_ = std::move(host);
        });
    }
    ~Shadertoy() { releaseOnGlThread(gl_, host_, context_); }  // GL objects go with their context current
    Shadertoy(const Shadertoy&) = delete;
    Shadertoy& operator=(const Shadertoy&) = delete;

    // `count` frames from frame 0 of `instance` (the program's instance
    // uniform): float32 (count, height, width, 3).
    py::array_t<float> frames(int count, int instance) {
        if (count < 1 || count > 100000)
            throw InputError::parameter("count", "must be in [1, 100000], got " + std::to_string(count));
        const ShadertoySettings s = gl_->run([this] { return host_->settings(); });
        const size_t frameFloats = size_t(s.width) * size_t(s.height) * 3;
        if (double(frameFloats) * sizeof(float) * count > kMaxFramesBytes)
            throw InputError::parameter("count", std::to_string(count) + " frames of " + std::to_string(s.width) + "x" +
                                                     std::to_string(s.height) + " would take more than " +
                                                     std::to_string(kMaxFramesBytes >> 30) +
                                                     " GiB; take them in parts (reset, then next)");
        Image::Buffer all(frameFloats * size_t(count));
        gl_->run([&] {
            host_->reset(instance);
            for (int k = 0; k < count; ++k) {
                host_->renderFrame();
                const Image image = host_->image();
                std::memcpy(all.data() + frameFloats * size_t(k), image.data().data(), frameFloats * sizeof(float));
            }
        });
        return ownedArray<float>(std::move(all), {count, s.height, s.width, 3});
    }

    // Back to frame 0 of `instance`.
    void reset(int instance) {
        gl_->run([&] { host_->reset(instance); });
    }
    // The next frame, as float32 (height, width, 3).
    py::array_t<float> next() {
        return imageArray(gl_->run([this] {
            host_->renderFrame();
            return host_->image();
        }));
    }
    int frame() {
        return gl_->run([this] { return host_->frame(); });
    }
    std::string programName() const {
        return gl_->run([this] { return host_->spec().name; });
    }
    // Source pixel (0, 0) is the frame's centre; time t is frame round((t − start_time)·fps).
    void use(const std::function<void(const TextureSource&)>& f) const override {
        gl_->run([&] { f(ShadertoySource(*host_)); });
    }
    std::string name() const override { return programName() + " (ShaderToy program)"; }
    double startTime() const override {
        return gl_->run([this] { return host_->settings().startTime; });
    }
    double frameStep() const override {
        return gl_->run([this] { return 1.0 / host_->settings().fps; });
    }

private:
    std::unique_ptr<GlThread> gl_ = std::make_unique<GlThread>();  // first: it outlives what it made
    std::unique_ptr<GlContext> context_;
    std::unique_ptr<ShadertoyHost> host_;
};

}  // namespace

void bindShadertoy(py::module_& m) {
    py::class_<Shadertoy, PySource>(m, "Shadertoy",
                                    "A ShaderToy program (a folder, our manifest or ShaderToy's export JSON; "
                                    "docs/SHADERTOY.md) on a headless OpenGL context: its frames as arrays.")
        .def(py::init([](const std::string& path, int width, int height, double fps, double startTime) {
                 ShadertoySettings s;
                 s.width = width;
                 s.height = height;
                 s.fps = fps;
                 s.startTime = startTime;
                 return std::make_unique<Shadertoy>(path, s);
             }),
             py::arg("path"), py::kw_only(), py::arg("width") = ShadertoySettings{}.width,
             py::arg("height") = ShadertoySettings{}.height, py::arg("fps") = ShadertoySettings{}.fps,
             py::arg("start_time") = ShadertoySettings{}.startTime)
        .def("frames", &Shadertoy::frames, py::arg("count"), py::kw_only(), py::arg("instance") = 0,
             "Frames 0..count−1 of an instance as float32 (count, height, width, 3), the Image pass's RGB, row 0 "
             "on top (as ShaderToy shows it). Deterministic: the same call gives the same frames.")
        .def("reset", &Shadertoy::reset, py::kw_only(), py::arg("instance") = 0,
             "Back to frame 0, buffers cleared, the instance uniform set.")
        .def("next", &Shadertoy::next, "Renders the next frame: float32 (height, width, 3).")
        .def_property_readonly("frame", &Shadertoy::frame, "Frames rendered since the last reset.")
        .def_property_readonly("name", &Shadertoy::programName);
}

}  // namespace stochtex::python
