// OpenEXR through the OpenEXR library (docs/lut.md, "Files it reads"): a baked table written as
// float or half, and an engine's image read as stored.
#pragma once
#include <string>

#include "decoded.hpp"

namespace verify {

// Scanline, no compression, channels named R, G, B, A (or Y for one), float or half; row 0 is the
// first scanline.
std::string encode_exr(const lut_image& image, bool half);

// Half or float channels Y, R G, R G B or R G B A, all of one type, not subsampled; any data
// window; read in strips. Throws bad_input (args.hpp) naming path: truncated or corrupt, integer
// channels, other channel names, a size of 0 or more than max_side a side.
decoded_lut read_exr(const std::string& path, const std::string& bytes);

}  // namespace verify
