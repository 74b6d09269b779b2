// Several frame studies on one page (studies/frame_analysis.h): each study
// is the one its own command runs, over one window and one run of frames.
#include "stochtex/studies/frame_analysis.h"

#include <gtest/gtest.h>

#include <set>

#include "stochtex/core/error.h"
#include "stochtex/studies/flow_study.h"
#include "stochtex/studies/spectrum_study.h"
#include "test_util.h"

namespace stochtex {
namespace {

FrameAnalysisOptions allThree() {
    FrameAnalysisOptions o;
    o.analyses = {FrameAnalysis::Spectrum, FrameAnalysis::Flow, FrameAnalysis::Coherence};
    o.region = SourceRegion::centred(64, 48);
    o.time = 0.1;
    o.timeStep = 0.05;
    o.frames = 4;
    return o;
}

TEST(FrameAnalysis, RunsEachStudyAsItsCommandDoes) {
    ZoomParams p;
    p.layers = 4;
    const ZoomSource source(p, ZoomBase{64, 5, {}});
    const FrameAnalysisOptions o = allThree();
    const FrameAnalysisResult r = frameAnalysis(source, o);
    std::set<std::string> files;
    for (const Figure& f : r.figures) EXPECT_TRUE(files.insert(f.file).second) << f.file << " twice";
    EXPECT_TRUE(files.count("spectrum.png") && files.count("flow_arrows.png") && files.count("appearance.png"));
    ASSERT_EQ(r.tables.size(), 5u);  // spectrum, radial, flow, coherence, coherence_frames
    EXPECT_EQ(r.tables[2].first, "flow.csv");
    const std::string page = reportPage(r.report);
    EXPECT_NE(page.find("Power spectrum"), std::string::npos);
    EXPECT_NE(page.find("Temporal coherence"), std::string::npos);
    ASSERT_EQ(r.report.sections.size(), 3u);  // each study's section writes its own tables
    EXPECT_EQ(r.report.sections[1].tables.front().file, "flow.csv");
    // The spectrum section is spectrumStudy's own on the first frame.
    SpectrumStudyOptions s;
    s.region = o.region;
    s.times = {o.time};
    s.frameTransfer = o.frameTransfer;
    EXPECT_EQ(r.tables[0].second.csv(), spectrumStudy(source, s).summary.csv());
    // The flow is DIS over the frames time + k·step.
    FlowStudyOptions f;
    f.region = o.region;
    f.time = o.time;
    f.timeStep = o.timeStep;
    f.frames = o.frames;
    f.method = FlowMethod::Dis;
    f.frameTransfer = o.frameTransfer;
    EXPECT_EQ(r.tables[2].second.csv(), flowStudy(source, f).summary.csv());
}

// The flicker in parts of pairs, each rendering its own frames, joined: the
// very section of one pass (tables, the worst pair's map), whatever the split.
TEST(FrameAnalysis, FlickerInPartsIsTheFlickerOfTheRun) {
    ZoomParams p;
    p.layers = 4;
    p.offsets = ZoomOffsets::Hashed;
    const ZoomSource source(p, ZoomBase{64, 5, {}});
    FrameAnalysisOptions o;
    o.analyses = {FrameAnalysis::Flicker};
    o.region = SourceRegion::centred(48, 40);
    o.timeStep = 0.2;
    o.frames = 6;
    o.sourceName = "zoom";
    const FrameAnalysisResult whole = frameAnalysis(source, o);
    const std::vector<FlickerPairs> parts{flickerPairs(source, o, 0, 2), flickerPairs(source, o, 2, 1),
                                          flickerPairs(source, o, 3, 2)};
    const FrameAnalysisResult joined = flickerFromPairs(o, parts);
    ASSERT_EQ(joined.tables.size(), whole.tables.size());
    for (size_t t = 0; t < whole.tables.size(); ++t) {
        EXPECT_EQ(joined.tables[t].first, whole.tables[t].first);
        EXPECT_EQ(joined.tables[t].second.csv(), whole.tables[t].second.csv());
    }
    ASSERT_EQ(joined.figures.size(), whole.figures.size());
    for (size_t f = 0; f < whole.figures.size(); ++f)
        EXPECT_EQ(joined.figures[f].image.data(), whole.figures[f].image.data()) << whole.figures[f].file;
    EXPECT_EQ(reportPage(joined.report), reportPage(whole.report));
    // Pairs outside the run, or parts with a gap, are refused by name.
    EXPECT_EQ(test::inputErrorOf([&] { flickerPairs(source, o, 5, 1); }).parameter(), "first");
    EXPECT_EQ(test::inputErrorOf([&] { flickerPairs(source, o, 3, 3); }).parameter(), "count");
    const std::vector<FlickerPairs> gap{parts[0], parts[2]};
    EXPECT_EQ(test::inputErrorOf([&] { flickerFromPairs(o, gap); }).parameter(), "parts");
}

TEST(FrameAnalysis, RefusesNothingToDoRepeatsAndTheStudiesOwnLimits) {
    const auto message = [](const FrameAnalysisOptions& o) {
        try {
            validateFrameAnalysis(o);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    FrameAnalysisOptions o = allThree();
    o.analyses.clear();
    EXPECT_NE(message(o).find("analyses must name at least one"), std::string::npos);
    o.analyses = {FrameAnalysis::Flow, FrameAnalysis::Flow};
    EXPECT_NE(message(o).find("names flow twice"), std::string::npos);
    o = allThree();
    o.frames = 1;  // a flow needs two frames
    EXPECT_NE(message(o).find("frames"), std::string::npos) << message(o);
}

}  // namespace
}  // namespace stochtex
