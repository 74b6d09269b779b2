// stochtex view: the workbench window on a pattern, a texture graph or a
// ShaderToy program (src/stochtex/workbench: panels, view modes, live
// analyses, reload, screenshots, recording).
// --frames N --screenshot FILE renders N frames, saves the picture area of
// the last and exits; --script FILE drives the window as a person would
// (how the tests try it under Xvfb).
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "common.h"
#include "stochtex/pattern/view.h"
#include "stochtex/workbench/workbench.h"

namespace stochtex::cli {

void registerView(CLI::App& app) {
    struct Args {
        PatternSource source;
        std::string shadertoy, script, mesh, mapping;
        WorkbenchOptions window;
        ResponseFlags response;
        std::vector<int> size{960, 640};
        bool noPanel = false;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("view",
                                   "The workbench window (GLSL): edit a pattern, graph or ShaderToy program "
                                   "live, watch its spectrum, flow or correlation; F1 in the window lists the keys");
    WorkbenchOptions& w = args->window;
    addPatternSource(*cmd, args->source);
    // The window edits and saves a file, so it reads files only (no inline JSON).
    cmd->get_option("pattern")->description(
        "A pattern or texture graph: its JSON file (docs/PATTERNS.md, docs/GRAPHS.md)");
    cmd->add_option("--shadertoy", args->shadertoy, "A ShaderToy program: its folder or manifest (docs/SHADERTOY.md)");
    addFilterFlag(*cmd, w.filter, "Starting mode: none | paper | smooth", gpuFilterNames());
    addCameraFlags(*cmd, w.camera, false);
    // One flag for where the pattern is seen: the window's views extend the
    // cameras' (zoom, plane) with the 3D objects.
    cmd->remove_option(cmd->get_option("--view"));
    const CLI::Option* view = addEnumFlag(*cmd, "--view", w.view, kWorkbenchViewNames, "view",
                                          "Where the pattern is seen: zoom (flat) | plane (perspective ground plane) | "
                                          "sphere | torus | mesh (--mesh FILE; V cycles)");
    cmd->add_option("--mesh", args->mesh, "A mesh for the mesh view: .obj, .gltf or .glb (shown first unless --view)");
    cmd->add_option("--mapping", args->mapping,
                    "The mesh's mapping: uv | triplanar (default uv, triplanar for a mesh without uv)");
    addParameterOption(*cmd, viewScaleParam(), w.camera.view.scale);  // the starting scale
    addAnisoFlag(*cmd, w.filter.aniso);
    addResponseFlags(*cmd, args->response);
    cmd->add_option("--size", args->size, "Picture area: N or W,H (the panel adds 380 pixels at the left)")
        ->delimiter(',')
        ->expected(1, 2);
    addEnumFlag(*cmd, "--mode", w.mode, kWorkbenchModeNames, "mode", "What the picture shows (M cycles)");
    addEnumFlag(*cmd, "--analysis", w.analysis, kLiveAnalysisNames, "analysis", "The live analysis (A cycles)");
    cmd->add_option("--fps", w.shadertoy.fps,
                    "Recordings' frame rate (a pattern's frames on the wall clock); a program's iFrameRate")
        ->capture_default_str();
    cmd->add_flag("--no-panel", args->noPanel, "Start with the panel hidden (Tab shows it)");
    cmd->add_option("--script", args->script, "Steps to run, a JSON file (docs/WORKBENCH.md)");
    addMemberOption(*cmd, optionMember(workbenchOptionsMembers(), "frames"), w);
    cmd->add_option("--screenshot", w.screenshot, "Save the picture area of the last frame to this PNG/EXR");
    cmd->callback([args, cmd, view] {
        applyResponseFlags(*cmd, args->response, args->window.filter);
        WorkbenchOptions o = args->window;
        if (!o.screenshot.empty()) checkImageOutput(o.screenshot);
        o.camera.view.width = args->size[0];
        o.camera.view.height = args->size.size() > 1 ? args->size[1] : args->size[0];
        o.panel = !args->noPanel;
        if (!gpuHasSource(o.filter.source)) refuseOption(*cmd, "--filter", "the window shows none, paper or smooth");
        validateCamera(o.camera);
        if (!args->mapping.empty() && args->mesh.empty()) refuseOption(*cmd, "--mapping", "give it with --mesh");
        if (!args->mesh.empty()) {
            auto mesh = std::make_shared<const LoadedMesh>(loadMesh(args->mesh));
            o.mapping = meshMapping(*mesh, args->mapping, args->mesh);
            o.mesh = std::move(mesh);
            if (view->count() == 0) o.view = WorkbenchView::Mesh;
        }
        o.camera.kind = o.view == WorkbenchView::Plane ? Camera::Kind::Plane : Camera::Kind::Zoom;
        if (!args->script.empty()) o.script = parseWorkbenchScript(readJsonFile(args->script), args->script);
        if (!args->source.file.empty() && args->source.file.front() == '{')
            throw InputError("pattern: the window edits and saves a file, so it takes a JSON file, not inline JSON");
        const bool program = !args->shadertoy.empty();
        if (program && (!args->source.file.empty() || !args->source.preset.empty()))
            refuseOption(*cmd, "--shadertoy", "give a program or a pattern, not both");
        WorkbenchDocument doc = program                      ? WorkbenchDocument::shadertoy(args->shadertoy)
                                : !args->source.file.empty() ? WorkbenchDocument::patternFile(args->source.file)
                                : !args->source.preset.empty()
                                    ? WorkbenchDocument::preset(args->source.preset)
                                    : throw InputError("give a pattern file, --preset NAME or --shadertoy PROGRAM");
        if (args->source.seed) {
            if (program) refuseOption(*cmd, "--seed", "a ShaderToy program has no pattern seed");
            doc.set("/seed", *args->source.seed);
        }
        const int frames = runWorkbench(std::move(doc), o);
        if (!o.screenshot.empty()) std::printf("wrote %s after %d frames\n", o.screenshot.c_str(), frames);
    });
}

}  // namespace stochtex::cli
