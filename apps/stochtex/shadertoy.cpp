// stochtex shadertoy: a ShaderToy program (a folder or a manifest) rendered
// headless: its last frame, a contact sheet of its frames, a folder of
// frames or an MP4; --inspect prints a pass's pixel after the last frame;
// --analyse runs frame studies (spectrum, flow, coherence, flicker, statistics) on its frames.
#include <chrono>
#include <cstdio>

#include "common.h"
#include "progress.h"
#include "shadertoy_flags.h"
#include "stochtex/analysis/sound_spectrum.h"
#include "stochtex/gpu/shadertoy.h"
#include "stochtex/image/image_io.h"
#include "stochtex/report/wav.h"
#include "stochtex/studies/frame_analysis.h"

namespace stochtex::cli {

void registerShadertoy(CLI::App& app) {
    struct Args {
        std::string program, output, inspect, convert, media, sound;
        double soundSeconds = 10;
        ShadertoyFlags flags;
        FrameAnalysisFlags analysis;
        int frames = 1;
        bool sheet = false;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("shadertoy", "Run a ShaderToy program (Common, Buffer A-D, Image) headless");
    cmd->add_option("program", args->program,
                    "A folder (image.glsl, common.glsl, buffer_a.glsl, ... or ShaderToy's "
                    "tab names; shadertoy.json), a manifest .json, or a shader exported "
                    "from ShaderToy (.json; docs/SHADERTOY.md)")
        ->required();
    bindParameter(*cmd,
                  cmd->add_option("--convert", args->convert,
                                  "Write the program as a folder (shadertoy.json and a .glsl file per "
                                  "pass) instead of running it: a ShaderToy export made editable"),
                  "output");
    cmd->add_option("--media", args->media,
                    "Where a ShaderToy export's textures are found by file name (default: "
                    "the export's folder; ShaderToy's noise textures are built in)");
    cmd->add_option("-o,--output", args->output,
                    std::string("An image (the last frame, or with --sheet all frames; ") + kImageOutputFormats +
                        "), or the frames as " + kSequenceOutputHelp + "; with --analyse the report's folder");
    cmd->add_option("--sound", args->sound,
                    "Write the program's Sound pass (sound.glsl) as a WAV file, 16-bit stereo "
                    "at iSampleRate, and print its spectrum's peak");
    cmd->add_option(
           "--sound-seconds", args->soundSeconds,
           "Seconds of sound --sound renders (at most " + formatValue(kMaxSoundSeconds) + ", as ShaderToy plays)")
        ->capture_default_str();
    addShadertoyFlags(*cmd, args->flags);
    cmd->add_option("--frames", args->frames,
                    "Frames rendered from frame 0 (iFrame 0 at --time); with --analyse, "
                    "the frames analysed from --first-frame");
    cmd->add_flag("--sheet", args->sheet, "An image output shows every frame, as a contact sheet (at most 64)");
    CLI::Option* inspect = cmd->add_option("--inspect", args->inspect,
                                           "PASS:X,Y: print the RGBA of a pass (image, buffer_a, ...) at pixel "
                                           "(X, Y), y up, after the last frame");
    bindParameter(*cmd, inspect, "pass");
    bindParameter(*cmd, inspect, "pixel");
    addFrameAnalysisFlags(*cmd, args->analysis);
    cmd->callback([args, cmd] {
        const Args& a = *args;
        if (!a.convert.empty()) {
            if (!a.output.empty() || !a.inspect.empty() || !a.analysis.list.empty())
                refuseOption(*cmd, "--convert",
                             "writes the program and runs nothing; run the folder it writes with -o, --inspect or "
                             "--analyse");
            const ShadertoySpec spec = loadShadertoy(a.program, a.media);
            const std::string manifest = convertShadertoy(spec, a.convert);
            std::printf("wrote %s and %zu pass file%s (%s)\n", manifest.c_str(),
                        spec.passes.size() + (spec.common.empty() ? 0 : 1), spec.passes.size() > 0 ? "s" : "",
                        spec.name.c_str());
            return;
        }
        if (a.output.empty() && a.inspect.empty() && a.sound.empty())
            throw InputError("nothing to do: give -o/--output, --inspect, --sound or --convert");
        if (!a.sound.empty()) {
            if (!a.sound.ends_with(".wav"))
                refuseOption(*cmd, "--sound", "writes a .wav file, got \"" + a.sound + "\"");
            checkOutputFile(a.sound);
        }
        if (a.analysis.list.empty() && a.flags.firstFrame != 0)
            refuseOption(*cmd, "--first-frame", "has no effect without --analyse");
        const Inspect inspect = parseInspect(*cmd, a.inspect);
        const ShadertoySpec spec = loadShadertoy(a.program, a.media);
        const ShadertoySettings settings = shadertoySettings(*cmd, a.flags);
        FrameOutputs outputs(*cmd, a.analysis.list.empty() ? a.output : "", a.sheet, a.frames, settings);
        const auto start = std::chrono::steady_clock::now();
        auto context = GlContext::headless();
        ShadertoyHost host(spec, *context, settings);
        if (!inspect.pass.empty()) host.checkPixel(inspect.pass, inspect.x, inspect.y);
        ProgressLine line("shadertoy");
        if (!a.analysis.list.empty()) {  // the studies' frames through the texture-source interface
            const ShadertoySource source(host);
            FrameAnalysisOptions o = frameAnalysisOptions(*cmd, a.analysis, settings, a.frames, a.flags.firstFrame);
            o.sourceName = spec.name;
            const FrameAnalysisResult r = frameAnalysis(source, o, line.callback());  // validates before any frame
            line.finish();
            writeReport(a.output, r.report);
            std::printf("%swrote %zu figures, %zu tables and index.html to %s\n", r.markdown.c_str(), r.figures.size(),
                        r.tables.size(), a.output.c_str());
        } else {
            renderShadertoyFrames(host, a.frames, outputs.sink(), line.callback(), outputs.readBack());
            line.finish();
            const std::string written = outputs.finish();
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (!written.empty())
                std::printf("wrote %s (%dx%d, %s, %d frame%s from iTime %g at %g fps, %s, %.2f s)\n", written.c_str(),
                            settings.width, settings.height, spec.name.c_str(), a.frames, a.frames == 1 ? "" : "s",
                            settings.startTime, settings.fps, context->describe().c_str(), seconds);
        }
        if (!inspect.pass.empty()) printInspect(host, inspect);
        if (!a.sound.empty()) {
            ProgressLine soundLine("sound");
            const std::vector<float> samples = host.renderSound(a.soundSeconds, soundLine.callback());
            soundLine.finish();
            writeWav(a.sound, samples, 2, int(std::lround(settings.sampleRate)));
            const SoundSpectrum spectrum = soundSpectrum(samples, 2, settings.sampleRate);
            std::printf("wrote %s (%g s, %g Hz stereo; rms %.4f, spectrum peak at %.1f Hz)\n", a.sound.c_str(),
                        a.soundSeconds, settings.sampleRate, spectrum.rms, spectrum.peakFrequency);
        }
    });
}

}  // namespace stochtex::cli
