#pragma once
// Helpers shared by the unit tests.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include "owned_folder.h"
#include "stochtex/core/error.h"
#include "stochtex/image/image.h"
#include "stochtex/image/image_io.h"
#include "stochtex/noise/spectrum.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/pattern_spec.h"

namespace stochtex::test {

// Mean over the pixels of the RGB 2-norm ‖a − b‖ (3-channel images of one size).
inline double meanRgbDistance(const Image& a, const Image& b) {
    double s = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            double d2 = 0;
            for (int c = 0; c < 3; ++c)
                d2 += (double(a.at(x, y, c)) - b.at(x, y, c)) * (double(a.at(x, y, c)) - b.at(x, y, c));
            s += std::sqrt(d2);
        }
    return s / double(a.pixelCount());
}

// A path under the temp folder unique to this test process, so that
// parallel ctest runs and other checkouts' tests never share files. A death
// test in the "threadsafe" style re-executes the test binary, whose child
// runs the test again from its fixture: it takes its parent's paths, so that
// what the child leaves is where the parent looks (and removes).
inline std::filesystem::path scratchPath(const std::string& name) {
    const bool deathTestChild = !GTEST_FLAG_GET(internal_run_death_test).empty();
    return std::filesystem::temp_directory_path() /
           (name + "_" + std::to_string(deathTestChild ? ::getppid() : ::getpid()));
}

// A fresh folder at scratchPath(name), removed with this object (also when
// an assertion ends the test early), for a test that writes files.
class ScratchDir : public OwnedFolder {
public:
    explicit ScratchDir(const std::string& name) : OwnedFolder(scratchPath(name)) {}
};

// A fixture with a fresh folder of its own (named after the suite and the
// process), removed after each test.
class ScratchFolder : public testing::Test {
protected:
    void SetUp() override { std::filesystem::create_directories(dir_); }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    const std::filesystem::path dir_ =
        scratchPath(std::string("stochtex_") + testing::UnitTest::GetInstance()->current_test_suite()->name());
};

// A one-component spectrum (mean ½, σ 1/6).
inline SpectrumSpec spectrumSpec(SpectrumShape shape, double f, double b, double theta, uint32_t seed, int size) {
    SpectrumSpec s;
    s.size = size;
    s.seed = seed;
    SpectrumComponent c;
    c.shape = shape;
    c.frequency = f;
    c.bandwidth = b;
    c.orientation = theta;
    s.components.push_back(c);
    return s;
}

inline Image example(SpectrumShape shape, double f, double b, double theta, uint32_t seed, int size) {
    return synthesizeExample(spectrumSpec(shape, f, b, theta, seed, size));
}

// A pattern file's text as parsePatternSpec reads it: errors name the file
// `name`, relative paths are against the working directory.
inline PatternSpec parsePatternText(const std::string& text, const std::string& name = "g.json") {
    return parsePatternSpec(JsonReader(JsonReader::parse(text, name), name), ".");
}

// A pattern whose two noises are a bimodal 64² exemplar (plateaus at 0.2
// and 0.8), Gaussianized, under the `gaussian` colormap (H = x shows
// T⁻¹(N_x)): the exemplar is written into `dir`, which must exist.
inline PatternSpec gaussianizedBimodalPattern(const std::filesystem::path& dir) {
    Image ex(64, 64, 1);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            ex.at(x, y) = (std::sin(x * 0.3) * std::cos(y * 0.2) > 0 ? 0.8f : 0.2f) +
                          0.05f * float((x * 7 + y * 13) % 10) / 10.0f;
    writeImage((dir / "bimodal.png").string(), ex, kNoTransfer);  // noise values: data
    const std::string text = R"({"name": "exemplar", "seed": 3,
        "noise_x": {"type": "image", "path": "bimodal.png", "gaussianize": true},
        "noise_y": {"type": "image", "path": "bimodal.png", "gaussianize": true},
        "colormap": {"type": "gaussian"}})";
    return parsePatternSpec(JsonReader(JsonReader::parse(text, "test"), "test"), dir);
}

// The InputError that `f` throws; a test failure (and a placeholder error)
// if it throws none. Other exceptions propagate and fail the test.
template <class F>
InputError inputErrorOf(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no InputError was thrown";
    return InputError("(none thrown)");
}

}  // namespace stochtex::test
