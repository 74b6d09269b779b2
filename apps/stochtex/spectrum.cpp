// stochtex spectrum: the power spectrum of image files, a pattern or the zoom
// texture, averaged over frames and instances (thesis §2.7, Figure 2.22).
#include <cstdio>

#include "common.h"
#include "progress.h"
#include "stochtex/core/parallel.h"
#include "stochtex/studies/spectrum_study.h"
#include "texture_source_flags.h"

namespace stochtex::cli {

void registerSpectrum(CLI::App& app) {
    struct Args {
        SpectrumStudyOptions study;
        WindowSizeFlag window;
        std::string dir;
        int threads = 0;
    };
    auto args = std::make_shared<Args>();
    auto* cmd =
        app.add_subcommand("spectrum",
                           "Power spectrum (centred, log scale), radial and angular profiles and "
                           "anisotropy of images, a pattern, the zoom or marble texture, or a ShaderToy program: "
                           "spectrum [flags] images|pattern|zoom|marble|shadertoy ...");
    cmd->fallthrough();
    addOutputFolderFlag(*cmd, args->dir);
    addWindowSizeFlag(*cmd, args->window, "Window size");
    const auto& members = spectrumStudyMembers();
    const CLI::Option* instances = addMemberOption(*cmd, optionMember(members, "instances"), args->study);
    addEnumFlag(*cmd, "--window", args->study.window, kSpectrumWindowNames, "window",
                "Taper before the DFT: hann (frames) | none (periodic images)");
    addMemberOption(*cmd, optionMember(members, "radialBins"), args->study);
    addThreadsFlag(*cmd, args->threads);
    addTextureSourceCommands(*cmd, [args, instances](const TextureSource& source, const SourceInfo& info) {
        SpectrumStudyOptions o = args->study;
        o.frameTransfer = info.transfer;
        o.region = studyRegion(args->window, info, "on image files (the spectrum covers each whole file)");
        if (info.images) {
            refuseWithoutEffect(instances, false, "on image files (every file is averaged)");
            o.times.clear();
            for (int k = 0; k < info.frames; ++k) o.times.push_back(k);
            o.instances = 1;
        } else {
            o.times = {info.time};
        }
        validateSpectrumStudy(o, &source);
        ThreadLimit limit(args->threads);
        ensureFolder(args->dir);
        ProgressLine progress("spectrum");
        const SpectrumStudyResult r = spectrumStudy(source, o, progress.callback());
        progress.finish();
        const std::vector<std::string> files = writeReport(args->dir, spectrumReport(r, info.name));
        std::printf("%s\nwrote %s to %s\n", r.summary.markdown().c_str(), listNames(files).c_str(), args->dir.c_str());
    });
}

}  // namespace stochtex::cli
