#pragma once
// Reading and writing images through OpenCV imgcodecs.
//
// Formats by extension: .png (8-bit by default, 16-bit on request) and .exr
// (float32, values written as they are). Reading converts any 8/16-bit or
// float file to float in [0,1] (floats as stored), with RGB channel order.
// Writing is atomic: the file is encoded in memory, written to a temporary
// file beside the target and renamed, so a failure never leaves a partial
// file under the requested name.
#include <string>

#include "stochtex/image/image.h"

namespace stochtex {

struct WriteOptions {
    int pngBitDepth = 8;  // 8 or 16
    bool exrHalf = false;  // EXR channels as 16-bit half floats (else 32-bit float)
};

// Throws InputError naming the path if the file is missing or not an image.
Image readImage(const std::string& path);

// Throws InputError for an unsupported extension or an unwritable place.
void writeImage(const std::string& path, const Image& image, const WriteOptions& options = {});

// Writes bytes atomically (temp + rename); used by every file the CLI writes.
void writeFileAtomic(const std::string& path, const std::string& bytes);

// True if the extension of path is one writeImage accepts.
bool isSupportedImagePath(const std::string& path);

}  // namespace stochtex
