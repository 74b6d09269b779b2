// The option structs' tables (OptionMember, pattern/param_info.h): the
// flag is the name in kebab case unless the entry says otherwise, and the
// struct's own validator refuses a value just outside the entry's range,
// naming the entry, while the range's ends pass (where no cross-check of
// the struct bounds them further).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "stochtex/pattern/presets.h"
#include "stochtex/studies/artifact_report.h"
#include "stochtex/studies/flow_study.h"
#include "stochtex/studies/graph_filtering.h"
#include "stochtex/studies/image_base_study.h"
#include "stochtex/studies/marble_study.h"
#include "stochtex/studies/normal_maps.h"
#include "stochtex/studies/paper.h"
#include "stochtex/studies/phasor_figures.h"
#include "stochtex/studies/spectrum_study.h"
#include "stochtex/studies/stability_study.h"
#include "stochtex/studies/stimuli.h"
#include "stochtex/studies/temporal_coherence_study.h"
#include "stochtex/studies/zoom_studies.h"
#include "stochtex/textures/marble_texture.h"
#include "stochtex/textures/zoom_texture.h"
#include "test_util.h"

namespace stochtex {
namespace {

TEST(OptionMembers, KebabCaseIsTheFlagOfACamelCaseName) {
    EXPECT_EQ(kebabCase("truthSamples"), "truth-samples");
    EXPECT_EQ(kebabCase("frames"), "frames");
    EXPECT_EQ(kebabCase("levelAmplitude"), "level-amplitude");
}

// Every member of `members` through `check`, the struct's own validator,
// from a valid struct `valid`: the next value outside either end (the next
// float, or ±1 for an integer) and NaN (a number) are refused naming the
// member; both ends pass `check` too where `endsPass` (else only the member's
// own check: the struct's cross-checks bound them further, said per table).
template <class Options, class Check>
void expectRangesChecked(std::span<const OptionMember<Options>> members, const Options& valid, Check check,
                         bool endsPass = true) {
    ASSERT_FALSE(members.empty());
    EXPECT_NO_THROW(check(valid));
    for (const OptionMember<Options>& m : members) {
        const ParamInfo& p = m.info;
        SCOPED_TRACE(p.name);
        EXPECT_FALSE(p.flag.empty());
        EXPECT_LT(p.min, p.max);
        std::visit(
            [&](auto member) {
                using T = std::remove_cvref_t<decltype(valid.*member)>;
                const auto with = [&](double v) {
                    Options o = valid;
                    o.*member = T(v);
                    return o;
                };
                const double below = std::is_same_v<T, int> ? p.min - 1 : std::nextafter(p.min, -1e300);
                const double above = std::is_same_v<T, int> ? p.max + 1 : std::nextafter(p.max, 1e300);
                for (const double v : {below, above}) {
                    const InputError e = test::inputErrorOf([&] { check(with(v)); });
                    EXPECT_EQ(e.parameter(), p.name) << v;
                }
                if constexpr (std::is_same_v<T, double>) {
                    const InputError e = test::inputErrorOf([&] { check(with(std::nan(""))); });
                    EXPECT_EQ(e.parameter(), p.name);
                }
                for (const double v : {p.min, p.max}) {
                    if (endsPass) {
                        EXPECT_NO_THROW(check(with(v))) << v;
                    }
                    EXPECT_NO_THROW(checkMembers(with(v), members)) << v;
                }
            },
            m.member);
    }
}

TEST(OptionMembers, EveryStudysNumbersAreCheckedByTheirEntries) {
    StabilityStudyOptions stability;
    stability.filters.emplace_back();
    expectRangesChecked(stabilityStudyMembers(), stability, [](const auto& o) { validateStabilityStudy(o); });
    FlowStudyOptions flow;
    flow.region = SourceRegion::centred(4096, 4096);  // the widest window: step may reach its entry's max
    expectRangesChecked(flowStudyMembers(), flow, [](const auto& o) { validateFlowStudy(o); });
    // rMin at its top (0.75) is not below rMax.
    expectRangesChecked(
        spectrumStudyMembers(), SpectrumStudyOptions{}, [](const auto& o) { validateSpectrumStudy(o); }, false);
    expectRangesChecked(contrastStudyMembers(), ContrastStudyOptions{},
                        [](const auto& o) { validateContrastStudy(o); });
    expectRangesChecked(correlationStudyMembers(), CorrelationStudyOptions{},
                        [](const auto& o) { validateCorrelationStudy(o); });
    // The study also needs images: the entries alone.
    expectRangesChecked(imageBaseStudyMembers(), ImageBaseStudyOptions{},
                        [](const auto& o) { checkMembers(o, imageBaseStudyMembers()); });
    // A size of 32 is below the default correlation window (96).
    expectRangesChecked(
        marbleStudyMembers(), MarbleStudyOptions{}, [](const auto& o) { validateMarbleStudy(o); }, false);
    // A size of 8 is not divided by the default tiles (16, 32).
    expectRangesChecked(
        stimulusSetMembers(), StimulusSetOptions{}, [](const auto& o) { validateStimulusSet(o); }, false);
    TemporalCoherenceOptions coherence;
    coherence.times = {0.0, 1.0};
    expectRangesChecked(temporalCoherenceMembers(), coherence, [](const auto& o) { validateTemporalCoherence(o); });
    expectRangesChecked(artifactReportMembers(), ArtifactReportOptions{},
                        [](const auto& o) { validateArtifactReport(o); });
    expectRangesChecked(zoomParamsMembers(), ZoomParams{}, [](const auto& o) { validateZoomParams(o); });
    expectRangesChecked(marbleParamsMembers(), MarbleParams{}, [](const auto& o) { validateMarbleParams(o); });
}

TEST(OptionMembers, EveryPaperFiguresNumbersAreCheckedByTheirEntries) {
    expectRangesChecked(figure4Members(), Figure4Options{}, [](const auto& o) { validateFigure4(o); });
    expectRangesChecked(figure10Members(), Figure10Options{}, [](const auto& o) { validateFigure10(o); });
    Figure12Options figure12;
    figure12.pattern = loadPreset(figure12.name);
    expectRangesChecked(figure12Members(), figure12, [](const auto& o) { validateFigure12(o); });
    expectRangesChecked(figure14Members(), figure14Options(), [](const auto& o) { validateFigure14(o); });
}

// The report's parts that follow the others: at the frame size and instance
// count within their own ranges, so that every --frame-size and --instances
// the report's entries allow gives a report that validates.
TEST(OptionMembers, TheReportsDerivedPartsStayWithinTheirEntries) {
    ArtifactReportOptions o;
    o.frameSize = 256;
    o.correlation.instances = 40;
    o.correlation.zoom.layers = 5;
    ArtifactReportOptions d = withDerivedParts(o);
    EXPECT_EQ(d.marble.size, 256);
    EXPECT_EQ(d.marble.correlationSize, 96);
    EXPECT_EQ(d.marble.flowStep, 16);
    EXPECT_EQ(d.marble.instances, 40);
    EXPECT_EQ(d.imageBase.instances, 40);
    EXPECT_EQ(d.imageBase.zoom.layers, 8);  // Figure 2.17, whatever the correlation's
    EXPECT_NO_THROW(validateArtifactReport(d));
    // Past a part's range: that part at its end, still a valid report.
    o.frameSize = int(optionMember(artifactReportMembers(), "frameSize").info.max);  // 2048
    o.correlation.instances = 2;
    d = withDerivedParts(o);
    EXPECT_EQ(d.marble.size, int(optionMember(marbleStudyMembers(), "size").info.max));
    EXPECT_EQ(d.marble.correlationSize, 384);
    EXPECT_EQ(d.marble.flowStep, 64);
    EXPECT_EQ(d.marble.instances, int(optionMember(marbleStudyMembers(), "instances").info.min));
    EXPECT_EQ(d.imageBase.instances, 2);
    EXPECT_NO_THROW(validateArtifactReport(d));
    o.frameSize = int(optionMember(artifactReportMembers(), "frameSize").info.min);  // 32
    d = withDerivedParts(o);
    EXPECT_EQ(d.marble.size, 32);
    EXPECT_EQ(d.marble.correlationSize, 16);  // 12, raised to the entry's least
    EXPECT_EQ(d.marble.flowStep, 4);          // 2, likewise
    EXPECT_NO_THROW(validateArtifactReport(d));
}

// The flags that differ from the names, and the validators that still bound
// a member by another (what one entry cannot say).
TEST(OptionMembers, FlagsAndCrossChecks) {
    EXPECT_EQ(optionMember(flowStudyMembers(), "timeStep").info.flag, "dt");
    EXPECT_EQ(optionMember(marbleStudyMembers(), "flowStep").info.flag, "step");
    EXPECT_EQ(optionMember(stabilityStudyMembers(), "truthSamples").info.flag, "truth-samples");
    EXPECT_THROW(optionMember(stabilityStudyMembers(), "nothing"), std::logic_error);
    MarbleStudyOptions marble;
    marble.size = 64;  // correlationSize 96 > size
    EXPECT_EQ(test::inputErrorOf([&] { validateMarbleStudy(marble); }).parameter(), "correlationSize");
    FlowStudyOptions flow;
    flow.region = SourceRegion::centred(64, 64);
    flow.step = 65;  // within the entry, beyond the window
    EXPECT_EQ(test::inputErrorOf([&] { validateFlowStudy(flow); }).parameter(), "step");
    SpectrumStudyOptions spectrum;
    spectrum.instances = 100000;
    spectrum.times = {0, 1};  // 200000 frames
    EXPECT_EQ(test::inputErrorOf([&] { validateSpectrumStudy(spectrum); }).parameter(), "instances");
}

}  // namespace
}  // namespace stochtex
