#pragma once
// The mapping of output pixels to texture space that every unfiltered
// render and the zoom camera use, and the caps on an output's size. Its own
// unit, below the pattern file's parser and every evaluator, so both can
// speak of a view without including each other.

namespace stochtex {

constexpr int kMaxOutputSide = 16384;
constexpr long long kMaxOutputPixels = 8192LL * 8192LL;

// Maps output pixels to texture space: pixel (px, py) covers example texels
// offset + (p + ½)·scale, i.e. uv = (offset + (p + ½)·scale) / W.
struct View {
    int width = 512, height = 512;
    double scale = 1.0;              // example texels per output pixel
    double offsetU = 0, offsetV = 0;  // in example texels
};

// Checks a view against the output caps; InputError::parameter naming size,
// scale or offset otherwise.
void validateView(const View& view);

}  // namespace stochtex
