// What a decimal printed in a text holds (a CSV's cells, a source file's array; docs/lut.md,
// "Checking an engine's table"): half a unit in the last digit its column prints.
#pragma once
#include <string>

namespace verify {

// The digits a decimal was printed with: after the point (less the exponent: 1.5e-3 has 4) and
// significant ones (from the first nonzero digit).
struct printed_digits {
    long decimals = 0, significant = 0;
};
printed_digits digits_of(const std::string& text);

// What a value printed in a column holds: half a unit in the last digit the column prints, as
// fixed decimals or as significant digits, whichever is coarser at this value. The column's
// finest cell shows its format: a value printed "0.5" beside others of 17 digits is exact
// (shortest round-trip printing of doubles); beside "0.123457" it is 0.5 to 6 digits. A column
// of at most 9 significant digits may be floats printed shortest (0.33333334 reads back as the
// float, not as the double): it holds what a float holds as well, 2^-24 relative, and 2^-150
// absolute below a float's normal range (where a value that underflowed prints 0).
double printed_precision(double v, const printed_digits& column);

}  // namespace verify
