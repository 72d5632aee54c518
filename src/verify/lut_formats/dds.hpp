// DirectDraw Surface (Microsoft, "Programming Guide for DDS": DDS_HEADER, DDS_PIXELFORMAT and
// DDS_HEADER_DXT10; the DXGI_FORMAT enumeration): the legacy header with
// its bit masks or a float FourCC, and the DX10 extension (docs/lut.md, "Files it reads").
// OpenImageIO 2.4, Debian's, reads no float DDS: this reader is normzoo's own.
#pragma once
#include <cstdint>
#include <string>

#include "decoded.hpp"

namespace verify {

// The DXGI formats read (from the DX10 header, or from a legacy float FourCC) and written.
struct dds_format {
    std::uint32_t dxgi;
    const char* name;  // without the DXGI_FORMAT_ prefix
    std::size_t channels;
    value_encoding encoding;
    bool srgb;
};
const dds_format* dds_format_of(std::uint32_t dxgi);  // null if not one of those read
// The format of that many channels (1, 2 or 4) stored so, or null; sRGB for R8G8B8A8 alone.
const dds_format* dds_format_with(std::size_t channels, value_encoding encoding, bool srgb);
std::string dxgi_format_name(std::uint32_t dxgi);     // "R11G11B10_FLOAT", else "DXGI format N"

// A DDS file with the DX10 header: one 2D level, the image's values in DXGI format `dxgi` (one
// of dds_format_of's, as many channels as the image), rows top to bottom as D3D lays them out.
// std::invalid_argument for another format or channel count.
std::string encode_dds(const lut_image& image, std::uint32_t dxgi);

// The top level of a 2D texture (not a cube map, a volume or an array of more than one): with
// the DX10 header in a format dds_format_of reads; with the legacy header, the float FourCCs
// 112, 113, 115, 116 (G16R16F, A16B16G16R16F, G32R32F, A32B32G32R32F) or RGB bit masks of 8- or
// 16-bit channels on byte boundaries (A8B8G8R8 is R8G8B8A8_UNORM, A8R8G8B8 B8G8R8A8_UNORM, G16R16
// R16G16_UNORM). Channels come in the order R, G, B, A, as a sampler returns them. Throws
// bad_input (args.hpp) naming path and the culprit for anything else.
decoded_lut read_dds(const std::string& path, const std::string& bytes);

}  // namespace verify
