// A table kept in a source file as a number array (docs/lut.md, "Files it reads"): a C or C++
// header (Filament's dfg.inc, EEVEE's brdf_ggx[64][64][2]), a JavaScript or TypeScript module
// (three.js's `new Uint16Array([0x2cd9, ...])` of half bits), WGSL or GLSL; or a PNG in a string
// (Babylon.js's base64 BRDF texture, plain or as a data: URI).
#pragma once
#include <cstddef>
#include <string>

#include "decoded.hpp"

namespace verify {

// What the caller says of the array: its name (empty: the first array, or base64 PNG string, the
// file initialises) and its size (0 x 0: the file's, if it gives one).
struct array_request {
    std::string name;
    std::size_t width = 0, height = 0;
};

// The extensions read as source files: .h .hpp .inc .c .cpp .js .ts .wgsl .glsl (any case).
bool is_source_file_name(const std::string& path);

// The array a declaration initialises (NAME = [...], {...}, new T([...]), T.from([...]),
// array<T, N>(...), T[](...); constructors such as vec2(...) inside are flattened), comments
// skipped; in a file without one, the file itself where it is numbers alone, comma-separated (what
// an initialiser's #include holds). Its elements are decimals (float suffixes f, F, h; exponents), read with what their
// digits hold as a CSV column does (encoding decimal_text; a float or half literal, or an array
// of float, f32, vecN, f16, also what that type's rounding moves), or integers with at least one hex
// among them, returned as the integers (hex_integer) for the caller to read (interpret_hex).
// The shape comes from the request, else from the array's declared dimensions ([H][W][C]), a
// call that hands it on with its size (DataTexture(DATA, W, H, ...)) or the one size constant the
// file defines (#define or NAME = N, a name holding "size" or "resolution": N x N); without one
// the array is one row (shaped false). A string is read as a PNG (lut_formats/png.hpp) when it is
// a base64 data: URI or plain base64 of one. Throws bad_input (args.hpp) naming path (and the
// line) for a file without such an array, a malformed one, or a shape that does not fit it.
decoded_lut read_source_array(const std::string& path, const std::string& text, const array_request& request);

// How the caller reads an array of integers: IEEE binary16 bit patterns, or unorm8 or unorm16.
enum class hex_meaning { binary16, unorm8, unorm16 };
// The integers of a hex_integer array as their values, with the tolerance of that storage
// (texels.hpp); bad_input naming path where an integer does not fit (over 0xffff, or 0xff for
// unorm8).
void interpret_hex(const std::string& path, decoded_lut& d, hex_meaning m);

}  // namespace verify
