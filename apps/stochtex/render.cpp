// stochtex render: a pattern seen through a camera, unfiltered (S = H∘N at
// pixel centres), filtered (Ŝ = H̄(μ̂, σ̂)) or as the reference S̄.
#include <chrono>
#include <cstdio>

#include "common.h"
#include "pattern_renderer.h"
#include "progress.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/image_io.h"

namespace stochtex::cli {

void registerRender(CLI::App& app) {
    struct Args {
        PatternSource source;
        ViewFlags view;
        Camera camera;
        FilterOptions options;
        ResponseFlags response;
        DeviceFlags device;
        std::string output;
        int bits = 8, threads = 0;
    };
    auto args = std::make_shared<Args>();
    args->options.use(parseFilter("none"));  // render shows S itself unless asked
    auto* cmd = app.add_subcommand(
        "render", "Render a pattern to PNG, EXR, JPEG or TIFF, unfiltered, filtered or as the reference");
    addPatternSource(*cmd, args->source);
    addViewFlags(*cmd, args->view);
    addOutputImageFlag(*cmd, args->output);
    addFilterFlag(*cmd, args->options,
                  "none (S at pixel centres) | paper (estimators + section-5 table: σ ≤ 0.125, below the "
                  "presets' 1/6, so distant areas drift ~4/255, docs/PATTERNS.md) | smooth (estimators + "
                  "interpolated table up to σ = 1: no drift) | exact (brute-force statistics + table) | "
                  "reference (supersampled S̄)");
    addAnisoFlag(*cmd, args->options.aniso);
    addResponseFlags(*cmd, args->response);
    addEstimatorFlag(*cmd, args->options);
    addCameraFlags(*cmd, args->camera);
    addParameterOption(*cmd, referenceMaxSamplesParam(), args->options.referenceMaxSamples);
    cmd->add_flag("--pack8", args->options.pack8,
                  "Store the mean/variance pyramids in 8 bits (paper §5: RGBA8 = E_x, E_y, 16V_x, 16V_y)");
    const CLI::Option* bits = addBitsFlag(*cmd, args->bits);
    addDeviceFlags(*cmd, args->device,
                   "Render with the GLSL implementation on a headless OpenGL context (--filter none, paper or smooth)",
                   true);
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args, cmd, bits] {
        applyResponseFlags(*cmd, args->response, args->options);
        refuseUnusedFilterFlags(*cmd, args->options);
        refuseUnusedCameraFlags(*cmd, args->camera);
        refuseUnusedDeviceFlags(*cmd, args->device);
        checkBitsApply(bits, args->output);
        checkImageOutput(args->output, args->bits);
        const PatternSpec spec = loadPatternSource(*cmd, args->source, args->options);
        Camera camera = args->camera;
        camera.view = makeView(spec, args->view);
        validateCamera(camera);  // before building anything; the renderer checks the options
        ThreadLimit limit(args->threads);
        const auto start = std::chrono::steady_clock::now();
        checkDeviceFilter(args->device, args->options);  // before the pattern is built
        ProgressLine progress("render");
        progress.update(0.0, "building the pattern and its tables");
        const std::unique_ptr<ViewRenderer> renderer = makeRenderer(spec, args->options, args->device);
        const Image image = renderer->render(camera, progressPart(progress.callback(), 0.0, 1.0, "rendering"));
        progress.finish();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        // The PBR maps are data: their codes are the values (no sRGB encoding).
        writeImage(args->output, image,
                   WriteOptions{args->bits, false,
                                writesData(args->options.response.kind) ? Transfer::Linear : Transfer::Srgb});
        std::printf("wrote %s (%dx%d, %s, %s view, filter %s, %s, %.2f s)\n", args->output.c_str(), camera.view.width,
                    camera.view.height, spec.name.c_str(), enumName(Camera::kKindNames, camera.kind).c_str(),
                    filterLabel(args->options).c_str(), renderer->device().c_str(), seconds);
    });
}

}  // namespace stochtex::cli
