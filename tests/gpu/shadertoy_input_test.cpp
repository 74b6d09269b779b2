// A ShaderToy program's keyboard and mouse (gpu/shadertoy_input.h) without
// GL: ShaderToy's click semantics frame by frame, the timeline's JSON and
// text forms, and their errors.
#include "stochtex/gpu/shadertoy_input.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "stochtex/core/error.h"
#include "stochtex/pattern/json_reader.h"

namespace stochtex {
namespace {

using Mouse = std::array<float, 4>;
using K = ShadertoyInput::Kind;

// iMouse.w is positive on the frame the button goes down only; z is
// positive while it is held and negative after the release; xy follow a
// held button and keep the last position after it.
TEST(ShadertoyInput, MouseFollowsShadertoysClickSemantics) {
    ShadertoyInputState s;
    s.reset({}, {});
    EXPECT_EQ(s.mouse(), (Mouse{0, 0, 0, 0}));
    s.mouseMove(5, 6);  // no button: nothing
    EXPECT_EQ(s.mouse(), (Mouse{0, 0, 0, 0}));
    s.mouseDown(10, 20);
    EXPECT_EQ(s.mouse(), (Mouse{10, 20, 10, 20}));  // the frame of the click: w > 0
    s.endFrame();
    EXPECT_EQ(s.mouse(), (Mouse{10, 20, 10, -20}));  // held: z > 0, w < 0
    s.mouseMove(15, 25);
    s.endFrame();
    EXPECT_EQ(s.mouse(), (Mouse{15, 25, 10, -20}));
    s.mouseUp();
    EXPECT_EQ(s.mouse(), (Mouse{15, 25, -10, -20}));  // released: z < 0
    s.mouseMove(99, 99);
    s.endFrame();
    EXPECT_EQ(s.mouse(), (Mouse{15, 25, -10, -20}));
    s.apply({0, K::MouseDown, 0, 30, 40});  // a second click is "just clicked" again
    EXPECT_EQ(s.mouse(), (Mouse{30, 40, 30, 40}));
    s.scaleMouse(2, 0.5f);
    EXPECT_EQ(s.mouse(), (Mouse{60, 20, 60, 20}));
}

// Row 0 held, row 1 pressed on one frame only, row 2 toggled by each press.
TEST(ShadertoyInput, KeysArePressedForOneFrameAndToggle) {
    ShadertoyInputState s;
    s.reset({65}, {});
    const auto row = [&](int r, int key) { return s.keyboard()[size_t(r * ShadertoyInputState::kKeys + key)]; };
    EXPECT_TRUE(s.takeKeyboardChange());
    EXPECT_EQ(row(0, 65) + row(1, 65) + row(2, 65), 3.0f);
    s.endFrame();
    EXPECT_TRUE(s.takeKeyboardChange());
    EXPECT_EQ(row(1, 65), 0.0f);
    s.endFrame();
    EXPECT_FALSE(s.takeKeyboardChange());  // nothing changed: no upload
    s.apply({0, K::KeyUp, 65});
    s.apply({0, K::KeyDown, 32});
    EXPECT_EQ(row(0, 65), 0.0f);
    EXPECT_EQ(row(2, 65), 1.0f);
    EXPECT_EQ(row(0, 32) + row(1, 32) + row(2, 32), 3.0f);
    s.apply({0, K::KeyUp, 32});
    s.apply({0, K::KeyDown, 32});  // a second press toggles back
    EXPECT_EQ(row(2, 32), 0.0f);
    EXPECT_THROW(s.setKey(256, true), InputError);
}

TEST(ShadertoyInput, TimelineReadsFramesAndTimesInOrder) {
    const nlohmann::json j = nlohmann::json::parse(R"([
        {"frame": 2, "mousedown": [10, 20]}, {"mousemove": [12, 20]},
        {"time": 0.5, "mouseup": true}, {"frame": 40, "keydown": 32}, {"frame": 41, "keyup": 32}])");
    const std::vector<ShadertoyInput> t = parseShadertoyInputs(JsonReader(j, "timeline.json"), 60, 0.25);
    ASSERT_EQ(t.size(), 5u);
    EXPECT_EQ(t[0].frame, 2);
    EXPECT_EQ(t[0].kind, K::MouseDown);
    EXPECT_EQ(t[1].frame, 2);  // no frame: the step before's
    EXPECT_EQ(t[1].x, 12.0f);
    EXPECT_EQ(t[2].frame, 15);  // iTime 0.25 + 15/60 = 0.5
    EXPECT_EQ(t[3].key, 32);
    // The first frame at or after a time: 0.26 s at 60 fps from 0 is frame 16 (iTime 0.2667).
    EXPECT_EQ(shadertoyFrameAt(0.26, 60, 0), 16);
    EXPECT_EQ(shadertoyFrameAt(0.1, 30, 0), 3);  // 0.1 · 30 = 3.0000000000000004 is still frame 3

    const auto error = [](const std::string& text) {
        try {
            (void)parseShadertoyInputs(JsonReader(nlohmann::json::parse(text), "t.json"), 60, 0);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_NE(
        error(R"([{"frame": 5, "keydown": 1}, {"frame": 3, "keyup": 1}])").find("t.json: /1: frames never go back"),
        std::string::npos);
    EXPECT_NE(error(R"([{"frame": 5, "keydown": 300}])").find("/0/keydown"), std::string::npos);
    EXPECT_NE(error(R"([{"frame": 5}])").find("a step needs one event"), std::string::npos);
    EXPECT_NE(error(R"([{"frame": 5, "keydown": 1, "mouseup": true}])").find("one event per step"), std::string::npos);
    EXPECT_NE(error(R"([{"time": -1, "mouseup": true}])").find("/0/time"), std::string::npos);
    EXPECT_NE(error(R"([{"frame": 1, "mousedown": [1]}])").find("needs [x, y]"), std::string::npos);
    EXPECT_NE(error(R"([{"frame": 1, "click": [1, 2]}])").find("click"), std::string::npos);
}

TEST(ShadertoyInput, TextEventsParseOrNameTheFlag) {
    ShadertoyInput e = parseShadertoyInputText("12:keydown:32", 60, 0);
    EXPECT_EQ(e.frame, 12);
    EXPECT_EQ(e.kind, K::KeyDown);
    EXPECT_EQ(e.key, 32);
    e = parseShadertoyInputText("1.5s:mousedown:100,50.5", 60, 0.5);
    EXPECT_EQ(e.frame, 60);
    EXPECT_EQ(e.x, 100.0f);
    EXPECT_EQ(e.y, 50.5f);
    e = parseShadertoyInputText("3:mouseup", 60, 0);
    EXPECT_EQ(e.kind, K::MouseUp);
    for (const char* bad : {"", "x:keydown:1", "1:keydown", "1:keydown:256", "1:mousedown:1", "1:mouseup:3",
                            "1:wheel:2", "99999999:keyup:1", "0.1s:keyup:1:2"}) {
        try {
            (void)parseShadertoyInputText(bad, 60, 0.5);
            ADD_FAILURE() << "accepted \"" << bad << "\"";
        } catch (const InputError& err) {
            EXPECT_EQ(err.parameter(), "event") << bad;
            EXPECT_NE(std::string(err.what()).find(std::string("\"") + bad + "\""), std::string::npos) << err.what();
        }
    }
}

}  // namespace
}  // namespace stochtex
