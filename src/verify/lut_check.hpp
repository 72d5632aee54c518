// `verify lut --check FILE` (docs/lut.md, "Checking an engine's table"): an engine's table read
// back (lut_read.hpp, or an image under its layout: lut_layout.hpp, a preset's or the one
// --detect finds) against the exact one at the same coordinates (lut_exact.hpp), one lut-check
// record per channel. check_lut_file (lut.hpp) is the scenes' way in.
#pragma once
#include <optional>
#include <string>

#include <normzoo/microfacet/composition.hpp>

#include "lut_exact.hpp"
#include "lut_layout.hpp"
#include "part_inputs.hpp"
#include "writers.hpp"

namespace verify {

// The lut-check records of the table in path (a .csv, else an image); parts: F0 (read for E and
// Eavg) and the parts' parameters as typed; tolerance: absolute, else what the file's storage holds.
table_output check_lut_table(const std::string& path, lut_kind kind, const normzoo::microfacet::composition& c,
                             const lut_reading& reading, std::optional<double> tolerance, unsigned jobs, const part_inputs& parts);

// The same table with its console report: a line per channel (and, for an image, its lookup's
// error), the largest error per row and column, the error in 8-bit display steps, what --detect
// found, and where a failing image reads far better under another layout, that (the output stage
// prints it; a failing record: exit 1); and for an image the error map the output stage draws
// with --out (lut_lookup.hpp).
table_output lut_check_output(const std::string& path, lut_kind kind, const normzoo::microfacet::composition& c,
                              const lut_reading& reading, std::optional<double> tolerance, unsigned jobs, const part_inputs& parts);

}  // namespace verify
