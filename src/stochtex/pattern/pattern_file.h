#pragma once
// The values a pattern file describes (docs/PATTERNS.md): its noises, its
// colormap, its normal map and their shading, and the pattern's header.
// Plain values and limits only: the parser (pattern_parts.h,
// pattern_spec.h), the table of its numbers (pattern_members.h) and the
// evaluators read them, and this header includes none of them.
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stochtex/core/enum_names.h"
#include "stochtex/filter/variance_estimator.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/noise/spectrum.h"
#include "stochtex/noise/tiling_blending.h"
#include "stochtex/pattern/colormap.h"

namespace stochtex {

// The values image files may hold (8/16-bit PNGs always do; float EXRs may
// not, and are refused): an exemplar's pixels are noise values, in the
// colormap's domain [0, 1]; a colormap's are colours, at most the largest
// half float (the GPU table and the engine export may store halves).
constexpr double kMinExemplarValue = 0.0, kMaxExemplarValue = 1.0;
constexpr double kMaxColormapValue = 65504.0;
// What a graph's linear field may hold (half float's range, as a colormap):
// its squares and products stay finite in the float pyramids.
constexpr double kMaxFieldValue = 65504.0;

struct NoiseSpec {
    enum class Source { Spectrum, Image };
    Source source = Source::Spectrum;
    SpectrumSpec spectrum;        // Source::Spectrum
    bool explicitSeed = false;    // spectrum.seed came from the file
    std::filesystem::path image;  // Source::Image (resolved against the file's folder)
    bool gaussianize = true;      // Source::Image: blend T(E), apply T⁻¹ after
    int channel = -1;             // Source::Image: −1, the gray of its channels; else this channel
    // Source::Image with a channel: how its codes become values (Srgb: a
    // colour channel decoded to linear light; unset: Srgb, but Linear for a
    // float file). The gray of an exemplar is its codes, as data.
    std::optional<Transfer> transfer;

    // Equal specs build the same example (the workbench's previews reuse it).
    bool operator==(const NoiseSpec&) const = default;
};

struct ColormapSpec {
    enum class Source { Analytic, Phasor, Image, Painted };
    Source source = Source::Analytic;
    AnalyticColormap analytic = AnalyticColormap::Gaussian;
    PhasorProfile profile = PhasorProfile::Sine;
    double duty = 0.5;
    std::vector<Rgb> palette;     // Phasor: P's value through these colours (as given, sRGB unless linear)
    std::filesystem::path image;  // Image; Phasor with profile Image: the W×1 profile
    PaintedColormap painted;
    int resolution = 256;
    // How the colours given (hex, [r, g, b], the analytic H, an image's codes)
    // become table entries (docs/PATTERNS.md): Srgb decodes them to linear
    // light, Linear takes them as data. Unset: Srgb, except a float (EXR)
    // image, whose values are linear already.
    std::optional<Transfer> transfer;

    // Equal specs build the same table (the workbench's previews reuse it).
    bool operator==(const ColormapSpec&) const = default;
};

// How a normal map is lit and shaded (kernel/lean.glsl, docs/MATH.md "LEAN
// mapping"). Directions are in the texture frame (x along u, y along v, z
// up out of the plane), unit length, z > 0.
struct LeanShading {
    double roughness = 0.1;                       // base Beckmann roughness m (> 0)
    std::array<double, 3> light{0.0, -0.6, 0.8};  // towards the light
    // Towards the viewer; unset: from the camera (Camera::viewDirection).
    std::optional<std::array<double, 3>> view;
    Rgb albedo{0.18f, 0.18f, 0.18f};  // linear light
    double specular = 0.05;           // weight of the lobe's reflection
};

// Pattern JSON "normal_map": a height example (a noise, before any
// Gaussianization) whose slopes, scaled to an RMS slope `amplitude`, are
// the normals; shaded by the lean response.
struct NormalMapSpec {
    NoiseSpec height;
    double amplitude = 0.3;  // RMS slope per axis
    LeanShading shading;
};

// Pattern JSON "offsets".
enum class OffsetMode { Independent, Shared };
inline const EnumNames<OffsetMode> kOffsetModeNames{{"independent", OffsetMode::Independent},
                                                    {"shared", OffsetMode::Shared}};

struct TextureGraph;  // texture_graph.h

struct PatternSpec {
    std::string name = "pattern";
    uint32_t seed = 1;
    int width = 512, height = 512;
    double scale = 1.0;  // example texels per output pixel
    OffsetMode offsets = OffsetMode::Independent;
    double gridDensity = kDefaultGridDensity;  // 2√3 triangle-grid cells per uv unit (as a float)
    // A tileable pattern's period in example periods along u and v, both
    // ≥ 1: its grid is stretched along u to repeat with it (GridLayout::
    // periodic), so the whole pattern does. (0, 0): the plane.
    std::array<int, 2> gridPeriods{0, 0};
    NoiseSpec noise[2];
    bool quadraturePair = false;  // noise_y is "quadrature": the Hilbert pair of noise_x
    ColormapSpec colormap;
    std::optional<NormalMapSpec> normalMap;  // the pattern also carries normals
    // The footprint estimator its filtered renders read, where the file names
    // one ("estimator"); a command's --estimator overrides it.
    std::optional<VarianceEstimator> estimator;
    // A graph file (texture_graph.h): its nodes give the two examples and the
    // colormap (`colormap` holds the output node's); noise[] is unused.
    std::shared_ptr<const TextureGraph> graph;
};

}  // namespace stochtex
