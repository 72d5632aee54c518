// --brdf's --texture NAME=FILE (docs/brdf-code.md#textures): a table in any file `lut --check`
// reads, under --layout's keys that mean something to a sampler (row0, col0, encoding, size),
// made into the texels a shader's sampler2D or Texture2D sees: four channels per texel (those the
// file lacks as a GPU fills them, 0, 0, 0, 1), row 0 at v = 0, column 0 at u = 0; and each
// texel at the low and the high end of what its storage holds, for the albedo's storage bound.
// Bad input throws bad_input naming the option or the file.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "lut_layout.hpp"

namespace verify {

struct texture_option {
    std::string name, file;
};

// One --texture value: NAME=FILE, NAME an identifier as shading languages spell them, FILE not
// empty. bad_input naming --texture otherwise.
texture_option parse_texture_option(const std::string& text);

// Every --texture value, a name bound at most once.
std::vector<texture_option> parse_texture_options(const std::vector<std::string>& given);

// --layout's text as a sampler reads it: lut's keys (lut_layout.hpp), of which rows, cols, grid
// and channels, which say what a table's texels mean, and encoding=rgbd, which a shader decodes
// after filtering, are refused with why.
layout_keys parse_texture_layout(const std::string& text);

struct texture_table {
    std::string name, file, format;
    std::size_t width = 0, height = 0;
    std::vector<double> rgba, low, high;  // [4 * (row * width + column) + channel]: the value, its storage's ends
    double largest_step = 0;             // the largest (high - low) / 2
};

// The most texels a bound table may have (docs/brdf-code.md#textures).
constexpr std::size_t max_texture_texels = std::size_t(1) << 20;

// The file read under the layout keys; bad_input naming --texture NAME and the file, or for a
// table of more than max_texture_texels.
texture_table read_texture(const texture_option& t, const layout_keys& layout);

}  // namespace verify
