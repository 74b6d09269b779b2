#pragma once
// What an image's values mean, and the conversions between sRGB codes and
// linear light (docs/MATH.md, "Colour space"). The curve itself is
// kernel/colour.glsl, shared with the shaders; these apply it to images.
//
// stochtex keeps colours linear in memory (colormap tables, renders): they
// are decoded where they enter (colormap specs and images) and encoded where
// they leave as integer codes (8/16-bit PNG, video frames, the window).
// Float files (EXR) hold linear values as they are.
#include <algorithm>
#include <cmath>

#include "stochtex/core/enum_names.h"
#include "stochtex/image/image.h"

namespace stochtex {

// The transfer function between an image's values and the codes of an
// integer file.
//   Srgb:   the values are linear-light colour; integer codes are sRGB
//           (decode on reading, encode on writing).
//   Linear: no transfer function: codes are the values. For data (noise
//           values, heights, roughness, normals) and for images already
//           composed in display codes (plots, sheets).
enum class Transfer { Srgb, Linear };
inline const EnumNames<Transfer> kTransferNames{{"srgb", Transfer::Srgb}, {"linear", Transfer::Linear}};

// The sRGB curve on one value (clamped to [0, 1]).
float srgbFromLinear(float linear);
float linearFromSrgb(float code);

// Every channel of an image through the curve (values clamped to [0, 1]).
Image srgbFromLinear(const Image& linear);
Image linearFromSrgb(const Image& codes);
// As written to (or read from) an integer file with this transfer: the
// encoded (decoded) image for Srgb, the image itself for Linear.
Image encodeTransfer(const Image& image, Transfer transfer);
Image decodeTransfer(const Image& image, Transfer transfer);

// A value (after the transfer) as an integer code 0..maxCode (255, 65535):
// clamped to [0, 1] (NaN to 0), then rounded half to even as OpenCV's
// convertTo rounds, so every integer file (PNG, TIFF, JPEG) gets the same codes.
inline long integerCode(float v, float maxCode) { return v > 0.0f ? std::lrint(maxCode * std::min(v, 1.0f)) : 0; }

}  // namespace stochtex
