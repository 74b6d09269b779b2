#include "stochtex/studies/image_base_study.h"

#include <algorithm>
#include <cmath>

#include "stochtex/core/error.h"
#include "stochtex/report/plot.h"
#include "stochtex/studies/instance_statistics.h"

namespace stochtex {

namespace {

std::array<int, 2> reference(const ImageBaseStudyOptions& o) {
    return {o.referenceX >= 0 ? o.referenceX : o.size * 3 / 4, o.referenceY >= 0 ? o.referenceY : o.size * 3 / 4};
}

// The correlation of every frame pixel with the reference point over the
// source's instances.
Image pointCorrelation(const TextureSource& source, const ImageBaseStudyOptions& o, const Progress& progress) {
    const auto r = reference(o);
    InstanceStatisticsOptions s;
    s.region = {o.size, o.size, 0.0, 0.0};
    s.time = o.zoom.time;
    s.instances = o.instances;
    s.pointX = r[0];
    s.pointY = r[1];
    return instanceStatistics(source, s, progress).correlationWithPoint();
}

// The strongest echo: the largest correlation at least `radius` pixels from
// the reference (non-finite values, a constant pixel's, are skipped).
double strongestEcho(const Image& c, const ImageBaseStudyOptions& o) {
    const auto r = reference(o);
    double best = 0;
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x) {
            const double d2 = double(x - r[0]) * (x - r[0]) + double(y - r[1]) * (y - r[1]);
            if (d2 <= double(o.echoRadius) * o.echoRadius || !std::isfinite(c.at(x, y))) continue;
            best = std::max(best, double(c.at(x, y)));
        }
    return best;
}

// The map coloured cyan (−1) – white (0) – black (+1) as the thesis draws it,
// with the reference point marked by a green cross.
Image correlationImage(const Image& c, const ImageBaseStudyOptions& o) {
    Image out(c.width(), c.height(), 3);
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x) {
            const float v = std::isfinite(c.at(x, y)) ? std::clamp(c.at(x, y), -1.0f, 1.0f) : 0.0f;
            const float rgb[3] = {v < 0 ? 1 + v : 1 - v, v < 0 ? 1.0f : 1 - v, v < 0 ? 1.0f : 1 - v};
            for (int k = 0; k < 3; ++k) out.at(x, y, k) = rgb[k];
        }
    const auto r = reference(o);
    const int arm = std::max(2, o.size / 32);
    for (int d = -arm; d <= arm; ++d)
        for (const auto& [x, y] : {std::array<int, 2>{r[0] + d, r[1]}, std::array<int, 2>{r[0], r[1] + d}})
            if (x >= 0 && y >= 0 && x < out.width() && y < out.height()) {
                out.at(x, y, 0) = 0.1f;
                out.at(x, y, 1) = 0.8f;
                out.at(x, y, 2) = 0.1f;
            }
    return out;
}

}  // namespace

std::span<const OptionMember<ImageBaseStudyOptions>> imageBaseStudyMembers() {
    using O = ImageBaseStudyOptions;
    static const OptionMember<O> members[] = {
        {"size", "Frame and correlation-map side in pixels", 8, 1024, &O::size},
        {"instances", "Translations of each image averaged", 2, 100000, &O::instances},
    };
    return members;
}

void validateImageBaseStudy(const ImageBaseStudyOptions& o, const std::vector<ImageBase>& images) {
    if (images.empty()) throw InputError::parameter("images", "must name at least one image");
    checkMembers(o, imageBaseStudyMembers());
    if (o.referenceX >= o.size)
        throw InputError::parameter("referenceX", "must be below the size, got " + std::to_string(o.referenceX));
    if (o.referenceY >= o.size)
        throw InputError::parameter("referenceY", "must be below the size, got " + std::to_string(o.referenceY));
    if (o.echoRadius < 0) throw InputError::parameter("echoRadius", "must be ≥ 0, got " + std::to_string(o.echoRadius));
    validateZoomParams(o.zoom);
    for (const ImageBase& b : images) {
        try {
            LatticeTexture::checkImage(toGray(b.image));
        } catch (const InputError& e) {
            throw InputError(b.name + ": " + e.what());
        }
    }
}

ImageBaseStudyResult imageBaseStudy(const std::vector<ImageBase>& images, const ImageBaseStudyOptions& o,
                                    const StudyProgress& progress) {
    validateImageBaseStudy(o, images);
    ImageBaseStudyResult r;
    r.table.columns = {{"image", "image", ""},
                       {"echo_base", "strongest echo: image", ""},
                       {"echo_no_offsets", "zoom, no offsets", ""},
                       {"echo_hashed_offsets", "zoom, hashed offsets", ""}};
    std::vector<std::vector<Image>> rows15(2), rows17;
    std::vector<std::vector<std::string>> captions15(2), captions17;
    const SourceRegion frame{o.size, o.size, 0.0, 0.0};
    for (size_t i = 0; i < images.size(); ++i) {
        const ImageBase& b = images[i];
        const Image gray = toGray(b.image);
        const Progress part = progressPart(progress, int(i), int(images.size()), b.name);
        const ImageTextureSource plain(gray);
        const Image base = pointCorrelation(plain, o, progressPart(part, 0.0, 0.2));
        ZoomParams none = o.zoom, hashed = o.zoom;
        none.offsets = ZoomOffsets::None;
        hashed.offsets = ZoomOffsets::Hashed;
        ZoomBase zb;
        zb.image = gray;
        const ZoomSource zoomNone(none, zb), zoomHashed(hashed, zb);
        const Image cNone = pointCorrelation(zoomNone, o, progressPart(part, 0.2, 0.6));
        const Image cHashed = pointCorrelation(zoomHashed, o, progressPart(part, 0.6, 1.0));
        const double e0 = strongestEcho(base, o), e1 = strongestEcho(cNone, o), e2 = strongestEcho(cHashed, o);
        r.table.add({b.name, TableCell::value(e0, "%.3f"), TableCell::value(e1, "%.3f"), TableCell::value(e2, "%.3f")});
        const Image shownBase = toRgb(plain.render(frame, 0, 0));
        rows15[0].push_back(shownBase);
        rows15[1].push_back(correlationImage(base, o));
        captions15[0].push_back(b.name);
        captions15[1].push_back("correlation, echo " + TableCell::value(e0, "%.2f").text);
        rows17.push_back({shownBase, toRgb(zoomNone.render(frame, o.zoom.time, 0)), correlationImage(cNone, o),
                          toRgb(zoomHashed.render(frame, o.zoom.time, 0)), correlationImage(cHashed, o)});
        captions17.push_back(
            {b.name, "zoom texture, no offsets", "its correlation, echo " + TableCell::value(e1, "%.2f").text,
             "zoom texture, hashed offsets", "its correlation, echo " + TableCell::value(e2, "%.2f").text});
    }
    const std::string scale =
        "correlation from cyan (−1) through white (0) to black (+1), reference point marked "
        "by the green cross; " +
        std::to_string(o.instances) + " periodic translations of each image.";
    r.figures.push_back({"figure2_15.png", sheet(rows15, captions15),
                         "Figure 2.15: the base images (gray by I = 0.21r + 0.72g + 0.07b) and their correlation with "
                         "a point, " +
                             scale});
    r.figures.push_back(
        {"figure2_17.png", sheet(rows17, captions17),
         "Figure 2.17: each image as the base of the zoom texture (n = " + std::to_string(o.zoom.layers) +
             ") without offsets and with hashed offsets, and their correlation with a point, " + scale +
             " Strongest echo: the largest correlation more than " + std::to_string(o.echoRadius) +
             " pixels from the reference."});
    return r;
}

Report imageBaseReport(const ImageBaseStudyResult& r) {
    return sectionReport(
        "Image textures as the base (section 2.7.1, Figures 2.15 and 2.17)", {{"fractalize.csv", r.table}}, r.figures,
        "<p>Each image's correlation with a point over its periodic translations, then the zoom texture over it "
        "without and with hashed offsets: regular structures echo (ghosting).</p>");
}

}  // namespace stochtex
