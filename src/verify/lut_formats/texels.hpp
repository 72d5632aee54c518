// What the binary readers and writers share (KTX2, DDS): little-endian fields, binary16 and
// binary32 bit patterns, tightly packed texels decoded into doubles and encoded back, and the
// tolerance each storage implies.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "decoded.hpp"

namespace verify {

// Little-endian fields of bytes at `at`; the caller has checked that they are there.
inline std::uint32_t le16(const std::string& b, std::size_t at) {
    return std::uint32_t(std::uint8_t(b[at])) | std::uint32_t(std::uint8_t(b[at + 1])) << 8;
}
inline std::uint32_t le32(const std::string& b, std::size_t at) { return le16(b, at) | le16(b, at + 2) << 16; }
inline std::uint64_t le64(const std::string& b, std::size_t at) { return le32(b, at) | std::uint64_t(le32(b, at + 4)) << 32; }
inline void put16(std::string& out, std::uint32_t v) { out += char(v & 0xff), out += char(v >> 8 & 0xff); }
inline void put32(std::string& out, std::uint32_t v) { put16(out, v & 0xffff), put16(out, v >> 16); }
inline void put64(std::string& out, std::uint64_t v) { put32(out, std::uint32_t(v)), put32(out, std::uint32_t(v >> 32)); }

double half_to_double(std::uint16_t bits);      // exact, subnormals, infinities and NaN included
std::uint16_t double_to_half(double v);         // rounded to nearest, ties to even
double float_to_double(std::uint32_t bits);     // exact
std::uint32_t double_to_float(double v);        // rounded to nearest

// Slice k of a table of slices read as width x (height D) texels, slice after slice (lut_layout's
// size=WxHxD): width x height texels with their precision. k < D, and the table that many texels.
decoded_lut decoded_slice(const decoded_lut& d, std::size_t width, std::size_t height, std::size_t k);

// The bytes one value takes in a packed texel: 1 (unorm8), 2 (unorm16, half) or 4 (float32).
std::size_t value_bytes(value_encoding e);

// `count` little-endian values from p, appended to out as doubles.
void decode_values(const char* p, std::size_t count, value_encoding e, std::vector<double>& out);
// The values as little-endian bytes: unorm clamped to [0, 1] and rounded (NaN as 0), half and
// float rounded to nearest.
void encode_values(const std::vector<double>& values, value_encoding e, std::string& out);

// The writers' precondition: a whole image of 1 to 4 channels, of a size every format can hold
// (which also keeps width * height * channels from overflowing); std::invalid_argument if not.
void check_image(const lut_image& image);

// What a stored value holds (decoded_lut::absolute, relative): half a step of 255 or 65535, half
// an ulp of a half (2^-11 relative; 2^-25 absolute below its normal range) or of a float (2^-24).
void set_storage_tolerance(decoded_lut& d, value_encoding e);

}  // namespace verify
