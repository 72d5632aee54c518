// How an engine lays out its table (docs/lut.md, "Layouts"): which quantity the rows and the
// columns index, which end each starts at, where the texels sit, what the channels hold in file
// order and how the values are encoded. One small value, read from `--layout KEY=VALUE,...` (or a
// preset's keys, lut_presets.hpp), with one canonical text: the lut-check records' `layout`.
#pragma once
#include <cstddef>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "lut_exact.hpp"

namespace verify {

enum class lut_axis { r, alpha, mu, sqrt_mu };               // what an axis indexes
enum class lut_origin { low, high };                         // the first row (column) is its low or high end
enum class lut_spacing { centres, edges, filament };         // where the texels sit along an axis
enum class lut_encoding { linear, srgb, rgbd, half, unorm8, unorm10, unorm16 };

struct lut_layout {
    lut_axis rows = lut_axis::r, cols = lut_axis::mu;
    lut_origin row0 = lut_origin::low, col0 = lut_origin::low;
    lut_spacing grid = lut_spacing::centres;
    std::vector<std::string> channels;  // file order: A, B, A+B, E, E_avg, "-" (skipped); empty: the kind's
    lut_encoding encoding = lut_encoding::linear;
    std::size_t width = 0, height = 0;  // size=WxH; 0: the file's own shape
    // size=WxHxD: D slices of W x H stored one after another ([D][H][W], as a C array declares
    // them), each at its own index eta (docs/lut.md, "Slices"); 1: one table
    std::size_t slices = 1;
};

// A --layout text's keys in the order given, each value checked: bad_input beginning with
// `what` ("lut: --layout") and naming the key for an unknown key or value, a key given twice, or
// an item that is not KEY=VALUE (but the channels' own items: channels=B,A+B,-).
using layout_keys = std::vector<std::pair<std::string, std::string>>;
layout_keys parse_layout_keys(const std::string& text, const std::string& what);

// How the checked file is read: the layout (a preset's keys, then --layout's), which keys the
// user fixed, which ones the preset or --layout names, and whether the layout and model are to be
// found.
struct lut_reading {
    lut_layout layout;
    layout_keys given;             // --layout's keys: detection keeps them
    std::set<std::string> stated;  // the keys the preset or --layout names
    bool detect = false;           // --detect
    bool model_given = false;      // --model (or a preset's): detection keeps it
    // size=WxHxD: the index eta of each slice, in the order stored (--eta's list, or the preset's)
    std::vector<normzoo::decimal> slice_eta;
};

// The keys set in l (later ones win).
void apply_layout_keys(lut_layout& l, const layout_keys& keys);

// bad_input (beginning with `what`) for a layout no table of kind has: two roughness axes or
// two of mu, channels that are not the kind's, a key Eavg's one axis does not read.
void check_layout(const lut_layout& l, lut_kind kind, const layout_keys& given, const std::string& what);

// The channels read, in file order ("-" included): l.channels, or the kind's (A,B; E; E_avg).
std::vector<std::string> layout_channels(const lut_layout& l, lut_kind kind);

// The canonical text: every key the kind reads in one order ("rows=mu,cols=r,row0=low,col0=low,
// grid=centres,channels=A,B,encoding=half"), size last where given; Eavg has no cols or col0.
std::string layout_text(const lut_layout& l, lut_kind kind);

// The names of an axis and an encoding, as the keys take them.
std::string axis_name(lut_axis a);
std::string encoding_name(lut_encoding e);

inline bool is_roughness(lut_axis a) { return a == lut_axis::r || a == lut_axis::alpha; }

// The coordinate texel i of n holds along an axis (r, alpha, mu or sqrt-mu as the axis names it):
// centres (t + 0.5)/n, edges t/(n - 1), filament min(1, (t + 1.5)/n) on a roughness axis and
// centres on mu; t = i from the low end, n - 1 - i from the high end (docs/lut.md, "Layouts").
double axis_coordinate(lut_spacing grid, bool roughness, lut_origin origin, std::size_t i, std::size_t n);

// mu from a coordinate along a mu axis, alpha from one along a roughness axis.
inline double mu_of_coordinate(lut_axis a, double u) { return a == lut_axis::sqrt_mu ? u * u : u; }
inline double alpha_of_coordinate(lut_axis a, double u) { return a == lut_axis::r ? u * u : u; }

// Whether the exact values take a point: mu and alpha at least 1e-8 (microfacet/albedo.hpp).
bool comparable_point(double mu, double alpha);

// Whether c's split-sum pair has its limit at an edge point (mu = 0 or alpha = 0, a grid=edges
// texel): split_sum_to gives it for Smith's two G and refuses other compositions (docs/lut.md,
// "Edges").
bool pair_has_limit(const normzoo::microfacet::composition& c, double mu, double alpha);

// The file at path as a check under `reading` reads it (docs/lut.md, "Files it reads"): a source
// file's array shaped by size=WxH, its hex integers read as encoding=half, unorm8 or unorm16 says.
// What neither the file nor the layout says is refused (bad_input naming the file) rather than
// compared wrongly: an array without a size, hex integers without one of those encodings, a KTX2
// KTXorientation other than rd where the layout names no row0 (for ?u) or col0 (for l?) and
// --detect does not find them, an HDR picture with EXPOSURE=, a KTX2 or DDS format of
// sRGB-encoded values unless encoding=srgb (or --detect, which then tries srgb alone).
decoded_lut read_laid_out(const std::string& path, const lut_reading& reading, lut_kind kind);

// A KTX2 or DDS file of an sRGB format: its values are what a sampler decodes (a PNG's colour
// chunks are metadata only).
bool sampled_as_srgb(const decoded_lut& d);

// A stored value decoded as its encoding says, with how far it is known to be from what was
// stored before rounding (what the file holds of it, decoded_lut::tolerance, carried through the
// decode).
struct stored_value {
    double value = 0, tolerance = 0;
};
stored_value decode_texel(const decoded_lut& d, lut_encoding e, std::size_t texel, std::size_t channel);

// Half the step of values stored as e at v: half an ulp of half (2^-11 |v| + 2^-25), half of
// 1/255, 1/1023 or 1/65535; 0 for the others (their storage is the file's).
double encoding_step(lut_encoding e, double v);

// A table of l.slices slices (size=WxHxD) as read: its texels as W x (H D), slice after slice;
// bad_input naming the file where the file's texel count is not W H D.
decoded_lut slices_of(decoded_lut d, const lut_layout& l, const std::string& path);

// (Slice k of it: lut_formats/texels.hpp, decoded_slice.)

// d as the layout shapes it: size=WxH applied (the same texels, row by row), and an Eavg table
// (one row or one column) as one column of n rows. bad_input naming the file for a size that is
// not the file's texel count, a shape the kind cannot have, too few channels for the layout.
decoded_lut shaped_lut(decoded_lut d, const lut_layout& l, lut_kind kind, const std::string& path);

// An engine's table as the check reads it: per texel its values in the named channels with
// what their storage holds, and per compared texel its point.
struct read_table {
    std::string format;
    std::size_t width = 0, height = 0;       // columns and rows; a CSV's points: one row
    bool grid = false;                       // rows and columns have coordinates (an image)
    std::vector<std::string> channels;       // named, in file order ("-" left out)
    std::vector<double> values, tolerance;   // [texel * channels.size() + c]
    lut_grid points;                         // the compared texels' mu and roughness (r or alpha), points = true
    std::vector<std::size_t> texel;          // point p is texel texel[p]
    std::vector<double> row_coord, col_coord;  // grid: each row's and column's own coordinate
    lut_axis row_axis = lut_axis::r, col_axis = lut_axis::mu;
};

// A shaped table (shaped_lut) read under l. edges: for a split-sum table, the model whose limits
// the texels at r = 0 and mu = 0 are compared with where it has them (pair_has_limit); the
// others there, and every one without it, are not compared.
read_table lay_out(const decoded_lut& d, const lut_layout& l, lut_kind kind,
                   const normzoo::microfacet::composition* edges = nullptr);

// The exact value of a named channel at point p of t: A, B, their sum A+B (the bounds summed),
// E or E_avg.
normzoo::quadrature::estimate<double> exact_channel(const exact_table& t, const std::string& name, std::size_t p);

}  // namespace verify
