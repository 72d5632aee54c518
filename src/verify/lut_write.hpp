// `verify lut` writing a table as an engine loads it (docs/lut.md, "Formats" and "Layouts"):
// which formats hold which layouts, the points a layout gives its texels in file order, the exact
// values there (the split-sum pair's limits at r = 0 and mu = 0), and the texels as the file
// stores them: the layout's channels in file order, its encoding, the container's own channels.
// lut.cpp checks a request with it before anything is computed; lut_make.cpp writes with it.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <normzoo/microfacet/composition.hpp>

#include "lut_exact.hpp"
#include "lut_layout.hpp"

namespace verify {

// The formats --format takes, in the order the help lists them.
const std::vector<std::string>& lut_formats();

// A table to write in a layout (--layout, --preset): the layout, the keys that gave it, its size.
struct lut_writing {
    lut_layout layout;
    std::string preset;                 // --preset ENGINE, or empty
    layout_keys preset_keys, given;     // the preset's keys, --layout's (which replace them)
    std::size_t width = 0, height = 0;  // texels: columns and rows (Eavg: one row or one column)
    // Which option set a key, for messages: "--layout encoding=half" or "--preset bevy (encoding=half)".
    std::string named(const std::string& key) const;
};

// What the layout w asks of the file in `format`, refused before anything is computed (bad_input
// beginning "lut: " and naming the option): an encoding the format cannot hold (half in a PNG,
// rgbd in OpenEXR, ...), channels a CSV or JSON does not have (they hold the records, A and B by
// name) or more than an image's four, an edges grid of fewer than two texels along an axis, and
// edges where c has no limit derived (docs/lut.md, "Edges"). writes_file: a file in `format` is
// written (--out, or --format given); without one, only the points and sizes are checked.
void check_lut_writing(const lut_writing& w, lut_kind kind, const std::string& format, bool writes_file,
                       const normzoo::microfacet::composition& c);

// The points of w's texels in file order, row by row (docs/lut.md, "Layouts"): for dfg and E a
// list of points (lut_grid::points), for Eavg the roughness of each texel.
lut_grid layout_grid(const lut_writing& w, lut_kind kind);

// The exact values at g's points (layout_grid), one row of them as exact_lut makes a list's, each
// with its bound. E and E_avg at r = 0 or mu = 0 are the pair's A + B there (F = one; the split-sum
// pair's limits, split_sum_to.hpp), which check_lut_writing has made sure exist.
exact_table laid_out_exact(lut_kind kind, const normzoo::microfacet::composition& c, const lut_grid& g, unsigned jobs);

// t's texels (t.width x t.height, file order) as a file in `format` stores them under l: l's
// channels in file order (A, B, A+B, E, E_avg), l's encoding applied (half, unorm codes, sRGB,
// Babylon's RGBD with its divisor in a fourth channel), with what the container adds: png8 is
// RGBA, a KTX2 or DDS of three channels (or of sRGB) has four. A channel "-" or one the container
// adds holds 0, or 1 as the fourth (an alpha, opaque).
lut_image stored_image(const exact_table& t, const lut_layout& l, lut_kind kind, const std::string& format);

// The values of t's named channels that a store under l in `format` clamps: outside [0, 1] in a
// unorm code (an 8- or 16-bit PNG, unorm encodings, sRGB), above 255 in RGBD (its divisor's
// least, 1/255); none in a float. `largest` the largest of them.
std::size_t clamped_values(const exact_table& t, const lut_layout& l, lut_kind kind, const std::string& format, double& largest);

// The file's bytes of a stored image in an image format (png8, png16, exr, exr-half, ktx2,
// ktx2-zstd, dds); a KTX2's VkFormat and a DDS's DXGI format from the image's channels and e.
std::string encode_lut_image(const lut_image& image, const std::string& format, lut_encoding e);

}  // namespace verify
