#include "stochtex/studies/instance_statistics.h"

#include <algorithm>
#include <array>

#include "stochtex/analysis/correlation_shape.h"
#include "stochtex/core/error.h"

namespace stochtex {

namespace {

std::array<int, 2> point(const InstanceStatisticsOptions& o) {
    return {o.pointX < 0 ? o.region.width / 2 : o.pointX, o.pointY < 0 ? o.region.height / 2 : o.pointY};
}

}  // namespace

std::span<const OptionMember<InstanceStatisticsOptions>> instanceStatisticsMembers() {
    using O = InstanceStatisticsOptions;
    static const OptionMember<O> members[] = {
        {"instances", "Instances N of the statistical accumulator", 2, 1000000, &O::instances},
        {"chunk", "Instances per chunk (chunks are summed from zero, then added in order)", 1, 1000000, &O::chunk},
        {"pointX", "Correlation point x in window pixels (−1: the centre)", -1, 1023, &O::pointX},
        {"pointY", "Correlation point y in window pixels (−1: the centre)", -1, 1023, &O::pointY},
        {"referenceRow", "Row the non-radial correlation is taken against (−1: the point's)", -1, 1023,
         &O::referenceRow},
        {"probeRow", "Row whose pixel pairs give the radial correlation matrix (−1: the point's)", -1, 1023,
         &O::probeRow},
    };
    return members;
}

void validateInstanceStatistics(const InstanceStatisticsOptions& o, const TextureSource* source) {
    checkMembers(o, instanceStatisticsMembers());
    if (o.region.width < 4 || o.region.height < 4 || o.region.width > 1024 || o.region.height > 1024)
        throw InputError::parameter("size", "statistics need a window of 4…1024 pixels a side, got " +
                                                std::to_string(o.region.width) + "x" + std::to_string(o.region.height));
    const auto [px, py] = point(o);
    if (px >= o.region.width || py >= o.region.height)
        throw InputError::parameter("point", "(" + std::to_string(px) + ", " + std::to_string(py) +
                                                 ") lies outside the " + std::to_string(o.region.width) + "x" +
                                                 std::to_string(o.region.height) + " window");
    if (o.referenceRow >= o.region.height)
        throw InputError::parameter("referenceRow",
                                    "must lie inside the window's " + std::to_string(o.region.height) + " rows");
    if (o.probeRow >= o.region.height)
        throw InputError::parameter("probeRow",
                                    "must lie inside the window's " + std::to_string(o.region.height) + " rows");
    if (source) {
        source->checkWindow(o.region, o.time);
        source->checkInstances(o.instances);
    }
}

int instanceChunkCount(const InstanceStatisticsOptions& o) { return (o.instances + o.chunk - 1) / o.chunk; }

CorrelationAccumulator emptyInstanceStatistics(const InstanceStatisticsOptions& o) {
    validateInstanceStatistics(o);
    const auto [px, py] = point(o);
    return CorrelationAccumulator(o.region.width, o.region.height, px, py, o.referenceRow < 0 ? py : o.referenceRow,
                                  o.probeRow < 0 ? py : o.probeRow);
}

CorrelationAccumulator instanceChunk(const TextureSource& source, const InstanceStatisticsOptions& o, int index) {
    CorrelationAccumulator acc = emptyInstanceStatistics(o);
    if (index < 0 || index >= instanceChunkCount(o))
        throw InputError::parameter(
            "index", "must be in [0, " + std::to_string(instanceChunkCount(o)) + "), got " + std::to_string(index));
    const int first = index * o.chunk, last = std::min(o.instances, first + o.chunk);
    for (int i = first; i < last; ++i) {
        const Image frame = source.render(o.region, o.time, i);
        acc.add(frame.channels() == 1 ? frame : toGray(frame));
    }
    return acc;
}

CorrelationAccumulator instanceStatistics(const TextureSource& source, const InstanceStatisticsOptions& o,
                                          const Progress& progress) {
    validateInstanceStatistics(o, &source);
    CorrelationAccumulator total = emptyInstanceStatistics(o);
    const int chunks = instanceChunkCount(o);
    for (int k = 0; k < chunks; ++k) {
        if (progress) progress(double(k) / chunks, "instance " + std::to_string(k * o.chunk + 1));
        total.merge(instanceChunk(source, o, k));
    }
    return total;
}

Image windowMap(const Image& values, const SourceRegion& region, const std::string& title, double lo, double hi,
                HeatPalette palette) {
    HeatmapOptions h;
    h.title = title;
    h.vmin = lo;
    h.vmax = hi;
    h.palette = palette;
    h.yUp = false;
    h.xMax = region.width;
    h.yMax = region.height;
    h.xLabel = "x (pixels)";
    h.yLabel = "y (pixels, down)";
    return heatmapPlot(values, h);
}

InstanceStatisticsSummary summarizeInstanceStatistics(const CorrelationAccumulator& acc, const SourceRegion& region) {
    const int px = acc.referenceX(), py = acc.referenceY();
    const Image mean = acc.mean(), variance = acc.variance(), corr = acc.correlationWithPoint();
    const ChannelStats m = channelStats(mean), v = channelStats(variance);
    const CorrelationShape shape = correlationShape(corr, px, py);
    InstanceStatisticsSummary out;
    out.summary.columns = {{"instances", "instances", ""},
                           {"mean", "mean of the mean", "codes"},
                           {"mean_spread", "spread of the mean", "codes"},
                           {"variance", "mean variance", "codes²"},
                           {"area", "Corr ≥ ½ area", "pixels"},
                           {"elongation", "elongation", ""},
                           {"anti", "anti-correlation", ""}};
    out.summary.add({TableCell::integer(acc.count()), TableCell::value(m.mean), TableCell::value(m.stddev),
                     TableCell::value(v.mean), TableCell::integer(shape.area),
                     TableCell::value(shape.elongation, "%.2f"), TableCell::value(shape.antiCorrelation, "%.3f")});
    const auto map = [&](const Image& values, const std::string& title, double lo, double hi, HeatPalette palette) {
        return windowMap(values, region, title, lo, hi, palette);
    };
    const double vmax = std::max(1e-6, v.mean + 3 * v.stddev);
    const std::string n = std::to_string(acc.count()) + " instances";
    out.figures.push_back({"statistics_mean.png", map(mean, "Mean over " + n, 0, 1, HeatPalette::Viridis),
                           "Per-pixel mean of the gray values: a stationary texture is flat."});
    out.figures.push_back({"statistics_variance.png",
                           map(variance, "Variance over " + n, 0, vmax, HeatPalette::Viridis),
                           "Per-pixel variance: a stationary texture is flat."});
    out.figures.push_back(
        {"statistics_correlation.png",
         map(corr, "Corr with (" + std::to_string(px) + ", " + std::to_string(py) + ")", -1, 1, HeatPalette::Diverging),
         "Correlation of every pixel with the point over the instances (thesis eq. 3.1)."});
    return out;
}

}  // namespace stochtex
