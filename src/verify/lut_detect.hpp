// --detect (docs/lut.md, "Detecting a layout"): the layouts and models engines use, each tried
// on a subsample of an engine's table against the exact values (computed once per distinct
// (mu, alpha) and model), ranked by their largest error. The check then reads the whole table
// under the best (lut_check.cpp); the same ranking tells a failing check that another reading
// fits far better.
#pragma once
#include <set>
#include <string>
#include <vector>

#include "lut_layout.hpp"
#include "part_inputs.hpp"

namespace verify {

struct layout_candidate {
    lut_layout layout;
    std::string model;
    double max_abs_error = 0;  // on the subsample; infinite where a value is not finite
};

// What to try: every value of the keys not fixed (rows and cols as one roughness axis and one mu
// axis, row0, col0, grid, channels as A,B or B,A+B, the encodings that change values), each with
// each model.
struct layout_search {
    lut_kind kind = lut_kind::dfg;
    lut_layout start;                 // the fixed keys' values (size: always as given)
    std::set<std::string> fixed;      // the keys kept, by name
    std::vector<std::string> models;  // composition ids
    part_inputs parts;
    unsigned jobs = 1;
};

struct layout_ranking {
    std::vector<layout_candidate> ranked;  // best first; ties in the order tried (defaults first)
    std::size_t texels = 0;                // in the subsample
};

// The candidates on d (shaped_lut), best first. d must hold at least the kind's channels.
layout_ranking rank_layouts(const decoded_lut& d, const layout_search& s);

// --detect on the file at path: the table read as `reading` says and ranked under s; an array of
// hex integers (which the file does not say are binary16 bits, unorm8 or unorm16) unless its
// encoding is given, read each way and ranked together. The image the best candidate reads.
struct detected_table {
    decoded_lut image;
    layout_ranking ranking;
};
detected_table detect_table(const std::string& path, const lut_reading& reading, lut_kind kind, layout_search s);

// The models engines bake with: GGX with height-correlated Smith, separable Smith, Schlick-GGX
// (k = alpha/2) and the remapped Schlick-GGX (k = (r + 1)^2/8), F = one.
std::vector<std::string> baked_models();

}  // namespace verify
