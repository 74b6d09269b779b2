#include "stochtex/workbench/script.h"

#include <GLFW/glfw3.h>

#include <cctype>
#include <tuple>

#include "stochtex/core/atomic_file.h"
#include "stochtex/image/image_io.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/workbench/live_analysis.h"

namespace stochtex {

WorkbenchCommand WorkbenchCommand::of(Action action, double amount, std::string text) {
    WorkbenchCommand c;
    c.action = action;
    c.amount = amount;
    c.text = std::move(text);
    return c;
}

WorkbenchCommand WorkbenchCommand::at(Action action, double x, double y, double amount) {
    WorkbenchCommand c = of(action, amount);
    c.x = x;
    c.y = y;
    return c;
}

std::pair<int, int> parseKeyChord(const std::string& text) {
    std::string rest;
    for (const char c : text) rest += char(std::tolower(static_cast<unsigned char>(c)));
    int mods = 0;
    for (auto [prefix, bit] : {std::pair{"ctrl+", GLFW_MOD_CONTROL}, {"shift+", GLFW_MOD_SHIFT}})
        if (rest.rfind(prefix, 0) == 0) mods |= bit, rest.erase(0, std::string(prefix).size());
    if (rest.rfind("shift+", 0) == 0) mods |= GLFW_MOD_SHIFT, rest.erase(0, 6);  // "ctrl+shift+z"
    int key = -1;
    if (rest.size() == 1 && std::isalpha(static_cast<unsigned char>(rest[0]))) key = GLFW_KEY_A + (rest[0] - 'a');
    if (rest.size() == 1 && std::isdigit(static_cast<unsigned char>(rest[0]))) key = GLFW_KEY_0 + (rest[0] - '0');
    if (rest.size() >= 2 && rest.size() <= 3 && rest[0] == 'f' && std::isdigit(static_cast<unsigned char>(rest[1]))) {
        const int n = std::stoi(rest.substr(1));
        if (n >= 1 && n <= 12 && std::to_string(n) == rest.substr(1)) key = GLFW_KEY_F1 + n - 1;
    }
    for (auto [name, code] : {std::pair{"tab", GLFW_KEY_TAB},
                              {"escape", GLFW_KEY_ESCAPE},
                              {"space", GLFW_KEY_SPACE},
                              {"enter", GLFW_KEY_ENTER},
                              {"up", GLFW_KEY_UP},
                              {"down", GLFW_KEY_DOWN},
                              {"left", GLFW_KEY_LEFT},
                              {"right", GLFW_KEY_RIGHT},
                              {"[", GLFW_KEY_LEFT_BRACKET},
                              {"]", GLFW_KEY_RIGHT_BRACKET}})
        if (rest == name) key = code;
    if (key < 0)
        throw InputError("unknown key \"" + text +
                         "\" (a letter, a digit, F1-F12, tab, escape, space, enter, "
                         "up, down, left, right, [ or ], after ctrl+ or shift+)");
    return {key, mods};
}

std::vector<WorkbenchStep> parseWorkbenchScript(const nlohmann::json& script, const std::string& source) {
    const JsonReader r(script, source);
    std::vector<WorkbenchStep> steps;
    int frame = 0;
    using A = WorkbenchStep::Action;
    const size_t n = r.arraySize();
    if (n > 100000) r.fail("at most 100000 steps");
    for (size_t i = 0; i < n; ++i) {
        const JsonReader s = r.at(i);
        s.expectObject(
            {"frame",          "zoom",     "at",   "pan",  "filter",    "aniso",     "estimator",  "set",  "value",
             "mode",           "analysis", "view", "tilt", "pick",      "pause",     "screenshot", "save", "record",
             "stop_recording", "undo",     "redo", "key",  "mousedown", "mousemove", "mouseup",    "quit"});
        WorkbenchStep step;
        if (s.has("frame")) {
            const int f = s.integer("frame", 0, 0, 1000000);
            if (f < frame)
                s.at("frame").fail("frames never go back (the step before runs at frame " + std::to_string(frame) +
                                   ")");
            frame = f;
        }
        step.frame = frame;
        int actions = 0;
        auto point = [&](const JsonReader& p) {
            if (p.arraySize() != 2) p.fail("needs [x, y] in pixels");
            step.x = p.at(0).number(-1e6, 1e6);
            step.y = p.at(1).number(-1e6, 1e6);
        };
        if (auto z = s.find("zoom")) {
            ++actions, step.action = A::Zoom, step.amount = z->number(1.0 / 4096, 4096);
            if (auto at = s.find("at"))
                point(*at);
            else
                s.fail("zoom needs \"at\": [x, y], the pixel that stays put");
        }
        if (auto p = s.find("pan")) ++actions, step.action = A::Pan, point(*p);
        // A program's mouse, in its pixels (y up), with ShaderToy's click semantics.
        if (auto p = s.find("mousedown")) ++actions, step.action = A::MouseDown, point(*p);
        if (auto p = s.find("mousemove")) ++actions, step.action = A::MouseMove, point(*p);
        if (auto p = s.find("pick")) ++actions, step.action = A::Pick, point(*p);
        if (auto f = s.find("filter")) {
            ++actions, step.action = A::Filter, step.text = f->choice({"none", "paper", "smooth"});
        }
        if (auto a = s.find("aniso"))
            ++actions, step.action = A::Aniso, step.amount = a->integer(int(anisoParam().min), int(anisoParam().max));
        if (auto e = s.find("estimator"))
            ++actions, step.action = A::Estimator,
                       step.text = enumName(kVarianceEstimatorNames, e->choice(kVarianceEstimatorNames));
        if (auto t = s.find("tilt"))
            ++actions, step.action = A::Tilt, step.amount = t->number(cameraTiltParam().min, cameraTiltParam().max);
        if (auto set = s.find("set")) {
            ++actions, step.action = A::Set, step.text = set->string();
            if (!s.has("value")) s.fail("set needs \"value\"");
            step.value = s.at("value").value();
        }
        if (auto m = s.find("mode"))
            ++actions, step.action = A::Mode, step.text = enumName(kWorkbenchModeNames, m->choice(kWorkbenchModeNames));
        if (auto a = s.find("analysis"))
            ++actions, step.action = A::Analysis,
                       step.text = enumName(kLiveAnalysisNames, a->choice(kLiveAnalysisNames));
        if (auto v = s.find("view"))
            ++actions, step.action = A::View, step.text = enumName(kWorkbenchViewNames, v->choice(kWorkbenchViewNames));
        if (auto k = s.find("key")) {
            ++actions, step.action = A::Key, step.text = k->string();
            try {
                std::tie(step.key, step.mods) = parseKeyChord(step.text);
            } catch (const InputError& e) {
                k->fail(e.what());
            }
        }
        if (auto p = s.find("pause")) ++actions, step.action = A::Pause, step.amount = s.boolean("pause", true);
        for (auto [key, action] : {std::pair{"screenshot", A::Screenshot}, {"save", A::Save}, {"record", A::Record}})
            if (auto f = s.find(key)) {
                ++actions, step.action = action, step.text = f->string();
                if (step.text.empty()) f->fail("needs a file name");
                // Checked now, not when the step runs: a run that cannot write
                // what its script asks for fails before its first frame.
                if (action == A::Screenshot) {
                    try {
                        checkOutputFile(step.text);
                        checkImageOutputFormat(step.text);
                    } catch (const InputError& e) {
                        f->fail(e.what());
                    }
                }
            }
        // Steps that take no value are written `true`.
        for (auto [key, action] : {std::pair{"undo", A::Undo},
                                   {"redo", A::Redo},
                                   {"stop_recording", A::StopRecording},
                                   {"mouseup", A::MouseUp},
                                   {"quit", A::Quit}})
            if (s.has(key)) {
                if (!s.boolean(key, false)) s.at(key).fail("is written true");
                ++actions, step.action = action;
            }
        if (actions != 1)
            s.fail(actions == 0 ? "a step needs one action (zoom, pan, filter, set, screenshot, …)"
                                : "one action per step");
        steps.push_back(std::move(step));
    }
    return steps;
}

}  // namespace stochtex
