// The one entry by which a table's file is read (docs/lut.md, "Files it reads"): its kind told
// from its first bytes, or for a source file from its name, then its own reader.
#pragma once
#include <string>

#include "decoded.hpp"
#include "source_array.hpp"

namespace verify {

// PNG, OpenEXR, KTX2, DDS and Radiance HDR by their signatures; a source file's array
// (source_array.hpp, with `request`) by its extension. Throws bad_input (args.hpp) naming path:
// unreadable, none of these, more than 1 GiB, or what its reader refuses.
decoded_lut read_lut_file(const std::string& path, const array_request& request);

}  // namespace verify
