#pragma once
// Helpers shared by the unit tests.
#include <cstdint>

#include "stochtex/noise/spectrum.h"

namespace stochtex::test {

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

}  // namespace stochtex::test
