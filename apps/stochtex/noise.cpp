// stochtex noise: writes a noise example (and optionally its power spectrum
// or a tiled-and-blended rendering of it).
#include <cstdio>

#include "common.h"
#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/image_io.h"
#include "stochtex/noise/spectrum.h"
#include "stochtex/pattern/json_reader.h"

namespace stochtex::cli {

void registerNoise(CLI::App& app) {
    struct Args {
        std::string spec, output, spectrum;
        std::optional<uint32_t> seed;
        int bits = 8;
        int threads = 0;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("noise", "Write a noise example defined by a JSON noise spec");
    cmd->add_option("spec", args->spec, "Noise spec: a JSON file or inline JSON ({\"type\":\"spectrum\",...})")
        ->required();
    addOutputImageFlag(*cmd, args->output);
    cmd->add_option("--spectrum", args->spectrum, "Also write the log power spectrum (centred) to this image");
    addSeedFlag(*cmd, "--seed", args->seed, "Seed (overrides the spec's)");
    const CLI::Option* bits = addBitsFlag(*cmd, args->bits);
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args, bits] {
        checkBitsApply(bits, args->output);
        checkImageOutput(args->output, args->bits);
        if (!args->spectrum.empty()) checkImageOutput(args->spectrum);
        ThreadLimit limit(args->threads);
        const JsonArgument json = readJsonArgument(args->spec);
        NoiseSpec spec = parseNoiseSpec(JsonReader(json.json, json.source), json.baseDir);
        if (args->seed) spec.spectrum.seed = *args->seed;
        const Image example = buildExampleImage(spec, json.source);
        // Noise values are data: written as they are, as an exemplar is read.
        writeImage(args->output, example, WriteOptions{.bitDepth = args->bits, .transfer = Transfer::Linear});
        const ChannelStats s = channelStats(example);
        std::printf("wrote %s (%dx%d, mean %.4f, std %.4f)\n", args->output.c_str(), example.width(),
                    example.height(), s.mean, s.stddev);
        if (!args->spectrum.empty()) {
            writeImage(args->spectrum, displaySpectrum(powerSpectrum(example)), kNoTransfer);
            std::printf("wrote %s (log power spectrum, zero frequency at the centre)\n", args->spectrum.c_str());
        }
    });
}

}  // namespace stochtex::cli
