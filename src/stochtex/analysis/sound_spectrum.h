#pragma once
// The spectrum of a sound (a ShaderToy program's Sound pass): Welch's
// average of Hann-windowed periodograms of the mono mix, so a tone reads as
// a peak at its frequency whatever the sound's length.
#include <vector>

namespace stochtex {

struct SoundSpectrum {
    std::vector<double> frequency;  // Hz, 0 to the Nyquist frequency
    std::vector<double> power;      // mean |DFT|² / Σw² per frequency (a tone of amplitude A: A²/4 at its peak bin)
    double peakFrequency = 0;       // the strongest frequency above 0 Hz (interpolated between bins)
    double rms = 0;                 // of the mono mix
};

// interleaved: `channels` samples per instant (1 or 2); rate in Hz.
// InputError for fewer than 64 instants, a channel count other than 1 or 2,
// a rate outside (0, 10⁶].
SoundSpectrum soundSpectrum(const std::vector<float>& interleaved, int channels, double rate);

}  // namespace stochtex
