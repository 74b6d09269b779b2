// stochtex stability: flicker of a zoom-out sequence, per filter mode, as the
// change of the frames and as the change of their error against the ground
// truth S̄ (studies/stability_study.h).
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "common.h"
#include "progress.h"
#include "stochtex/core/parallel.h"
#include "stochtex/report/frame_sequence.h"
#include "stochtex/studies/stability_study.h"

namespace stochtex::cli {

void registerStability(CLI::App& app) {
    struct Args {
        PatternSource source;
        StabilityStudyOptions study;
        std::vector<std::string> filters{"none", "paper", "smooth", "exact", "reference"};  // kFilterNames
        std::vector<std::string> estimators{"paper"};                                       // kVarianceEstimatorNames
        FilterOptions options;
        std::string dir;
        int threads = 0;
        bool writeFrames = false, video = false;
    };
    auto args = std::make_shared<Args>();
    args->options.referenceMaxSamples = 32;  // a sequence of references: fewer samples than a still
    auto* cmd =
        app.add_subcommand("stability",
                           "Zoom-out sequence per filter mode: error flicker (the change of frame − S̄ from frame "
                           "to frame, zoom undone), accuracy and image change");
    addPatternSource(*cmd, args->source);
    addOutputFolderFlag(*cmd, args->dir, "Output folder for stability.csv (and frames)");
    cmd->add_option("--filters", args->filters, "Filter modes to compare")
        ->delimiter(',')
        ->check(nameValidator(kFilterNames, "filter"))
        ->type_name("ENUM")
        ->default_str("none,paper,smooth,exact,reference");
    cmd->add_option("--estimators", args->estimators,
                    "Footprint estimators: each filter that reads them (paper, smooth) is measured once per name")
        ->delimiter(',')
        ->check(nameValidator(kVarianceEstimatorNames, "estimator"))
        ->type_name("ENUM")
        ->default_str("paper");
    addParameterOptions(*cmd, stabilityStudyMembers(), args->study);
    addAnisoFlag(*cmd, args->options.aniso);
    addParameterOption(*cmd, referenceMaxSamplesParam(), args->options.referenceMaxSamples);
    cmd->add_flag("--write-frames", args->writeFrames, "Also write every frame as PNG");
    cmd->add_flag("--video", args->video, "Also write each filter's sequence as <filter>.mp4 (30 fps)");
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args, cmd] {
        const CLI::Option* estimatorsFlag = cmd->get_option("--estimators");
        std::vector<FilterOptions> named;  // a filter per --filters name
        for (const std::string& name : args->filters) named.emplace_back(args->options).use(parseFilter(name));
        refuseWithoutEffect(
            estimatorsFlag,
            std::any_of(named.begin(), named.end(),
                        [](const FilterOptions& f) { return f.source == StatisticsSource::Estimators; }),
            "without a filter over the estimators (paper, smooth)");
        refuseUnusedFilterFlags(*cmd, named);
        const PatternSpec spec = loadPatternSource(args->source, named);
        std::vector<VarianceEstimator> estimators;  // none given: the pattern file's
        if (estimatorsFlag->count() > 0)
            for (const std::string& name : args->estimators)
                estimators.push_back(parseEnum(kVarianceEstimatorNames, name, "estimator"));
        StabilityStudyOptions study = args->study;
        study.filters = stabilityFilters(spec, args->filters, estimators, args->options);
        validateStabilityStudy(study);
        ThreadLimit limit(args->threads);
        const GraphPattern pattern = GraphPattern::build(spec);  // what only building shows, before any output
        const std::string& dir = args->dir;
        ensureFolder(dir);
        FrameSequenceSet outputs(dir, stabilitySequenceNames(study.filters), study.size, study.size,
                                 {.video = args->video, .frames = args->writeFrames});
        StabilityFrameSink writeFrame;
        if (outputs.writes()) writeFrame = [&](size_t m, int k, const Image& frame) { outputs.write(m, k, frame); };
        std::printf("%d frames, scale %g -> %g, %dx%d, ground truth: S̄ with at most %d samples per axis\n",
                    study.frames, study.from, study.to, study.size, study.size, study.truthSamples);
        ProgressLine progress("stability");
        const StabilityStudyResult r = stabilityStudy(pattern, study, progress.callback(), writeFrame);
        progress.finish();
        std::printf("%s", r.summary.markdown().c_str());
        for (const std::string& video : outputs.finish()) std::printf("wrote %s\n", video.c_str());
        const std::vector<std::string> files = writeReport(dir, stabilityReport(r, spec.name));
        std::printf("wrote %s to %s\n", listNames(files).c_str(), dir.c_str());
    });
}

}  // namespace stochtex::cli
