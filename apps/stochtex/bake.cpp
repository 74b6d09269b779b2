// stochtex bake: export a filtered pattern for an engine — data files, a
// manifest, one self-contained GLSL include and a README (gpu/export.h).
#include <cstdio>

#include "common.h"
#include "stochtex/core/error.h"
#include "stochtex/gpu/export.h"

namespace stochtex::cli {

void registerBake(CLI::App& app) {
    struct Args {
        PatternSource source;
        std::string dir, filter = "smooth";
        int aniso = 8;
        std::string precision = "half";
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("bake", "Export a filtered pattern for engines: EXR data, manifest.json, "
                                           "stochtex.glsl (vec4 stochtex_sample(vec2 uv)) and a README");
    addPatternSource(*cmd, args->source);
    cmd->add_option("-o,--output", args->dir, "Output folder")->required();
    cmd->add_option("--filter", args->filter, "Table: smooth | paper");
    cmd->add_option("--aniso", args->aniso, "Anisotropic probes K the shader takes (1..16)");
    cmd->add_option("--table-precision", args->precision,
                    "half (default: half the size, error <= 0.06/255) | float (bit-exact with render --gpu)");
    cmd->callback([args] {
        FilterOptions o;
        o.mode = parseFilterMode(args->filter);
        o.aniso = args->aniso;
        ExportOptions e;
        if (args->precision == "float")
            e.halfTable = false;
        else if (args->precision != "half")
            throw InputError("--table-precision: unknown \"" + args->precision + "\" (expected half or float)");
        const PatternSpec spec = loadPatternSource(args->source);
        const Pattern pattern = Pattern::build(spec);
        exportPattern(pattern, o, args->dir, e);
        std::printf("exported %s (%s table) to %s: manifest.json, stochtex.glsl, README.md and the data\n",
                    spec.name.c_str(), args->filter.c_str(), args->dir.c_str());
    });
}

}  // namespace stochtex::cli
