// An engine's table read back for `verify lut --check` (docs/lut.md, "Checking an engine's
// table"): a CSV of points, each value with what its printed digits hold (an image or a source
// file's array is read under its layout: lut_layout.hpp). Bad input throws bad_input (args.hpp)
// naming the file (and line).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <normzoo/microfacet/composition.hpp>

#include "lut_exact.hpp"
#include "part_inputs.hpp"

namespace verify {

// An engine's table read back: values, and per value what its format can hold.
struct stored_table {
    std::size_t width = 0, height = 0, channels = 0;
    std::vector<double> values, precision;
    lut_grid grid;
    std::string format;
};

// What a row that `verify lut` wrote (its `table` cell is "lut") must name for the check to be of
// the same table: its kind, model, F0 (E, Eavg) and the parameters the model reads. Another is
// refused, naming the line: comparing it would only fail, without saying why.
struct own_rows {
    std::string kind;
    const normzoo::microfacet::composition* c = nullptr;
    const part_inputs* parts = nullptr;  // F0 as well
};

// A CSV with a header naming mu, alpha or r, and the kind's value columns (the lut records' CSV
// is one); '#' lines are comments. Each row is a texel at the coordinates it gives.
stored_table read_csv_table(const std::string& path, lut_kind kind, const own_rows& own);

}  // namespace verify
