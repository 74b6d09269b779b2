#include "stochtex/report/wav.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "stochtex/core/atomic_file.h"

namespace stochtex {

namespace {

void put16(std::string& out, uint16_t v) {
    out += char(v & 0xff);
    out += char(v >> 8);
}
void put32(std::string& out, uint32_t v) {
    put16(out, uint16_t(v & 0xffff));
    put16(out, uint16_t(v >> 16));
}

}  // namespace

void writeWav(const std::string& path, const std::vector<float>& interleaved, int channels, int sampleRate) {
    if (channels < 1 || channels > 8) throw std::invalid_argument("writeWav: channels must be 1 to 8");
    if (sampleRate < 1 || sampleRate > 384000) throw std::invalid_argument("writeWav: rate must be 1 to 384000 Hz");
    const size_t instants = interleaved.size() / size_t(channels);
    const uint64_t dataBytes = uint64_t(instants) * uint64_t(channels) * 2;
    if (dataBytes > 0xffffffffull - 36) throw std::invalid_argument("writeWav: over 4 GiB");
    std::string out;
    out.reserve(size_t(44 + dataBytes));
    out += "RIFF";
    put32(out, uint32_t(36 + dataBytes));
    out += "WAVEfmt ";
    put32(out, 16);  // the format chunk's size
    put16(out, 1);   // PCM
    put16(out, uint16_t(channels));
    put32(out, uint32_t(sampleRate));
    put32(out, uint32_t(sampleRate) * uint32_t(channels) * 2);  // bytes a second
    put16(out, uint16_t(channels * 2));                         // bytes an instant
    put16(out, 16);                                             // bits a sample
    out += "data";
    put32(out, uint32_t(dataBytes));
    for (size_t i = 0; i < instants * size_t(channels); ++i) {
        const float v = std::isfinite(interleaved[i]) ? std::clamp(interleaved[i], -1.0f, 1.0f) : 0.0f;
        put16(out, uint16_t(int16_t(std::lround(v * 32767.0f))));
    }
    writeFileAtomic(path, out);
}

}  // namespace stochtex
