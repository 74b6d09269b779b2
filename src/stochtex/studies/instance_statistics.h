#pragma once
// Statistics over instances of a texture source (thesis §3.3, the
// statistical accumulator) in chunks: the instances [k·chunk, (k+1)·chunk)
// are accumulated from zero, and the chunks' sums are added to the total in
// chunk order. Any run that computes the chunks wherever it likes (another
// thread, process or machine: python/stochtex/dask.py) and merges them in
// that order gets the single-process result bit for bit. The chunk size is
// part of the result's definition (sums in double are rounded per chunk).
#include <span>
#include <string>
#include <vector>

#include "stochtex/analysis/correlation_accumulator.h"
#include "stochtex/core/progress.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/report/page.h"
#include "stochtex/report/plot.h"
#include "stochtex/report/table.h"
#include "stochtex/textures/texture_source.h"

namespace stochtex {

struct InstanceStatisticsOptions {
    SourceRegion region = SourceRegion::centred(256, 256);  // 4…1024 pixels a side
    double time = 0;                                        // every instance at this time
    int instances = 64;                                     // instances 0…N−1
    int pointX = -1, pointY = -1;  // the correlation's point in window pixels; −1: the centre
    int referenceRow = -1;         // correlationWithRow's row; −1: the point's
    int probeRow = -1;             // the probe matrix's row; −1: the point's
    int chunk = 16;                // instances per chunk
};
// The numbers' entries (ranges; the CLI's flags and Python's keywords).
std::span<const OptionMember<InstanceStatisticsOptions>> instanceStatisticsMembers();
// InputError naming the parameter (with the source's checkWindow and
// checkInstances where one is given), before any work.
void validateInstanceStatistics(const InstanceStatisticsOptions& options, const TextureSource* source = nullptr);

// ⌈instances / chunk⌉.
int instanceChunkCount(const InstanceStatisticsOptions& options);
// An accumulator of no frame with the options' window, point and rows.
CorrelationAccumulator emptyInstanceStatistics(const InstanceStatisticsOptions& options);
// The sums of chunk `index` (0 ≤ index < instanceChunkCount): its instances'
// frames, gray where the source has colour (toGray: the thesis's luminosity).
CorrelationAccumulator instanceChunk(const TextureSource& source, const InstanceStatisticsOptions& options, int index);
// Every chunk, merged in order.
CorrelationAccumulator instanceStatistics(const TextureSource& source, const InstanceStatisticsOptions& options,
                                          const Progress& progress = {});

// What the statistics show: a summary (instances, mean and spread of the
// mean, mean variance, the correlation's Corr ≥ ½ area, elongation and
// anti-correlation) and maps of the mean, the variance and the correlation
// with the point over the window.
struct InstanceStatisticsSummary {
    std::string title = "Statistics over instances (the statistical accumulator)";  // a report section's heading
    Table summary;
    std::vector<Figure> figures;
};
InstanceStatisticsSummary summarizeInstanceStatistics(const CorrelationAccumulator& statistics,
                                                      const SourceRegion& region);

// A map over a study's window as a heat map, axes in window pixels, rows down.
Image windowMap(const Image& values, const SourceRegion& region, const std::string& title, double lo, double hi,
                HeatPalette palette);

}  // namespace stochtex
