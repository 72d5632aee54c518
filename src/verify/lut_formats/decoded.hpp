// A table as a file holds it (docs/lut.md, "Files it reads"): the texels as stored (rows in the
// file's order, row 0 first; channels in the format's order), how each value was stored, what the
// file declares about its colour encoding, and what a stored value can hold. Every reader of
// lut_formats/ returns one; none turns rows over, reorders channels or decodes a colour encoding:
// that is the caller's, which can honour what the file declares or say that it does not.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace verify {

// Row j, column i, channel c of an image is data[(j * width + i) * channels + c].
struct lut_image {
    std::size_t width = 0, height = 0, channels = 0;  // channels: 1 to 4
    std::vector<double> data;
    double at(std::size_t row, std::size_t col, std::size_t channel) const {
        return data[(row * width + col) * channels + channel];
    }
};

// How each value is stored in the file.
enum class value_encoding {
    unorm8,        // v / 255
    unorm16,       // v / 65535
    half,          // IEEE binary16
    float32,       // IEEE binary32
    rgbe,          // Radiance's shared exponent: (c + 0.5) 2^(E - 136)
    decimal_text,  // a decimal printed in a source file
    hex_integer,   // an integer in a source file, for the caller to read (binary16 bits, unorm8, unorm16)
};
const char* encoding_name(value_encoding e);  // "unorm8", ..., "decimal-text", "hex-integer"

// What a file declares about the colour encoding of its values. `declared` is the one that
// governs by the format's own rule (PNG: iCCP, else sRGB, else gAMA; ISO/IEC 15948 section 11.3.3);
// the others are what else the file says.
struct colour_declaration {
    enum class kind { none, srgb, gamma, icc, linear };
    kind declared = kind::none;
    std::optional<int> srgb_intent;  // PNG's sRGB chunk: 0 perceptual ... 3 absolute colorimetric
    // the file gamma: stored = linear^gamma (PNG's gAMA, 0.45455 for 1/2.2; 1 / Radiance's GAMMA=)
    std::optional<double> gamma;
    // white x, y, then red, green and blue x, y (PNG's cHRM order; Radiance's PRIMARIES= reordered)
    std::optional<std::array<double, 8>> chromaticities;
    std::string icc_name, icc_profile;  // PNG's iCCP: the profile's name and its bytes, decompressed
};
const char* colour_name(colour_declaration::kind k);  // "none", "srgb", "gamma", "icc", "linear"

struct decoded_lut {
    lut_image image;
    // the container, for records: png8, png16, exr-half, exr-float, ktx2-R16G16_SFLOAT,
    // dds-R16G16_FLOAT, hdr, array-hex, array-decimal, base64-png8, base64-png16
    std::string format;
    value_encoding encoding = value_encoding::float32;
    colour_declaration colour;
    // what a stored value v holds: absolute + relative |v| (8-bit: 0.5/255; 16-bit: 0.5/65535;
    // half: 2^-11 relative, 2^-25 absolute below the normal range; float: 2^-24), or per value
    // where it varies (an RGBE pixel's exponent, a decimal's digits)
    double absolute = 0, relative = 0;
    std::vector<double> precision;  // empty, or one per value of image.data
    double tolerance(std::size_t k) const {
        return precision.empty() ? absolute + relative * std::abs(image.data[k]) : precision[k];
    }

    // The row order the file declares where the format lets it choose: KTX2's KTXorientation
    // ("rd", its default, when absent), Radiance's resolution line ("-Y H +X W", the only one read).
    // Empty for formats with one row order (PNG, OpenEXR, DDS: the first row first).
    std::string orientation;
    double exposure = 1;  // Radiance's EXPOSURE= (their product): the pixels were multiplied by it

    // A source file's array (lut_formats/source_array.hpp): its name, the element type the file
    // names (Uint16Array, float, f32, ...; empty where it names none) and where its shape came
    // from. Without a shape (shaped false) the image is one row of single values.
    std::string array_name, element_type, shape_from;
    bool shaped = true;
};

// Bounds every reader checks before it allocates: a table is at most 4096 texels a side (the
// largest `verify lut --size` makes; a 4097^2 image, every texel an albedo, ran past a minute),
// and a file at most 1 GiB.
constexpr std::size_t max_side = 4096;
constexpr std::size_t max_file_bytes = std::size_t(1) << 30;

}  // namespace verify
