#include "stochtex/pattern/pattern_parts.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "stochtex/core/error.h"
#include "stochtex/core/notes.h"
#include "stochtex/filter/pyramid.h"
#include "stochtex/image/image_io.h"
#include "stochtex/noise/example.h"
#include "stochtex/pattern/pattern_members.h"

namespace stochtex {
namespace fs = std::filesystem;

SpectrumComponent parseSpectrumComponent(const JsonReader& r) {
    r.expectObject({"shape", "frequency", "cutoff", "bandwidth", "orientation", "weight"});
    SpectrumComponent c;
    const std::string shape = r.at("shape").choice({"lowpass", "ring", "bilobe"});
    if (shape == "lowpass") {
        c.shape = SpectrumShape::LowPass;
        c.frequency = readNumber(r, patternMembers().cutoff);
        if (r.has("frequency") || r.has("bandwidth") || r.has("orientation"))
            r.fail("a lowpass component takes only \"cutoff\" and \"weight\"");
    } else {
        c.shape = shape == "ring" ? SpectrumShape::Ring : SpectrumShape::BiLobe;
        c.frequency = readNumber(r, patternMembers().frequency);
        c.bandwidth = readNumber(r, patternMembers().bandwidth);
        if (c.shape == SpectrumShape::BiLobe)
            c.orientation = readNumber(r, patternMembers().orientation);
        else if (r.has("orientation"))
            r.fail("a ring is isotropic: \"orientation\" applies to bilobe components only");
        if (r.has("cutoff")) r.fail("\"cutoff\" applies to lowpass components only");
    }
    c.weight = readNumber(r, patternMembers().weight);
    return c;
}

namespace {

Rgb parseColour(const JsonReader& r) {
    if (r.value().is_string()) {
        const std::string s = r.string();
        auto hex = [](char ch) -> int {
            if (ch >= '0' && ch <= '9') return ch - '0';
            if (ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
            if (ch >= 'A' && ch <= 'F') return ch - 'A' + 10;
            return -1;
        };
        if (s.size() == 7 && s[0] == '#') {
            Rgb c;
            for (int k = 0; k < 3; ++k) {
                const int hi = hex(s[size_t(1 + 2 * k)]), lo = hex(s[size_t(2 + 2 * k)]);
                if (hi < 0 || lo < 0) r.fail("invalid colour \"" + s + "\" (expected #rrggbb)");
                c[size_t(k)] = float(hi * 16 + lo) / 255.0f;
            }
            return c;
        }
        r.fail("invalid colour \"" + s + "\" (expected #rrggbb or [r, g, b] in [0,1])");
    }
    if (r.arraySize() != 3) r.fail("a colour array needs 3 components");
    return {float(r.at(0).number(0, 1)), float(r.at(1).number(0, 1)), float(r.at(2).number(0, 1))};
}

std::array<double, 2> parsePoint(const JsonReader& r) {
    if (r.arraySize() != 2) r.fail("a point needs 2 coordinates [x, y]");
    const ParamInfo& c = patternMembers().coordinate;
    return {r.at(0).number(c.min, c.max), r.at(1).number(c.min, c.max)};
}

PaintedShape parseShape(const JsonReader& r) {
    const std::string kind = r.at("shape").choice({"rectangle", "disc", "ring", "halfplane", "band", "polygon"});
    PaintedShape s;
    if (kind == "rectangle") {
        r.expectObject({"shape", "colour", "min", "max"});
        s.kind = PaintedShape::Kind::Rectangle;
        s.a = parsePoint(r.at("min"));
        s.b = parsePoint(r.at("max"));
        if (s.b[0] < s.a[0] || s.b[1] < s.a[1]) r.at("max").fail("max must not be below min");
    } else if (kind == "disc") {
        r.expectObject({"shape", "colour", "center", "radius"});
        s.kind = PaintedShape::Kind::Disc;
        s.a = parsePoint(r.at("center"));
        s.radius = readNumber(r, patternMembers().radius);
    } else if (kind == "ring") {
        r.expectObject({"shape", "colour", "center", "inner", "outer"});
        s.kind = PaintedShape::Kind::Ring;
        s.a = parsePoint(r.at("center"));
        s.innerRadius = readNumber(r, patternMembers().inner);
        s.radius = readNumber(r, patternMembers().outer);
        if (s.radius < s.innerRadius) r.at("outer").fail("outer radius must be >= inner radius");
    } else if (kind == "halfplane" || kind == "band") {
        if (kind == "halfplane")
            r.expectObject({"shape", "colour", "point", "angle"});
        else
            r.expectObject({"shape", "colour", "point", "angle", "width"});
        s.kind = kind == "halfplane" ? PaintedShape::Kind::HalfPlane : PaintedShape::Kind::Band;
        s.a = parsePoint(r.at("point"));
        s.setAngle(readNumber(r, patternMembers().angle));
        if (kind == "band") s.width = readNumber(r, patternMembers().width);
    } else {
        r.expectObject({"shape", "colour", "points"});
        s.kind = PaintedShape::Kind::Polygon;
        const JsonReader pts = r.at("points");
        const size_t n = pts.arraySize();
        if (n < 3) pts.fail("a polygon needs at least 3 points");
        for (size_t i = 0; i < n; ++i) s.points.push_back(parsePoint(pts.at(i)));
    }
    s.colour = parseColour(r.at("colour"));
    return s;
}

}  // namespace

void checkSpectrumSpec(const JsonReader& r, const SpectrumSpec& s) {
    // Every render path builds MIP pyramids that halve the example.
    if (!isPowerOfTwo(s.size))
        r.at("size").fail("must be a power of two (the filtered renders build MIP pyramids that halve the "
                          "example), got " + std::to_string(s.size));
    double total = 0;
    for (const auto& c : s.components) total += c.weight;
    if (total <= 0) r.at("components").fail("component weights sum to zero");
    r.check([&] { validateSpectrumWork(s); });
}

fs::path resolveInputPath(const JsonReader& r, const fs::path& baseDir) {
    const fs::path p = r.string();
    if (p.empty()) r.fail("empty path");
    return p.is_absolute() ? p : baseDir / p;
}

NoiseSpec parseNoiseSpec(const JsonReader& r, const fs::path& baseDir) {
    NoiseSpec spec;
    const std::string type = r.at("type").choice({"spectrum", "image"});
    if (type == "spectrum") {
        r.expectObject({"type", "size", "seed", "mean", "stddev", "components", "quadrature"});
        SpectrumSpec& s = spec.spectrum;
        s.size = readInteger(r, patternMembers().noiseSize);
        if (auto seed = r.find("seed")) {
            s.seed = seed->uint32();
            spec.explicitSeed = true;
        }
        s.mean = readNumber(r, patternMembers().noiseMean);
        s.stddev = readNumber(r, patternMembers().noiseStddev);
        s.quadrature = r.boolean("quadrature", false);
        const JsonReader comps = r.at("components");
        const size_t n = comps.arraySize();
        if (n == 0) comps.fail("needs at least one spectrum component");
        for (size_t i = 0; i < n; ++i) s.components.push_back(parseSpectrumComponent(comps.at(i)));
        checkSpectrumSpec(r, s);
    } else {
        r.expectObject({"type", "path", "gaussianize"});
        spec.source = NoiseSpec::Source::Image;
        spec.image = resolveInputPath(r.at("path"), baseDir);
        spec.gaussianize = r.boolean("gaussianize", true);
    }
    return spec;
}

ColormapSpec parseColormapSpec(const JsonReader& r, const fs::path& baseDir) {
    ColormapSpec spec;
    const std::string type = r.at("type").choice({"gaussian", "ridged", "phasor", "image", "painted"});
    if (type == "gaussian" || type == "ridged") {
        r.expectObject({"type", "resolution", "transfer"});
        spec.source = ColormapSpec::Source::Analytic;
        spec.analytic = type == "gaussian" ? AnalyticColormap::Gaussian : AnalyticColormap::Ridged;
    } else if (type == "phasor") {
        r.expectObject({"type", "resolution", "profile", "duty", "path", "palette", "transfer"});
        spec.source = ColormapSpec::Source::Phasor;
        spec.profile = r.choice("profile", PhasorProfile::Sine, kPhasorProfileNames);
        spec.duty = readNumber(r, patternMembers().duty);
        if (spec.profile == PhasorProfile::Image)
            spec.image = resolveInputPath(r.at("path"), baseDir);
        else if (r.has("path"))
            r.at("path").fail("\"path\" is the profile image: it needs \"profile\": \"image\"");
        if (auto palette = r.find("palette")) {
            const size_t n = palette->arraySize();
            if (n < 2 || n > 256) palette->fail("a palette needs 2 to 256 colours, got " + std::to_string(n));
            for (size_t i = 0; i < n; ++i) spec.palette.push_back(parseColour(palette->at(i)));
        }
    } else if (type == "image") {
        r.expectObject({"type", "path", "transfer"});
        spec.source = ColormapSpec::Source::Image;
        spec.image = resolveInputPath(r.at("path"), baseDir);
    } else {
        r.expectObject({"type", "resolution", "background", "shapes", "transfer"});
        spec.source = ColormapSpec::Source::Painted;
        spec.painted.background = r.has("background") ? parseColour(r.at("background")) : Rgb{0, 0, 0};
        if (auto shapes = r.find("shapes")) {
            const size_t n = shapes->arraySize();
            for (size_t i = 0; i < n; ++i) spec.painted.shapes.push_back(parseShape(shapes->at(i)));
        }
    }
    if (r.has("transfer")) spec.transfer = r.at("transfer").choice(kTransferNames);
    spec.resolution = readInteger(r, patternMembers().colormapResolution);
    if (spec.source == ColormapSpec::Source::Painted) r.check([&] { spec.painted.validateWork(spec.resolution); });
    return spec;
}

LeanShading validatedShading(LeanShading s) {
    const PatternMembers& m = patternMembers();
    for (const auto& [p, v] : {std::pair{&m.roughness, s.roughness}, std::pair{&m.specular, s.specular}})
        if (!(std::isfinite(v) && v >= p->min && v <= p->max))
            throw InputError::parameter(p->name, "must be in [" + formatValue(p->min) + ", " + formatValue(p->max) +
                                                     "], got " + formatValue(v));
    for (const char* name : {"light", "view"}) {
        if (std::string(name) == "view" && !s.view) continue;
        auto& d = std::string(name) == "light" ? s.light : *s.view;
        const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        // Above the plane, not grazing: the lobe's D(h)/(4 v_z) needs v_z > 0.
        if (!(std::isfinite(n) && n > 0 && d[2] / n >= 0.01))
            throw InputError::parameter(name, "must point above the plane (z/|d| >= 0.01), got [" + formatValue(d[0]) +
                                                  ", " + formatValue(d[1]) + ", " + formatValue(d[2]) + "]");
        for (double& c : d) c /= n;
    }
    return s;
}

Rgb parseLinearColour(const JsonReader& r) {
    Rgb c = parseColour(r);
    for (float& v : c) v = linearFromSrgb(v);
    return c;
}

NormalMapSpec parseNormalMapSpec(const JsonReader& r, const fs::path& baseDir) {
    r.expectObject({"height", "amplitude", "roughness", "light", "view", "albedo", "specular"});
    NormalMapSpec spec;
    spec.height = parseNoiseSpec(r.at("height"), baseDir);
    spec.amplitude = readNumber(r, patternMembers().amplitude);
    LeanShading& s = spec.shading;
    // Any number here: validatedShading states the domain (and is what the library checks too).
    s.roughness = r.number("roughness", s.roughness, -1e300, 1e300);
    s.specular = r.number("specular", s.specular, -1e300, 1e300);
    for (const char* name : {"light", "view"})
        if (auto d = r.find(name)) {
            if (d->arraySize() != 3) d->fail("a direction needs 3 components [x, y, z]");
            if (std::string(name) == "view") s.view.emplace();
            auto& out = std::string(name) == "light" ? s.light : *s.view;
            for (size_t k = 0; k < 3; ++k) out[k] = d->at(k).number(-1e3, 1e3);
        }
    if (r.has("albedo")) s.albedo = parseLinearColour(r.at("albedo"));
    r.check([&] { s = validatedShading(s); });
    return spec;
}

nlohmann::json readJsonFile(const std::string& path) { return JsonReader::parse(readJsonText(path), path); }

std::string readJsonText(const std::string& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw InputError(path + ": is a folder, not a JSON file");
    if (!fs::exists(path, ec)) throw InputError(path + ": no such file");
    if (!fs::is_regular_file(path, ec)) throw InputError(path + ": not a regular file");
    // Refused before reading: a huge file would cost its size (and its DOM ~20×) in memory.
    const auto bytes = fs::file_size(path, ec);
    if (!ec) JsonReader::checkSize(bytes, path);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open file");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

Image buildExampleImage(const NoiseSpec& spec, const std::string& context) {
    if (spec.source == NoiseSpec::Source::Spectrum) return synthesizeExample(spec.spectrum);
    const Image raw = readImage(spec.image.string());
    checkPixelRange(raw, spec.image.string(), kMinExemplarValue, kMaxExemplarValue, "exemplar");
    if (spec.channel >= raw.channels())
        throw InputError(context + ": " + spec.image.string() + " has " + std::to_string(raw.channels()) +
                         " channel" + (raw.channels() == 1 ? "" : "s") + "; there is no channel " +
                         std::to_string(spec.channel));
    Image img = spec.channel < 0 ? toGray(raw) : channelOf(raw, spec.channel);
    const Transfer transfer = spec.transfer.value_or(holdsFloatValues(spec.image.string()) ? Transfer::Linear : Transfer::Srgb);
    if (spec.channel >= 0 && spec.channel < 3 && transfer == Transfer::Srgb) img = decodeTransfer(img, transfer);
    if (img.width() != img.height())
        throw InputError(context + ": exemplar " + spec.image.string() + " is " + std::to_string(img.width()) + "x" +
                         std::to_string(img.height()) + "; examples must be square (they tile with period 1)");
    if (img.width() < 8 || img.width() > kMaxExampleSize)
        throw InputError(context + ": exemplar " + spec.image.string() + " must be between 8 and " +
                         std::to_string(kMaxExampleSize) + " pixels wide");
    if (isPowerOfTwo(img.width())) return img;
    // The filtered paths build MIP pyramids that halve the example down to
    // one texel, and every path of a pattern must see the same example: so
    // any exemplar is resampled up to the next power of two (no detail lost;
    // ≤ 4096 since the exemplar is). The pattern's scale then counts texels
    // of the resampled example.
    const int size = nextPowerOfTwo(img.width());
    note(spec.image.string() + ": exemplar resampled from " + std::to_string(img.width()) + "x" +
         std::to_string(img.height()) + " to " + std::to_string(size) + "x" + std::to_string(size) +
         " (periodic bicubic): filtering needs a power-of-two example, and scale counts its texels");
    return resamplePeriodic(img, size, float(kMinExemplarValue), float(kMaxExemplarValue));
}

NoiseExample buildNoiseExample(const NoiseSpec& spec, const std::string& context) {
    Image img = buildExampleImage(spec, context);
    if (spec.source == NoiseSpec::Source::Image && spec.gaussianize) {
        HistogramTransform t = HistogramTransform::fit(img);
        Image g = t.forward(img);
        return NoiseExample(std::move(g), std::move(t));
    }
    return NoiseExample(std::move(img));
}

namespace {

// Table entries through the transfer function, where they enter (once).
ColormapTable decodedTable(const ColormapTable& table, Transfer transfer) {
    return transfer == Transfer::Linear ? table : ColormapTable(decodeTransfer(table.table(), transfer));
}

}  // namespace

PhasorColourProfile buildPhasorProfile(const ColormapSpec& spec) {
    if (spec.source != ColormapSpec::Source::Phasor) throw std::invalid_argument("buildPhasorProfile: not a phasor colormap");
    const Transfer transfer = spec.transfer.value_or(Transfer::Srgb);
    std::vector<Rgb> palette = spec.palette;
    if (transfer == Transfer::Srgb)
        for (Rgb& c : palette)
            for (float& v : c) v = linearFromSrgb(v);
    if (spec.profile != PhasorProfile::Image)
        return PhasorColourProfile::analytic(spec.profile, spec.duty, transfer == Transfer::Srgb, std::move(palette));

    const std::string file = spec.image.string();
    const Image img = readImage(file);
    checkPixelRange(img, file, -kMaxColormapValue, kMaxColormapValue, "profile");
    if (img.height() != 1 || img.width() < 2 || img.width() > kMaxColormapResolution)
        throw InputError(file + ": a phasor profile image must be one row over one period (W×1, W in [2, " +
                         std::to_string(kMaxColormapResolution) + "]), got " + std::to_string(img.width()) + "x" +
                         std::to_string(img.height()));
    const bool gray = img.channels() == 1;
    if (!palette.empty() && !gray)
        throw InputError(file + ": a profile image that indexes a palette must be grayscale, got " +
                         std::to_string(img.channels()) + " channels");
    // Codes are decoded as a colormap image's are; a palette's index is data.
    const Image values =
        palette.empty() ? decodeTransfer(toRgb(img), spec.transfer.value_or(holdsFloatValues(file) ? Transfer::Linear
                                                                                                 : transfer))
                        : toRgb(img);
    std::vector<Rgb> samples(size_t(values.width()));
    for (int k = 0; k < values.width(); ++k) samples[size_t(k)] = {values.at(k, 0, 0), values.at(k, 0, 1), values.at(k, 0, 2)};
    return PhasorColourProfile::sampled(std::move(samples), std::move(palette));
}

ColormapTable buildColormap(const ColormapSpec& spec) {
    const Transfer transfer = spec.transfer.value_or(Transfer::Srgb);
    switch (spec.source) {
        case ColormapSpec::Source::Analytic:
            return decodedTable(makeAnalyticColormap(spec.analytic, spec.resolution), transfer);
        case ColormapSpec::Source::Phasor: return makePhasorColormap(buildPhasorProfile(spec), spec.resolution);
        case ColormapSpec::Source::Image: {
            const Image img = readImage(spec.image.string());
            checkPixelRange(img, spec.image.string(), -kMaxColormapValue, kMaxColormapValue, "colormap");
            if (img.width() < 2 || img.height() < 2)
                throw InputError(spec.image.string() + ": a colormap image needs at least 2x2 pixels");
            if (img.width() > kMaxColormapResolution || img.height() > kMaxColormapResolution)
                throw InputError(spec.image.string() + ": colormap image larger than " +
                                 std::to_string(kMaxColormapResolution) + " pixels per side");
            const bool floats = holdsFloatValues(spec.image.string());
            return decodedTable(ColormapTable::fromImage(img), spec.transfer.value_or(floats ? Transfer::Linear : transfer));
        }
        case ColormapSpec::Source::Painted: {
            // Decoded before rasterising, so anti-aliased edges average linear light.
            PaintedColormap painted = spec.painted;
            const auto decode = [&](Rgb& c) {
                if (transfer == Transfer::Srgb)
                    for (float& v : c) v = linearFromSrgb(v);
            };
            decode(painted.background);
            for (PaintedShape& shape : painted.shapes) decode(shape.colour);
            return painted.rasterize(spec.resolution);
        }
    }
    throw InputError("unknown colormap source");
}

}  // namespace stochtex
