// A baked table as an image, in the formats engines load (docs/lut.md): 16-bit PNG (libpng),
// float or half OpenEXR (the OpenEXR library) and a C header of floats; and an engine's own
// image read back for `verify lut --check` (8- or 16-bit PNG, half or float EXR).
// Row j of the image is the j-th roughness, column i the i-th mu; channel c of texel (j, i) is
// data[(j * width + i) * channels + c].
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace verify {

struct lut_image {
    std::size_t width = 0, height = 0, channels = 0;  // channels: 1 to 4
    std::vector<double> data;
    double at(std::size_t row, std::size_t col, std::size_t channel) const {
        return data[(row * width + col) * channels + channel];
    }
};

// An image read from a file, with what its format can hold: a value v is known to within
// absolute + relative |v| (8-bit: 0.5/255; 16-bit: 0.5/65535; half: 2^-11 relative, float 2^-24).
struct decoded_lut {
    lut_image image;
    std::string format;  // "png8", "png16", "exr-half", "exr-float"
    double absolute = 0, relative = 0;
};

// The bytes of a file (staged through file_set, so nothing is half-written). PNG: 16 bits per
// channel, values clamped to [0, 1] and rounded to the nearest of 65535 steps: 1 channel gray,
// 2 channels RGB with B = 0 (a split-sum texture's layout), 3 RGB, 4 RGBA.
std::string encode_png16(const lut_image& image);
// OpenEXR, scanline, no compression, channels named R, G, B, A (or Y for one), float or half.
std::string encode_exr(const lut_image& image, bool half);
// A C header: `static const float NAME[HEIGHT][WIDTH][CHANNELS] = {...};` with each value printed
// to 9 significant digits (a float's round trip), preceded by `comment` as // lines.
std::string encode_c_header(const lut_image& image, const std::string& name, const std::string& comment);

// Reads an engine's table: PNG (8 or 16 bit; gray, gray+alpha, RGB or RGBA) or OpenEXR (half or
// float; channels R, G, B, A or Y), told apart by their signatures. Throws bad_input (args.hpp)
// naming the file and what is wrong: not a PNG or EXR, truncated, unreadable, palette images,
// an image of size 0.
decoded_lut read_lut_image(const std::string& path);

}  // namespace verify
