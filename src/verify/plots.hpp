// Plots drawn by gnuplot (Debian gnuplot-nox) into SVG, staged like every other results file.
#pragma once
#include "writers.hpp"

namespace verify {

// Each Blinn-Phong normalization over its lower bound against n, with both bounds.
// Returns false (and says why on stderr) when gnuplot is missing or fails; the tables stand.
bool plot_bounds(const table_output& bounds, file_set& files);

}  // namespace verify
