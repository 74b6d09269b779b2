#pragma once
// A PNG written a band of rows at a time (libpng), so images larger than
// memory can be produced: memory is one band, whatever the image size. The
// file appears under its name only when finish() succeeds (AtomicFile). The
// same encoder writes into memory (a page's data: URI), so a PNG's bytes are
// the same wherever they go.
#include <memory>
#include <string>
#include <vector>

#include "stochtex/image/colour_space.h"
#include "stochtex/image/image.h"

namespace stochtex {

class PngStreamWriter {
public:
    // bits: 8 or 16; the bands written must have `channels` channels (1: grey,
    // 2: grey + alpha, 3: RGB, 4: RGBA);
    // transfer: of the codes, as WriteOptions::transfer (Srgb: bands are linear colour).
    PngStreamWriter(const std::string& path, int width, int height, int channels, int bits = 8,
                    Transfer transfer = Transfer::Srgb);
    // Into `out` (appended to), complete when finish() returns; `name` is what errors name.
    PngStreamWriter(std::vector<unsigned char>& out, const std::string& name, int width, int height, int channels,
                    int bits = 8, Transfer transfer = Transfer::Srgb);
    ~PngStreamWriter();  // removes the temporary file if finish() was not reached
    PngStreamWriter(const PngStreamWriter&) = delete;
    PngStreamWriter& operator=(const PngStreamWriter&) = delete;

    // The next band of rows, top to bottom (values clamped to [0, 1], then encoded).
    void writeRows(const Image& band);
    void finish();

private:
    void start(int width, int height, int channels, int bits, Transfer transfer);
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace stochtex
