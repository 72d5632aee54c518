// `verify lut` making a table (docs/lut.md): the options as typed, and the table computed on its
// grid, exact or as engines bake it, with its file in --format and its console line for the
// output stage (output.hpp). lut.cpp reads the options.
#pragma once
#include <algorithm>
#include <cstddef>
#include <string>
#include <thread>
#include <vector>

#include <normzoo/microfacet/composition.hpp>

#include "lut_exact.hpp"
#include "lut_write.hpp"
#include "writers.hpp"

namespace verify {

// The options of `verify lut` as typed (lut.hpp has the command line).
struct lut_options {
    std::string kind_text, model = "ggx/smith-height-correlated/one", alpha_text, r_text, mu_text, map = "r",
                format = "csv", out_dir, check_path, tolerance_text, f0_text, layout_text, preset;
    bool detect = false;
    std::size_t size = 0;
    unsigned monte_carlo = 0;
    unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::string> part_texts;  // the parts' parameters (add_part_options)
};

// The table of kind on g (its options checked): computed, with the file the output stage writes
// to --out in --format (none where a value is not finite: that record fails, exit 1) and its
// console line. w: the layout it is written in (--layout, --preset; g its points, layout_grid),
// or null for the plain table on g's grid. bad_input for --monte-carlo with another kind, map or
// model than the split-sum pair of the default model by r.
table_output make_lut(const lut_options& o, lut_kind kind, const normzoo::microfacet::composition& c, const lut_grid& g,
                      const lut_writing* w = nullptr);

}  // namespace verify
