// The option structs' tables (OptionMember, pattern/param_info.h): each
// entry's default is its struct's own initialiser, its flag the name in
// kebab case unless it says otherwise, and the struct's check refuses a
// value just outside the entry's range, naming the entry, while the range's
// ends pass.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "stochtex/studies/artifact_report.h"
#include "stochtex/studies/flow_study.h"
#include "stochtex/studies/image_base_study.h"
#include "stochtex/studies/marble_study.h"
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

// Every member of `members` through `check` (the struct's validator) on a
// valid struct `valid`: its ends pass, the next values outside and NaN (for
// a number) are refused with the member's name.
template <class Options, class Check>
void expectRangesChecked(std::span<const OptionMember<Options>> members, const Options& valid, Check check) {
    ASSERT_FALSE(members.empty());
    EXPECT_NO_THROW(check(valid));
    for (const OptionMember<Options>& m : members) {
        const ParamInfo& p = m.info;
        SCOPED_TRACE(p.name);
        EXPECT_FALSE(p.flag.empty());
        EXPECT_LT(p.min, p.max);
        std::visit(
            [&](auto member) {
                using T = std::remove_reference_t<decltype(Options{}.*member)>;
                EXPECT_EQ(p.typical(), double(Options{}.*member));  // the default is the struct's
                EXPECT_EQ(p.type, (std::is_same_v<T, int> ? ParamType::Integer : ParamType::Number));
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
                if constexpr (std::is_same_v<T, double>)
                    EXPECT_EQ(test::inputErrorOf([&] { check(with(std::nan(""))); }).parameter(), p.name);
                // Both ends pass the member's own check (others may bound it further).
                for (const double v : {p.min, p.max}) EXPECT_NO_THROW(checkMembers(with(v), members)) << v;
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
    expectRangesChecked(flowStudyMembers(), flow, [](const auto& o) { checkMembers(o, flowStudyMembers()); });
    expectRangesChecked(spectrumStudyMembers(), SpectrumStudyOptions{},
                        [](const auto& o) { checkMembers(o, spectrumStudyMembers()); });
    expectRangesChecked(contrastStudyMembers(), ContrastStudyOptions{},
                        [](const auto& o) { validateContrastStudy(o); });
    expectRangesChecked(correlationStudyMembers(), CorrelationStudyOptions{},
                        [](const auto& o) { validateCorrelationStudy(o); });
    expectRangesChecked(imageBaseStudyMembers(), ImageBaseStudyOptions{},
                        [](const auto& o) { checkMembers(o, imageBaseStudyMembers()); });
    expectRangesChecked(marbleStudyMembers(), MarbleStudyOptions{},
                        [](const auto& o) { checkMembers(o, marbleStudyMembers()); });
    expectRangesChecked(stimulusSetMembers(), StimulusSetOptions{},
                        [](const auto& o) { checkMembers(o, stimulusSetMembers()); });
    expectRangesChecked(temporalCoherenceMembers(), TemporalCoherenceOptions{},
                        [](const auto& o) { checkMembers(o, temporalCoherenceMembers()); });
    expectRangesChecked(artifactReportMembers(), ArtifactReportOptions{},
                        [](const auto& o) { checkMembers(o, artifactReportMembers()); });
    expectRangesChecked(zoomParamsMembers(), ZoomParams{}, [](const auto& o) { validateZoomParams(o); });
    expectRangesChecked(marbleParamsMembers(), MarbleParams{}, [](const auto& o) { validateMarbleParams(o); });
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
