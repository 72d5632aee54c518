// What a check of an engine's table measures beside its verdict (docs/lut.md, "The lookup's
// error"): the error of the bilinear lookup a shader makes of the table as stored, on a grid finer
// than the texels, and the map of each texel's error the check's figure draws. Neither changes
// pass or fail.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <normzoo/microfacet/composition.hpp>

#include "lut_layout.hpp"
#include "plots.hpp"

namespace verify {

// The largest error of a lookup and where: mu, the roughness as the table indexes it (r or
// alpha) and alpha. error < 0: no point measured.
struct lookup_worst {
    double error = -1, mu = 0, roughness = 0, alpha = 0;
    double between = 0;  // the largest between the outermost texels (in no band): the interpolation's alone
};

// A table's lookup against the exact values: per channel (read_table::channels' order) and, for
// a split-sum table, of E = F0 A + B at F0 = 0.04 and 1; at how many points.
struct lookup_errors {
    std::size_t points = 0;
    std::vector<lookup_worst> channels;
    std::optional<lookup_worst> dielectric, metal;
};

// The table t (an image, read under its layout) sampled as a shader samples it: along each axis
// linear between the coordinates its texels hold (bilinear between texel centres for
// grid=centres), held constant beyond the outermost (clamp to edge), in the axis' own coordinate
// (r or alpha, mu or sqrt-mu). Measured at the middles of the cells and of their edges, and in the
// bands between the outermost texels and the ends of each axis (0 and 1: mu = 0, r = 0 where the
// model has its limit there, else the least mu or alpha the exact values take): every cell up to
// 257 texels a side; beyond, every s-th cell, s = ceil((n - 1)/200), with every cell of the first
// and last rows and columns and of the bands. Each exact value is computed as the check computes
// its texels (wanted_tolerances, at the texel nearest below the point). c: the model checked.
lookup_errors measure_lookup(const read_table& t, lut_kind kind, const normzoo::microfacet::composition& c,
                             std::optional<double> tolerance, unsigned jobs);

// The absolute tolerance the exact values are computed to at each of `texels` (read_table texel
// indices), laid out as exact_lut's values: A and B to a hundredth of the tolerance of each stored
// channel that reads them (A+B: a two-hundredth each), E or E_avg to a hundredth of its own; 1e-10
// at least (docs/lut.md, "How a check chooses its accuracy").
std::vector<double> wanted_tolerances(const read_table& t, lut_kind kind, std::optional<double> tolerance,
                                      const std::vector<std::size_t>& texels);

// The error map the check's figure draws (plots.hpp, plot_lut_check): each compared texel's
// |stored - exact| per channel and, for a split-sum table, of E = F0 A + B at F0 = 0.04, and which
// channels are beyond their tolerance; at most 256 cells a side (a cell of k x k texels shows its
// largest), in ascending coordinates. exact: at t's points, in their order.
lut_error_map error_map_of(const read_table& t, const exact_table& exact, lut_kind kind, std::optional<double> tolerance);

}  // namespace verify
