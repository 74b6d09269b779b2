// Patterns, their renderers and their footprint statistics, for Python.
// Keyword arguments carry the library's parameter names (size, scale,
// offset, aniso, estimator, ...), so an InputError's parameter is the
// keyword the caller wrote.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "bindings.h"
#include "gl_thread.h"
#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/filter/footprint.h"
#include "stochtex/filter/footprint_stats.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/image/image_io.h"
#include "stochtex/image/image_stream.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/cpu_renderer.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/pattern_parts.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/pattern/presets.h"

namespace stochtex::python {

namespace {

PatternSpec reseeded(PatternSpec spec, const std::optional<uint32_t>& seed) {
    if (seed) spec.seed = *seed;
    return spec;
}

// The CLI's render defaults: no filter, K = 8 probes where the footprint is
// anisotropic, the file's estimator unless one is named.
FilterOptions filterOptions(const PatternSpec& spec, const std::string& filter, int aniso,
                            const std::optional<std::string>& estimator, const std::string& response, bool covariance,
                            bool pack8, int referenceMaxSamples, const std::string& kernel) {
    FilterOptions o;
    o.use(parseFilter(filter));
    o.aniso = aniso;
    o.estimator = estimator ? parseEnum(kVarianceEstimatorNames, *estimator, "estimator")
                            : spec.estimator.value_or(VarianceEstimator::Paper);
    o.response.kind = parseEnum(kResponseKindNames, response, "response");
    o.response.covariance = covariance;
    o.pack8 = pack8;
    o.referenceMaxSamples = referenceMaxSamples;
    o.cpuKernel = parseEnum(kCpuKernelNames, kernel, "kernel");
    validateFilterOptions(o);
    return o;
}

// A pattern's renderer (the CPU evaluator or the GPU host) with what it was
// made from: building it builds the runtime data (pyramids, tables) once,
// and every render reuses them.
class Renderer {
public:
    Renderer(PatternSpec spec, FilterOptions options, bool gpu) : spec_(std::move(spec)), options_(options) {
        if (gpu && !gpuHasSource(options_.source))
            throw InputError::parameter(
                "filter", "must be none, paper or smooth on the GPU, got \"" + filterName(options_) + "\"");
        if (gpu) {
            // The GPU's context lives on a thread of its own (gl_thread.h).
            gl_ = std::make_unique<GlThread>();
            gl_->run([this] { renderer_ = makeGpuRenderer(spec_, options_); });
        } else {
            py::gil_scoped_release release;
            renderer_ = makeCpuRenderer(spec_, options_);
        }
    }
    ~Renderer() { releaseOnGlThread(gl_, renderer_); }  // GL objects go with their context current
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // The camera of a view: the pattern's size and scale unless given.
    Camera camera(const std::optional<SizeArgument>& size, const std::optional<double>& scale,
                  const std::optional<std::vector<double>>& offset, const std::string& kind, double tilt, double fov,
                  ViewUse use = ViewUse::Render) const {
        Camera c;
        c.kind = parseEnum(Camera::kKindNames, kind, "camera");
        c.view = patternView(spec_, size ? sizeSides(*size) : std::vector<int>{}, scale,
                             offset.value_or(std::vector<double>{}), use);
        c.tiltDeg = tilt;
        c.fovDeg = fov;
        if (use == ViewUse::Render) validateCamera(c);
        return c;
    }

    // f(renderer) where the renderer lives (the GPU's GL thread; else here on
    // `threads` worker threads, 0: every core), the GIL released.
    template <class F>
    auto use(int threads, F&& f) const {
        if (threads < 0)
            throw InputError::parameter("threads", "must be ≥ 0 (0: every core), got " + std::to_string(threads));
        if (gl_) return gl_->run([&] { return f(static_cast<const ViewRenderer&>(*renderer_)); });
        py::gil_scoped_release release;
        return withThreads(threads, [&] { return f(static_cast<const ViewRenderer&>(*renderer_)); });
    }

    py::array_t<float> render(const std::optional<SizeArgument>& size, const std::optional<double>& scale,
                              const std::optional<std::vector<double>>& offset, const std::string& kind, double tilt,
                              double fov, const std::optional<std::array<int, 2>>& rows, int threads) const {
        // Rows of a view are a band of a bake: the view may be as high as one.
        const Camera c = camera(size, scale, offset, kind, tilt, fov, rows ? ViewUse::BandedBake : ViewUse::Render);
        return imageArray(use(threads, [&](const ViewRenderer& r) {
            return rows ? renderRows(r, c, (*rows)[0], (*rows)[1] - (*rows)[0]) : r.render(c);
        }));
    }

    // The view written to a PNG or EXR in bands of rows (bake-image).
    void bake(const std::string& path, const std::optional<SizeArgument>& size, const std::optional<double>& scale,
              const std::optional<std::vector<double>>& offset, int band, int bits, int threads,
              const py::object& progress) const {
        const Camera c = camera(size, scale, offset, "zoom", 60, 60, ViewUse::BandedBake);
        if (band < 1 || band > 4096)
            throw InputError::parameter("band", "must be in [1, 4096] rows, got " + std::to_string(band));
        checkImageStreamFormat(path);
        WriteOptions options;
        options.bitDepth = bits;
        checkImageOutputFormat(path, options);
        const Progress report = pythonProgress(progress);
        use(threads, [&](const ViewRenderer& r) {
            const std::unique_ptr<ImageStreamWriter> out = openImageStream(path, c.view.width, c.view.height, 3, bits);
            renderInBands(
                r, c, band, [&](const Image& rows) { out->writeRows(rows); }, report);
            out->finish();
        });
    }

    const PatternSpec& spec() const { return spec_; }
    int exampleSize() const { return renderer_->exampleSize(); }
    std::string device() const { return renderer_->device(); }
    std::string filter() const { return filterLabel(options_); }

private:
    std::unique_ptr<GlThread> gl_;  // the GPU's, else none
    PatternSpec spec_;
    FilterOptions options_;
    std::unique_ptr<ViewRenderer> renderer_;
};

// A renderer's camera as a texture source: a window of the camera's view,
// instance i moving it (another draw of the tile offsets). The renderer
// must outlive it (Python keeps it alive).
class PatternView : public PySource {
public:
    PatternView(const Renderer& renderer, const Camera& camera) : renderer_(renderer), camera_(camera) {}
    void use(const std::function<void(const TextureSource&)>& f) const override {
        renderer_.use(0, [&](const ViewRenderer& r) { f(CameraSource(r, camera_)); });
    }
    std::string name() const override { return renderer_.spec().name + ", filter " + renderer_.filter(); }
    Transfer frameTransfer() const override { return Transfer::Srgb; }  // linear-light colour renders

private:
    const Renderer& renderer_;
    Camera camera_;
};

// The footprint statistics of one pair of a pattern's leaves (a plain
// pattern's N = (N_x, N_y)): the estimators on the pair's pyramids and the
// exact statistics by dense sampling, for arrays of footprints.
class FootprintStatistics {
public:
    FootprintStatistics(const PatternSpec& spec, int field, bool covariance, bool pack8) {
        py::gil_scoped_release release;
        const GraphPattern program = GraphPattern::build(spec);
        const int fields = int(program.leafPairs().size());
        if (field < 0 || field >= fields)
            throw InputError::parameter(
                "field", "must be in [0, " + std::to_string(fields - 1) + "], got " + std::to_string(field));
        field_ = program.leafPairs()[size_t(field)];
        if (field_.channelCount() != 2)
            throw InputError::parameter("field", "must be a pair of leaves, got one of " +
                                                     std::to_string(field_.channelCount()) + " (a lone leaf)");
        estimator_ = std::make_unique<FootprintEstimator>(field_, covariance, pack8);
    }

    // uv: (N, 2) in example periods; jacobian: (N, 2, 2), row r = ∂uv_r/∂(x, y).
    py::tuple estimate(const py::array_t<double, py::array::c_style | py::array::forcecast>& uv,
                       const py::array_t<double, py::array::c_style | py::array::forcecast>& jacobian,
                       const std::string& estimator, int aniso) const {
        const VarianceEstimator mode = parseEnum(kVarianceEstimatorNames, estimator, "estimator");
        FilterOptions check;
        check.aniso = aniso;
        validateFilterOptions(check);
        return run(uv, jacobian, [&](double u, double v, const Jacobian& j) {
            return estimator_->estimate(makeFootprint(u, v, j, estimator_->exampleSize(), estimator_->maxLod(), aniso),
                                        mode);
        });
    }

    py::tuple exact(const py::array_t<double, py::array::c_style | py::array::forcecast>& uv,
                    const py::array_t<double, py::array::c_style | py::array::forcecast>& jacobian,
                    int maxSamples) const {
        if (maxSamples < 1 || maxSamples > 4096)
            throw InputError::parameter("max_samples", "must be in [1, 4096], got " + std::to_string(maxSamples));
        return run(uv, jacobian,
                   [&](double u, double v, const Jacobian& j) { return bruteForceStats(field_, u, v, j, maxSamples); });
    }

    int exampleSize() const { return field_.exampleSize(); }
    int maxLevel() const { return estimator_->maxLod(); }

private:
    template <class Statistics>
    static py::tuple run(const py::array_t<double, py::array::c_style | py::array::forcecast>& uv,
                         const py::array_t<double, py::array::c_style | py::array::forcecast>& jacobian,
                         Statistics&& statistics) {
        if (uv.ndim() != 2 || uv.shape(1) != 2) throw InputError::parameter("uv", "must be an array of shape (N, 2)");
        const py::ssize_t n = uv.shape(0);
        if (jacobian.ndim() != 3 || jacobian.shape(0) != n || jacobian.shape(1) != 2 || jacobian.shape(2) != 2)
            throw InputError::parameter(
                "jacobian", "must be an array of shape (N, 2, 2) with N = " + std::to_string(n) + " (uv's)");
        if (n > (py::ssize_t(1) << 31) - 1) throw InputError::parameter("uv", "has too many footprints");
        const double* p = uv.data();
        const double* jp = jacobian.data();
        // The grids index texels with 32-bit integers: footprints within a
        // million periods of the origin (the views' 1e9-texel offsets), sides
        // within 1e4 periods (any footprint a camera makes).
        for (py::ssize_t k = 0; k < 2 * n; ++k)
            if (!std::isfinite(p[k]) || std::abs(p[k]) > 1e6)
                throw InputError::parameter("uv", "must be finite and within 1e6 periods, got " + formatValue(p[k]) +
                                                      " at footprint " + std::to_string(k / 2));
        for (py::ssize_t k = 0; k < 4 * n; ++k)
            if (!std::isfinite(jp[k]) || std::abs(jp[k]) > 1e4)
                throw InputError::parameter("jacobian", "must be finite and within 1e4 periods per pixel, got " +
                                                            formatValue(jp[k]) + " at footprint " +
                                                            std::to_string(k / 4));
        std::vector<float> mean(size_t(n) * 2), cov(size_t(n) * 4);
        {
            py::gil_scoped_release release;
            parallelRows(int(n), [&](int k0, int k1) {
                for (int k = k0; k < k1; ++k) {
                    const double* jk = jp + size_t(k) * 4;
                    const FootprintStats s = statistics(p[2 * k], p[2 * k + 1], Jacobian{jk[0], jk[2], jk[1], jk[3]});
                    mean[2 * size_t(k)] = s.mean[0];
                    mean[2 * size_t(k) + 1] = s.mean[1];
                    float* c = cov.data() + 4 * size_t(k);
                    c[0] = s.varX;
                    c[1] = c[2] = s.cov;
                    c[3] = s.varY;
                }
            });
        }
        return py::make_tuple(ownedArray<float>(std::move(mean), {n, 2}), ownedArray<float>(std::move(cov), {n, 2, 2}));
    }

    TiledField field_;
    std::unique_ptr<FootprintEstimator> estimator_;
};

}  // namespace

void bindPatterns(py::module_& m) {
    py::class_<PatternView, PySource>(m, "PatternView", "A renderer's camera as a TextureSource (Renderer.source).");
    m.def("presets", &presetNames, "The names of the embedded presets, sorted.");
    m.def("band_rows", &bandRows, py::arg("width"), py::arg("band"),
          "The rows of a bake's band for a view `width` pixels wide: `band`, fewer where it would hold more than "
          "16384 × 256 pixels (bake-image's and Renderer.bake's bands).");

    m.def(
        "example",
        [](const std::string& text, const std::string& source, const std::string& baseDir,
           std::optional<uint32_t> seed) {
            NoiseSpec spec = parseNoiseSpec(JsonReader(JsonReader::parse(text, source), source), baseDir);
            if (seed) spec.spectrum.seed = *seed;
            Image image;
            {
                py::gil_scoped_release release;
                image = buildExampleImage(spec, source);
            }
            const int w = image.width(), h = image.height();
            return ownedArray<float>(std::move(image.data()), {h, w});
        },
        py::arg("text"), py::arg("source") = "<json>", py::arg("base_dir") = ".", py::arg("seed") = py::none(),
        "A noise example from a NOISE object's JSON (docs/PATTERNS.md; `stochtex noise`): float32 (W, W), the "
        "values before any Gaussianization, as `stochtex noise` writes them.");
    m.def(
        "colormap",
        [](const std::string& text, const std::string& source, const std::string& baseDir) {
            const ColormapSpec spec = parseColormapSpec(JsonReader(JsonReader::parse(text, source), source), baseDir);
            Image table;
            {
                py::gil_scoped_release release;
                table = buildColormap(spec).table();
            }
            return imageArray(std::move(table));
        },
        py::arg("text"), py::arg("source") = "<json>", py::arg("base_dir") = ".",
        "A colormap H from a COLORMAP object's JSON (docs/PATTERNS.md; `stochtex colormap`): its table as "
        "float32 (Ry, Rx, 3), linear light, row j = y index j (H(x, y) at (j, i)).");

    py::class_<PatternSpec>(m, "Pattern", "A parsed pattern or texture-graph file (docs/PATTERNS.md).")
        .def_static(
            "preset",
            [](const std::string& name, std::optional<uint32_t> seed) { return reseeded(loadPreset(name), seed); },
            py::arg("name"), py::arg("seed") = py::none(), "An embedded preset (stochtex.presets()).")
        .def_static(
            "load",
            [](const std::string& path, std::optional<uint32_t> seed) { return reseeded(loadPatternFile(path), seed); },
            py::arg("path"), py::arg("seed") = py::none(), "A pattern or graph file.")
        .def_static(
            "parse",
            [](const std::string& text, const std::string& source, const std::string& baseDir,
               std::optional<uint32_t> seed) {
                return reseeded(parsePatternSpec(JsonReader(JsonReader::parse(text, source), source), baseDir), seed);
            },
            py::arg("text"), py::arg("source") = "<json>", py::arg("base_dir") = ".", py::arg("seed") = py::none(),
            "A pattern file's JSON text; errors name `source`, relative paths are against base_dir.")
        .def_readonly("name", &PatternSpec::name)
        .def_readonly("seed", &PatternSpec::seed)
        .def_readonly("width", &PatternSpec::width)
        .def_readonly("height", &PatternSpec::height)
        .def_readonly("scale", &PatternSpec::scale, "Example texels per output pixel.")
        .def_property_readonly("is_graph", [](const PatternSpec& s) { return bool(s.graph); })
        .def("__repr__", [](const PatternSpec& s) {
            return "<stochtex.Pattern " + s.name + (s.graph ? " (graph)" : "") + ", " + std::to_string(s.width) + "x" +
                   std::to_string(s.height) + ", seed " + std::to_string(s.seed) + ">";
        });

    py::class_<Renderer>(m, "Renderer",
                         "A pattern's renderer: the CPU evaluator, or with gpu=True the GLSL implementation on a "
                         "headless OpenGL context. Its runtime data (pyramids, tables) is built once.")
        .def(py::init([](const PatternSpec& spec, const std::string& filter, int aniso,
                         const std::optional<std::string>& estimator, const std::string& response, bool covariance,
                         bool pack8, int referenceMaxSamples, const std::string& kernel, bool gpu) {
                 return std::make_unique<Renderer>(spec,
                                                   filterOptions(spec, filter, aniso, estimator, response, covariance,
                                                                 pack8, referenceMaxSamples, kernel),
                                                   gpu);
             }),
             py::arg("pattern"), py::kw_only(), py::arg("filter") = "none", py::arg("aniso") = kDefaultAniso,
             py::arg("estimator") = py::none(), py::arg("response") = "prefiltered-colormap",
             py::arg("covariance") = true, py::arg("pack8") = false, py::arg("reference_max_samples") = 64,
             py::arg("kernel") = "simd", py::arg("gpu") = false)
        .def("render", &Renderer::render, py::kw_only(), py::arg("size") = py::none(), py::arg("scale") = py::none(),
             py::arg("offset") = py::none(), py::arg("camera") = "zoom", py::arg("tilt_deg") = 60.0,
             py::arg("fov_deg") = 60.0, py::arg("rows") = py::none(), py::arg("threads") = 0,
             "The view as a float32 array (height, width, 3): linear-light RGB, row 0 on top. size: N or "
             "(width, height), default the pattern's; scale: example texels per pixel; offset: (u, v) in texels; "
             "camera: zoom or plane (tilt_deg, fov_deg); rows: (y0, y1), only those rows of a zoom view, as "
             "bake-image renders a band (a view up to 65536 a side, in tiles of 16384 columns); threads: 0 for every "
             "core (the result does not depend on it).")
        .def(
            "view",
            [](const Renderer& r, const std::optional<SizeArgument>& size, const std::optional<double>& scale,
               const std::optional<std::vector<double>>& offset, bool baked) {
                const View v =
                    r.camera(size, scale, offset, "zoom", 60, 60, baked ? ViewUse::BandedBake : ViewUse::Render).view;
                py::dict d;
                d["width"] = v.width;
                d["height"] = v.height;
                d["scale"] = v.scale;
                d["offset"] = py::make_tuple(v.offsetU, v.offsetV);
                return d;
            },
            py::kw_only(), py::arg("size") = py::none(), py::arg("scale") = py::none(), py::arg("offset") = py::none(),
            py::arg("baked") = false,
            "The zoom view these keywords give (the pattern's own where not given), checked as a render's, or "
            "with baked=True as a bake's (65536 pixels a side): {width, height, scale, offset}.")
        .def("bake", &Renderer::bake, py::arg("path"), py::kw_only(), py::arg("size") = py::none(),
             py::arg("scale") = py::none(), py::arg("offset") = py::none(), py::arg("band") = 256, py::arg("bits") = 8,
             py::arg("threads") = 0, py::arg("progress") = py::none(),
             "The zoom view written to a PNG (bits 8 or 16) or EXR in bands of `band` rows (band_rows: fewer for "
             "views over 16384 wide), memory one band whatever the size: the same file as `stochtex bake-image` "
             "with the same options.")
        .def(
            "source",
            [](const Renderer& r, const std::optional<double>& scale, const std::optional<std::vector<double>>& offset,
               const std::string& camera, double tilt, double fov) {
                return std::make_unique<PatternView>(r, r.camera(std::nullopt, scale, offset, camera, tilt, fov));
            },
            py::kw_only(), py::arg("scale") = py::none(), py::arg("offset") = py::none(), py::arg("camera") = "zoom",
            py::arg("tilt_deg") = 60.0, py::arg("fov_deg") = 60.0, py::keep_alive<0, 1>(),
            "This renderer's view as a TextureSource for the studies (instance_statistics, frame_analysis): "
            "source pixel (0, 0) is the view's pixel (0, 0); instance i moves the view (another draw of the tile "
            "offsets); static in time. A plane camera's windows start at (0, 0): pass origin=(0, 0).")
        .def_property_readonly("example_size", &Renderer::exampleSize, "W: the examples' side in texels.")
        .def_property_readonly("device", &Renderer::device, "\"CPU\" or the OpenGL context's description.")
        .def_property_readonly("filter", &Renderer::filter);

    py::class_<FootprintStatistics>(m, "FootprintStatistics",
                                    "The statistics of N = (N_x, N_y) over footprints, for one pair of a pattern's "
                                    "leaves (field k of its program; a plain pattern has one).")
        .def(py::init<const PatternSpec&, int, bool, bool>(), py::arg("pattern"), py::kw_only(), py::arg("field") = 0,
             py::arg("covariance") = false, py::arg("pack8") = false)
        .def("estimate", &FootprintStatistics::estimate, py::arg("uv"), py::arg("jacobian"), py::kw_only(),
             py::arg("estimator") = "paper", py::arg("aniso") = 1,
             "μ̂ (N, 2) and Σ̂ (N, 2, 2), float32, of the footprints uv + J·(s, t), s, t in [−½, ½]: uv (N, 2) in "
             "example periods, J (N, 2, 2) with row r = ∂uv_r/∂(x, y).")
        .def("exact", &FootprintStatistics::exact, py::arg("uv"), py::arg("jacobian"), py::kw_only(),
             py::arg("max_samples") = 512, "The exact μ and Σ by dense sampling (two samples per texel and axis).")
        .def_property_readonly("example_size", &FootprintStatistics::exampleSize)
        .def_property_readonly("max_level", &FootprintStatistics::maxLevel);
}

}  // namespace stochtex::python
