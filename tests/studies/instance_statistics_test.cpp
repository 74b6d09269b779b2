// Statistics over instances in chunks (studies/instance_statistics.h): the
// chunks' sums added in order are the result, so a split run can equal it.
#include "stochtex/studies/instance_statistics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "stochtex/core/error.h"

namespace stochtex {
namespace {

ZoomSource smallZoom() {
    ZoomParams p;
    p.layers = 4;
    p.offsets = ZoomOffsets::Hashed;
    return ZoomSource(p, ZoomBase{32, 7, {}});
}

InstanceStatisticsOptions smallOptions() {
    InstanceStatisticsOptions o;
    o.region = SourceRegion::centred(24, 20);
    o.instances = 37;  // not a multiple of the chunk: the last chunk is short
    o.chunk = 8;
    o.pointX = 5;
    o.pointY = 9;
    return o;
}

void expectSameSums(const CorrelationAccumulator& a, const CorrelationAccumulator& b) {
    ASSERT_EQ(a.count(), b.count());
    for (int k = 0; k < CorrelationAccumulator::kSums; ++k) EXPECT_EQ(*a.sums()[size_t(k)], *b.sums()[size_t(k)]) << k;
}

TEST(InstanceStatistics, IsTheChunksMergedInOrder) {
    const ZoomSource source = smallZoom();
    const InstanceStatisticsOptions o = smallOptions();
    ASSERT_EQ(instanceChunkCount(o), 5);
    const CorrelationAccumulator all = instanceStatistics(source, o);
    EXPECT_EQ(all.count(), 37);
    EXPECT_EQ(all.referenceRow(), 9);  // −1: the point's row
    EXPECT_EQ(all.probeRow(), 9);
    // What a distributed run does: each chunk anywhere, then the merge in order.
    CorrelationAccumulator merged = emptyInstanceStatistics(o);
    for (int k = 0; k < instanceChunkCount(o); ++k) {
        CorrelationAccumulator travelled = emptyInstanceStatistics(o);  // as a pickled copy arrives
        const CorrelationAccumulator chunk = instanceChunk(source, o, k);
        std::array<std::vector<double>, CorrelationAccumulator::kSums> sums;
        for (int s = 0; s < CorrelationAccumulator::kSums; ++s) sums[size_t(s)] = *chunk.sums()[size_t(s)];
        travelled.restore(chunk.count(), std::move(sums));
        merged.merge(travelled);
    }
    expectSameSums(all, merged);
    EXPECT_EQ(instanceChunk(source, o, 4).count(), 5);  // 32…36
}

TEST(InstanceStatistics, OneChunkIsThePlainAccumulatorAndChunkingOnlyRounds) {
    const ZoomSource source = smallZoom();
    InstanceStatisticsOptions o = smallOptions();
    o.chunk = o.instances;
    CorrelationAccumulator plain(24, 20, 5, 9, 9, 9);
    for (int i = 0; i < o.instances; ++i) plain.add(source.render(o.region, o.time, i));
    expectSameSums(instanceStatistics(source, o), plain);
    // Chunks of 3 sum the same frames in another order: equal to rounding.
    o.chunk = 3;
    const Image a = instanceStatistics(source, o).correlationWithPoint(), b = plain.correlationWithPoint();
    double worst = 0;
    for (size_t i = 0; i < a.data().size(); ++i) worst = std::max(worst, std::abs(double(a.data()[i]) - b.data()[i]));
    EXPECT_LT(worst, 1e-6);
    EXPECT_NEAR(a.at(5, 9), 1.0, 1e-6);  // the point with itself
}

TEST(InstanceStatistics, SummarisesWhatItMeasured) {
    const ZoomSource source = smallZoom();
    InstanceStatisticsOptions o = smallOptions();
    o.instances = 400;
    o.chunk = 64;
    const CorrelationAccumulator acc = instanceStatistics(source, o);
    const InstanceStatisticsSummary s = summarizeInstanceStatistics(acc, o.region);
    ASSERT_EQ(s.summary.rows.size(), 1u);
    EXPECT_EQ(s.summary.rows[0][0].text, "400");
    // White noise in [0, 1) blended over layers: the mean over 400 instances
    // is ½ within 5 standard errors of the per-pixel mean (σ ≤ 1/√12).
    const double mean = s.summary.rows[0][1].number.value_or(-1);
    EXPECT_NEAR(mean, 0.5, 5 * std::sqrt(1.0 / 12 / 400));
    ASSERT_EQ(s.figures.size(), 3u);
    EXPECT_EQ(s.figures[2].file, "statistics_correlation.png");
}

TEST(InstanceStatistics, RefusesBadOptionsNamingThem) {
    const ZoomSource source = smallZoom();
    const auto parameterOf = [&](InstanceStatisticsOptions o) -> std::string {
        try {
            instanceStatistics(source, o);
        } catch (const InputError& e) {
            return e.parameter();
        }
        return "";
    };
    InstanceStatisticsOptions o = smallOptions();
    o.instances = 1;
    EXPECT_EQ(parameterOf(o), "instances");
    o = smallOptions();
    o.chunk = 0;
    EXPECT_EQ(parameterOf(o), "chunk");
    o = smallOptions();
    o.pointX = 24;
    EXPECT_EQ(parameterOf(o), "point");
    o = smallOptions();
    o.probeRow = 20;
    EXPECT_EQ(parameterOf(o), "probeRow");
    o = smallOptions();
    o.region.width = 2000;
    EXPECT_EQ(parameterOf(o), "size");
    EXPECT_THROW(instanceChunk(source, smallOptions(), 5), InputError);
    EXPECT_THROW(instanceChunk(source, smallOptions(), -1), InputError);
    CorrelationAccumulator a = emptyInstanceStatistics(smallOptions());
    InstanceStatisticsOptions other = smallOptions();
    other.pointY = 3;
    EXPECT_THROW(a.merge(emptyInstanceStatistics(other)), InputError);
    EXPECT_THROW(a.restore(1, {}), InputError);   // sums of the wrong size
    EXPECT_THROW(a.restore(-1, {}), InputError);  // a negative count
}

}  // namespace
}  // namespace stochtex
