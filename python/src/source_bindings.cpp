// Texture sources for Python (the zoom texture here; a ShaderToy program in
// shadertoy_bindings.cpp) and the statistics over their instances (thesis
// §3.3), in the chunks a distributed run splits them into
// (studies/instance_statistics.h; stochtex/dask.py merges them).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "bindings.h"
#include "stochtex/core/error.h"
#include "stochtex/image/image_io.h"
#include "stochtex/report/report.h"
#include "stochtex/studies/artifact_report.h"
#include "stochtex/studies/image_base_study.h"
#include "stochtex/studies/instance_statistics.h"
#include "stochtex/studies/zoom_studies.h"

namespace stochtex::python {

namespace {

// The stationary zoom texture over a white-noise lattice or a gray image.
class ZoomTexture : public PySource {
public:
    ZoomTexture(const ZoomParams& params, ZoomBase base) : source_(params, std::move(base)) {}
    void use(const std::function<void(const TextureSource&)>& f) const override {
        py::gil_scoped_release release;
        f(source_);
    }
    const ZoomSource& source() const { return source_; }
    std::string name() const override { return "zoom texture, n = " + std::to_string(source_.params().layers); }
    double startTime() const override { return source_.params().time; }

private:
    ZoomSource source_;
};

// Image textures as bases: a dict {name: pixels or path} or a sequence of
// paths (each named by its path, as the CLI names its files).
std::vector<ImageBase> imageBases(const py::object& images) {
    const auto base = [](const std::string& name, const py::handle& value) {
        if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__")) {
            const std::string path = py::str(py::module_::import("os").attr("fspath")(value));
            py::gil_scoped_release release;
            return ImageBase{name, readImage(path)};
        }
        return ImageBase{name, imageOf(value.cast<Pixels>(), "images")};
    };
    std::vector<ImageBase> out;
    if (images.is_none()) return out;
    if (py::isinstance<py::dict>(images)) {
        for (const auto& [name, value] : images.cast<py::dict>()) out.push_back(base(py::str(name), value));
        return out;
    }
    if (py::isinstance<py::str>(images) || !py::isinstance<py::sequence>(images))
        throw InputError::parameter("images", "must be a dict {name: pixels or path} or a sequence of paths");
    for (const py::handle& path : images.cast<py::sequence>()) {
        if (!py::isinstance<py::str>(path) && !py::hasattr(path, "__fspath__"))
            throw InputError::parameter("images", "a sequence must hold paths (name arrays in a dict)");
        out.push_back(base(py::str(py::module_::import("os").attr("fspath")(path)), path));
    }
    return out;
}

// Keywords split between option tables, in order: each table takes the
// ones it names; one no table names is an InputError listing them all.
template <class... Options>
void setSplitMembers(const py::dict& numbers, std::pair<Options*, std::span<const OptionMember<Options>>>... tables) {
    std::string known;
    const auto names = [&](const auto& table) {
        for (const auto& m : table.second) known += (known.empty() ? "" : ", ") + keywordOf(m.info.name);
    };
    (names(tables), ...);
    for (const auto& item : numbers) {
        const std::string keyword = py::str(item.first);
        bool named = false;
        const auto match = [&](const auto& table) {
            for (const auto& m : table.second) named = named || keywordOf(m.info.name) == keyword;
        };
        (match(tables), ...);
        if (!named) throw InputError::parameter(keyword, "is not an option of this study (its numbers: " + known + ")");
    }
    (setMembers(*tables.first, tables.second, keywordsOf(tables.second, numbers, true)), ...);
}

}  // namespace

std::vector<int> sizeSides(const SizeArgument& size) {
    std::vector<int> sides =
        std::holds_alternative<int>(size) ? std::vector<int>{std::get<int>(size)} : std::get<std::vector<int>>(size);
    if (sides.empty() || sides.size() > 2)
        throw InputError::parameter("size",
                                    "must be N or (width, height), got " + std::to_string(sides.size()) + " numbers");
    return sides;
}

SourceRegion sourceRegion(const SizeArgument& size, const std::optional<std::vector<double>>& origin) {
    const std::vector<int> sides = sizeSides(size);
    for (const int side : sides)
        if (side < 1 || side > 16384)
            throw InputError::parameter("size", "must be in [1, 16384] pixels a side, got " + std::to_string(side));
    SourceRegion region = SourceRegion::centred(sides[0], sides.size() > 1 ? sides[1] : sides[0]);
    if (origin) {
        if (origin->size() != 2)
            throw InputError::parameter("origin", "must be (x0, y0), the window's first pixel in the source's, got " +
                                                      std::to_string(origin->size()) + " numbers");
        region.x0 = (*origin)[0];
        region.y0 = (*origin)[1];
    }
    return region;
}

namespace {

// The window, time and numbers of a statistics run, from Python's keywords.
InstanceStatisticsOptions instanceOptions(const SizeArgument& size, const std::optional<std::vector<double>>& origin,
                                          double time, const py::dict& numbers) {
    InstanceStatisticsOptions o;
    o.region = sourceRegion(size, origin);
    o.time = time;
    setMembers(o, instanceStatisticsMembers(), numbers);
    validateInstanceStatistics(o);
    return o;
}

// The sums of some instances of a source, with the run's options (for the
// summary's window and for pickling).
class InstanceStatistics {
public:
    explicit InstanceStatistics(const InstanceStatisticsOptions& options)
        : options_(options), sums_(emptyInstanceStatistics(options)) {}
    InstanceStatistics(const InstanceStatisticsOptions& options, CorrelationAccumulator&& sums)
        : options_(options), sums_(std::move(sums)) {}

    void merge(const InstanceStatistics& other) {
        py::gil_scoped_release release;
        sums_.merge(other.sums_);
    }
    int count() const { return sums_.count(); }
    py::array_t<float> map(Image (CorrelationAccumulator::*which)() const) const {
        Image image;
        {
            py::gil_scoped_release release;
            image = (sums_.*which)();
        }
        return ownedArray<float>(std::move(image.data()), {image.height(), image.width()});
    }
    py::dict report() const {
        Report report;
        {
            py::gil_scoped_release release;
            InstanceStatisticsSummary s = summarizeInstanceStatistics(sums_, options_.region);
            report.title = "Statistics over instances";
            ReportSection section;
            section.heading = s.title;
            section.tables.push_back({"statistics.csv", std::move(s.summary), true});
            section.figures = std::move(s.figures);
            report.sections.push_back(std::move(section));
        }
        return reportDict(std::move(report));
    }

    // (options, count, sums): what pickling keeps.
    // Pickled as the keywords it was made from (instanceOptions checks them
    // again) and its sums.
    py::tuple state() const {
        const InstanceStatisticsOptions& o = options_;
        py::list sums;
        for (const std::vector<double>* s : sums_.sums())
            sums.append(ownedArray<double>(std::vector<double>(*s), {py::ssize_t(s->size())}));
        return py::make_tuple(py::make_tuple(o.region.width, o.region.height), py::make_tuple(o.region.x0, o.region.y0),
                              o.time, membersDict(o, instanceStatisticsMembers()), sums_.count(), sums);
    }
    static InstanceStatistics fromState(const py::tuple& state) {
        if (state.size() != 6) throw InputError("InstanceStatistics: not a pickled state");
        InstanceStatistics out(instanceOptions(state[0].cast<std::vector<int>>(), state[1].cast<std::vector<double>>(),
                                               state[2].cast<double>(), state[3].cast<py::dict>()));
        const auto arrays =
            state[5].cast<std::vector<py::array_t<double, py::array::c_style | py::array::forcecast>>>();
        if (arrays.size() != CorrelationAccumulator::kSums) throw InputError("InstanceStatistics: not a pickled state");
        std::array<std::vector<double>, CorrelationAccumulator::kSums> sums;
        for (size_t k = 0; k < sums.size(); ++k) sums[k].assign(arrays[k].data(), arrays[k].data() + arrays[k].size());
        out.sums_.restore(state[4].cast<int>(), std::move(sums));
        return out;
    }

    const InstanceStatisticsOptions& options() const { return options_; }
    std::array<int, 2> point() const { return {sums_.referenceX(), sums_.referenceY()}; }

private:
    InstanceStatisticsOptions options_;
    CorrelationAccumulator sums_;
};

// f(source, options) for a Python source, the GIL released, with progress.
template <class F>
InstanceStatistics measure(const PySource& source, const InstanceStatisticsOptions& o, F&& f) {
    std::optional<InstanceStatistics> out;
    source.use([&](const TextureSource& s) {
        validateInstanceStatistics(o, &s);
        out.emplace(o, f(s));
    });
    return std::move(*out);
}

}  // namespace

void bindSources(py::module_& m) {
    py::class_<PySource>(m, "TextureSource",
                         "Frames of a texture for the studies: a window of its plane at a time, for an instance "
                         "(a realisation of its random process). ZoomTexture, Shadertoy.");

    py::class_<ZoomTexture, PySource>(
        m, "ZoomTexture",
        "The stationary zoom texture (Tavernier 2017, eq. 2.1): layers of one white-noise lattice of period "
        "base_size (instance i: the lattice of seed i's hash) or of a gray image (instance i: the image moved), "
        "each scaled by its own factor and blended. Source pixels are the plane's points relative to the zoom "
        "centre.")
        .def(py::init([](const std::string& scaling, const std::string& offsets, const std::string& interpolation,
                         uint32_t offsetSeed, uint32_t seed,
                         const std::optional<py::array_t<float, py::array::c_style | py::array::forcecast>>& image,
                         const py::kwargs& numbers) {
                 ZoomParams p;
                 p.scaling = parseEnum(kZoomScalingNames, scaling, "scaling");
                 p.offsets = parseEnum(kZoomOffsetsNames, offsets, "offsets");
                 p.interpolation = parseEnum(kLatticeInterpolationNames, interpolation, "interpolation");
                 p.offsetSeed = offsetSeed;
                 ZoomBase base;
                 base.seed = seed;
                 setMembers(base, zoomBaseMembers(), keywordsOf(zoomBaseMembers(), numbers, true));
                 setMembers(p, zoomParamsMembers(), keywordsOf(zoomBaseMembers(), numbers, false));
                 if (image) {
                     if (image->ndim() != 2)
                         throw InputError::parameter("image", "must be a gray image: a float array (height, width)");
                     base.image = Image(int(image->shape(1)), int(image->shape(0)), 1, Image::Uninitialized{});
                     std::copy(image->data(), image->data() + image->size(), base.image.data().begin());
                 }
                 py::gil_scoped_release release;
                 return std::make_unique<ZoomTexture>(p, std::move(base));
             }),
             py::kw_only(), py::arg("scaling") = "exponential", py::arg("offsets") = "none",
             py::arg("interpolation") = "linear", py::arg("offset_seed") = ZoomParams{}.offsetSeed,
             py::arg("seed") = ZoomBase{}.seed, py::arg("image") = py::none(),
             "Numbers as keywords: layers, max_scale, time, envelope_sigma (eq. 2.1's n, H, t, s) and base_size.")
        .def(
            "render",
            [](const ZoomTexture& z, const SizeArgument& size, const std::optional<std::vector<double>>& origin,
               double time, int instance) {
                const SourceRegion region = sourceRegion(size, origin);
                Image image;
                {
                    py::gil_scoped_release release;
                    z.source().checkWindow(region, time);
                    image = z.source().render(region, time, instance);
                }
                return ownedArray<float>(std::move(image.data()), {image.height(), image.width()});
            },
            py::kw_only(), py::arg("size") = 256, py::arg("origin") = py::none(), py::arg("time") = 0.0,
            py::arg("instance") = 0,
            "A window as float32 (height, width): size N or (width, height), origin (x0, y0) its first pixel in "
            "the plane (default: centred on the zoom centre).");

    py::class_<InstanceStatistics>(
        m, "InstanceStatistics",
        "Sums over instances of a source (the statistical accumulator, thesis §3.3): per-pixel mean and variance, "
        "correlation with a point, with a row, and between the pixels of the probe row. Merges with the sums of "
        "other instances of the same window; pickles (for Dask).")
        .def(py::init([](const SizeArgument& size, const std::optional<std::vector<double>>& origin, double time,
                         const py::kwargs& numbers) {
                 return InstanceStatistics(instanceOptions(size, origin, time, numbers));
             }),
             py::kw_only(), py::arg("size") = 256, py::arg("origin") = py::none(), py::arg("time") = 0.0,
             "No instance yet, for the options instance_statistics takes.")
        .def("merge", &InstanceStatistics::merge, py::arg("other"),
             "Adds the other's sums (the same window, point and rows).")
        .def_property_readonly("count", &InstanceStatistics::count, "Instances summed.")
        .def_property_readonly("point", &InstanceStatistics::point, "(x, y): the correlation's point in the window.")
        .def_property_readonly("mean", [](const InstanceStatistics& s) { return s.map(&CorrelationAccumulator::mean); })
        .def_property_readonly("variance",
                               [](const InstanceStatistics& s) { return s.map(&CorrelationAccumulator::variance); })
        .def_property_readonly(
            "correlation",
            [](const InstanceStatistics& s) { return s.map(&CorrelationAccumulator::correlationWithPoint); },
            "Corr[I(point), I(x, y)] (thesis eq. 3.1), float32 (height, width).")
        .def_property_readonly(
            "correlation_row",
            [](const InstanceStatistics& s) { return s.map(&CorrelationAccumulator::correlationWithRow); },
            "Corr[I(x, reference_row), I(x, y)], float32 (height, width).")
        .def_property_readonly(
            "probe_correlation",
            [](const InstanceStatistics& s) { return s.map(&CorrelationAccumulator::probeCorrelation); },
            "Corr[I(x, probe_row), I(y, probe_row)], float32 (width, width).")
        .def(py::pickle([](const InstanceStatistics& s) { return s.state(); },
                        [](const py::tuple& state) { return InstanceStatistics::fromState(state); }));

    m.def(
        "instance_statistics",
        [](const PySource& source, const SizeArgument& size, const std::optional<std::vector<double>>& origin,
           double time, const py::object& progress, const py::kwargs& numbers) {
            const InstanceStatisticsOptions o = instanceOptions(size, origin, time, numbers);
            const Progress report = pythonProgress(progress);
            return measure(source, o, [&](const TextureSource& s) { return instanceStatistics(s, o, report); });
        },
        py::arg("source"), py::kw_only(), py::arg("size") = 256, py::arg("origin") = py::none(), py::arg("time") = 0.0,
        py::arg("progress") = py::none(),
        "Statistics over instances 0…N−1 of a source's window at one time, frames gray (the thesis's luminosity). "
        "size: N or (width, height), 4…1024; origin: (x0, y0), default centred; numbers as keywords: instances, "
        "chunk (instances summed from zero before they are added in order: part of the result's definition), "
        "point_x, point_y, reference_row, probe_row (−1: the centre, the point's row). progress(fraction, step) "
        "is called as it goes.");
    m.def(
        "correlation",
        [](const ZoomTexture& zoom, const std::vector<std::string>& variants, const std::vector<int>& layers,
           const py::object& progress, const py::kwargs& numbers) {
            CorrelationStudyOptions o;
            o.zoom = zoom.source().params();
            o.base = zoom.source().base();
            o.variants.clear();
            for (const std::string& v : variants) o.variants.push_back(parseEnum(kZoomVariantNames, v, "variants"));
            o.layers = layers;
            setMembers(o, correlationStudyMembers(), numbers);
            validateCorrelationStudy(o);
            const Progress report = pythonProgress(progress);
            Report result;
            {
                py::gil_scoped_release release;
                result = correlationReport(correlationStudy(o, report), o);
            }
            return reportDict(std::move(result));
        },
        py::arg("zoom"), py::kw_only(),
        py::arg("variants") = std::vector<std::string>{"sliding", "fixed", "simple", "random"},
        py::arg("layers") = CorrelationStudyOptions{}.layers, py::arg("progress") = py::none(),
        "The thesis's correlation study (`stochtex correlation`, Figures 2.8–2.10): per zoom variant and layer "
        "count, the correlation over instances measured beside its closed form. The zoom texture gives the "
        "numbers and the base; each cell sets its variant's scaling and offsets and its layer count. Numbers of "
        "its option table as keywords: instances, plot_size.");
    m.def(
        "contrast",
        [](const ZoomTexture& zoom, const py::kwargs& numbers) {
            ContrastStudyOptions o;
            setMembers(o, contrastStudyMembers(), numbers);
            validateContrastStudy(o);
            Report result;
            {
                py::gil_scoped_release release;
                result = contrastReport(zoomContrastStudy(zoom.source().params(), zoom.source().base(), o),
                                        zoom.source().params().layers);
            }
            return reportDict(std::move(result));
        },
        py::arg("zoom"), py::kw_only(),
        "The thesis's contrast corrections (`stochtex contrast`, §2.4): linear, polynomial and sigmoid "
        "correction of the zoom texture (at its time) against its base's statistics. Numbers of its option table as "
        "keywords: "
        "size.");
    m.def(
        "fractalize",
        [](const py::object& images, int layers, double maxScale, const py::object& progress,
           const py::kwargs& numbers) {
            ImageBaseStudyOptions o;
            o.zoom.layers = layers;
            o.zoom.maxScale = maxScale;
            checkMembers(o.zoom, zoomParamsMembers());
            setMembers(o, imageBaseStudyMembers(), numbers);
            const std::vector<ImageBase> bases = imageBases(images);
            validateImageBaseStudy(o, bases);
            const Progress report = pythonProgress(progress);
            Report result;
            {
                py::gil_scoped_release release;
                result = imageBaseReport(imageBaseStudy(bases, o, report));
            }
            return reportDict(std::move(result));
        },
        py::arg("images"), py::kw_only(), py::arg("layers") = 8, py::arg("max_scale") = ZoomParams{}.maxScale,
        py::arg("progress") = py::none(),
        "Image textures as the zoom texture's base (`stochtex fractalize`, thesis Figures 2.15–2.17): each "
        "image's correlation and the zoom texture's over it, without and with hashed offsets. images: a dict "
        "{name: pixels or path} (pixels as read_image gives them; colour is made gray by 0.21r + 0.72g + 0.07b) "
        "or a sequence of paths. layers and max_scale: the zoom texture's. Numbers of the study's option table as "
        "keywords: size, instances, reference_x, reference_y, echo_radius.");
    m.def(
        "analyze",
        [](const ZoomTexture& zoom, const py::object& images, const std::vector<int>& layers,
           const std::vector<int>& coherenceLayers, const py::object& progress, const py::kwargs& numbers) {
            ArtifactReportOptions o;
            o.correlation.zoom = zoom.source().params();
            o.correlation.base = zoom.source().base();
            o.correlation.layers = layers;
            o.coherenceLayers = coherenceLayers;
            setSplitMembers(numbers, std::pair{&o.correlation, correlationStudyMembers()},
                            std::pair{&o.contrast, contrastStudyMembers()}, std::pair{&o, artifactReportMembers()});
            o.imageBases = imageBases(images);
            o = withDerivedParts(std::move(o));
            validateArtifactReport(o);
            const Progress report = pythonProgress(progress);
            Report result;
            {
                py::gil_scoped_release release;
                result = artifactReport(o, report);
            }
            return reportDict(std::move(result));
        },
        py::arg("zoom"), py::kw_only(), py::arg("images") = py::none(),
        py::arg("layers") = CorrelationStudyOptions{}.layers,
        py::arg("coherence_layers") = ArtifactReportOptions{}.coherenceLayers, py::arg("progress") = py::none(),
        "The report page on the zoom texture's artifacts (`stochtex analyze`): sliding, contrast and its "
        "corrections, correlation, spectrum, optical flow, temporal coherence and its curve over the layer counts "
        "coherence_layers, the image bases (images as fractalize takes them), the marble texture and the "
        "perception stimuli (the marble's sliding videos are left out: the CLI writes them). The zoom texture "
        "gives the numbers and the base; layers: the correlation grid's layer counts. Numbers as keywords: "
        "instances, plot_size (correlation), size (contrast), frame_size, spectrum_instances, coherence_frames.");
    m.def("instance_report", &InstanceStatistics::report, py::arg("statistics"),
          "The summary (instances, mean and its spread, mean variance, the correlation's Corr ≥ ½ area, elongation "
          "and anti-correlation) and maps, as `stochtex shadertoy --analyse statistics` reports them.");
    m.def(
        "instance_chunk",
        [](const PySource& source, int index, const SizeArgument& size,
           const std::optional<std::vector<double>>& origin, double time, const py::kwargs& numbers) {
            const InstanceStatisticsOptions o = instanceOptions(size, origin, time, numbers);
            return measure(source, o, [&](const TextureSource& s) { return instanceChunk(s, o, index); });
        },
        py::arg("source"), py::arg("index"), py::kw_only(), py::arg("size") = 256, py::arg("origin") = py::none(),
        py::arg("time") = 0.0,
        "The sums of chunk `index` of instance_statistics with the same options: merged in index order into "
        "InstanceStatistics(same options), the chunks give instance_statistics' result exactly.");
    m.def(
        "instance_chunk_count",
        [](const SizeArgument& size, const std::optional<std::vector<double>>& origin, double time,
           const py::kwargs& numbers) { return instanceChunkCount(instanceOptions(size, origin, time, numbers)); },
        py::kw_only(), py::arg("size") = 256, py::arg("origin") = py::none(), py::arg("time") = 0.0,
        "⌈instances / chunk⌉ for these options.");
}

}  // namespace stochtex::python
