// stochtex bake-image: a large texture of the pattern (up to 65536² pixels)
// rendered in bands of rows and streamed into a PNG or an OpenEXR file, so
// memory stays at one band (a few tens of MB) whatever the image size. The
// bands, and their tiles of 16384 columns, are exact sub-views: the image is
// the same as one `render` of the whole (same flags).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "common.h"
#include "pattern_renderer.h"
#include "progress.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/image_stream.h"
#include "stochtex/pattern/part_cache.h"
#include "stochtex/pattern/tileable.h"

namespace stochtex::cli {

namespace {

// The PBR set's images (kPbrMaps): OUTPUT's name with _albedo, _normal,
// _roughness and _height before its extension.
std::vector<std::pair<ResponseKind, std::string>> pbrImages(const std::string& output) {
    const std::filesystem::path path(output);
    const std::string stem = (path.parent_path() / path.stem()).string(), ext = path.extension().string();
    std::vector<std::pair<ResponseKind, std::string>> images;
    for (const auto& [kind, name] : kPbrMaps) images.emplace_back(kind, stem + "_" + name + ext);
    return images;
}

}  // namespace

void registerBakeImage(CLI::App& app) {
    struct Args {
        PatternSource source;
        ViewFlags view;
        FilterOptions options;
        ResponseFlags response;
        DeviceFlags device;
        std::string output;
        int bits = 8, band = 256, threads = 0;
        bool tileable = false, pbr = false;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("bake-image",
                                   "Render a large PNG or EXR in bands of rows with bounded memory "
                                   "(e.g. --size 8192), on the CPU or with --gpu");
    addPatternSource(*cmd, args->source);
    addViewFlags(*cmd, args->view);
    addOutputImageFlag(*cmd, args->output,
                       "Output image: .png (8 or 16 bits, --bits) or .exr (32-bit float, ZIP-compressed, linear values "
                       "as rendered)");
    addFilterFlag(*cmd, args->options, "none | paper | smooth", gpuFilterNames());
    addAnisoFlag(*cmd, args->options.aniso);
    addResponseFlags(*cmd, args->response);
    const CLI::Option* bits = addBitsFlag(*cmd, args->bits);
    cmd->add_option("--band", args->band,
                    "Rows rendered at a time (fewer for views over 16384 wide: a band holds at most 16384 x 256 "
                    "pixels)")
        ->check(CLI::Range(1, 4096));
    addDeviceFlags(*cmd, args->device, "Render the bands with the GLSL implementation", false);
    addThreadsFlag(*cmd, args->threads);
    cmd->add_flag("--tileable", args->tileable,
                  "An image that wraps without a seam: the pattern made periodic over it (its grid stretched along u "
                  "to a whole number of cells; --scale moves to a whole number of example periods)");
    cmd->add_flag("--pbr", args->pbr,
                  "A PBR material's maps of a pattern with a normal_map, one image each: OUT_albedo (its colours), "
                  "OUT_normal (tangent space, OpenGL convention), OUT_roughness (GGX, the slope lobe's spread) and "
                  "OUT_height, the last three as data (no sRGB encoding); with --tileable, all tile");
    cmd->callback([args, cmd, bits] {
        applyResponseFlags(*cmd, args->response, args->options);
        refuseUnusedFilterFlags(*cmd, args->options);
        refuseUnusedDeviceFlags(*cmd, args->device);
        checkBitsApply(bits, args->output);
        checkImageOutput(args->output, args->bits);
        checkImageStreamFormat(args->output);  // .jpg and .tif are written whole, not in bands
        if (!gpuHasSource(args->options.source))
            refuseOption(*cmd, "--filter", "bake-image renders none, paper or smooth");
        PatternSpec spec = loadPatternSource(*cmd, args->source, args->options);
        if (args->pbr && cmd->count("--response"))
            refuseOption(*cmd, "--pbr", "writes every response of the PBR set itself; drop --response");
        if (args->pbr && !spec.normalMap)
            refuseOption(*cmd, "--pbr", "needs a pattern with a normal_map (" + spec.name + " has none)");
        if (args->pbr) args->options.response.kind = ResponseKind::PrefilteredColormap;  // the albedo's view rules
        Camera whole;
        whole.view = makeView(spec, args->view, ViewUse::BandedBake);  // memory is one band: 65536 a side
        // The parts of every program this command builds (the period's, each
        // PBR image's), so that each example and pyramid is built once.
        PartCache parts;
        std::string tiling;
        if (args->tileable) {
            const TilePeriod t = makeTileable(spec, args->options.response, whole.view, &parts);
            char text[160];
            std::snprintf(text, sizeof text, ", tileable: %d x %d example periods of %d texels, grid x%.4f along u",
                          t.periodsU, t.periodsV, t.exampleSize, t.stretch);
            tiling = text;
        }
        ThreadLimit limit(args->threads);
        const auto start = std::chrono::steady_clock::now();
        ProgressLine progress("bake-image");
        progress.update(0.0, "building the pattern and its tables");
        // One image, or the PBR set: each its program (one response each), its
        // view in the same uv as the first's (a program's view is in texels
        // of its own first example, which may differ in size).
        std::vector<std::pair<ResponseKind, std::string>> images{{args->options.response.kind, args->output}};
        if (args->pbr) images = pbrImages(args->output);
        int firstExampleSize = 0;
        std::string written;
        for (size_t i = 0; i < images.size(); ++i) {
            FilterOptions options = args->options;
            options.response.kind = images[i].first;
            const std::unique_ptr<ViewRenderer> renderer = makeRenderer(spec, options, args->device, &parts);
            if (i == 0) firstExampleSize = renderer->exampleSize();
            Camera camera = whole;
            camera.view = sameUvView(whole.view, firstExampleSize, renderer->exampleSize());
            const View& v = camera.view;
            const std::unique_ptr<ImageStreamWriter> out =
                openImageStream(images[i].second, v.width, v.height, 3, args->bits,
                                writesData(options.response.kind) ? Transfer::Linear : Transfer::Srgb);
            renderInBands(
                *renderer, camera, args->band, [&](const Image& rows) { out->writeRows(rows); },
                progressPart(progress.callback(), double(i) / double(images.size()),
                             double(i + 1) / double(images.size()),
                             enumName(kResponseKindNames, options.response.kind)));
            out->finish();
            written += (i ? ", " : "") + images[i].second;
        }
        progress.finish();
        const View& v = whole.view;
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("wrote %s (%dx%d, %s, filter %s, %s, bands of %d rows%s, %.1f s)\n", written.c_str(), v.width,
                    v.height, spec.name.c_str(), filterLabel(args->options).c_str(), args->device.gpu ? "GPU" : "CPU",
                    bandRows(v.width, args->band), tiling.c_str(), seconds);
    });
}

}  // namespace stochtex::cli
