// stochtex marble: the marble texture's artifacts (thesis §2.7.2, §2.8), continuous
// scaling vs the fix: stretching, correlation, spectra, sliding (with videos).
#include <algorithm>
#include <cstdio>
#include <memory>

#include "common.h"
#include "marble_flags.h"
#include "progress.h"
#include "stochtex/core/parallel.h"
#include "stochtex/report/frame_sequence.h"
#include "stochtex/studies/marble_study.h"

namespace stochtex::cli {

void registerMarble(CLI::App& app) {
    struct Args {
        MarbleStudyOptions study;
        std::vector<double> point;
        std::string dir;
        int threads = 0;
    };
    auto args = std::make_shared<Args>();
    MarbleStudyOptions& s = args->study;
    auto* cmd = app.add_subcommand("marble",
                                   "The marble texture (thesis eq. 2.29): stretching, correlation, spectra "
                                   "and sliding, continuous scaling vs the blended fix; videos of the sliding");
    addOutputFolderFlag(*cmd, args->dir);
    addMarbleFlags(*cmd, s.marble, false);
    cmd->add_option("--scalings", s.scalings, "Scalings compared: continuous, blended, blended-corrected")
        ->delimiter(',')
        ->transform(enumTransformer(kMarbleScalingNames, "scalings"))
        ->default_str("continuous,blended-corrected");
    const auto& members = marbleStudyMembers();
    for (const char* name : {"size", "correlationSize"}) addMemberOption(*cmd, optionMember(members, name), s);
    CLI::Option* point = cmd->add_option("--point", args->point,
                                         "Correlation reference X,Y in pixels from the origin (default: x = "
                                         "-period/4 of l, where the scaling shears the noise most, y halfway "
                                         "to the edge)")
                             ->delimiter(',')
                             ->expected(2);
    bindParameter(*cmd, point, "pointX");
    bindParameter(*cmd, point, "pointY");
    for (const char* name : {"instances", "spectrumInstances", "slideRate", "frames", "timeStep", "flowStep"})
        addMemberOption(*cmd, optionMember(members, name), s);
    addEnumFlag(*cmd, "--method", s.flowMethod, kFlowMethodNames, "method",
                "Optical flow: dis (default: exact on the smooth noise), farneback or lucas-kanade");
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args] {
        MarbleStudyOptions o = args->study;
        if (!args->point.empty()) o.pointX = args->point[0], o.pointY = args->point[1];
        validateMarbleStudy(o);
        ThreadLimit limit(args->threads);
        ensureFolder(args->dir);
        FrameSequenceSet videos(args->dir, marbleVideoNames(o), o.size, o.size,
                                {true, false, std::min(30.0, 1.0 / o.timeStep), Transfer::Linear});
        ProgressLine progress("marble");
        const MarbleStudyResult r =
            marbleStudy(o, progress.callback(), [&](size_t v, int k, const Image& f) { videos.write(v, k, f); });
        videos.finish();
        progress.finish();
        const std::vector<std::string> files = writeReport(args->dir, marbleReport(r, true));
        std::printf("%s\n%s\n%s\nwrote %zu videos (MP4 + animated WebP), %s to %s\n", r.correlation.markdown().c_str(),
                    r.spectra.markdown().c_str(), r.sliding.markdown().c_str(), r.videos.size(),
                    listNames(files).c_str(), args->dir.c_str());
    });
}

}  // namespace stochtex::cli
