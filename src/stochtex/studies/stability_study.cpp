#include "stochtex/studies/stability_study.h"

#include <cmath>
#include <string>

#include "stochtex/core/error.h"

namespace stochtex {

namespace {

void checkScale(double s, const char* what) {
    if (!(s > 0) || !std::isfinite(s) || s > 1e6)
        throw InputError::parameter(what, "must be a finite scale in (0, 1e6], got " + formatValue(s));
}

}  // namespace

void validateStabilityStudy(const StabilityStudyOptions& o) {
    if (o.filters.empty()) throw InputError::parameter("filters", "must name at least one filter");
    if (o.frames < 2 || o.frames > 1000)
        throw InputError::parameter("frames", "must be in [2, 1000], got " + std::to_string(o.frames));
    if (o.size < 8 || o.size > 2048)
        throw InputError::parameter("size", "must be in [8, 2048], got " + std::to_string(o.size));
    checkScale(o.from, "from");
    checkScale(o.to, "to");
}

StabilityStudyResult stabilityStudy(const Pattern& pattern, const StabilityStudyOptions& o,
                                    const StudyProgress& progress, const StabilityFrameSink& onFrame) {
    validateStabilityStudy(o);
    StabilityStudyResult r;
    r.summary.columns = {{"filter", "filter", ""}, {"mean_difference", "mean |dI|", ""}, {"max_difference", "max |dI|", ""}};
    r.perFrame.columns = {{"filter", "filter", ""}, {"frame", "frame", ""}, {"scale", "scale", ""},
                          {"difference", "|dI|", ""}};
    for (size_t m = 0; m < o.filters.size(); ++m) {
        const FilteredPattern filtered(pattern, o.filters[m]);
        const std::string name = filterName(o.filters[m]);
        const Progress part = progressPart(progress, int(m), int(o.filters.size()),
                                           "stability: " + name + ", " + std::to_string(o.frames) + " frames");
        if (part) part(0.0, "");
        int k = 0;
        const ZoomStability z = measureZoomStability(
            [&](double s) {
                Camera cam;
                cam.view.width = cam.view.height = o.size;
                cam.view.scale = s;
                // Zoom about a fixed texture point: the view centre stays at texel (0, 0).
                cam.view.offsetU = cam.view.offsetV = -0.5 * o.size * s;
                Image frame = filtered.render(cam, progressPart(part, k, o.frames));
                if (onFrame) onFrame(m, k, frame);
                ++k;
                return frame;
            },
            o.frames, o.from, o.to);
        r.summary.add({name, TableCell::value(z.mean, "%.5f"), TableCell::value(z.max, "%.5f")});
        for (size_t f = 0; f < z.differences.size(); ++f)
            r.perFrame.add({name, TableCell::integer((long long)f), TableCell::value(z.scales[f], "%g"),
                            TableCell::value(z.differences[f], "%.5f")});
        r.measurements.push_back(z);
    }
    return r;
}

}  // namespace stochtex
