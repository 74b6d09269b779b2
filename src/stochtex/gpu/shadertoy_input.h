#pragma once
// A ShaderToy program's keyboard and mouse (issue "Run real ShaderToy
// programs as published", item 5): the state a browser gives a shader, the
// events that change it, and a timeline of events at given frames. No GL:
// ShadertoyHost (gpu/shadertoy.h) uploads the state before every frame.
//
// ShaderToy's semantics, which shaders' "just clicked" and "dragging" logic
// relies on:
// * iMouse.xy is where the button is held (it keeps the last position after
//   the release; a move with the button up changes nothing);
// * iMouse.zw is where it went down: z is positive while the button is held
//   and negative after the release; w is positive only on the frame the
//   button went down, negative on every later one.
// * The keyboard texture (256 × 3, by JavaScript keyCode): row 0 a key held,
//   row 1 pressed on this frame only, row 2 toggled by every press.
//
// A timeline is a JSON array of steps, each one event at a frame or a time:
//   [{"frame": 0, "mousedown": [100, 50]},   // pixels, y up
//    {"frame": 5, "mousemove": [120, 60]},
//    {"time": 0.5, "mouseup": true},          // the first frame whose iTime ≥ 0.5
//    {"frame": 30, "keydown": 32}, {"frame": 31, "keyup": 32}]
// A step without "frame" or "time" happens at the frame of the step before
// it; frames never go back. The same events as text (the --event flag):
// "FRAME:keydown:CODE", "FRAME:mousedown:X,Y", "FRAME:mousemove:X,Y",
// "FRAME:mouseup", FRAME a frame number or a time "1.5s".
#include <array>
#include <string>
#include <vector>

#include "stochtex/core/enum_names.h"

namespace stochtex {

class JsonReader;

struct ShadertoyInput {
    enum class Kind { KeyDown, KeyUp, MouseDown, MouseMove, MouseUp };
    int frame = 0;  // happens before this frame (iFrame) renders
    Kind kind = Kind::KeyDown;
    int key = 0;         // KeyDown, KeyUp: JavaScript keyCode, 0–255
    float x = 0, y = 0;  // MouseDown, MouseMove: pixels, y up
};
inline const EnumNames<ShadertoyInput::Kind> kShadertoyInputNames{{"keydown", ShadertoyInput::Kind::KeyDown},
                                                                  {"keyup", ShadertoyInput::Kind::KeyUp},
                                                                  {"mousedown", ShadertoyInput::Kind::MouseDown},
                                                                  {"mousemove", ShadertoyInput::Kind::MouseMove},
                                                                  {"mouseup", ShadertoyInput::Kind::MouseUp}};

// InputError naming `input` (or `key`): a key code outside 0–255, a frame
// outside [0, 10⁶], a position that is not finite or beyond ±10⁶ pixels.
void validateShadertoyInput(const ShadertoyInput& input);

class ShadertoyInputState {
public:
    static constexpr int kKeys = 256;
    // Keys held (down and toggled, pressed on the next frame) and iMouse as given.
    void reset(const std::vector<int>& heldKeys, const std::array<float, 4>& mouse);
    void apply(const ShadertoyInput& input);
    void setKey(int keyCode, bool down);
    void mouseDown(float x, float y);
    void mouseMove(float x, float y);
    void mouseUp();
    // iMouse as it is, without click semantics (a state given by hand).
    void setMouse(const std::array<float, 4>& mouse) { mouse_ = mouse; }
    // The mouse in pixels of a resized frame.
    void scaleMouse(float sx, float sy);
    // After a frame: a key's "pressed" and the click's positive w last one frame.
    void endFrame();

    const std::array<float, 3 * kKeys>& keyboard() const { return keys_; }
    const std::array<float, 4>& mouse() const { return mouse_; }
    // Whether the keyboard changed since the last call (the host uploads it then).
    bool takeKeyboardChange();

private:
    std::array<float, 3 * kKeys> keys_{};  // rows: down, pressed this frame, toggled
    std::array<float, 4> mouse_{};
    bool keyboardChanged_ = true;
};

// The frame of an event at `time` seconds: the first whose iTime = start +
// frame / fps is at or after it. InputError naming `time` before the start.
int shadertoyFrameAt(double time, double fps, double startTime);

// A timeline (the JSON array above), in order of frame. InputError naming
// the source and the step's JSON pointer.
std::vector<ShadertoyInput> parseShadertoyInputs(const JsonReader& steps, double fps, double startTime);
std::vector<ShadertoyInput> loadShadertoyInputs(const std::string& path, double fps, double startTime);
// One event as text ("12:keydown:32", "1.5s:mousedown:100,50"); InputError naming `event`.
ShadertoyInput parseShadertoyInputText(const std::string& text, double fps, double startTime);

}  // namespace stochtex
