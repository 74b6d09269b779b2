#pragma once
// The parts of a pattern file — a NOISE, a COLORMAP, a NORMAL_MAP — read
// from JSON with every error at its JSON pointer, and built into what the
// evaluators take (an example, a colormap table). Both the pattern parser
// (pattern_spec.h) and the graph parser (texture_graph.h) read them.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "stochtex/noise/example.h"
#include "stochtex/noise/spectrum.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/pattern_file.h"

namespace stochtex {

NoiseSpec parseNoiseSpec(const JsonReader& r, const std::filesystem::path& baseDir);
// The checks of a spectrum noise read from r (its members size and
// components): a power-of-two size, weights that do not sum to zero, the
// synthesis' work budget; failures at r's members.
void checkSpectrumSpec(const JsonReader& r, const SpectrumSpec& s);
// One spectrum component object (a NOISE's "components" entry).
SpectrumComponent parseSpectrumComponent(const JsonReader& r);
// A path member, relative to baseDir unless absolute; fails if empty.
std::filesystem::path resolveInputPath(const JsonReader& r, const std::filesystem::path& baseDir);
ColormapSpec parseColormapSpec(const JsonReader& r, const std::filesystem::path& baseDir);
// A colour of a pattern file ("#rrggbb" or [r, g, b] in [0, 1], sRGB
// components) decoded to linear light.
Rgb parseLinearColour(const JsonReader& r);
NormalMapSpec parseNormalMapSpec(const JsonReader& r, const std::filesystem::path& baseDir);
// InputError naming the parameter (roughness, amplitude, specular, light,
// view) if the shading is unusable; directions are normalised.
LeanShading validatedShading(LeanShading s);

// Reads a file (InputError if missing) and parses it as JSON.
// The text of a JSON file, with readJsonFile's checks before reading (a
// folder, a missing file, a file too large), not yet parsed.
std::string readJsonText(const std::string& path);
nlohmann::json readJsonFile(const std::string& path);

// The example image (1 channel, W×W, values in [0,1]) as specified,
// before any Gaussianization.
Image buildExampleImage(const NoiseSpec& spec, const std::string& context);
// The example prepared for tiling and blending (Gaussianized if asked).
NoiseExample buildNoiseExample(const NoiseSpec& spec, const std::string& context);
// The table H in linear light (or as data, with transfer Linear): the one
// place colours of a pattern enter.
ColormapTable buildColormap(const ColormapSpec& spec);
// A phasor colormap's profile P in the table's space (Source::Phasor only):
// palette colours decoded, a profile image read and checked (W×1, else an
// InputError naming the file).
PhasorColourProfile buildPhasorProfile(const ColormapSpec& spec);

}  // namespace stochtex
