// stochtex bake: export a filtered pattern for an engine — data files, a
// manifest, one self-contained GLSL include and a README (gpu/export.h).
#include <cstdio>

#include "common.h"
#include "stochtex/core/error.h"
#include "stochtex/gpu/export.h"

namespace stochtex::cli {
namespace {

enum class TablePrecision { Half, Float };
const EnumNames<TablePrecision> kTablePrecisionNames{{"half", TablePrecision::Half}, {"float", TablePrecision::Float}};

}  // namespace

void registerBake(CLI::App& app) {
    struct Args {
        PatternSource source;
        FilterOptions options;
        ResponseFlags response;
        std::string dir;
        TablePrecision precision = TablePrecision::Half;
        ExportFormat format = ExportFormat::Float;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("bake",
                                   "Export a filtered pattern for engines: EXR data, manifest.json, "
                                   "stochtex.glsl (vec4 stochtex_sample(vec2 uv)) and a README");
    addPatternSource(*cmd, args->source);
    addOutputFolderFlag(*cmd, args->dir, "Output folder");
    addFilterFlag(*cmd, args->options,
                  "Table: smooth | paper (σ ≤ 0.125: distant areas drift ~4/255 for the presets, docs/PATTERNS.md)");
    addAnisoFlag(*cmd, args->options.aniso);
    addEstimatorFlag(*cmd, args->options);
    addResponseFlags(*cmd, args->response);
    addEnumFlag(*cmd, "--format", args->format, kExportFormatNames, "format",
                "float | half | 8bit: the data's storage (the paper's 8-bit layout: pyramids RGBA8 per leaf pair, "
                "tables sRGB8); each format's measured accuracy is in the export's README");
    CLI::Option* precisionFlag =
        addEnumFlag(*cmd, "--table-precision", args->precision, kTablePrecisionNames, "tablePrecision",
                    "with --format float: half (half the size, error <= 0.06/255) | float (bit-exact with render "
                    "--gpu)");
    cmd->callback([args, cmd, precisionFlag] {
        applyResponseFlags(*cmd, args->response, args->options);
        if (precisionFlag->count() > 0 && args->format != ExportFormat::Float)
            refuseOption(*cmd, "--table-precision",
                         "applies to --format float only, got --format " + enumName(kExportFormatNames, args->format));
        ExportOptions e;
        e.format = args->format;
        e.halfTable = args->precision == TablePrecision::Half;
        const PatternSpec spec = loadPatternSource(*cmd, args->source, args->options);
        exportPatternSpec(spec, args->options, args->dir, e);
        std::printf(
            "exported %s (filter %s, %s data) to %s: manifest.json, stochtex.glsl (and .hlsl, _unity.hlsl, "
            ".gdshaderinc, .gdshader), README.md and the data\n",
            spec.name.c_str(), filterLabel(args->options).c_str(), enumName(kExportFormatNames, args->format).c_str(),
            args->dir.c_str());
    });
}

}  // namespace stochtex::cli
