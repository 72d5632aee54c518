// `verify lut --check FILE` (docs/lut.md, "Checking an engine's table"): an engine's table read
// back (lut_read.hpp) against the exact one at the same coordinates (lut_exact.hpp), one
// lut-check record per channel. check_lut_file (lut.hpp) is the scenes' way in.
#pragma once
#include <optional>
#include <string>

#include <normzoo/microfacet/composition.hpp>

#include "lut_exact.hpp"
#include "part_inputs.hpp"
#include "writers.hpp"

namespace verify {

// The lut-check records of the table in path (a .csv, else an image); parts: F0 (read for E and
// Eavg) and the parts' parameters as typed; tolerance: absolute, else what the file's format holds.
table_output check_lut_table(const std::string& path, lut_kind kind, const normzoo::microfacet::composition& c, bool perceptual,
                             std::optional<double> tolerance, unsigned jobs, const part_inputs& parts);

// The check, printed (json: one JSON document {records, skipped}); returns the exit code: 1 where
// a texel is beyond its tolerance, else 0.
int run_lut_check(const std::string& path, lut_kind kind, const normzoo::microfacet::composition& c, bool perceptual,
                  std::optional<double> tolerance, bool json, unsigned jobs, const part_inputs& parts);

}  // namespace verify
