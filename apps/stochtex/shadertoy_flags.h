#pragma once
// The flags of a ShaderToy program's run (`shadertoy`, and the `shadertoy`
// texture source of spectrum, flow and coherence): size, time, fps, mouse,
// date and keys, to ShadertoySettings; --inspect's PASS:X,Y.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "stochtex/gpu/shadertoy.h"

namespace stochtex::cli {

struct ShadertoyFlags {
    std::vector<int> size{640, 360};
    double time = 0, fps = 60;
    std::vector<float> mouse;
    std::string date = "2026-01-01T12:00:00";
    std::vector<int> keys;
};
void addShadertoyFlags(CLI::App& cmd, ShadertoyFlags& flags);
// The settings the flags give; InputError naming the flag when unusable.
ShadertoySettings shadertoySettings(const ShadertoyFlags& flags);

struct Inspect {
    std::string pass;  // empty: nothing to inspect
    int x = 0, y = 0;
};
// "PASS:X,Y" (empty: none); InputError naming --inspect otherwise.
Inspect parseInspect(const std::string& text);
// Prints "PASS (X, Y) at iFrame N: r g b a".
void printInspect(const ShadertoyHost& host, const Inspect& inspect);

// A frame for 8-bit outputs: every value clamped to [0, 1] (a shader may write any float).
Image clampedFrame(const Image& frame);
// InputError naming --sheet when `frames` frames of this size make no sheet.
void checkSheet(int frames, int width, int height);
// The frames as a contact sheet, eight to a row, each captioned.
Image sheetOf(const std::vector<Image>& frames, const std::vector<std::string>& captions);

}  // namespace stochtex::cli
