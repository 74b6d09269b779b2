// The studies, for Python: their report values (tables as columns, figures
// as arrays), and the pieces a distributed run splits them into
// (stochtex/dask.py): the per-footprint terms of Table 1 and their merge.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "stochtex/analysis/estimator_error.h"
#include "stochtex/pattern/prefiltered_colormap.h"
#include "stochtex/studies/estimator_renders.h"
#include "stochtex/studies/frame_analysis.h"
#include "stochtex/studies/graph_filtering.h"
#include "stochtex/studies/marble_study.h"
#include "stochtex/studies/normal_maps.h"
#include "stochtex/studies/paper.h"
#include "stochtex/studies/phasor_figures.h"
#include "stochtex/studies/stability_study.h"
#include "stochtex/studies/stimuli.h"

namespace stochtex::python {

namespace {

Table1Options table1Options(int count, const std::vector<int>& footprints, uint32_t seed, uint32_t noiseSeed,
                            int maxSamples) {
    Table1Options o;
    o.errors.count = count;
    o.errors.footprints = footprints;
    o.errors.seed = seed;
    o.errors.maxSamplesPerAxis = maxSamples;
    o.seed = noiseSeed;
    validateTable1(o);
    if (maxSamples < 1 || maxSamples > 4096)
        throw InputError::parameter("max_samples", "must be in [1, 4096], got " + std::to_string(maxSamples));
    return o;
}

py::dict table1Dict(Table1Result&& result) {
    py::list tables, figures;
    for (const Table& t : result.tables) tables.append(tableTuple(t));
    for (Figure& f : result.figures) figures.append(py::make_tuple(f.file, f.caption, imageArray(std::move(f.image))));
    py::dict d;
    d["data"] = tableTuple(result.data);
    d["tables"] = tables;
    d["figures"] = figures;
    return d;
}

// The Table 1 pair of one noise and what measures its footprints' terms.
class Table1Sampler {
public:
    Table1Sampler(int which, const Table1Options& options) {
        if (which != 0 && which != 1) throw InputError::parameter("noise", "must be 0 (low) or 1 (high)");
        py::gil_scoped_release release;
        sampler_ = std::make_unique<EstimatorErrorSampler>(table1Field(which, options.seed), options.errors);
    }
    py::array_t<double> terms(int footprint, int first, int count) const {
        std::vector<double> t;
        {
            py::gil_scoped_release release;
            t = sampler_->terms(footprint, first, count);
        }
        const py::ssize_t width = py::ssize_t(EstimatorErrorSampler::termsPerFootprint());
        return ownedArray<double>(std::move(t), {py::ssize_t(count), width});
    }

private:
    std::unique_ptr<EstimatorErrorSampler> sampler_;
};

// A study's report: its numbers set from keywords (the study's option
// table, the one the CLI's flags come from), then run with the GIL released.
template <class Options, class Run>
py::dict studyReport(Options options, std::span<const OptionMember<Options>> members, const py::dict& numbers,
                     const py::object& progress, Run&& run) {
    setMembers(options, members, numbers);
    const Progress report = pythonProgress(progress);
    Report result;
    {
        py::gil_scoped_release release;
        result = run(options, report);
    }
    return reportDict(std::move(result));
}

// A stability study's options from Python's keywords, as the CLI's
// `stability` makes them: the filters by name over aniso and the reference's
// samples, those over the estimators once per estimator.
StabilityStudyOptions stabilityOptions(const PatternSpec& pattern, const std::vector<std::string>& filters,
                                       const std::vector<std::string>& estimatorNames, int aniso,
                                       int referenceMaxSamples, const py::kwargs& numbers) {
    FilterOptions base;
    base.aniso = aniso;
    base.referenceMaxSamples = referenceMaxSamples;
    validateFilterOptions(base);
    std::vector<VarianceEstimator> estimators;
    for (const std::string& name : estimatorNames)
        estimators.push_back(parseEnum(kVarianceEstimatorNames, name, "estimators"));
    StabilityStudyOptions o;
    o.filters = stabilityFilters(pattern, filters, estimators, base);
    setMembers(o, stabilityStudyMembers(), numbers);
    validateStabilityStudy(o);
    return o;
}

py::tuple framesTuple(StabilityFrames&& f) {
    const auto arrays = [](std::vector<std::vector<double>>& perFilter) {
        py::list out;
        for (std::vector<double>& v : perFilter) {
            const py::ssize_t n = py::ssize_t(v.size());
            out.append(ownedArray<double>(std::move(v), {n}));
        }
        return out;
    };
    return py::make_tuple(f.first, f.count, arrays(f.accuracy), arrays(f.imageChange), arrays(f.errorFlicker));
}

StabilityFrames framesOf(const py::tuple& t) {
    if (t.size() != 5) throw InputError::parameter("parts", "must hold StabilitySampler.frames' tuples");
    const auto lists = [](const py::handle& h) {
        std::vector<std::vector<double>> out;
        for (const auto& a : h.cast<std::vector<py::array_t<double, py::array::c_style | py::array::forcecast>>>())
            out.emplace_back(a.data(), a.data() + a.size());
        return out;
    };
    return {t[0].cast<int>(), t[1].cast<int>(), lists(t[2]), lists(t[3]), lists(t[4])};
}

// A stability study's pattern, filters and ground truth, built once.
class PyStabilitySampler {
public:
    PyStabilitySampler(const PatternSpec& spec, const StabilityStudyOptions& options)
        : frames_(options.frames), pattern_(GraphPattern::build(spec)), sampler_(pattern_, options) {}
    int frameCount() const { return frames_; }
    py::tuple frames(int first, int count, const py::object& progress) const {
        const Progress report = pythonProgress(progress);
        StabilityFrames f;
        {
            py::gil_scoped_release release;
            f = sampler_.frames(first, count, report);
        }
        return framesTuple(std::move(f));
    }

private:
    int frames_;
    GraphPattern pattern_;  // before the sampler: its filters refer to it
    StabilitySampler sampler_;
};

// A frame study's run of a Python source: its window, its first frame's time
// and step (the source's where not given), its frames; named as the source.
FrameAnalysisOptions frameOptions(const PySource& source, std::vector<FrameAnalysis> analyses, const SizeArgument& size,
                                  const std::optional<std::vector<double>>& origin, const std::optional<double>& time,
                                  const std::optional<double>& timeStep, int frames) {
    FrameAnalysisOptions o;
    o.analyses = std::move(analyses);
    o.region = sourceRegion(size, origin);
    o.time = time.value_or(source.startTime());
    o.timeStep = timeStep.value_or(source.frameStep());
    o.frames = frames;
    o.frameTransfer = source.frameTransfer();
    o.sourceName = source.name();
    return o;  // checked by the study it is for
}

}  // namespace

void bindStudies(py::module_& m) {
    // What stochtex.dask splits a frame study's run by, where no frames are given.
    m.attr("_frame_analysis_frames") = FrameAnalysisOptions{}.frames;
    m.def(
        "stability",
        [](const PatternSpec& pattern, const std::vector<std::string>& filters,
           const std::vector<std::string>& estimators, int aniso, int referenceMaxSamples, const py::object& progress,
           const py::kwargs& numbers) {
            const StabilityStudyOptions o =
                stabilityOptions(pattern, filters, estimators, aniso, referenceMaxSamples, numbers);
            const Progress report = pythonProgress(progress);
            Report result;
            {
                py::gil_scoped_release release;
                result = stabilityReport(stabilityStudy(GraphPattern::build(pattern), o, report), pattern.name);
            }
            return reportDict(std::move(result));
        },
        py::arg("pattern"), py::kw_only(),
        py::arg("filters") = std::vector<std::string>{"none", "paper", "smooth", "exact", "reference"},
        py::arg("estimators") = std::vector<std::string>{}, py::arg("aniso") = kDefaultAniso,
        py::arg("reference_max_samples") = 32, py::arg("progress") = py::none(),
        "Temporal stability under a zoom (`stochtex stability`): per filter the error flicker, accuracy and "
        "image change of a zoom-out sequence against its ground truth. estimators: each filter over them is "
        "measured once per name (default: the pattern file's, else paper). Numbers of its option table as "
        "keywords: frames, size, from, to, truth_samples.");
    py::class_<PyStabilitySampler>(m, "StabilitySampler",
                                   "A stability study's filters and ground truth, built once, measuring ranges of "
                                   "its frames (stochtex.dask.stability); stability_from_frames joins them.")
        .def(py::init([](const PatternSpec& pattern, const std::vector<std::string>& filters,
                         const std::vector<std::string>& estimators, int aniso, int referenceMaxSamples,
                         const py::kwargs& numbers) {
                 const StabilityStudyOptions o =
                     stabilityOptions(pattern, filters, estimators, aniso, referenceMaxSamples, numbers);
                 py::gil_scoped_release release;
                 return std::make_unique<PyStabilitySampler>(pattern, o);
             }),
             py::arg("pattern"), py::kw_only(),
             py::arg("filters") = std::vector<std::string>{"none", "paper", "smooth", "exact", "reference"},
             py::arg("estimators") = std::vector<std::string>{}, py::arg("aniso") = kDefaultAniso,
             py::arg("reference_max_samples") = 32)
        .def("frames", &PyStabilitySampler::frames, py::arg("first"), py::arg("count"), py::kw_only(),
             py::arg("progress") = py::none(),
             "Frames [first, first + count): (first, count, accuracy, image_change, error_flicker), each a list "
             "per filter of float64 arrays (accuracy per frame; the changes per pair (k − 1, k), k ≥ 1 in the "
             "range).")
        .def_property_readonly("frame_count", &PyStabilitySampler::frameCount, "The study's frames.");
    m.def(
        "stability_from_frames",
        [](const std::vector<py::tuple>& parts, const PatternSpec& pattern, const std::vector<std::string>& filters,
           const std::vector<std::string>& estimators, int aniso, int referenceMaxSamples, const py::kwargs& numbers) {
            const StabilityStudyOptions o =
                stabilityOptions(pattern, filters, estimators, aniso, referenceMaxSamples, numbers);
            std::vector<StabilityFrames> frames;
            for (const py::tuple& t : parts) frames.push_back(framesOf(t));
            Report result;
            {
                py::gil_scoped_release release;
                result = stabilityReport(stabilityFromFrames(o, frames), pattern.name);
            }
            return reportDict(std::move(result));
        },
        py::arg("parts"), py::arg("pattern"), py::kw_only(),
        py::arg("filters") = std::vector<std::string>{"none", "paper", "smooth", "exact", "reference"},
        py::arg("estimators") = std::vector<std::string>{}, py::arg("aniso") = kDefaultAniso,
        py::arg("reference_max_samples") = 32,
        "The stability study from StabilitySampler.frames' parts covering every frame in order: exactly "
        "stability() with the same options.");

    m.def(
        "frame_analysis",
        [](const PySource& source, const std::vector<std::string>& analyses, const SizeArgument& size,
           const std::optional<std::vector<double>>& origin, const std::optional<double>& time,
           const std::optional<double>& timeStep, int frames, int instances, int pointX, int pointY,
           const py::object& progress) {
            std::vector<FrameAnalysis> parsed;
            for (const std::string& a : analyses) parsed.push_back(parseEnum(kFrameAnalysisNames, a, "analyses"));
            FrameAnalysisOptions o = frameOptions(source, std::move(parsed), size, origin, time, timeStep, frames);
            o.instances = instances;
            o.pointX = pointX;
            o.pointY = pointY;
            validateFrameAnalysis(o);
            const Progress report = pythonProgress(progress);
            Report result;
            source.use([&](const TextureSource& s) { result = frameAnalysis(s, o, report).report; });
            return reportDict(std::move(result));
        },
        py::arg("source"), py::kw_only(), py::arg("analyses") = std::vector<std::string>{"spectrum"},
        py::arg("size") = 256, py::arg("origin") = py::none(), py::arg("time") = py::none(),
        py::arg("time_step") = py::none(), py::arg("frames") = FrameAnalysisOptions{}.frames,
        py::arg("instances") = FrameAnalysisOptions{}.instances, py::arg("point_x") = -1, py::arg("point_y") = -1,
        py::arg("progress") = py::none(),
        "Frame studies of a source's window on one page (`stochtex shadertoy PROG --analyse ...`): spectrum (the "
        "first frame's power spectrum), flow (optical flow between consecutive frames), coherence, flicker (what "
        "the flow does not explain), statistics (over instances). Frame k at time + k·time_step (defaults: the "
        "source's start and frame step).");
    m.def(
        "flicker_pairs",
        [](const PySource& source, int first, int count, const SizeArgument& size,
           const std::optional<std::vector<double>>& origin, const std::optional<double>& time,
           const std::optional<double>& timeStep, int frames) {
            const FrameAnalysisOptions o =
                frameOptions(source, {FrameAnalysis::Flicker}, size, origin, time, timeStep, frames);
            FlickerPairs f;
            source.use([&](const TextureSource& s) { f = flickerPairs(s, o, first, count); });
            std::vector<double> residual, contrast, relative;
            for (const FlickerMeasure& m : f.measures) {
                residual.push_back(m.residual);
                contrast.push_back(m.contrast);
                relative.push_back(m.relative);
            }
            const py::ssize_t n = py::ssize_t(f.measures.size());
            return py::make_tuple(f.first, ownedArray<double>(std::move(residual), {n}),
                                  ownedArray<double>(std::move(contrast), {n}),
                                  ownedArray<double>(std::move(relative), {n}), imageArray(std::move(f.worstMap)));
        },
        py::arg("source"), py::arg("first"), py::arg("count"), py::kw_only(), py::arg("size") = 256,
        py::arg("origin") = py::none(), py::arg("time") = py::none(), py::arg("time_step") = py::none(),
        py::arg("frames") = FrameAnalysisOptions{}.frames,
        "The flicker of pairs [first, first + count) of frame_analysis' run with the same options (pair k: frame "
        "k → k + 1): (first, residual, contrast, relative, worst_map), the part's frames rendered here.");
    m.def(
        "flicker_from_pairs",
        [](const PySource& source, const std::vector<py::tuple>& parts, const SizeArgument& size,
           const std::optional<std::vector<double>>& origin, const std::optional<double>& time,
           const std::optional<double>& timeStep, int frames) {
            const FrameAnalysisOptions o =
                frameOptions(source, {FrameAnalysis::Flicker}, size, origin, time, timeStep, frames);
            std::vector<FlickerPairs> pairs;
            for (const py::tuple& t : parts) {
                if (t.size() != 5) throw InputError::parameter("parts", "must hold flicker_pairs' tuples");
                FlickerPairs f;
                f.first = t[0].cast<int>();
                const auto column = [&](int k) {
                    return t[size_t(k)].cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
                };
                const auto residual = column(1), contrast = column(2), relative = column(3);
                if (residual.size() != contrast.size() || residual.size() != relative.size())
                    throw InputError::parameter("parts", "must hold flicker_pairs' tuples");
                for (py::ssize_t i = 0; i < residual.size(); ++i)
                    f.measures.push_back({residual.data()[i], contrast.data()[i], relative.data()[i]});
                const auto map = t[4].cast<py::array_t<float, py::array::c_style | py::array::forcecast>>();
                if (map.ndim() != 3) throw InputError::parameter("parts", "must hold flicker_pairs' tuples");
                f.worstMap = Image(int(map.shape(1)), int(map.shape(0)), int(map.shape(2)), Image::Uninitialized{});
                std::copy(map.data(), map.data() + map.size(), f.worstMap.data().begin());
                pairs.push_back(std::move(f));
            }
            Report result;
            {
                py::gil_scoped_release release;
                result = flickerFromPairs(o, pairs).report;
            }
            return reportDict(std::move(result));
        },
        py::arg("source"), py::arg("parts"), py::kw_only(), py::arg("size") = 256, py::arg("origin") = py::none(),
        py::arg("time") = py::none(), py::arg("time_step") = py::none(),
        py::arg("frames") = FrameAnalysisOptions{}.frames,
        "frame_analysis(source, ['flicker'], same options) from flicker_pairs' parts covering every pair in "
        "order: exactly its report.");

    m.def(
        "stimulus",
        [](int size, int tile, double correlation, uint32_t seed, double mean, double contrast) {
            StimulusOptions o{size, tile, correlation, seed, mean, contrast};
            validateStimulus(o);
            Image image;
            {
                py::gil_scoped_release release;
                image = stimulusImage(o);
            }
            return ownedArray<float>(std::move(image.data()), {image.height(), image.width()});
        },
        py::kw_only(), py::arg("size") = StimulusOptions{}.size, py::arg("tile") = StimulusOptions{}.tile,
        py::arg("correlation") = StimulusOptions{}.correlation, py::arg("seed") = StimulusOptions{}.seed,
        py::arg("mean") = StimulusOptions{}.mean, py::arg("contrast") = StimulusOptions{}.contrast,
        "One perception stimulus (thesis §2.6.2): tiled white noise whose pixels one tile apart correlate as "
        "asked (eq. 2.28), float32 (size, size) display values in [0, 1].");
    m.def(
        "stimuli",
        [](const std::vector<int>& tiles, const std::vector<double>& correlations, uint32_t seed, double mean,
           double contrast, const py::object& progress, const py::kwargs& numbers) {
            StimulusSetOptions o;
            o.tiles = tiles;
            o.correlations = correlations;
            o.seed = seed;
            o.mean = mean;
            o.contrast = contrast;
            return studyReport(o, stimulusSetMembers(), numbers, progress,
                               [](const StimulusSetOptions& o, const Progress& p) {
                                   validateStimulusSet(o);
                                   return stimulusSetReport(stimulusSet(o, p));
                               });
        },
        py::kw_only(), py::arg("tiles") = StimulusSetOptions{}.tiles,
        py::arg("correlations") = StimulusSetOptions{}.correlations, py::arg("seed") = StimulusSetOptions{}.seed,
        py::arg("mean") = StimulusSetOptions{}.mean, py::arg("contrast") = StimulusSetOptions{}.contrast,
        py::arg("progress") = py::none(),
        "The perception experiment's stimulus set (`stochtex stimuli`): the grid of tile sizes × correlations × "
        "repeats in a seeded order, stimuli.csv, the stimuli and experiment.html (the report's files). Numbers of "
        "its option table as keywords: size, repeats, duration_ms, reset_ms.");
    m.def(
        "marble",
        [](const std::vector<std::string>& scalings, const std::optional<std::array<double, 2>>& point,
           const std::string& method, uint32_t seed, const py::object& progress, const py::kwargs& numbers) {
            MarbleStudyOptions o;
            o.scalings.clear();
            for (const std::string& name : scalings)
                o.scalings.push_back(parseEnum(kMarbleScalingNames, name, "scalings"));
            o.flowMethod = parseEnum(kFlowMethodNames, method, "method");
            o.marble.seed = seed;
            if (point) o.pointX = (*point)[0], o.pointY = (*point)[1];
            setMembers(o.marble, marbleParamsMembers(), keywordsOf(marbleParamsMembers(), numbers, true));
            return studyReport(o, marbleStudyMembers(), keywordsOf(marbleParamsMembers(), numbers, false), progress,
                               [](const MarbleStudyOptions& o, const Progress& p) {
                                   validateMarbleStudy(o);
                                   return marbleReport(marbleStudy(o, p), false);
                               });
        },
        py::kw_only(), py::arg("scalings") = std::vector<std::string>{"continuous", "blended-corrected"},
        py::arg("point") = py::none(), py::arg("method") = "dis", py::arg("seed") = MarbleParams{}.seed,
        py::arg("progress") = py::none(),
        "The thesis's marble study (`stochtex marble`, §2.7.2–2.8): stretching, correlation, spectra and "
        "sliding of the marble texture, continuous scaling against the blended fix. point: the correlation's "
        "reference (x, y) in pixels from the origin (default: where the scaling shears the noise most). Numbers "
        "of the texture's option table (band_period, level, ...) and the study's (size, correlation_size, "
        "instances, spectrum_instances, slide_rate, frames, time_step, flow_step) as keywords.");
    m.def(
        "figure11",
        [](const std::vector<int>& footprints, double referenceTolerance, const py::object& progress,
           const py::kwargs& numbers) {
            Figure4Options o = figure11Options();
            o.footprints = footprints;
            o.referenceTolerance = referenceTolerance;
            return studyReport(o, figure4Members(), numbers, progress, [](const Figure4Options& o, const Progress& p) {
                return figure4Report(figure4(o, p), o.figure);
            });
        },
        py::kw_only(), py::arg("footprints") = Figure4Options{}.footprints,
        py::arg("reference_tolerance") = Figure4Options{}.referenceTolerance, py::arg("progress") = py::none(),
        "Paper Figure 11 (`stochtex reproduce figure11`): Figure 4's comparison for the phasor sine pattern "
        "(phasor-stripes), fading to the profile's mean colour. Numbers of Figure 4's option table as keywords: "
        "size, reference_samples.");
    m.def(
        "figures7to9",
        [](int size, const py::object& progress) {
            validateFigures7to9(size);
            const Progress report = pythonProgress(progress);
            Report result;
            {
                py::gil_scoped_release release;
                result = figures7to9Report(figures7to9(size, report));
            }
            return reportDict(std::move(result));
        },
        py::kw_only(), py::arg("size") = 384, py::arg("progress") = py::none(),
        "Paper Figures 7–9 (`stochtex reproduce figures7-9`): sheets of four presets each (colormaps over one "
        "pair of noises; noises), `size` pixels per pattern.");
    m.def(
        "figure10",
        [](const py::object& progress, const py::kwargs& numbers) {
            return studyReport(
                Figure10Options{}, figure10Members(), numbers, progress,
                [](const Figure10Options& o, const Progress& p) { return figure10Report(figure10(o, p)); });
        },
        py::kw_only(), py::arg("progress") = py::none(),
        "Paper Figure 10 (`stochtex reproduce figure10`): the phasor variants, and procedural phasor noise beside "
        "ours. Numbers of its option table as keywords.");
    m.def(
        "figure12",
        [](const PatternSpec& pattern, int size, double tilt, int aniso, const py::object& progress,
           const py::kwargs& numbers) {
            Figure12Options o;
            o.pattern = pattern;
            o.name = pattern.name;
            o.width = size;
            o.height = size * 5 / 8;  // as the CLI's --size
            o.tiltDeg = tilt;
            o.aniso = aniso;
            return studyReport(
                o, figure12Members(), numbers, progress,
                [](const Figure12Options& o, const Progress& p) { return figure12Report(figure12(o, p)); });
        },
        py::arg("pattern"), py::kw_only(), py::arg("size") = Figure12Options{}.width,
        py::arg("tilt_deg") = Figure12Options{}.tiltDeg, py::arg("aniso") = Figure12Options{}.aniso,
        py::arg("progress") = py::none(),
        "Paper Figure 12 (`stochtex reproduce figure12`): a LEAN-mapped procedural normal map seen on a plane, four "
        "variants: size is the global view's width (its height 5/8 of it). Numbers of its option table as keywords.");
    m.def(
        "figure14",
        [](const PatternSpec& pattern, const std::vector<int>& footprints, const std::string& prefilter,
           const py::object& progress, const py::kwargs& numbers) {
            Figure14Options o;
            o.pattern = pattern;
            o.name = pattern.name;
            o.footprints = footprints;
            o.prefilter = parseEnum(kPrefilterModeNames, prefilter, "prefilter");
            return studyReport(
                o, figure14Members(), numbers, progress,
                [](const Figure14Options& o, const Progress& p) { return figure14Report(figure14(o, p)); });
        },
        py::arg("pattern"), py::kw_only(), py::arg("footprints") = Figure14Options{}.footprints,
        py::arg("prefilter") = "smooth", py::arg("progress") = py::none(),
        "Paper Figure 14 (`stochtex reproduce figure14`): a graph filtered per footprint against its reference. "
        "Numbers of its option table as keywords.");
    m.def(
        "estimator_renders",
        [](const std::vector<std::string>& presets, const std::vector<double>& scales, bool plane,
           const std::string& prefilter, const py::object& progress, const py::kwargs& numbers) {
            EstimatorRendersOptions o;
            o.presets = presets;
            o.scales = scales;
            o.plane = plane;
            o.prefilter = parseEnum(kPrefilterModeNames, prefilter, "prefilter");
            return studyReport(o, estimatorRendersMembers(), numbers, progress,
                               [](const EstimatorRendersOptions& o, const Progress& p) {
                                   return estimatorRendersReport(estimatorRenders(o, p));
                               });
        },
        py::kw_only(), py::arg("presets") = EstimatorRendersOptions{}.presets,
        py::arg("scales") = EstimatorRendersOptions{}.scales, py::arg("plane") = EstimatorRendersOptions{}.plane,
        py::arg("prefilter") = "smooth", py::arg("progress") = py::none(),
        "The estimators' rendered error (`stochtex reproduce estimators`): each preset at zoom scales and on a "
        "plane, every estimator against the reference. Numbers of its option table as keywords.");

    m.def(
        "figure4",
        [](const PatternSpec& pattern, const std::vector<int>& footprints, const std::string& prefilter,
           double referenceTolerance, const py::kwargs& numbers) {
            Figure4Options o;
            o.pattern = pattern;
            o.name = pattern.name;
            o.footprints = footprints;
            o.response.prefilter = parseEnum(kPrefilterModeNames, prefilter, "prefilter");
            o.referenceTolerance = referenceTolerance;
            setMembers(o, figure4Members(), numbers);
            validateFigure4(o);
            Report report;
            {
                py::gil_scoped_release release;
                report = figure4Report(figure4(o), o.figure);
            }
            return reportDict(std::move(report));
        },
        py::arg("pattern"), py::kw_only(), py::arg("footprints") = Figure4Options{}.footprints,
        py::arg("prefilter") = "smooth", py::arg("reference_tolerance") = Figure4Options{}.referenceTolerance,
        "Paper Figure 4 (`stochtex reproduce figure4`): per footprint, the reference S̄, Ŝ from the exact "
        "statistics and from the estimators, and their errors. Numbers of the study's option table as keywords: "
        "size, reference_samples.");

    m.def(
        "table1",
        [](int count, const std::vector<int>& footprints, uint32_t seed, uint32_t noiseSeed, int maxSamples) {
            const Table1Options o = table1Options(count, footprints, seed, noiseSeed, maxSamples);
            Table1Result result;
            {
                py::gil_scoped_release release;
                result = table1(o);
            }
            return table1Dict(std::move(result));
        },
        py::kw_only(), py::arg("count") = EstimatorErrorOptions{}.count,
        py::arg("footprints") = EstimatorErrorOptions{}.footprints, py::arg("seed") = EstimatorErrorOptions{}.seed,
        py::arg("noise_seed") = Table1Options{}.seed,
        py::arg("max_samples") = EstimatorErrorOptions{}.maxSamplesPerAxis,
        "Paper Table 1: the estimators' errors over `count` random square footprints per size.");

    py::class_<Table1Sampler>(m, "Table1Sampler",
                              "The per-footprint error terms of one Table 1 noise (0: low, 1: high), for runs split "
                              "into chunks; table1_from_terms merges them.")
        .def(py::init([](int which, int count, const std::vector<int>& footprints, uint32_t seed, uint32_t noiseSeed,
                         int maxSamples) {
                 return std::make_unique<Table1Sampler>(which,
                                                        table1Options(count, footprints, seed, noiseSeed, maxSamples));
             }),
             py::arg("noise"), py::kw_only(), py::arg("count") = EstimatorErrorOptions{}.count,
             py::arg("footprints") = EstimatorErrorOptions{}.footprints, py::arg("seed") = EstimatorErrorOptions{}.seed,
             py::arg("noise_seed") = Table1Options{}.seed,
             py::arg("max_samples") = EstimatorErrorOptions{}.maxSamplesPerAxis)
        .def("terms", &Table1Sampler::terms, py::arg("footprint"), py::arg("first"), py::arg("count"),
             "The terms of footprints [first, first + count) of size `footprint`: (count, terms_per_footprint) "
             "float64.")
        .def_property_readonly_static("estimators", [](py::object) { return EstimatorErrorSampler::estimators(); })
        .def_property_readonly_static("terms_per_footprint",
                                      [](py::object) { return EstimatorErrorSampler::termsPerFootprint(); });

    m.def(
        "table1_from_terms",
        [](const std::vector<std::vector<py::array_t<double, py::array::c_style | py::array::forcecast>>>& terms,
           int count, const std::vector<int>& footprints, uint32_t seed, uint32_t noiseSeed, int maxSamples) {
            const Table1Options o = table1Options(count, footprints, seed, noiseSeed, maxSamples);
            if (terms.size() != 2) throw InputError::parameter("terms", "must hold the two noises' terms");
            const py::ssize_t width = py::ssize_t(EstimatorErrorSampler::termsPerFootprint());
            std::array<std::vector<std::vector<double>>, 2> copied;
            for (size_t which = 0; which < 2; ++which) {
                if (terms[which].size() != footprints.size())
                    throw InputError::parameter("terms", "must hold one array per footprint size for each noise");
                for (const auto& a : terms[which]) {
                    if (a.ndim() != 2 || a.shape(0) != count || a.shape(1) != width)
                        throw InputError::parameter("terms", "must hold arrays of shape (count, " +
                                                                 std::to_string(width) +
                                                                 "): every footprint, in index order");
                    copied[which].emplace_back(a.data(), a.data() + a.size());
                }
            }
            Table1Result result;
            {
                py::gil_scoped_release release;
                std::array<std::vector<EstimatorError>, 2> rows;
                for (size_t which = 0; which < 2; ++which)
                    for (size_t k = 0; k < footprints.size(); ++k) {
                        const std::vector<EstimatorError> r = summarizeEstimatorErrors(footprints[k], copied[which][k]);
                        rows[which].insert(rows[which].end(), r.begin(), r.end());
                    }
                result = table1FromRows(std::move(rows), o);
            }
            return table1Dict(std::move(result));
        },
        py::arg("terms"), py::kw_only(), py::arg("count") = EstimatorErrorOptions{}.count,
        py::arg("footprints") = EstimatorErrorOptions{}.footprints, py::arg("seed") = EstimatorErrorOptions{}.seed,
        py::arg("noise_seed") = Table1Options{}.seed,
        py::arg("max_samples") = EstimatorErrorOptions{}.maxSamplesPerAxis,
        "Table 1 from the terms of every footprint: terms[noise][k] for footprints[k], all `count` footprints in "
        "index order. Equals table1() with the same options exactly.");
}

}  // namespace stochtex::python
