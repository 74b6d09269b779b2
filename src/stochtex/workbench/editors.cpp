#include "stochtex/workbench/editors.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "stochtex/pattern/graph_nodes.h"
#include "stochtex/pattern/pattern_members.h"

namespace stochtex {

using nlohmann::json;

bool colourCodes(const json& value, float rgb[3]) {
    if (value.is_string()) {
        const std::string s = value.get<std::string>();
        unsigned r = 0, g = 0, b = 0;
        if (s.size() != 7 || s[0] != '#' || std::sscanf(s.c_str() + 1, "%02x%02x%02x", &r, &g, &b) != 3) return false;
        rgb[0] = float(r) / 255.0f, rgb[1] = float(g) / 255.0f, rgb[2] = float(b) / 255.0f;
        return true;
    }
    if (value.is_array() && value.size() == 3) {
        for (int k = 0; k < 3; ++k) {
            if (!value[size_t(k)].is_number()) return false;
            rgb[k] = value[size_t(k)].get<float>();
        }
        return true;
    }
    return false;
}

std::string colourHex(const float rgb[3]) {
    char s[8];
    auto code = [](float v) { return unsigned(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    std::snprintf(s, sizeof s, "#%02x%02x%02x", code(rgb[0]), code(rgb[1]), code(rgb[2]));
    return s;
}

namespace {

// A new ring or bilobe component at its members' typical values.
json ringComponent(const std::string& shape) {
    const PatternMembers& m = patternMembers();
    json c{{"shape", shape}, {m.frequency.name, m.frequency.typical()}, {m.bandwidth.name, m.bandwidth.typical()}};
    if (shape == "bilobe") c[m.orientation.name] = m.orientation.typical();
    return c;
}

// The widgets of one panel: each reads a member of `object` (at `pointer`)
// and records an edit when the user changes it.
class Fields {
public:
    Fields(const json& object, std::string pointer, std::vector<JsonEdit>& edits)
        : object_(object), pointer_(std::move(pointer)), edits_(edits) {}

    // A number of a parameter table: dragged over [min, dragTop()], typed
    // (Ctrl+click) up to max; the label is its name, the tooltip its description.
    void number(const ParamInfo& p, const char* format = "%.4g") {
        float v = float(object_.is_object() ? object_.value(p.name, p.typical()) : p.typical());
        const float speed = float((p.dragTop() - p.min) / 1000.0);
        // A value typed past the drag range stays where it is until dragged below it.
        const float top = std::max(float(p.dragTop()), v);
        if (ImGui::DragFloat(p.name.c_str(), &v, speed, float(p.min), top, format))
            edit(p.name, json(std::clamp(double(v), p.min, p.max)));
        tooltip(p.description.c_str());
    }
    void integer(const ParamInfo& p) {
        int v = int(object_.is_object() ? object_.value(p.name, (long long)p.typical()) : (long long)p.typical());
        const int lo = int(std::max(p.min, -double(1 << 30)));
        const int top = std::max(int(std::min(p.dragTop(), double(1 << 30))), v);
        if (ImGui::DragInt(p.name.c_str(), &v, 1.0f, lo, top, "%d"))
            edit(p.name, json(std::clamp((long long)v, (long long)p.min, (long long)p.max)));
        tooltip(p.description.c_str());
    }
    void seed(const char* key, const char* label, const char* help = nullptr) {
        uint32_t v = object_.is_object() && object_.contains(key) && object_[key].is_number_unsigned()
                         ? object_[key].get<uint32_t>()
                         : 0;
        if (ImGui::InputScalar(label, ImGuiDataType_U32, &v, nullptr, nullptr, "%u",
                               ImGuiInputTextFlags_EnterReturnsTrue))
            edit(key, json(v));
        tooltip(help);
    }
    // A power of two in the parameter's range (example sizes).
    void powerOfTwo(const ParamInfo& p) {
        const int now = object_.is_object() ? object_.value(p.name, int(p.typical())) : int(p.typical());
        if (ImGui::BeginCombo(p.name.c_str(), std::to_string(now).c_str())) {
            for (int v = int(p.min); v <= int(p.max); v *= 2)
                if (ImGui::Selectable(std::to_string(v).c_str(), v == now) && v != now) edit(p.name, json(v));
            ImGui::EndCombo();
        }
        tooltip(p.description.c_str());
    }
    void boolean(const char* key, const char* label, bool fallback, const char* help = nullptr) {
        bool v = object_.is_object() ? object_.value(key, fallback) : fallback;
        if (ImGui::Checkbox(label, &v)) edit(key, json(v));
        tooltip(help);
    }
    void choice(const char* key, const char* label, const std::vector<std::string>& choices, const std::string& fallback,
                const char* help = nullptr) {
        const std::string now = object_.is_object() && object_.contains(key) && object_[key].is_string()
                                    ? object_[key].get<std::string>()
                                    : fallback;
        if (ImGui::BeginCombo(label, now.c_str())) {
            for (const std::string& c : choices)
                if (ImGui::Selectable(c.c_str(), c == now) && c != now) edit(key, json(c));
            ImGui::EndCombo();
        }
        tooltip(help);
    }
    // fallback: what an absent colour is (null: black).
    void colour(const char* key, const char* label, const json& fallback = nullptr) {
        float rgb[3] = {0, 0, 0};
        if (object_.is_object() && object_.contains(key)) colourCodes(object_[key], rgb);
        else if (!fallback.is_null()) colourCodes(fallback, rgb);
        if (ImGui::ColorEdit3(label, rgb, ImGuiColorEditFlags_NoInputs)) edit(key, json(colourHex(rgb)));
    }
    // An [x, y] point of a painted colormap.
    void point(const char* key, const char* label) {
        if (!object_.is_object() || !object_.contains(key) || !object_[key].is_array() || object_[key].size() != 2)
            return;
        const ParamInfo& c = patternMembers().coordinate;
        float v[2] = {object_[key][0].get<float>(), object_[key][1].get<float>()};
        if (ImGui::DragFloat2(label, v, 0.005f, float(c.min), float(c.max), "%.3f", ImGuiSliderFlags_AlwaysClamp))
            edit(key, json::array({double(v[0]), double(v[1])}));
    }
    void text(const char* key, const char* label) {
        std::string v = object_.is_object() ? object_.value(key, std::string()) : std::string();
        char buffer[512];
        std::snprintf(buffer, sizeof buffer, "%s", v.c_str());
        if (ImGui::InputText(label, buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue))
            edit(key, json(std::string(buffer)));
    }
    void edit(const std::string& key, json value) { edits_.push_back({pointer_ + "/" + key, std::move(value)}); }

private:
    static void tooltip(const char* help) {
        if (help && *help && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", help);
    }
    const json& object_;
    std::string pointer_;
    std::vector<JsonEdit>& edits_;
};

// Opens the next header or tree node when everything is to be shown.
void expand(const EditorPreviews& previews) {
    if (previews.expandAll) ImGui::SetNextItemOpen(true);
}

// A NOISE's spectrum components (or a spectral_noise node's).
void componentsEditor(const json& components, const std::string& pointer, std::vector<JsonEdit>& edits) {
    if (!components.is_array()) return;
    for (size_t i = 0; i < components.size(); ++i) {
        const json& c = components[i];
        const std::string at = pointer + "/" + std::to_string(i);
        ImGui::PushID(int(i));
        Fields f(c, at, edits);
        const std::string shape = c.value("shape", std::string("lowpass"));
        // Another shape has other members: the component is replaced whole, keeping its weight.
        if (ImGui::BeginCombo("shape", shape.c_str())) {
            for (const char* s : {"lowpass", "ring", "bilobe"})
                if (ImGui::Selectable(s, shape == s) && shape != s) {
                    const ParamInfo& cutoff = patternMembers().cutoff;
                    json next = std::string(s) == "lowpass" ? json{{"shape", s}, {cutoff.name, cutoff.typical()}}
                                                            : ringComponent(s);
                    if (c.contains("weight")) next["weight"] = c["weight"];
                    edits.push_back({at, next});
                }
            ImGui::EndCombo();
        }
        if (shape == "lowpass") {
            f.number(patternMembers().cutoff, "%.2f");
        } else {
            f.number(patternMembers().frequency, "%.2f");
            f.number(patternMembers().bandwidth, "%.2f");
            if (shape == "bilobe") f.number(patternMembers().orientation, "%.1f°");
        }
        f.number(patternMembers().weight, "%.3f");
        if (components.size() > 1 && ImGui::SmallButton("remove component")) edits.push_back({at, nullptr, true});
        ImGui::Separator();
        ImGui::PopID();
    }
    if (ImGui::SmallButton("add component"))
        edits.push_back({pointer + "/" + std::to_string(components.size()), ringComponent("ring")});
}

void noiseEditor(const json& noise, const std::string& pointer, std::vector<JsonEdit>& edits) {
    if (!noise.is_object()) {
        ImGui::TextDisabled("%s", noise.dump().c_str());
        return;
    }
    Fields f(noise, pointer, edits);
    if (noise.value("type", std::string()) == "image") {
        f.text("path", "image");
        f.boolean("gaussianize", "gaussianize", true, "blend in Gaussian space, keep the histogram");
        return;
    }
    f.powerOfTwo(patternMembers().noiseSize);
    f.number(patternMembers().noiseMean);
    f.number(patternMembers().noiseStddev);
    componentsEditor(noise.value("components", json::array()), pointer + "/components", edits);
}

// A painted colormap's shapes, and painting on its canvas.
void colormapEditor(const json& colormap, const std::string& pointer, const EditorPreviews& previews, PaintBrush& brush,
                    std::vector<JsonEdit>& edits) {
    if (!colormap.is_object()) return;
    Fields f(colormap, pointer, edits);
    const std::string type = colormap.value("type", std::string());
    f.choice("transfer", "transfer", {"srgb", "linear"}, "srgb", "colours as sRGB codes (colour) or as data");
    f.integer(patternMembers().colormapResolution);
    if (previews.colormap && pointer == previews.colormapPointer) {
        const ImVec2 at = ImGui::GetCursorScreenPos();
        // The canvas image holds y = 1 in its top row (ColormapTable::toImage).
        ImGui::Image(previews.colormap, ImVec2(previews.canvasSize, previews.canvasSize));
        const ImVec2 m = ImGui::GetMousePos();
        const double x = (m.x - at.x) / previews.canvasSize, y = 1.0 - (m.y - at.y) / previews.canvasSize;
        const json& shapes = colormap.value("shapes", json::array());
        if (type == "painted" && brush.shape == 3) {
            if (ImGui::IsItemClicked() && previews.painted) {
                brush.moving = -1;
                for (size_t i = previews.painted->shapes.size(); i-- > 0;)
                    if (previews.painted->shapes[i].contains(x, y)) {
                        brush.moving = int(i);
                        break;
                    }
            }
            if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) brush.moving = -1;
            const ImVec2 d = ImGui::GetIO().MouseDelta;
            if (brush.moving >= 0 && size_t(brush.moving) < shapes.size() && (d.x != 0 || d.y != 0)) {
                const double dx = d.x / previews.canvasSize, dy = -d.y / previews.canvasSize;
                json moved = shapes[size_t(brush.moving)];
                auto shift = [&](json& p) { p = json::array({p[0].get<double>() + dx, p[1].get<double>() + dy}); };
                for (const char* key : {"min", "max", "center", "point"})
                    if (moved.contains(key)) shift(moved[key]);
                if (moved.contains("points"))
                    for (json& p : moved["points"]) shift(p);
                edits.push_back({pointer + "/shapes/" + std::to_string(brush.moving), moved});
            }
        } else if (type == "painted" && ImGui::IsItemClicked()) {
            const std::string colour = colourHex(brush.colour);
            const double r = brush.radius;
            json shape = brush.shape == 0   ? json{{"shape", "disc"}, {"center", {x, y}}, {"radius", r}}
                         : brush.shape == 1 ? json{{"shape", "ring"}, {"center", {x, y}}, {"inner", 0.6 * r}, {"outer", r}}
                                            : json{{"shape", "rectangle"}, {"min", {x - r, y - r}}, {"max", {x + r, y + r}}};
            shape["colour"] = colour;
            edits.push_back({pointer + "/shapes/" + std::to_string(shapes.size()), shape});
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(type != "painted"    ? "the colormap H (x right, y up)"
                              : brush.shape == 3 ? "drag a shape to move it (x right, y up)"
                                                 : "click: paint the brush's shape here (x right, y up)");
    }
    if (type == "painted") {
        ImGui::Combo("brush", &brush.shape, "disc\0ring\0square\0move\0");
        ImGui::SliderFloat("brush size", &brush.radius, 0.005f, 0.5f, "%.3f");
        ImGui::ColorEdit3("brush colour", brush.colour, ImGuiColorEditFlags_NoInputs);
        f.colour("background", "background");
        const json& shapes = colormap.value("shapes", json::array());
        for (size_t i = 0; i < shapes.size(); ++i) {
            const json& s = shapes[i];
            const std::string at = pointer + "/shapes/" + std::to_string(i);
            ImGui::PushID(int(i));
            Fields g(s, at, edits);
            g.colour("colour", "##colour");
            ImGui::SameLine();
            const std::string kind = s.value("shape", std::string());
            expand(previews);
            if (ImGui::TreeNode("shape", "%zu: %s", i, kind.c_str())) {
                g.point("min", "min");
                g.point("max", "max");
                g.point("center", "center");
                g.point("point", "point");
                const PatternMembers& m = patternMembers();
                for (const ParamInfo* p : {&m.radius, &m.inner, &m.outer, &m.width})
                    if (s.contains(p->name)) g.number(*p, "%.3f");
                if (s.contains("angle")) g.number(patternMembers().angle, "%.1f°");
                if (ImGui::SmallButton("remove")) edits.push_back({at, nullptr, true});
                ImGui::TreePop();
            }
            ImGui::PopID();
        }
    } else if (type == "phasor") {
        f.choice("profile", "profile", {"sine", "sawtooth", "square", "image"}, "sine");
        if (colormap.value("profile", std::string()) == "square") f.number(patternMembers().duty);
        const json& palette = colormap.value("palette", json::array());
        for (size_t i = 0; i < palette.size(); ++i) {
            ImGui::PushID(int(i));
            Fields g(palette, pointer + "/palette", edits);
            float rgb[3] = {0, 0, 0};
            colourCodes(palette[i], rgb);
            if (ImGui::ColorEdit3("##p", rgb, ImGuiColorEditFlags_NoInputs)) g.edit(std::to_string(i), colourHex(rgb));
            ImGui::SameLine();
            ImGui::PopID();
        }
        ImGui::NewLine();
    } else if (type == "image") {
        f.text("path", "image");
    }
}

// A choice among node ids (an input's source, the output); an edit when another is picked.
void nodeChoice(const char* label, const std::string& now, const std::vector<std::string>& ids,
                const std::string& pointer, const char* help, std::vector<JsonEdit>& edits) {
    if (ImGui::BeginCombo(label, now.empty() ? "?" : now.c_str())) {
        for (const std::string& id : ids)
            if (ImGui::Selectable(id.c_str(), id == now) && id != now) edits.push_back({pointer, json(id)});
        ImGui::EndCombo();
    }
    if (help && *help && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", help);
}

// One graph node: which node feeds each input, a widget per parameter of
// its table entry, and removing it.
void nodeEditor(const json& graph, const std::string& id, const json& node, const std::string& pointer,
                const EditorPreviews& previews, PaintBrush& brush, std::vector<JsonEdit>& edits) {
    const NodeInfo* info = findGraphNode(node.value("type", std::string()));
    if (!info) return;
    Fields f(node, pointer, edits);
    for (const PortInfo& port : info->inputs)
        nodeChoice(port.name.c_str(), node.value(port.name, std::string()), nodesFitting(graph, port.type, id),
                   pointer + "/" + port.name, port.description.c_str(), edits);
    for (const ParamInfo& p : info->params) {
        const char* help = p.description.c_str();
        const json fallback = p.fallback.is_null() ? p.sample : p.fallback;
        switch (p.type) {
            case ParamType::Number: f.number(p); break;
            case ParamType::Integer: f.integer(p); break;
            case ParamType::Seed: f.seed(p.name.c_str(), p.name.c_str(), help); break;
            case ParamType::Boolean:
                f.boolean(p.name.c_str(), p.name.c_str(), fallback.is_boolean() && fallback.get<bool>(), help);
                break;
            case ParamType::Choice:
                f.choice(p.name.c_str(), p.name.c_str(), p.choices, fallback.is_string() ? fallback.get<std::string>() : "",
                         help);
                break;
            case ParamType::Path: f.text(p.name.c_str(), p.name.c_str()); break;
            case ParamType::Colour: f.colour(p.name.c_str(), p.name.c_str(), fallback); break;
            case ParamType::Components:
                expand(previews);
                if (ImGui::TreeNode(p.name.c_str()))
                    componentsEditor(node.value(p.name, json::array()), pointer + "/" + p.name, edits), ImGui::TreePop();
                break;
            case ParamType::Colormap:
                expand(previews);
                if (ImGui::TreeNode(p.name.c_str()))
                    colormapEditor(node.value(p.name, json::object()), pointer + "/" + p.name, previews, brush, edits),
                        ImGui::TreePop();
                break;
            case ParamType::Curve: {
                const json points = node.value(p.name, fallback);
                if (!points.is_array()) break;
                ImGui::TextUnformatted(p.name.c_str());
                for (size_t i = 0; i < points.size(); ++i) {
                    ImGui::PushID(int(i));
                    float v[2] = {points[i][0].get<float>(), points[i][1].get<float>()};
                    if (ImGui::DragFloat2("##pt", v, 0.002f, -10.0f, 10.0f, "%.3f")) {
                        json next = points;
                        next[i] = {double(v[0]), double(v[1])};
                        f.edit(p.name, next);
                    }
                    ImGui::PopID();
                }
                break;
            }
        }
    }
    // The parser refuses removing a node another reads, or the output, with its message.
    if (ImGui::SmallButton("remove node")) edits.push_back({pointer, nullptr, true});
}

// The graph's structure: its output, and adding a node of any type.
void graphEditor(const json& graph, NodeAddition& addition, std::vector<JsonEdit>& edits) {
    const std::vector<NodeInfo>& nodes = graphNodes();
    nodeChoice("output", graph.value("output", std::string()), nodesFitting(graph, PortType::Colour), "/output",
               "the node whose colour the pattern shows", edits);
    addition.type = std::clamp(addition.type, 0, int(nodes.size()) - 1);
    const NodeInfo& chosen = nodes[size_t(addition.type)];
    if (ImGui::BeginCombo("new node", chosen.name.c_str())) {
        for (size_t k = 0; k < nodes.size(); ++k)
            if (ImGui::Selectable(nodes[k].name.c_str(), int(k) == addition.type)) addition.type = int(k);
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", chosen.description.c_str());
    const bool needsImage = std::any_of(chosen.params.begin(), chosen.params.end(),
                                        [](const ParamInfo& p) { return p.type == ParamType::Path; });
    if (needsImage) ImGui::InputText("image", addition.image, sizeof addition.image);
    if (ImGui::SmallButton("add node")) edits.push_back(addGraphNode(graph, chosen, addition.image));
}

}  // namespace

std::vector<std::string> nodesFitting(const json& graph, PortType type, const std::string& except) {
    std::vector<std::string> ids;
    if (!graph.contains("nodes") || !graph["nodes"].is_object()) return ids;
    for (const auto& [id, node] : graph["nodes"].items()) {
        const NodeInfo* info = node.is_object() ? findGraphNode(node.value("type", std::string())) : nullptr;
        if (info && info->output == type && id != except) ids.push_back(id);
    }
    return ids;
}

JsonEdit addGraphNode(const json& graph, const NodeInfo& node, const std::string& imagePath) {
    static const json none = json::object();
    const json& nodes = graph.contains("nodes") && graph["nodes"].is_object() ? graph["nodes"] : none;
    std::string id;
    for (int k = 1; id.empty() || nodes.contains(id); ++k) id = node.name + "_" + std::to_string(k);
    json added = nodeWithSampleParams(node, imagePath);
    for (const PortInfo& port : node.inputs) {
        std::vector<std::string> fitting = nodesFitting(graph, port.type);
        // A spectral noise first: a Gaussian source is a valid input of every
        // field port (a channel of a Gaussianized exemplar is not, for a linear node).
        std::stable_partition(fitting.begin(), fitting.end(), [&](const std::string& id) {
            return nodes[id].value("type", std::string()) == "spectral_noise";
        });
        if (!fitting.empty()) added[port.name] = fitting.front();
    }
    return {"/nodes/" + id, added};
}

std::vector<JsonEdit> patternEditor(const json& pattern, const EditorPreviews& previews, EditorState& state) {
    PaintBrush& brush = state.brush;
    std::vector<JsonEdit> edits;
    Fields header(pattern, "", edits);
    expand(previews);
    if (ImGui::CollapsingHeader("Pattern", ImGuiTreeNodeFlags_DefaultOpen)) {
        header.seed("seed", "seed", "tile offsets and (unless a noise sets its own) the examples (Enter applies)");
        header.number(patternMembers().scale, "%.3f");
        header.choice("offsets", "offsets", {"independent", "shared"}, "independent");
    }
    if (pattern.contains("nodes") && pattern["nodes"].is_object()) {
        expand(previews);
        if (ImGui::CollapsingHeader("Graph nodes", ImGuiTreeNodeFlags_DefaultOpen)) {
            graphEditor(pattern, state.addition, edits);
            for (const auto& [id, node] : pattern["nodes"].items()) {
                ImGui::PushID(id.c_str());
                expand(previews);
                if (ImGui::TreeNode(id.c_str(), "%s (%s)", id.c_str(), node.value("type", std::string("?")).c_str())) {
                    nodeEditor(pattern, id, node, "/nodes/" + id, previews, brush, edits);
                    ImGui::TreePop();
                }
                ImGui::PopID();
            }
        }
        return edits;
    }
    for (int k = 0; k < 2; ++k) {
        const char* axis = k == 0 ? "noise_x" : "noise_y";
        if (!pattern.contains(axis)) continue;
        expand(previews);
        if (ImGui::CollapsingHeader(axis)) {
            ImGui::PushID(axis);
            if (previews.example[k]) {
                // The example (as the noise command writes it) and its power spectrum (zero frequency at the centre).
                ImGui::Image(previews.example[k], ImVec2(128, 128));
                if (ImGui::IsItemHovered()) ImGui::SetTooltip("the example");
                ImGui::SameLine();
                ImGui::Image(previews.spectrum[k], ImVec2(128, 128));
                if (ImGui::IsItemHovered()) ImGui::SetTooltip("its power spectrum, zero frequency at the centre");
            }
            noiseEditor(pattern[axis], std::string("/") + axis, edits);
            ImGui::PopID();
        }
    }
    if (pattern.contains("colormap")) expand(previews);
    if (pattern.contains("colormap") && ImGui::CollapsingHeader("Colormap", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::PushID("colormap");
        colormapEditor(pattern["colormap"], "/colormap", previews, brush, edits);
        ImGui::PopID();
    }
    const bool normalMap = pattern.contains("normal_map") && pattern["normal_map"].is_object();
    if (normalMap) expand(previews);
    if (normalMap && ImGui::CollapsingHeader("Normal map")) {
        Fields n(pattern["normal_map"], "/normal_map", edits);
        n.number(patternMembers().amplitude);
        n.number(patternMembers().roughness);
        n.number(patternMembers().specular);
        n.colour("albedo", "albedo");
    }
    return edits;
}

}  // namespace stochtex
