#include "stochtex/report/animated_gif.h"

#include <gif_lib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "stochtex/core/atomic_file.h"
#include "stochtex/core/error.h"

namespace stochtex {

struct AnimatedGifWriter::Encoder {
    std::unique_ptr<AtomicFile> file;
    GifFileType* gif = nullptr;
    ~Encoder() { close(); }
    // Closes giflib's handle (and with it the descriptor); false on a write error.
    bool close() {
        if (!gif) return true;
        int error = 0;
        const bool ok = EGifCloseFile(gif, &error) == GIF_OK;
        gif = nullptr;
        return ok;
    }
    void check(int status, const char* what) const {
        if (status != GIF_OK)
            throw InputError(file->path() + ": cannot write the GIF (" + what + ": " +
                             (GifErrorString(gif->Error) ? GifErrorString(gif->Error) : "unknown error") + ")");
    }
};

// A quantised frame waiting for its delay, which the next kept frame's start gives.
struct AnimatedGifWriter::Pending {
    int start = 0;  // centiseconds
    int bits = 1;   // log2 of the palette's size
    std::vector<GifColorType> palette;
    std::vector<GifByteType> indices;
};

AnimatedGifWriter::AnimatedGifWriter(const std::string& path, int width, int height, double fps)
    : width_(width), height_(height), fps_(fps), encoder_(std::make_unique<Encoder>()) {
    if (width < 1 || height < 1 || width > 65535 || height > 65535)
        throw InputError(path + ": a GIF is 1 to 65535 pixels a side, got " + std::to_string(width) + "x" +
                         std::to_string(height));
    if (!(fps > 0 && fps <= 1000)) throw InputError(path + ": fps must be in (0, 1000], got " + formatValue(fps));
    encoder_->file = std::make_unique<AtomicFile>(path, ".tmp.gif");
    int error = 0;
    // giflib owns the descriptor from here and closes it in EGifCloseFile.
    encoder_->gif = EGifOpenFileHandle(encoder_->file->releaseDescriptor(), &error);
    if (!encoder_->gif) throw InputError(path + ": cannot write the GIF (" + GifErrorString(error) + ")");
    EGifSetGifVersion(encoder_->gif, true);  // GIF89a: delays and looping
    encoder_->check(EGifPutScreenDesc(encoder_->gif, width, height, 8, 0, nullptr), "screen");
    // The NETSCAPE2.0 application extension: loop count 0, forever.
    const unsigned char application[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
    const unsigned char loop[] = {1, 0, 0};
    encoder_->check(EGifPutExtensionLeader(encoder_->gif, APPLICATION_EXT_FUNC_CODE), "loop");
    encoder_->check(EGifPutExtensionBlock(encoder_->gif, sizeof application, application), "loop");
    encoder_->check(EGifPutExtensionBlock(encoder_->gif, sizeof loop, loop), "loop");
    encoder_->check(EGifPutExtensionTrailer(encoder_->gif), "loop");
}

AnimatedGifWriter::~AnimatedGifWriter() = default;

void AnimatedGifWriter::add(const Image& codes) {
    if (codes.width() != width_ || codes.height() != height_ || (codes.channels() != 1 && codes.channels() != 3))
        throw std::invalid_argument("AnimatedGifWriter::add: frame of another size or channel count");
    if (!encoder_->gif) throw std::logic_error("AnimatedGifWriter::add after finish");
    // Frame k starts at round(100·k/fps) centiseconds. Browsers show a delay
    // under 2 cs as 10 cs, so a frame that would start under 2 cs after the
    // one before is dropped: above 50 fps the clip keeps its pace with fewer frames.
    const int start = int(std::lround(100.0 * count_ / fps_));
    ++count_;
    if (pending_ && start - pending_->start < 2) return;
    if (pending_) put(*pending_, start - pending_->start);
    else pending_ = std::make_unique<Pending>();

    const size_t n = size_t(width_) * size_t(height_);
    std::vector<GifByteType> red(n), green(n), blue(n);
    const int channels = codes.channels();
    for (size_t i = 0; i < n; ++i) {
        const float* p = codes.data().data() + i * size_t(channels);
        auto code = [](float v) { return GifByteType(std::lround(255.0f * std::clamp(v, 0.0f, 1.0f))); };
        red[i] = code(p[0]);
        green[i] = code(p[channels == 3 ? 1 : 0]);
        blue[i] = code(p[channels == 3 ? 2 : 0]);
    }
    Pending& f = *pending_;
    f.start = start;
    f.indices.resize(n);
    f.palette.assign(256, GifColorType{0, 0, 0});
    int colours = 256;
    if (GifQuantizeBuffer(unsigned(width_), unsigned(height_), &colours, red.data(), green.data(), blue.data(),
                          f.indices.data(), f.palette.data()) != GIF_OK)
        throw std::runtime_error("giflib: cannot quantise a frame");
    // giflib's median cut works on 5 bits a primary and gives each colour
    // the centre of its box at that precision (white comes out 248): each
    // entry becomes the mean of the 8-bit colours mapped to it, so a flat
    // area keeps its exact colour.
    std::vector<std::array<uint64_t, 4>> sums(size_t(colours), {0, 0, 0, 0});
    for (size_t i = 0; i < n; ++i) {
        std::array<uint64_t, 4>& sum = sums[f.indices[i]];
        sum[0] += red[i], sum[1] += green[i], sum[2] += blue[i], sum[3] += 1;
    }
    for (int k = 0; k < colours; ++k) {
        const std::array<uint64_t, 4>& sum = sums[size_t(k)];
        if (sum[3] == 0) continue;
        auto mean = [&](uint64_t total) { return GifByteType((2 * total + sum[3]) / (2 * sum[3])); };
        f.palette[size_t(k)] = GifColorType{mean(sum[0]), mean(sum[1]), mean(sum[2])};
    }
    // A palette's size is a power of two; the entries past `colours` stay black, unused.
    f.bits = 1;
    while ((1 << f.bits) < colours) ++f.bits;
}

void AnimatedGifWriter::put(const Pending& f, int delay) {
    ColorMapObject* map = GifMakeMapObject(1 << f.bits, f.palette.data());
    if (!map) throw std::bad_alloc();
    GraphicsControlBlock control{};
    control.DisposalMode = DISPOSE_DO_NOT;
    control.DelayTime = delay;
    control.TransparentColor = NO_TRANSPARENT_COLOR;
    GifByteType block[4];
    EGifGCBToExtension(&control, block);
    int status = EGifPutExtension(encoder_->gif, GRAPHICS_EXT_FUNC_CODE, sizeof block, block);
    if (status == GIF_OK) status = EGifPutImageDesc(encoder_->gif, 0, 0, width_, height_, false, map);
    GifFreeMapObject(map);
    for (int y = 0; y < height_ && status == GIF_OK; ++y)
        status = EGifPutLine(encoder_->gif, const_cast<GifByteType*>(f.indices.data()) + size_t(y) * size_t(width_), width_);
    encoder_->check(status, "frame");
}

std::string AnimatedGifWriter::finish() {
    if (!pending_) throw std::logic_error("AnimatedGifWriter::finish: no frame");
    const int end = int(std::lround(100.0 * count_ / fps_));
    put(*pending_, std::max(end - pending_->start, 2));
    pending_.reset();
    if (!encoder_->close()) throw InputError(encoder_->file->path() + ": cannot write the GIF (closing it failed)");
    encoder_->file->commit();
    return encoder_->file->path();
}

}  // namespace stochtex
