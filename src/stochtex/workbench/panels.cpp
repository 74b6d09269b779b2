#include "stochtex/workbench/panels.h"

#include <imgui.h>

#include <cfloat>
#include <cstdint>

#include "stochtex/pattern/param_info.h"

namespace stochtex {

namespace {

using A = WorkbenchCommand::Action;

// The keys, as the help window lists them (the model's applyKey acts on them).
struct KeyHelp {
    const char* keys;
    const char* what;
};
constexpr KeyHelp kPatternKeys[] = {
    {"wheel", "zoom about the cursor (3D: distance)"},
    {"left drag", "pan (3D: orbit)"},
    {"right click", "pick the correlation point"},
    {"Ctrl + drag", "move the split line"},
    {"1 / 2 / 3", "filter none / paper / smooth"},
    {"[ / ]", "anisotropy down / up"},
    {"L", "colours or LEAN normals (a pattern with a normal map)"},
    {"V", "view: zoom, plane, sphere, torus"},
    {"Up / Down", "tilt of the plane"},
    {"D", "footprints from the camera or the rasterizer"},
    {"M", "mode: texture, analysis, side by side, split, overlay"},
    {"A", "analysis: spectrum, flow, flicker, correlation"},
    {"Ctrl + Z / Ctrl + Y", "undo / redo an edit (a drag is one step)"},
};
constexpr KeyHelp kCommonKeys[] = {
    {"Tab", "show or hide the panel"},
    {"F1", "this help"},
    {"F2", "screenshot of the picture (PNG, current folder)"},
    {"F3", "start or stop recording (MP4, current folder)"},
    {"F4", "pause or run (ShaderToy)"},
    {"F5", "reload from disk"},
    {"Ctrl + S", "save the pattern (its file; a preset to NAME.json)"},
    {"Esc", "quit"},
};

// A combo over an enum's names: the name chosen, or "" when none was.
template <class E>
std::string enumCombo(const char* label, E value, const EnumNames<E>& names) {
    std::string chosen;
    if (ImGui::BeginCombo(label, enumName(names, value).c_str())) {
        for (const auto& [name, v] : names)
            if (ImGui::Selectable(name.c_str(), v == value)) chosen = name;
        ImGui::EndCombo();
    }
    return chosen;
}

void* imageId(unsigned texture) { return texture ? reinterpret_cast<void*>(uintptr_t(texture)) : nullptr; }

// Where the colormap the canvas shows lives in the JSON: the pattern's, or
// the output node's of a graph.
std::string outputColormapPointer(const nlohmann::json& j) {
    if (j.contains("nodes") && j.contains("output") && j["output"].is_string())
        return "/nodes/" + j["output"].get<std::string>() + "/colormap";
    return "/colormap";
}

}  // namespace

void WorkbenchPanels::draw(WorkbenchModel& model, const WorkbenchPicture& picture, float pixelScale, int windowHeight,
                           const DisplayRect& texture) {
    if (model.shown().help) drawHelp(model);
    if (!model.shown().panel) return;
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(float(kWorkbenchPanelWidth), float(windowHeight) / pixelScale));
    ImGui::Begin("stochtex", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoTitleBar);
    ImGui::TextWrapped("%s", model.document().source().c_str());
    ImGui::TextDisabled("F1: keys   Tab: hide panel");
    auto message = [](const std::string& text, const ImVec4& colour) {
        if (text.empty()) return;
        ImGui::PushStyleColor(ImGuiCol_Text, colour);
        ImGui::TextWrapped("%s", text.c_str());
        ImGui::PopStyleColor();
    };
    message(model.error(), ImVec4(1, 0.45f, 0.4f, 1));
    message(model.notice(), ImVec4(0.6f, 0.9f, 0.6f, 1));
    ImGui::PushID("view");  // the view's controls apart from the pattern's members of the same names
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) drawViewControls(model, picture, texture);
    if (model.analysing() && ImGui::CollapsingHeader("Analysis", ImGuiTreeNodeFlags_DefaultOpen))
        drawAnalysis(model, picture);
    ImGui::PopID();
    if (!model.isShadertoy()) drawEditors(model, picture);
    ImGui::End();
}

void WorkbenchPanels::drawEditors(WorkbenchModel& model, const WorkbenchPicture& picture) {
    EditorPreviews previews;
    previews.colormap = imageId(picture.colormapTexture());
    previews.colormapPointer = outputColormapPointer(model.document().json());
    const PatternSpec& spec = model.spec();
    if (!spec.graph && spec.colormap.source == ColormapSpec::Source::Painted) previews.painted = &spec.colormap.painted;
    for (int k = 0; k < 2; ++k)
        previews.example[k] = imageId(picture.exampleTexture(k)),
        previews.spectrum[k] = imageId(picture.spectrumTexture(k));
    ImGui::Checkbox("unfold every section", &expandAll_);
    previews.expandAll = expandAll_;
    const std::vector<JsonEdit> edits = patternEditor(model.document().json(), previews, editorState_);
    model.applyGesture(edits, ImGui::IsAnyItemActive() || ImGui::IsMouseDown(ImGuiMouseButton_Left));
    ImGui::BeginDisabled(!model.document().canUndo());
    if (ImGui::Button("Undo (Ctrl+Z)")) model.apply(WorkbenchCommand::of(A::Undo));
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!model.document().canRedo());
    if (ImGui::Button("Redo (Ctrl+Y)")) model.apply(WorkbenchCommand::of(A::Redo));
    ImGui::EndDisabled();
    if (ImGui::Button("Save JSON (Ctrl+S)")) model.apply(WorkbenchCommand::of(A::SaveDefault));
    ImGui::SameLine();
    ImGui::SetNextItemWidth(160);
    ImGui::InputText("##saveas", saveAs_, sizeof saveAs_);
    ImGui::SameLine();
    if (ImGui::Button("Save as")) model.apply(WorkbenchCommand::of(A::Save, 0, saveAs_));
}

void WorkbenchPanels::drawViewControls(WorkbenchModel& model, const WorkbenchPicture& picture,
                                       const DisplayRect& texture) {
    const WorkbenchShown& s = model.shown();
    if (auto m = enumCombo("mode", s.mode, kWorkbenchModeNames); !m.empty())
        model.apply(WorkbenchCommand::of(A::Mode, 0, m));
    float split = s.split, opacity = s.overlayOpacity;
    if (s.mode == WorkbenchMode::Split && ImGui::SliderFloat("split", &split, 0, 1))
        model.apply(WorkbenchCommand::of(A::Split, split));
    if (s.mode == WorkbenchMode::Overlay && ImGui::SliderFloat("opacity", &opacity, 0, 1))
        model.apply(WorkbenchCommand::of(A::Opacity, opacity));
    if (model.analysing())
        if (auto a = enumCombo("analysis", s.analysis, kLiveAnalysisNames); !a.empty())
            model.apply(WorkbenchCommand::of(A::Analysis, 0, a));
    if (model.isShadertoy()) {
        const int frame = picture.host() ? picture.host()->frame() : 0;
        const ShadertoySettings& settings = picture.host() ? picture.host()->settings() : ShadertoySettings{};
        ImGui::Text("frame %d, iTime %.2f s", frame, settings.startTime + frame / settings.fps);
        bool paused = s.paused;
        if (ImGui::Checkbox("pause (F4)", &paused)) model.apply(WorkbenchCommand::of(A::Pause, paused));
        ImGui::SameLine();
        if (ImGui::Button("restart")) model.apply(WorkbenchCommand::of(A::RestartProgram));
        return;
    }
    if (ImGui::BeginCombo("filter", s.filterName.c_str())) {
        for (const char* f : {"none", "paper", "smooth"})
            if (ImGui::Selectable(f, f == s.filterName)) model.apply(WorkbenchCommand::of(A::Filter, 0, f));
        ImGui::EndCombo();
    }
    int aniso = s.filter.aniso;
    if (ImGui::SliderInt("aniso", &aniso, int(anisoParam().min), int(anisoParam().max)))
        model.apply(WorkbenchCommand::of(A::Aniso, aniso));
    if (s.filterName != "none")
        if (auto e = enumCombo("estimator", s.filter.estimator, kVarianceEstimatorNames); !e.empty())
            model.apply(WorkbenchCommand::of(A::Estimator, 0, e));
    if (model.hasNormalMap()) {
        bool lean = s.response == ResponseKind::Lean;
        if (ImGui::Checkbox("LEAN normals (L)", &lean))
            model.apply(WorkbenchCommand::of(
                A::Response, 0,
                enumName(kResponseKindNames, lean ? ResponseKind::Lean : ResponseKind::PrefilteredColormap)));
    }
    if (auto v = enumCombo("view", s.view, kWorkbenchViewNames); !v.empty())
        model.apply(WorkbenchCommand::of(A::View, 0, v));
    if (s.view == WorkbenchView::Plane) {
        float tilt = float(s.camera.tiltDeg);
        if (ImGui::SliderFloat("tilt", &tilt, float(cameraTiltParam().min), float(cameraTiltParam().max), "%.1f°"))
            model.apply(WorkbenchCommand::of(A::Tilt, tilt));
    }
    if (!model.isScene()) {
        float scale = float(s.camera.view.scale);
        if (ImGui::SliderFloat("zoom", &scale, 1.0f / 64, 4096, "%.4g texels/px", ImGuiSliderFlags_Logarithmic)) {
            WorkbenchCommand zoom = WorkbenchCommand::of(A::Zoom, s.camera.view.scale / scale);
            zoom.x = texture.width / 2.0, zoom.y = texture.height / 2.0;  // about the texture's centre
            model.apply(zoom);
        }
        bool rasterizer = s.derivatives == GpuView::Derivatives::Rasterizer;
        if (ImGui::Checkbox("rasterizer derivatives (D)", &rasterizer))
            model.apply(WorkbenchCommand::of(A::Derivatives, rasterizer));
    }
}

void WorkbenchPanels::drawAnalysis(WorkbenchModel& model, const WorkbenchPicture& picture) {
    ImGui::TextUnformatted(picture.analysisSummary().c_str());
    const std::vector<float>& profile = picture.analysisProfile();
    if (!profile.empty())
        ImGui::PlotLines("##profile", profile.data(), int(profile.size()), 0, picture.analysisProfileLabel().c_str(),
                         FLT_MAX, FLT_MAX, ImVec2(float(kWorkbenchPanelWidth - 30), 80));
    const WorkbenchShown& s = model.shown();
    if (s.analysis == LiveAnalysisKind::Correlation) {
        if (auto v = enumCombo("show", s.statistic, kLiveStatisticNames); !v.empty())
            model.apply(WorkbenchCommand::of(A::Statistic, 0, v));
        ImGui::TextDisabled("right click: pick the point");
        // The same analysis again: its samples start over.
        if (ImGui::Button("restart the samples"))
            model.apply(WorkbenchCommand::of(A::Analysis, 0, enumName(kLiveAnalysisNames, s.analysis)));
    }
}

void WorkbenchPanels::drawHelp(WorkbenchModel& model) {
    const float panel = model.shown().panel ? float(kWorkbenchPanelWidth) : 0.0f;
    ImGui::SetNextWindowPos(ImVec2(panel + 20, 20), ImGuiCond_Appearing);
    bool open = true;
    ImGui::Begin("Keys (F1)", &open, ImGuiWindowFlags_AlwaysAutoResize);
    if (ImGui::BeginTable("keys", 2)) {
        auto rows = [](const auto& table) {
            for (const KeyHelp& k : table) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(k.keys);
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(k.what);
            }
        };
        if (!model.isShadertoy()) rows(kPatternKeys);
        rows(kCommonKeys);
        ImGui::EndTable();
    }
    if (model.isShadertoy())
        ImGui::TextWrapped("Other keys and the left button go to the program (keyboard texture, iMouse).");
    ImGui::End();
    if (!open) model.apply(WorkbenchCommand::of(A::Help));
}

}  // namespace stochtex
