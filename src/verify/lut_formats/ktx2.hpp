// KTX 2.0 (Khronos, "KTX File Format Specification", version 2.0; its data format descriptor in
// the "Khronos Data Format Specification", version 1.3): the container Bevy ships its DFG table
// in (dfg.ktx2, R16G16_SFLOAT, Zstandard). Debian has no libktx: this is a small, strict reader
// of what a table needs, and a writer of the same (docs/lut.md, "Files it reads").
#pragma once
#include <cstdint>
#include <string>

#include "decoded.hpp"

namespace verify {

// The VkFormats read and written (Vulkan's VkFormat values): uncompressed, one to four channels
// of unorm8, unorm16, half or float.
struct ktx2_format {
    std::uint32_t vk;
    const char* name;  // without the VK_FORMAT_ prefix
    std::size_t channels;
    value_encoding encoding;
    bool srgb;
};
// The format of value vk, or null if it is not one of those read.
const ktx2_format* ktx2_format_of(std::uint32_t vk);
// The format of that many channels stored so, or null: 1, 2 or 4 channels of each encoding (3
// of half alone), sRGB for R8G8B8A8 alone.
const ktx2_format* ktx2_format_with(std::size_t channels, value_encoding encoding, bool srgb);
// Vulkan's name of any core VkFormat value ("B10G11R11_UFLOAT_PACK32"), else "vkFormat N".
std::string vk_format_name(std::uint32_t vk);

// A KTX2 file of one 2D level, one layer, one face: the image's values in the format `vk` (one of
// ktx2_format_of's; as many channels as the image), uncompressed or each level compressed as one
// Zstandard frame (supercompressionScheme 2). Rows are written in the image's order, which is
// KTX2's default orientation ("rd": the first row at the top); the key KTXwriter says normzoo.
// std::invalid_argument for another format or a channel count that is not the format's.
std::string encode_ktx2(const lut_image& image, std::uint32_t vk, bool zstd);

// Level 0 of a 2D texture of one layer and one face, in one of ktx2_format_of's formats,
// uncompressed or Zstandard-supercompressed; the DFD must describe the format, the key/value data
// be well formed. Throws bad_input (args.hpp) naming path and the culprit for anything else.
decoded_lut read_ktx2(const std::string& path, const std::string& bytes);

}  // namespace verify
