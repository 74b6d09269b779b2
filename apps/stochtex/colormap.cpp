// stochtex colormap: writes a colormap H as an image (x right, y up).
#include <cstdio>

#include "common.h"
#include "stochtex/core/error.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/pattern_members.h"
#include "stochtex/pattern/presets.h"

namespace stochtex::cli {

void registerColormap(CLI::App& app) {
    struct Args {
        std::string spec;
        std::string preset;
        std::string output;
        std::optional<int> resolution;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("colormap", "Write a colormap defined by a JSON colormap spec or a preset");
    auto* spec = cmd->add_option("spec", args->spec, "Colormap spec: a JSON file or inline JSON ({\"type\":...})");
    auto* preset = cmd->add_option("--preset,-p", args->preset, "Take the colormap of this preset pattern");
    spec->excludes(preset);
    addOutputImageFlag(*cmd, args->output);
    // The file's member: its entry gives the flag's range and help, and checks the value.
    addParameterOption(*cmd, patternMembers().colormapResolution, args->resolution);
    cmd->callback([args] {
        checkImageOutput(args->output);
        ColormapSpec cm;
        if (!args->preset.empty()) {
            cm = loadPreset(args->preset).colormap;
        } else if (!args->spec.empty()) {
            const JsonArgument json = readJsonArgument(args->spec);
            cm = parseColormapSpec(JsonReader(json.json, json.source), json.baseDir);
        } else {
            throw InputError("give a colormap spec or --preset NAME");
        }
        if (args->resolution) cm.resolution = checkInteger(patternMembers().colormapResolution, *args->resolution);
        const ColormapTable table = buildColormap(cm);
        // A data colormap is written as data; colours as sRGB codes (PNG) or linear (EXR).
        writeImage(args->output, table.toImage(), WriteOptions{.transfer = cm.transfer.value_or(Transfer::Srgb)});
        std::printf("wrote %s (%dx%d colormap, x right, y up)\n", args->output.c_str(), table.resolutionX(),
                    table.resolutionY());
    });
}

}  // namespace stochtex::cli
