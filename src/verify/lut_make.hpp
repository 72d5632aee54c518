// `verify lut` making a table (docs/lut.md): the options as typed, and the table computed on its
// grid, exact or as engines bake it, written to --out and printed. lut.cpp reads the options.
#pragma once
#include <algorithm>
#include <cstddef>
#include <string>
#include <thread>
#include <vector>

#include <normzoo/microfacet/composition.hpp>

#include "lut_exact.hpp"

namespace verify {

// The options of `verify lut` as typed (lut.hpp has the command line).
struct lut_options {
    std::string kind_text, model = "ggx/smith-height-correlated/one", alpha_text, r_text, mu_text, map = "r",
                format = "csv", out_dir, check_path, tolerance_text, f0_text;
    std::size_t size = 0;
    unsigned monte_carlo = 0;
    bool json = false;
    unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::string> part_texts;  // the parts' parameters (add_part_options)
};

// The table of kind on g (its options checked, the output folder too): computed, written to
// --out in --format unless a value is not finite, and printed (--json) or summed up. Returns the
// exit code: 1 where a value is not finite, else 0. bad_input for --monte-carlo with another
// kind, map or model than the split-sum pair of the default model by r.
int make_lut(const lut_options& o, lut_kind kind, const normzoo::microfacet::composition& c, const lut_grid& g);

}  // namespace verify
