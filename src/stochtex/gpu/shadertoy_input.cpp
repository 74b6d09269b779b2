#include "stochtex/gpu/shadertoy_input.h"

#include <algorithm>
#include <cmath>
#include <regex>

#include "stochtex/core/error.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/pattern_parts.h"

namespace stochtex {

namespace {

constexpr int kMaxFrame = 1000000;
constexpr float kMaxPixels = 1e6f;

bool isMouse(ShadertoyInput::Kind k) {
    return k == ShadertoyInput::Kind::MouseDown || k == ShadertoyInput::Kind::MouseMove;
}

}  // namespace

void validateShadertoyInput(const ShadertoyInput& e) {
    const bool key = e.kind == ShadertoyInput::Kind::KeyDown || e.kind == ShadertoyInput::Kind::KeyUp;
    if (key && (e.key < 0 || e.key >= ShadertoyInputState::kKeys))
        throw InputError::parameter("input", "key codes are 0–255 (JavaScript keyCode), got " + std::to_string(e.key));
    if (e.frame < 0 || e.frame > kMaxFrame)
        throw InputError::parameter("input",
                                    "an event's frame must be in [0, 1000000], got " + std::to_string(e.frame));
    if (isMouse(e.kind) &&
        !(std::isfinite(e.x) && std::isfinite(e.y) && std::abs(e.x) <= kMaxPixels && std::abs(e.y) <= kMaxPixels))
        throw InputError::parameter("input", "a mouse position must be finite pixels within ±1e6, got (" +
                                                 formatValue(e.x) + ", " + formatValue(e.y) + ")");
}

void ShadertoyInputState::reset(const std::vector<int>& heldKeys, const std::array<float, 4>& mouse) {
    keys_.fill(0.0f);
    for (const int key : heldKeys) setKey(key, true);
    mouse_ = mouse;
    keyboardChanged_ = true;
}

void ShadertoyInputState::setKey(int keyCode, bool down) {
    if (keyCode < 0 || keyCode >= kKeys)
        throw InputError::parameter("key", "key codes are 0–255 (JavaScript keyCode), got " + std::to_string(keyCode));
    float& held = keys_[size_t(keyCode)];
    if (down && held == 0.0f) {
        keys_[size_t(kKeys + keyCode)] = 1.0f;
        float& toggled = keys_[size_t(2 * kKeys + keyCode)];
        toggled = 1.0f - toggled;
    }
    held = down ? 1.0f : 0.0f;
    keyboardChanged_ = true;
}

void ShadertoyInputState::mouseDown(float x, float y) { mouse_ = {x, y, x, y}; }

void ShadertoyInputState::mouseMove(float x, float y) {
    if (mouse_[2] > 0.0f) mouse_[0] = x, mouse_[1] = y;  // only a held button drags
}

void ShadertoyInputState::mouseUp() {
    mouse_[2] = -std::abs(mouse_[2]);
    mouse_[3] = -std::abs(mouse_[3]);
}

void ShadertoyInputState::scaleMouse(float sx, float sy) {
    for (int k = 0; k < 4; ++k) mouse_[size_t(k)] *= k % 2 == 0 ? sx : sy;
}

void ShadertoyInputState::endFrame() {
    if (std::any_of(keys_.begin() + kKeys, keys_.begin() + 2 * kKeys, [](float v) { return v != 0.0f; })) {
        std::fill(keys_.begin() + kKeys, keys_.begin() + 2 * kKeys, 0.0f);
        keyboardChanged_ = true;
    }
    mouse_[3] = -std::abs(mouse_[3]);  // "just clicked" is one frame
}

bool ShadertoyInputState::takeKeyboardChange() { return std::exchange(keyboardChanged_, false); }

void ShadertoyInputState::apply(const ShadertoyInput& e) {
    switch (e.kind) {
        case ShadertoyInput::Kind::KeyDown: setKey(e.key, true); break;
        case ShadertoyInput::Kind::KeyUp: setKey(e.key, false); break;
        case ShadertoyInput::Kind::MouseDown: mouseDown(e.x, e.y); break;
        case ShadertoyInput::Kind::MouseMove: mouseMove(e.x, e.y); break;
        case ShadertoyInput::Kind::MouseUp: mouseUp(); break;
    }
}

int shadertoyFrameAt(double time, double fps, double startTime) {
    const double frames = (time - startTime) * fps;
    if (!(std::isfinite(time) && frames > -1e-6 && frames <= kMaxFrame))
        throw InputError::parameter("time", "an event's time must be at or after the start (" + formatValue(startTime) +
                                                " s) and within 10⁶ frames, got " + formatValue(time));
    return int(std::ceil(frames - 1e-6));  // the frame whose iTime is the time, despite rounding
}

std::vector<ShadertoyInput> parseShadertoyInputs(const JsonReader& steps, double fps, double startTime) {
    std::vector<ShadertoyInput> out;
    const size_t n = steps.arraySize();
    int frame = 0;
    for (size_t i = 0; i < n; ++i) {
        const JsonReader s = steps.at(i);
        s.expectObject({"frame", "time", "keydown", "keyup", "mousedown", "mousemove", "mouseup"});
        if (s.has("frame") && s.has("time")) s.fail("give \"frame\" or \"time\", not both");
        const int at = s.has("frame") ? s.integer("frame", 0, 0, kMaxFrame)
                       : s.has("time") ? [&] {
                             const JsonReader t = s.at("time");
                             try {
                                 return shadertoyFrameAt(t.number(-1e9, 1e9), fps, startTime);
                             } catch (const InputError& e) {
                                 t.fail(e.what());
                             }
                         }()
                                       : frame;
        if (at < frame)
            s.fail("frames never go back: this step is at frame " + std::to_string(at) + ", after a step at frame " +
                   std::to_string(frame));
        frame = at;
        ShadertoyInput e;
        e.frame = frame;
        int actions = 0;
        for (const auto& [name, kind] : kShadertoyInputNames) {
            const auto v = s.find(name);
            if (!v) continue;
            ++actions;
            e.kind = kind;
            if (kind == ShadertoyInput::Kind::KeyDown || kind == ShadertoyInput::Kind::KeyUp) {
                e.key = v->integer(0, ShadertoyInputState::kKeys - 1);
            } else if (kind == ShadertoyInput::Kind::MouseUp) {
                if (!s.boolean(name, false)) v->fail("is written true");
            } else {
                if (v->arraySize() != 2) v->fail("needs [x, y] in pixels, y up");
                e.x = float(v->at(size_t(0)).number(-kMaxPixels, kMaxPixels));
                e.y = float(v->at(size_t(1)).number(-kMaxPixels, kMaxPixels));
            }
        }
        if (actions != 1)
            s.fail(actions == 0 ? "a step needs one event (keydown, keyup, mousedown, mousemove, mouseup)"
                                : "one event per step");
        out.push_back(e);
    }
    return out;
}

std::vector<ShadertoyInput> loadShadertoyInputs(const std::string& path, double fps, double startTime) {
    const nlohmann::json j = readJsonFile(path);
    return parseShadertoyInputs(JsonReader(j, path), fps, startTime);
}

ShadertoyInput parseShadertoyInputText(const std::string& text, double fps, double startTime) {
    static const std::regex form(
        R"(((?:\d+)|(?:\d+(?:\.\d*)?|\.\d+)s):(keydown|keyup|mousedown|mousemove|mouseup)(?::([^:]*))?)");
    std::smatch m;
    const auto bad = [&](const std::string& why) { throw InputError::parameter("event", "\"" + text + "\": " + why); };
    if (!std::regex_match(text, m, form))
        bad("expected FRAME:EVENT[:VALUE] (e.g. 12:keydown:32, 0:mousedown:100,50, 1.5s:mouseup), EVENT one of " +
            canonicalNames(kShadertoyInputNames, ", "));
    ShadertoyInput e;
    const std::string when = m[1].str();
    try {
        e.frame = when.ends_with('s') ? shadertoyFrameAt(std::stod(when), fps, startTime)
                                      : (when.size() > 7 ? kMaxFrame + 1 : std::stoi(when));
    } catch (const InputError& err) {
        bad(err.what());
    }
    e.kind = *findEnum(kShadertoyInputNames, m[2].str());
    const std::string value = m[3].str();
    const std::regex integer(R"(\d{1,3})"), point(R"((-?\d+(?:\.\d*)?),(-?\d+(?:\.\d*)?))");
    std::smatch v;
    switch (e.kind) {
        case ShadertoyInput::Kind::KeyDown:
        case ShadertoyInput::Kind::KeyUp:
            if (!std::regex_match(value, integer)) bad("a key event takes a JavaScript keyCode 0–255 (e.g. 32)");
            e.key = std::stoi(value);
            break;
        case ShadertoyInput::Kind::MouseDown:
        case ShadertoyInput::Kind::MouseMove:
            if (!std::regex_match(value, v, point) || v[1].length() > 12 || v[2].length() > 12)
                bad("a mouse event takes X,Y in pixels, y up (e.g. 100,50)");
            e.x = std::stof(v[1].str());
            e.y = std::stof(v[2].str());
            break;
        case ShadertoyInput::Kind::MouseUp:
            if (m[3].matched) bad("mouseup takes no value");
            break;
    }
    try {
        validateShadertoyInput(e);
    } catch (const InputError& err) {
        bad(err.what());
    }
    return e;
}

}  // namespace stochtex
