#pragma once
// The one image type of stochtex: W×H pixels of C float32 channels,
// interleaved, row-major, row 0 at the top. Values are nominally in [0,1].
#include <cstddef>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace stochtex {

// The allocator of bulk float data (images, pyramid levels, tables):
//   * it default-initialises: vector<float>(n) leaves the floats unset
//     instead of zeroing them, so a producer that writes every value (a
//     parallel render, a pyramid level) does not pay a serial memset and its
//     page faults first;
//   * a block of 2 MiB or more is 2 MiB aligned and advised to use
//     transparent huge pages (Debian's default THP mode is "madvise"), so
//     first touch costs one page fault per 2 MiB instead of 512: the faults
//     of a 4096² pyramid were most of its build time.
void* allocateBulk(size_t bytes);
void freeBulk(void* p) noexcept;

template <class T>
struct BulkAllocator {
    using value_type = T;
    BulkAllocator() = default;
    template <class U>
    BulkAllocator(const BulkAllocator<U>&) noexcept {}
    // Plain malloc alignment for small blocks.
    static_assert(alignof(T) <= alignof(std::max_align_t));
    T* allocate(size_t n) {
        if (n > std::numeric_limits<size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
        return static_cast<T*>(allocateBulk(n * sizeof(T)));
    }
    void deallocate(T* p, size_t) noexcept { freeBulk(p); }
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
    template <class U>
    bool operator==(const BulkAllocator<U>&) const noexcept {
        return true;
    }
};

class Image {
public:
    using Buffer = std::vector<float, BulkAllocator<float>>;
    struct Uninitialized {};

    Image() = default;
    Image(int width, int height, int channels, float fill = 0.0f);
    // Pixels left unset: for producers that overwrite every value.
    Image(int width, int height, int channels, Uninitialized);

    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return channels_; }
    bool empty() const { return data_.empty(); }
    size_t pixelCount() const { return size_t(width_) * size_t(height_); }

    float& at(int x, int y, int c = 0) { return data_[index(x, y, c)]; }
    float at(int x, int y, int c = 0) const { return data_[index(x, y, c)]; }
    float* row(int y) { return data_.data() + size_t(y) * size_t(width_) * size_t(channels_); }
    const float* row(int y) const { return data_.data() + size_t(y) * size_t(width_) * size_t(channels_); }
    Buffer& data() { return data_; }
    const Buffer& data() const { return data_; }

private:
    size_t index(int x, int y, int c) const {
        return (size_t(y) * size_t(width_) + size_t(x)) * size_t(channels_) + size_t(c);
    }
    int width_ = 0, height_ = 0, channels_ = 0;
    Buffer data_;
};

// Same pixels with 3 channels (gray is replicated; extra channels are dropped).
Image toRgb(const Image& image);
// One channel: RGB(A) by the thesis's luminosity formula
// I = 0.21 r + 0.72 g + 0.07 b (Tavernier 2017, Figure 2.17; alpha is not a
// colour), two channels by their average, one channel as it is.
Image toGray(const Image& image);
// Channel c of the image (0 ≤ c < channels, std::out_of_range otherwise), as a 1-channel image.
Image channelOf(const Image& image, int c);
// The image moved periodically: out(x, y) = in((x + dx) mod W, (y + dy) mod H).
Image shiftedPeriodic(const Image& image, int dx, int dy);
// Nearest-neighbour resize, used for showing small tables large in sheets.
Image resizeNearest(const Image& image, int width, int height);
// Bilinear (area for shrinking) resize through OpenCV.
Image resizeSmooth(const Image& image, int width, int height);
// The width × height pixels from (x, y); std::out_of_range unless inside the image.
Image crop(const Image& image, int x, int y, int width, int height);
// Copies src into dst with its top-left corner at (x, y); channels must match.
void paste(Image& dst, const Image& src, int x, int y);
// Writes a text label (white on a dark strip) at the bottom-left of a region.
void drawLabel(Image& image, int x, int y, int width, const char* text);

// Per-channel mean and (population) standard deviation.
struct ChannelStats {
    double mean = 0.0;
    double stddev = 0.0;
};
ChannelStats channelStats(const Image& image, int channel = 0);

// InputError naming `file` and the first pixel whose value leaves [lo, hi]
// (NaN and ±inf included): float images (EXR) can hold anything, and a value
// far out of range overflows the float moments of what is made from them
// (E² of 1e20 is inf, inf − inf a NaN σ). `what` names the use ("colormap").
void checkPixelRange(const Image& img, const std::string& file, double lo, double hi, const std::string& what);

}  // namespace stochtex
