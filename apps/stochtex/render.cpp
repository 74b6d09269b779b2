// stochtex render: a pattern seen through a camera, unfiltered (S = H∘N at
// pixel centres), filtered (Ŝ = H̄(μ̂, σ̂)) or as the reference S̄.
#include <chrono>
#include <cstdio>

#include "common.h"
#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/image_io.h"
#include "stochtex/gpu/gpu_pattern.h"
#include "stochtex/pattern/filtered_pattern.h"

namespace stochtex::cli {

void registerRender(CLI::App& app) {
    struct Args {
        PatternSource source;
        ViewFlags view;
        std::string output;
        std::string filter = "none";
        std::string camera = "zoom";
        std::string estimator = "paper";
        double tilt = 60, fov = 60;
        int aniso = 1;
        int referenceSamples = 64;
        int bits = 8;
        int threads = 0;
        bool pack8 = false;
        bool gpu = false;
        std::string derivatives = "camera";
        std::string pipeline = "fragment";
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("render", "Render a pattern to PNG or EXR, unfiltered, filtered or as the reference");
    addPatternSource(*cmd, args->source);
    addViewFlags(*cmd, args->view);
    cmd->add_option("-o,--output", args->output, "Output image (.png or .exr)")->required();
    cmd->add_option("--filter", args->filter,
                    "none (S at pixel centres) | paper (estimators + section-5 table) | smooth (estimators + "
                    "interpolated table) | exact (brute-force statistics + table) | reference (supersampled S̄)");
    cmd->add_option("--aniso", args->aniso, "Anisotropic probes K (1 = isotropic trilinear, up to 16)");
    cmd->add_option("--estimator", args->estimator, "Variance estimator: paper | deliot-heitz (one variance per LOD)");
    cmd->add_option("--view", args->camera, "zoom (flat, --scale texels per pixel) | plane (perspective ground plane)");
    cmd->add_option("--tilt", args->tilt, "Plane view: tilt from looking straight down, degrees [0, 89]");
    cmd->add_option("--fov", args->fov, "Plane view: vertical field of view, degrees");
    cmd->add_option("--reference-samples", args->referenceSamples,
                    "Max samples per axis and pixel for --filter reference/exact (n = clamp(2·extent, 8, this))");
    cmd->add_flag("--pack8", args->pack8, "Store the mean/variance pyramids in 8 bits (paper §5: RGBA8 = E_x, E_y, 16V_x, 16V_y)");
    cmd->add_option("--bits", args->bits, "PNG bit depth")->check(CLI::IsMember({8, 16}));
    cmd->add_flag("--gpu", args->gpu,
                  "Render with the GLSL implementation on a headless OpenGL context (--filter none, paper or smooth)");
    cmd->add_option("--derivatives", args->derivatives,
                    "--gpu footprints: camera (the view's exact Jacobian, as the CPU) | rasterizer (dFdx/dFdy)");
    addPipelineFlag(*cmd, args->pipeline);
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args] {
        checkImageOutput(args->output);
        const GpuPattern::Pipeline pipeline = parsePipeline(args->pipeline);
        if (args->derivatives != "camera" && args->derivatives != "rasterizer")
            throw InputError("--derivatives: unknown \"" + args->derivatives + "\" (expected camera or rasterizer)");
        FilterOptions options;
        options.mode = parseFilterMode(args->filter);
        options.aniso = args->aniso;
        options.referenceMaxSamples = args->referenceSamples;
        options.pack8 = args->pack8;
        if (args->estimator == "paper")
            options.estimator = VarianceEstimator::Paper;
        else if (args->estimator == "deliot-heitz")
            options.estimator = VarianceEstimator::DeliotHeitz;
        else
            throw InputError("--estimator: unknown \"" + args->estimator + "\" (expected paper or deliot-heitz)");
        Camera camera;
        if (args->camera == "plane")
            camera.kind = Camera::Kind::Plane;
        else if (args->camera != "zoom")
            throw InputError("--view: unknown \"" + args->camera + "\" (expected zoom or plane)");
        camera.tiltDeg = args->tilt;
        camera.fovDeg = args->fov;
        const PatternSpec spec = loadPatternSource(args->source);
        camera.view = makeView(spec, args->view);
        validateCamera(camera);  // before building anything; FilteredPattern checks the options
        ThreadLimit limit(args->threads);
        const auto start = std::chrono::steady_clock::now();
        if (args->gpu && options.mode != FilterMode::None && options.mode != FilterMode::Paper &&
            options.mode != FilterMode::Smooth)
            throw InputError("--gpu: the GPU renders --filter none, paper or smooth");
        const Pattern pattern = Pattern::build(spec);
        Image image;
        std::string device = "CPU";
        if (args->gpu) {
            auto context = GlContext::headless();
            device = context->describe();
            GpuPattern gpu(pattern, *context, options);
            if (args->derivatives == "rasterizer") gpu.setDerivatives(GpuPattern::Derivatives::Rasterizer);
            gpu.setPipeline(pipeline);
            image = gpu.render(camera);
        } else {
            image = FilteredPattern(pattern, options).render(camera);
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        writeImage(args->output, image, WriteOptions{args->bits});
        std::printf("wrote %s (%dx%d, %s, %s view, filter %s, %s, %.2f s)\n", args->output.c_str(), camera.view.width,
                    camera.view.height, spec.name.c_str(), args->camera.c_str(), args->filter.c_str(), device.c_str(),
                    seconds);
    });
}

}  // namespace stochtex::cli
