#include "stochtex/studies/estimator_renders.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "stochtex/core/error.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/part_cache.h"
#include "stochtex/pattern/presets.h"
#include "stochtex/report/plot.h"
#include "stochtex/studies/paper.h"
#include "stochtex/studies/reference_samples.h"

namespace stochtex {

std::span<const OptionMember<EstimatorRendersOptions>> estimatorRendersMembers() {
    using O = EstimatorRendersOptions;
    static const OptionMember<O> members[] = {
        {"size", "Image side per view", 16, 2048, &O::size},
        {"referenceSamples", "Max samples per axis of the reference and the exact statistics", 1, 4096,
         &O::referenceSamples},
        {"tiltDeg", "Plane view: tilt from looking straight down, degrees", 0, 89, &O::tiltDeg, "tilt"},
        {"planeScale", "Plane view: texels per pixel at the image centre", 0.0625, 64, &O::planeScale},
    };
    return members;
}

void validateEstimatorRenders(const EstimatorRendersOptions& o) {
    checkMembers(o, estimatorRendersMembers());
    validateReferenceTolerance(o.referenceTolerance);
    FilterOptions filter;
    filter.aniso = o.aniso;
    validateFilterOptions(filter);
    if (o.presets.empty()) throw InputError::parameter("presets", "must name at least one preset");
    const std::vector<std::string> known = presetNames();
    for (const std::string& p : o.presets)
        if (std::find(known.begin(), known.end(), p) == known.end())
            throw InputError::parameter("presets",
                                        "must name known presets (stochtex presets lists them), got \"" + p + "\"");
    if (o.scales.empty() && !o.plane) throw InputError::parameter("scales", "must not be empty without the plane view");
    for (const double s : o.scales)
        if (!(s >= 1.0 / 16 && s <= 4096))
            throw InputError::parameter("scales", "each must be in [0.0625, 4096], got " + formatValue(s));
}

namespace {

std::string scaleLabel(double s) { return "zoom ×" + formatValue(s); }

}  // namespace

EstimatorRendersResult estimatorRenders(const EstimatorRendersOptions& o, const Progress& progress) {
    validateEstimatorRenders(o);
    std::vector<Camera> cameras;
    for (const double s : o.scales) {
        Camera& c = cameras.emplace_back();
        c.view = View{o.size, o.size, s};
    }
    if (o.plane) {
        Camera& c = cameras.emplace_back();
        c.kind = Camera::Kind::Plane;
        c.view = View{o.size, o.size, o.planeScale};
        c.tiltDeg = o.tiltDeg;
        validateCamera(c);
    }
    EstimatorRendersResult res;
    const int parts = int(o.presets.size() * cameras.size());
    for (const std::string& name : o.presets) {
        const PatternSpec spec = loadPreset(name);
        const GraphPattern pattern = GraphPattern::build(spec);
        // Its tables and pyramids, built once for every render of its rows.
        PartCache partCache;
        // The pattern's own filtered response: the LEAN lobe where it has a
        // normal map (as Figure 12), else the prefiltered colormap.
        FilterOptions base;
        base.response = {spec.normalMap ? ResponseKind::Lean : ResponseKind::PrefilteredColormap, o.prefilter};
        base.aniso = o.aniso;
        base.referenceMaxSamples = o.referenceSamples;
        for (const Camera& cam : cameras) {
            EstimatorRendersRow row;
            row.pattern = name;
            row.view = cam.kind == Camera::Kind::Plane ? "plane " + formatValue(cam.tiltDeg) + "°"
                                                       : scaleLabel(cam.view.scale);
            row.scale = cam.kind == Camera::Kind::Plane ? 0.0 : cam.view.scale;
            const Progress part =
                progressPart(progress, int(res.rows.size()), parts, "estimators: " + name + ", " + row.view);
            // S̄ and the exact statistics take nearly all the time, about equally.
            FilterOptions reference = base;
            reference.source = StatisticsSource::Reference;
            reference = atConvergedSamples(pattern, reference, cam, o.referenceTolerance, row.referenceSamples,
                                           row.referenceChange, &partCache);
            const Image truth = FilteredGraph(pattern, reference, GraphMoments::Matched, &partCache)
                                    .render(cam, progressPart(part, 0.0, 0.5, "reference"));
            FilterOptions exact = base;
            exact.source = StatisticsSource::Exact;
            exact = atConvergedSamples(pattern, exact, cam, o.referenceTolerance, row.exactSamples, row.exactChange,
                                       &partCache);
            (void)errorMap(FilteredGraph(pattern, exact, GraphMoments::Matched, &partCache)
                               .render(cam, progressPart(part, 0.5, 1.0, "exact statistics")),
                           truth, row.exact);
            FilterOptions none = base;
            none.source = StatisticsSource::Point;
            (void)errorMap(FilteredGraph(pattern, none, GraphMoments::Matched, &partCache).render(cam), truth,
                           row.none);
            row.estimators = estimatorErrors(pattern, base, cam, truth, EstimatorSet::All, &partCache);
            res.rows.push_back(std::move(row));
        }
    }

    res.table.columns = {{"pattern", "pattern", ""},
                         {"view", "view", ""},
                         {"scale", "texels per pixel (zoom; 0: the plane)", ""},
                         {"mean_error_none", "none (pixel centres)", ""},
                         {"mean_error_exact", "exact statistics (the floor)", ""}};
    estimatorColumns(
        res.table, "mean_error_", [](const std::string& name) { return name; }, EstimatorSet::All);
    res.table.columns.push_back({"reference_samples", "S̄: samples per pixel", ""});
    res.table.columns.push_back({"reference_change", "S̄: change on doubling them", ""});
    res.table.columns.push_back({"exact_samples", "exact statistics: samples per pixel", ""});
    res.table.columns.push_back({"exact_change", "exact statistics: change on doubling them", ""});
    for (const EstimatorRendersRow& r : res.rows) {
        std::vector<TableCell> cells{TableCell(r.pattern), TableCell(r.view), TableCell::value(r.scale),
                                     TableCell::value(r.none), TableCell::value(r.exact)};
        for (const double e : r.estimators) cells.push_back(TableCell::value(e));
        cells.push_back(TableCell::value(r.referenceSamples * r.referenceSamples));
        cells.push_back(TableCell::value(r.referenceChange));
        cells.push_back(TableCell::value(r.exactSamples * r.exactSamples));
        cells.push_back(TableCell::value(r.exactChange));
        res.table.add(std::move(cells));
    }

    // Per pattern, the zoom views: error against scale, a line per estimator,
    // the floor and the pixel centres.
    if (o.scales.size() >= 2)
        for (const std::string& name : o.presets) {
            std::vector<PlotSeries> series;
            const auto add = [&](const std::string& label, const auto& value) {
                PlotSeries& s = series.emplace_back();
                s.name = label;
                s.colour = seriesColour(series.size() - 1);
                for (const EstimatorRendersRow& r : res.rows)
                    if (r.pattern == name && r.scale > 0) {
                        s.x.push_back(r.scale);
                        s.y.push_back(value(r));
                    }
            };
            add("none (pixel centres)", [](const EstimatorRendersRow& r) { return r.none; });
            for (size_t e = 0; e < kVarianceEstimatorNames.size(); ++e)
                add(kVarianceEstimatorNames[e].first, [e](const EstimatorRendersRow& r) { return r.estimators[e]; });
            add("exact statistics (floor)", [](const EstimatorRendersRow& r) { return r.exact; });
            LinePlotOptions plot;
            plot.title = name + ": rendered error per footprint estimator";
            plot.xLabel = "texels per pixel";
            plot.yLabel = "mean ‖Ŝ − S̄‖₂ (linear RGB)";
            plot.logX = plot.logY = true;
            res.figures.push_back({"estimators_" + name + ".png", linePlot(series, plot),
                                   name + ": mean ‖Ŝ − S̄‖₂ of the zoom views per estimator, " + std::to_string(o.size) +
                                       "² pixels, beside the exact statistics and the "
                                       "pixel centres (estimators.csv has the plane view)."});
        }
    return res;
}

Report estimatorRendersReport(const EstimatorRendersResult& r) {
    return sectionReport("The footprint estimators in the rendered image (issue 32)", {{"estimators.csv", r.table}},
                         r.figures);
}

}  // namespace stochtex
