// A baked table as an image, in the formats engines load (docs/lut.md): 16-bit PNG (libpng),
// float or half OpenEXR (the OpenEXR library) and a C header of floats; and an engine's own
// table read back for `verify lut --check`, from any of the files lut_formats/ reads (PNG,
// OpenEXR, KTX2, DDS, Radiance HDR, a source file's array), as decoded.hpp describes it.
// Row j of the image is the j-th roughness, column i the i-th mu; channel c of texel (j, i) is
// data[(j * width + i) * channels + c].
#pragma once
#include <string>

#include "lut_formats/decoded.hpp"
#include "lut_formats/exr.hpp"
#include "lut_formats/png.hpp"

namespace verify {

// A C header: `static const float NAME[HEIGHT][WIDTH][CHANNELS] = {...};` with each value printed
// to 9 significant digits (a float's round trip), preceded by `comment` as // lines.
std::string encode_c_header(const lut_image& image, const std::string& name, const std::string& comment);

// Reads an engine's table (lut_formats/read.hpp, read_lut_file, with no request): images told
// apart by their signatures, a source file's array by its name. Throws bad_input (args.hpp)
// naming the file and what is wrong: none of these, truncated, unreadable, palette images, an
// image of size 0.
decoded_lut read_lut_image(const std::string& path);

}  // namespace verify
