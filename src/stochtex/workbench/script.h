#pragma once
// Scripted steps for the workbench window: what a person does with the
// mouse and the panels, as data, so that a test (or a demo) can drive the
// window under a virtual display. Each step runs before the frame it names
// is drawn and goes through the same calls as the window's controls.
//
//   [{"frame": 2, "zoom": 2, "at": [80, 60]},       // wheel zoom about a pixel
//    {"frame": 3, "pan": [10, -4]},                   // drag by pixels
//    {"frame": 4, "filter": "paper"}, {"aniso": 4},   // filter mode, anisotropy
//    {"estimator": "sub-probes"},                     // the footprint estimator
//    {"frame": 5, "set": "/colormap/background", "value": "#203040"},  // an edit
//    {"undo": true}, {"redo": true},                  // Ctrl+Z, Ctrl+Y
//    {"mode": "split"}, {"analysis": "flow"}, {"pick": [40, 30]},
//    {"view": "plane"}, {"tilt": 60}, {"pause": true},
//    {"screenshot": "a.png"}, {"save": "edited.json"},
//    {"record": "clip.mp4"}, {"stop_recording": true},
//    {"key": "V"}, {"key": "ctrl+z"},                 // a key tapped within one frame
//    {"mousedown": [40, 30]}, {"mousemove": [50, 30]}, {"mouseup": true},  // a program's iMouse, its pixels, y up
//    {"quit": true}]
//
// A step without "frame" runs at the frame of the step before it; frames
// never go back. A step does one action.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "stochtex/core/enum_names.h"

namespace stochtex {

// What the picture area shows (thesis Figure 3.2): the texture, the live
// analysis, both side by side, the texture's left part and the analysis's
// right part split at a movable line, or the analysis blended over it.
enum class WorkbenchMode { Texture, Analysis, SideBySide, Split, Overlay };
inline const EnumNames<WorkbenchMode> kWorkbenchModeNames{{"texture", WorkbenchMode::Texture},
                                                          {"analysis", WorkbenchMode::Analysis},
                                                          {"side-by-side", WorkbenchMode::SideBySide},
                                                          {"split", WorkbenchMode::Split},
                                                          {"overlay", WorkbenchMode::Overlay}};
// How a pattern is seen: the 2D zoom view, the perspective plane, or on a 3D object.
// Mesh: the user's mesh (view --mesh FILE), offered only when one is loaded.
enum class WorkbenchView { Zoom, Plane, Sphere, Torus, Mesh };
inline const EnumNames<WorkbenchView> kWorkbenchViewNames{{"zoom", WorkbenchView::Zoom},
                                                          {"plane", WorkbenchView::Plane},
                                                          {"sphere", WorkbenchView::Sphere},
                                                          {"torus", WorkbenchView::Torus},
                                                          {"mesh", WorkbenchView::Mesh}};

// One thing done to the workbench: what a key, the mouse, a panel's control
// or a script step asks for, applied by one function (WorkbenchModel::apply).
struct WorkbenchCommand {
    enum class Action {
        Zoom,
        Pan,
        Filter,
        Aniso,
        Estimator,
        Set,
        Undo,
        Redo,
        Mode,
        Analysis,
        View,
        Tilt,
        Pick,
        Pause,
        Screenshot,
        Save,
        Record,
        StopRecording,
        Key,
        MouseDown,
        MouseMove,
        MouseUp,
        Quit,
        // The window's alone (no script step names them; a script taps their keys):
        Response,
        Derivatives,
        Split,
        Opacity,
        Statistic,
        Reload,
        SaveDefault,
        Panel,
        Help,
        ToggleRecording,
        RestartProgram
    };
    Action action = Action::Quit;
    double x = 0, y = 0,
           amount = 1;      // zoom: factor at (x, y); pan, pick, mousedown, mousemove: (x, y); aniso, tilt: amount
    int key = 0, mods = 0;  // key: the GLFW key and modifier bits, pressed and released in one frame
    std::string text;       // a name (filter, mode, analysis, view, response, …), a JSON pointer or a file
    nlohmann::json value;   // set: the value

    // A command of `action` with the amount and the name it takes (the
    // panel's widgets, the keys, a script's steps).
    static WorkbenchCommand of(Action action, double amount = 1, std::string text = {});
    // One at a point (x, y): zoom (amount: its factor), pan (x, y: the move
    // in pixels), split (amount), pick, the mouse.
    static WorkbenchCommand at(Action action, double x, double y, double amount = 1);
};

// A command of a script, run before the frame it names is drawn.
struct WorkbenchStep : WorkbenchCommand {
    int frame = 0;
};

// A key as a script names it: a letter, a digit, F1–F12, tab, escape,
// space, enter, up, down, left, right, [ or ], after any of "ctrl+",
// "shift+" (any case). The GLFW key and modifier bits; InputError otherwise.
std::pair<int, int> parseKeyChord(const std::string& text);

// InputError naming the source and the JSON pointer of a bad step.
std::vector<WorkbenchStep> parseWorkbenchScript(const nlohmann::json& script, const std::string& source);

}  // namespace stochtex
