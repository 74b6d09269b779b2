#pragma once
// Reading and writing images: PNG through libpng, EXR written by our
// streamed writer (ExrStreamWriter), the rest through OpenCV imgcodecs in
// the media plugin (media_codecs.h, loaded by the first such file).
//
// Writing, by extension (any case): .png and .tif/.tiff (8-bit by default,
// 16-bit on request; TIFF LZW-compressed), .jpg/.jpeg (8-bit, quality
// kJpegQuality) and .exr (float32 or half, values written as they are; the
// others clamp to [0, 1]). Integer formats go through the options' transfer
// function (colour_space.h): by default the image is linear-light colour and
// its codes are sRGB; EXR stays linear. PNG and EXR take 1 (grey), 3 (RGB)
// or 4 (RGBA) channels and are streamed in bands of rows (PngStreamWriter,
// ExrStreamWriter: ZIP-compressed), so writing holds a band and its encoding
// beside the image; JPEG and TIFF hold their 8- or 16-bit codes and the
// encoded file. Writing is atomic (AtomicFile): the file goes to a temporary file
// beside the target and is renamed, so a failure never leaves a partial file
// under the requested name.
//
// Reading, by content: PNG (through libpng), OpenEXR and JPEG (through OpenCV;
// EXR through a private temporary file, OpenCV's decoder reading only files),
// converted to float in [0,1] (floats as stored), RGB channel order. The
// size is read from the file's header and checked before anything is
// decoded, so a small file that declares a huge image costs nothing; every
// problem is one InputError naming the file (no library warning reaches the
// terminal).
#include <array>
#include <string>
#include <vector>

#include "stochtex/core/atomic_file.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/image/image.h"

namespace stochtex {

struct WriteOptions {
    int bitDepth = 8;      // PNG and TIFF: 8 or 16; JPEG: 8; EXR: not used
    bool exrHalf = false;  // EXR channels as 16-bit half floats (else 32-bit float)
    // Of the integer formats' codes: Srgb encodes linear colour, Linear writes data as it is.
    Transfer transfer = Transfer::Srgb;
};

// For images whose values are the file's codes already (plots, sheets
// composed in sRGB codes, data): no transfer function on writing.
inline const WriteOptions kNoTransfer{.transfer = Transfer::Linear};

// The output formats, as a message lists them.
constexpr const char* kImageOutputFormats = ".png, .exr, .jpg/.jpeg or .tif/.tiff";
// JPEG quality (OpenCV's 0…100 scale; libjpeg's default is 75): 95 keeps an
// 8-bit render within a few steps of the PNG's on smooth areas.
constexpr int kJpegQuality = 95;

// The largest input image: 4096² pixels (the exemplar and colormap limit of
// docs/PATTERNS.md; 256 MB as RGBA floats) in any shape, e.g. the 256 × 25600
// table atlas of an export, up to 65536 pixels per side.
constexpr long long kMaxImagePixels = 4096ll * 4096;
constexpr int kMaxImageSide = 65536;
// The largest input image file (a 4096² RGBA float EXR stored raw is 256 MB).
constexpr long long kMaxImageFileBytes = 512ll << 20;

// Throws InputError naming the path if the file is missing, not a PNG, EXR or
// JPEG image, corrupt, empty (0 pixels) or larger than kMaxImagePixels or
// kMaxImageSide.
Image readImage(const std::string& path);
// The width and height from the file's header, checked as readImage checks
// them, without decoding: what a caller budgets before reading many images.
std::array<int, 2> readImageSize(const std::string& path);

// Throws InputError for an unsupported extension, a bit depth the format
// cannot hold, or an unwritable place.
void writeImage(const std::string& path, const Image& image, const WriteOptions& options = {});
// The image encoded in memory in path's format (by its extension; the bytes
// writeImage writes), for files that embed an image (data: URIs of
// self-contained pages).
std::vector<unsigned char> encodeImage(const std::string& path, const Image& image, const WriteOptions& options = {});

// True if the file is an OpenEXR image (by its first bytes): its values are
// floats, linear as stored, where PNG and JPEG hold integer codes.
bool holdsFloatValues(const std::string& path);

// True if the extension of path is one writeImage accepts.
bool isSupportedImagePath(const std::string& path);
// What writeImage checks before writing anything: the extension is one of
// kImageOutputFormats and the format holds options.bitDepth. InputError
// naming the path otherwise.
void checkImageOutputFormat(const std::string& path, const WriteOptions& options = {});

}  // namespace stochtex
