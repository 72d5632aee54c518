// PNG through libpng (docs/lut.md, "Files it reads"): a baked table written as a 16- or 8-bit PNG, and
// an engine's PNG read as stored, with what its colour chunks declare.
#pragma once
#include <string>

#include "decoded.hpp"

namespace verify {

// 16 bits per channel, values clamped to [0, 1] and rounded to the nearest of 65535 steps:
// 1 channel gray, 2 channels RGB with B = 0 (a split-sum texture's layout), 3 RGB, 4 RGBA.
std::string encode_png16(const lut_image& image);

// The same in 8 bits per channel, 255 steps (`verify lut --format png8` hands it RGBA).
std::string encode_png8(const lut_image& image);

// An 8- or 16-bit PNG (gray, gray+alpha, RGB or RGBA; interlaced or not) held in bytes, as stored:
// alpha is never associated, no colour chunk is applied. Its sRGB, gAMA, cHRM and iCCP chunks
// (those before the image data, as the PNG specification places them) are reported in `colour`.
// Throws bad_input (args.hpp) naming path: truncated or corrupt, palette images, other depths,
// a size of 0 or more than max_side a side.
decoded_lut read_png(const std::string& path, const std::string& bytes);

}  // namespace verify
