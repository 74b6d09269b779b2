// stochtex scene: the pattern on a 3D object under a light (paper Fig. 15),
// rendered headless by the GLSL implementation.
#include <chrono>
#include <cstdio>

#include "common.h"
#include "stochtex/core/error.h"
#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/gpu/mesh_file.h"
#include "stochtex/gpu/scene_render.h"
#include "stochtex/image/image_io.h"

namespace stochtex::cli {

void registerScene(CLI::App& app) {
    struct Args {
        PatternSource source;
        FilterOptions options;
        ResponseFlags response;
        std::string output, object = "sphere", mesh, mapping;
        std::vector<int> size{768, 512};
        float tiling = kDefaultSceneTiling;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand(
        "scene", "The pattern on a lit 3D object (plane, sphere, torus or your OBJ/glTF mesh), headless OpenGL");
    addPatternSource(*cmd, args->source);
    addOutputImageFlag(*cmd, args->output);
    CLI::Option* object = cmd->add_option("--object", args->object, "plane | sphere | torus");
    cmd->add_option("--mesh", args->mesh,
                    "A mesh file instead: .obj, .gltf or .glb (centred, scaled to the sphere's size)")
        ->excludes(object);
    cmd->add_option("--mapping", args->mapping,
                    "uv (the mesh's texture coordinates) | triplanar (three projections blended by the normal); "
                    "default uv, triplanar for a mesh without uv");
    addFilterFlag(*cmd, args->options, "none | paper | smooth", gpuFilterNames());
    addAnisoFlag(*cmd, args->options.aniso);
    addResponseFlags(*cmd, args->response);
    cmd->add_option("--tiling", args->tiling, "Example periods across the object's uv square");
    const CLI::Option* size =
        cmd->add_option("--size", args->size, "Image size: N or W,H")->delimiter(',')->expected(1, 2);
    cmd->callback([args, cmd, size] {
        applyResponseFlags(*cmd, args->response, args->options);
        refuseUnusedFilterFlags(*cmd, args->options);
        checkImageOutput(args->output);
        const auto [w, h] = sizeFlagValue(size, args->size, 8192);
        const FilterOptions& options = args->options;
        LoadedMesh loaded;
        if (args->mesh.empty()) {
            loaded.mesh = makeObject(args->object);
            loaded.hasUv = loaded.hasNormals = true;
        } else {
            loaded = loadMesh(args->mesh);
        }
        const SurfaceMapping mapping = meshMapping(loaded, args->mapping, args->mesh);
        const Mesh& mesh = loaded.mesh;
        const PatternSpec spec = loadPatternSource(*cmd, args->source, args->options);
        const auto start = std::chrono::steady_clock::now();
        auto context = GlContext::headless();
        const std::unique_ptr<GpuView> gpu = makeGpuView(spec, *context, options);
        SceneCamera camera;
        if (args->mesh.empty() && args->object == "plane") {
            camera.eye = {0.0f, 0.2f, 2.6f};
            camera.target = {0.0f, -0.9f, -0.5f};
        }
        const Image image = renderScene(*gpu, mesh, camera, w, h, args->tiling, mapping);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        writeImage(args->output, image);
        const std::string on = args->mesh.empty() ? "a " + args->object : args->mesh;
        std::printf("wrote %s (%dx%d, %s on %s, %s mapping, filter %s, %s, %.2f s)\n", args->output.c_str(), w, h,
                    spec.name.c_str(), on.c_str(), enumName(kSurfaceMappingNames, mapping).c_str(),
                    filterLabel(options).c_str(), context->describe().c_str(), seconds);
    });
}

}  // namespace stochtex::cli
