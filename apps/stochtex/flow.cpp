// stochtex flow: optical flow of image files, the zoom texture or a pattern's
// frames (thesis §2.8, Figures 2.24–2.25), with the motion about the centre.
#include <algorithm>
#include <cstdio>

#include "common.h"
#include "progress.h"
#include "stochtex/core/parallel.h"
#include "stochtex/report/frame_sequence.h"
#include "stochtex/studies/flow_study.h"
#include "texture_source_flags.h"

namespace stochtex::cli {

void registerFlow(CLI::App& app) {
    struct Args {
        FlowStudyOptions study;
        WindowSizeFlag window;
        std::string dir;
        int threads = 0;
        bool video = false;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand(
        "flow",
        "Optical flow between consecutive frames (Farnebäck, DIS or Lucas–Kanade): "
        "HSV colours, arrows, outward motion: flow [flags] images|pattern|zoom|marble|shadertoy ...");
    cmd->fallthrough();
    addOutputFolderFlag(*cmd, args->dir);
    addWindowSizeFlag(*cmd, args->window, "Window size");
    const auto& members = flowStudyMembers();
    const CLI::Option* frames = addMemberOption(*cmd, optionMember(members, "frames"), args->study);
    const CLI::Option* dt = addMemberOption(*cmd, optionMember(members, "timeStep"), args->study);
    addEnumFlag(*cmd, "--method", args->study.method, kFlowMethodNames, "method",
                "farneback | dis (dense) | lucas-kanade (sparse, on the grid)");
    addMemberOption(*cmd, optionMember(members, "step"), args->study);
    addMemberOption(*cmd, optionMember(members, "arrowScale"), args->study);
    cmd->add_flag("--video", args->video,
                  "Also write the frames as frames.mp4 and an animated frames.webp shown in index.html");
    addThreadsFlag(*cmd, args->threads);
    addTextureSourceCommands(*cmd, [args, frames, dt](const TextureSource& source, const SourceInfo& info) {
        FlowStudyOptions o = args->study;
        o.frameTransfer = info.transfer;
        o.region = studyRegion(args->window, info, "on image files (the flow covers each whole file)");
        if (info.images) {
            refuseWithoutEffect(frames, false, "on image files (every file is a frame)");
            refuseWithoutEffect(dt, false, "on image files (one file per frame)");
            if (info.frames < 2) throw InputError("images: the flow needs at least 2 image files, got 1");
            o.time = 0;
            o.timeStep = 1;
            o.frames = info.frames;
        } else {
            o.time = info.time;
        }
        validateFlowStudy(o, &source);
        ThreadLimit limit(args->threads);
        ensureFolder(args->dir);
        FrameSequenceSet video(
            args->dir, {"frames"}, o.region.width, o.region.height,
            {.video = args->video, .fps = std::min(30.0, 1.0 / o.timeStep), .transfer = o.frameTransfer});
        ProgressLine progress("flow");
        const FlowStudyResult r =
            flowStudy(source, o, progress.callback(), [&](int k, const Image& frame) { video.write(0, k, frame); });
        progress.finish();
        video.finish();
        const std::vector<std::string> files = writeReport(args->dir, flowReport(r, info.name, args->video));
        std::printf("%s\nwrote %s to %s\n", r.summary.markdown().c_str(), listNames(files).c_str(), args->dir.c_str());
    });
}

}  // namespace stochtex::cli
