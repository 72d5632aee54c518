// The exact tables of `verify lut` (docs/lut.md): the kinds, the grid a table is computed on
// (texel centres, listed values or a checked CSV's points), each value with its bound, and the
// records and image made of them. Shared by lut.cpp, lut_make.cpp, lut_read.cpp and lut_check.cpp.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <normzoo/microfacet/composition.hpp>
#include <normzoo/quadrature/estimate.hpp>

#include "lut_image.hpp"
#include "part_inputs.hpp"
#include "writers.hpp"

namespace verify {

enum class lut_kind { dfg, e, eavg };

struct lut_grid {
    std::vector<double> mus;        // columns (empty for Eavg)
    std::vector<double> roughness;  // rows: r or alpha as given
    bool perceptual = true;         // roughness is r, alpha = r^2
    // Listed decimals: how far each mu and each alpha computed at can be from the one typed
    // (microfacet_tables.hpp, mu_of and alpha_of); empty at texel centres, which doubles hold.
    std::vector<double> mu_delta, alpha_delta;
    double f0 = 1, f0_delta = 0;  // E and Eavg: the F0 of the composition's F part (--f0), as typed
    part_inputs parts;            // the parts' parameters as typed (set in the composition too)
    bool points = false;          // a list of points (a CSV's rows): roughness[j] goes with mus[j]
    double alpha(std::size_t j) const { return perceptual ? roughness[j] * roughness[j] : roughness[j]; }
};

// Texel centres of an n-texel axis: (i + 0.5) / n (docs/lut.md, "Texel centres").
std::vector<double> texel_centres(std::size_t n);

// "dfg", "E" or "Eavg", as --kind takes it.
std::string lut_kind_name(lut_kind k);

// The kind --kind names; bad_input for another text.
lut_kind lut_kind_of(const std::string& text);

// --kind sheen-E: an E table of KHR_materials_sheen's sheen, charlie/charlie-sheen/one (the glTF
// Sample Viewer's lut_sheen_E, docs/lut.md#sheen-tables), unless --model names another.
inline const std::string sheen_e_kind = "sheen-E";
inline const std::string sheen_e_model = "charlie/charlie-sheen/one";

// The value columns of a kind: A and B (dfg), E, or E_avg.
std::vector<std::string> lut_channels(lut_kind k);

// The exact table: values[(j * width + i) * channels + c] with their bounds.
struct exact_table {
    std::size_t width = 0, height = 0, channels = 0;
    std::vector<normzoo::quadrature::estimate<double>> values;
};

// The exact values of kind at g's texels (one row of texels for Eavg and for a list of points),
// each bound widened by what the rounding of g's typed inputs can move it. wanted: the absolute
// tolerance each value is computed to (laid out as the values; a check's, docs/lut.md, "How a
// check chooses its accuracy"); null: 1e-10 each. E under Kulla-Conty takes 1e-10 whatever is
// wanted: its terms of alpha are computed once, at 1e-10.
exact_table exact_lut(lut_kind kind, const normzoo::microfacet::composition& c, const lut_grid& g, unsigned jobs,
                      const std::vector<double>* wanted = nullptr);

// One `lut` record per texel, and the table's head.
table_output lut_records(lut_kind kind, const normzoo::microfacet::composition& c, const lut_grid& g, const exact_table& t);

// The values alone, for the image and header formats.
lut_image lut_image_of(const exact_table& t);

}  // namespace verify
