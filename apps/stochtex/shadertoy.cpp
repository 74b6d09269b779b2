// stochtex shadertoy: a ShaderToy program (a folder or a manifest) rendered
// headless: its last frame, a contact sheet of its frames, a folder of
// frames or an MP4; --inspect prints a pass's pixel after the last frame.
#include <chrono>
#include <cstdio>

#include "common.h"
#include "progress.h"
#include "shadertoy_flags.h"
#include "stochtex/analysis/plot.h"
#include "stochtex/gpu/shadertoy.h"
#include "stochtex/image/image_io.h"
#include "stochtex/report/frame_sequence.h"

namespace stochtex::cli {

void registerShadertoy(CLI::App& app) {
    struct Args {
        std::string program, output, inspect;
        ShadertoyFlags flags;
        int frames = 1;
        bool sheet = false;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("shadertoy", "Run a ShaderToy program (Common, Buffer A-D, Image) headless");
    cmd->add_option("program", args->program, "A folder (image.glsl, common.glsl, buffer_a.glsl, ...; shadertoy.json) "
                                              "or a manifest .json (docs/SHADERTOY.md)")->required();
    cmd->add_option("-o,--output", args->output, "An image (the last frame, or with --sheet all frames), an .mp4, or a "
                                                 "folder of frame_NNNN.png");
    addShadertoyFlags(*cmd, args->flags);
    cmd->add_option("--frames", args->frames, "Frames rendered from frame 0 (iFrame 0 at --time)");
    cmd->add_flag("--sheet", args->sheet, "An image output shows every frame, as a contact sheet (at most 64)");
    cmd->add_option("--inspect", args->inspect, "PASS:X,Y: print the RGBA of a pass (image, buffer_a, ...) at pixel "
                                                "(X, Y), y up, after the last frame");
    cmd->callback([args] {
        const Args& a = *args;
        if (a.output.empty() && a.inspect.empty()) throw InputError("-o/--output or --inspect is required");
        const bool video = !a.output.empty() && isVideoPath(a.output);
        const bool image = !a.output.empty() && isSupportedImagePath(a.output);
        if (image) checkImageOutput(a.output);
        if (a.sheet && !image) throw InputError("--sheet: needs an image output");
        if (a.frames < 1 || a.frames > 1000000) throw InputError("--frames: must be in [1, 1000000], got " + std::to_string(a.frames));
        const Inspect inspect = parseInspect(a.inspect);
        const ShadertoySpec spec = loadShadertoy(a.program);
        const ShadertoySettings settings = shadertoySettings(a.flags);
        if (a.sheet) checkSheet(a.frames, settings.width, settings.height);
        const auto start = std::chrono::steady_clock::now();
        auto context = GlContext::headless();
        ShadertoyHost host(spec, *context, settings);
        if (!inspect.pass.empty()) host.checkPixel(inspect.pass, inspect.x, inspect.y);
        std::unique_ptr<FrameSequenceWriter> frames;
        if (!a.output.empty() && !image)
            frames = std::make_unique<FrameSequenceWriter>(a.output, settings.width, settings.height, settings.fps, "",
                                                           Transfer::Linear);
        Image last;
        std::vector<Image> sheetFrames;
        std::vector<std::string> captions;
        ProgressLine line("shadertoy");
        renderShadertoyFrames(host, a.frames, [&](int frame, const Image& img) {
            if (frames) frames->write(clampedFrame(img));
            if (a.sheet) sheetFrames.push_back(img), captions.push_back("iFrame " + std::to_string(frame));
            last = img;
        }, line.callback());
        line.finish();
        if (image) writeImage(a.output, a.sheet ? sheetOf(sheetFrames, captions) : last, kNoTransfer);
        const std::string written = frames ? frames->finish() : "";
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!inspect.pass.empty()) printInspect(host, inspect);
        if (!a.output.empty())
            std::printf("wrote %s (%dx%d, %s, %d frame%s from iTime %g at %g fps, %s, %.2f s)\n",
                        video ? written.c_str() : a.output.c_str(), settings.width, settings.height, spec.name.c_str(),
                        a.frames, a.frames == 1 ? "" : "s", settings.startTime, settings.fps,
                        context->describe().c_str(), seconds);
    });
}

}  // namespace stochtex::cli
