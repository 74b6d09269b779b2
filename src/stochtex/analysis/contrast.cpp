#include "stochtex/analysis/contrast.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"

namespace stochtex {

ContrastMethod parseContrastMethod(const std::string& s) {
    if (s == "linear") return ContrastMethod::Linear;
    if (s == "polynomial") return ContrastMethod::Polynomial;
    if (s == "sigmoid") return ContrastMethod::Sigmoid;
    throw InputError("unknown contrast correction \"" + s + "\" (expected linear, polynomial or sigmoid)");
}

const char* contrastMethodName(ContrastMethod m) {
    switch (m) {
        case ContrastMethod::Linear: return "linear";
        case ContrastMethod::Polynomial: return "polynomial";
        case ContrastMethod::Sigmoid: return "sigmoid";
    }
    return "?";
}

bool CubicCorrection::monotone() const {
    // h' is a parabola: its minimum on [0, 1] is at an end or at its vertex.
    double m = std::min(derivative(0.0), derivative(1.0));
    if (d != 0.0) {
        const double v = -c / (3.0 * d);
        if (v > 0.0 && v < 1.0) m = std::min(m, derivative(v));
    }
    return m >= 0.0;
}

CubicCorrection CubicCorrection::solve(double mu, double varianceF, double varianceR) {
    // Eq. 2.18, unknowns (b, c, d):
    //   b +       c +                 d = 1
    //   b + 2μ    c + 3μ²             d = √(σ_f²/σ_r²)
    //   μ b + (μ² + σ_r²) c + (μ³ + 3μσ_r²) d = μ
    const double s = std::sqrt(varianceF / varianceR);
    const std::array<std::array<double, 3>, 3> m = {{{1.0, 1.0, 1.0},
                                                     {1.0, 2.0 * mu, 3.0 * mu * mu},
                                                     {mu, mu * mu + varianceR, mu * mu * mu + 3.0 * mu * varianceR}}};
    const std::array<double, 3> r = {1.0, s, mu};
    auto det = [](const std::array<std::array<double, 3>, 3>& a) {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double d0 = det(m);
    if (std::abs(d0) < 1e-14) throw std::domain_error("contrast: eq. 2.18 is singular for these statistics");
    std::array<double, 3> x{};
    for (size_t k = 0; k < 3; ++k) {  // Cramer's rule: replace column k by r
        auto mk = m;
        for (size_t i = 0; i < 3; ++i) mk[i][k] = r[i];
        x[k] = det(mk) / d0;
    }
    return {x[0], x[1], x[2]};
}

double correctContrast(ContrastMethod m, double v, double meanF, double varianceF, double varianceR) {
    if (!(varianceR > 0)) return v;  // nothing to restore (a single-layer or constant pixel)
    const double s = std::sqrt(varianceF / varianceR);
    switch (m) {
        case ContrastMethod::Linear: return meanF + (v - meanF) * s;
        case ContrastMethod::Polynomial: return CubicCorrection::solve(meanF, varianceF, varianceR)(v);
        case ContrastMethod::Sigmoid: {
            if (std::abs(1.0 - s) < 1e-12) return v;  // k → ∞: the identity
            const double k = s / (1.0 - s);
            const double x = std::clamp(2.0 * v - 1.0, -1.0, 1.0);
            return 0.5 * (1.0 + k * x / (1.0 + k - std::abs(x)));
        }
    }
    return v;
}

ContrastResult correctContrast(ContrastMethod m, const Image& texture, const Image& varianceR, double meanF,
                               double varianceF) {
    if (texture.channels() != 1 || varianceR.channels() != 1 || texture.width() != varianceR.width() ||
        texture.height() != varianceR.height())
        throw InputError("contrast: texture and variance must be 1-channel images of the same size");
    ContrastResult res;
    res.image = Image(texture.width(), texture.height(), 1, Image::Uninitialized{});
    res.invalid = Image(texture.width(), texture.height(), 1, 0.0f);
    std::vector<long> clamped(size_t(texture.height()), 0), invalid(size_t(texture.height()), 0);
    parallelRows(texture.height(), [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < texture.width(); ++x) {
                const double vr = varianceR.at(x, y);
                double v;
                if (m == ContrastMethod::Polynomial && vr > 0) {
                    const CubicCorrection h = CubicCorrection::solve(meanF, varianceF, vr);
                    v = h(texture.at(x, y));
                    if (!h.monotone()) {
                        res.invalid.at(x, y) = 1.0f;
                        ++invalid[size_t(y)];
                    }
                } else {
                    v = correctContrast(m, texture.at(x, y), meanF, varianceF, vr);
                }
                if (v < 0.0 || v > 1.0) ++clamped[size_t(y)];
                res.image.at(x, y) = float(std::clamp(v, 0.0, 1.0));
            }
    });
    const double n = double(texture.pixelCount());
    long c = 0, i = 0;
    for (size_t y = 0; y < clamped.size(); ++y) {
        c += clamped[y];
        i += invalid[y];
    }
    res.clampedPercent = 100.0 * double(c) / n;
    res.invalidPercent = 100.0 * double(i) / n;
    return res;
}

}  // namespace stochtex
