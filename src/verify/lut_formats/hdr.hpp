// Radiance HDR, RGBE (Greg Ward, "Radiance File Formats", its Picture File Format, and "Real
// Pixels", Graphics Gems II, 1991; Radiance's color.c and header.c define the details): the
// header, the resolution line and run-length encoded or flat scanlines
// of red, green, blue mantissas sharing an exponent (docs/lut.md, "Files it reads").
#pragma once
#include <string>

#include "decoded.hpp"

namespace verify {

// A picture whose resolution line is "-Y H +X W" (rows top to bottom, pixels left to right:
// Radiance's standard order; the seven others are refused by name), FORMAT=32-bit_rle_rgbe or no
// FORMAT line, scanlines run-length encoded (Radiance 2.0's, 02 02 and the width, then four planes)
// or flat; the old run-length encoding (a pixel 1 1 1 n repeating the one before) is refused.
// Each value is Radiance's: (c + 0.5) 2^(E - 136), 0 for E = 0; it holds one step 2^(E - 136)
// (Radiance truncates to c, other writers round: a step covers both). EXPOSURE= lines are kept in
// `exposure`, GAMMA= and PRIMARIES= in `colour`. Throws bad_input (args.hpp) naming path and the
// culprit for anything else.
decoded_lut read_hdr(const std::string& path, const std::string& bytes);

}  // namespace verify
