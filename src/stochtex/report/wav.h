#pragma once
// A sound as a WAV file (RIFF, 16-bit PCM): what any player and audio tool opens.
#include <string>
#include <vector>

namespace stochtex {

// interleaved: `channels` samples per instant, each in [−1, 1] (clamped).
// Written atomically (a temporary file moved into place). InputError naming
// the path when it cannot be written; std::invalid_argument for channels
// outside 1–8 or a rate outside 1–384000 Hz.
void writeWav(const std::string& path, const std::vector<float>& interleaved, int channels, int sampleRate);

}  // namespace stochtex
