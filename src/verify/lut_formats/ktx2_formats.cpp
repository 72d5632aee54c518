// The VkFormats of KTX2 files: those read, and Vulkan's names of the others, so that a refusal
// names what the file holds (values from the Vulkan specification's VkFormat enumeration).
#include <array>
#include <string>

#include "ktx2.hpp"

namespace verify {

namespace {

using e = value_encoding;
// One-channel formats for E and E_avg, four-channel ones for three or four (docs/lut.md, "Formats").
const ktx2_format formats[] = {
    {9, "R8_UNORM", 1, e::unorm8, false},             {16, "R8G8_UNORM", 2, e::unorm8, false},
    {37, "R8G8B8A8_UNORM", 4, e::unorm8, false},      {43, "R8G8B8A8_SRGB", 4, e::unorm8, true},
    {70, "R16_UNORM", 1, e::unorm16, false},          {76, "R16_SFLOAT", 1, e::half, false},
    {77, "R16G16_UNORM", 2, e::unorm16, false},       {83, "R16G16_SFLOAT", 2, e::half, false},
    {90, "R16G16B16_SFLOAT", 3, e::half, false},      {91, "R16G16B16A16_UNORM", 4, e::unorm16, false},
    {97, "R16G16B16A16_SFLOAT", 4, e::half, false},   {100, "R32_SFLOAT", 1, e::float32, false},
    {103, "R32G32_SFLOAT", 2, e::float32, false},     {109, "R32G32B32A32_SFLOAT", 4, e::float32, false},
};

}  // namespace

const ktx2_format* ktx2_format_of(std::uint32_t vk) {
    for (const auto& f : formats)
        if (f.vk == vk) return &f;
    return nullptr;
}

const ktx2_format* ktx2_format_with(std::size_t channels, value_encoding encoding, bool srgb) {
    for (const auto& f : formats)
        if (f.channels == channels && f.encoding == encoding && f.srgb == srgb) return &f;
    return nullptr;
}

std::string vk_format_name(std::uint32_t vk) {
    // 9 to 121 run in groups over the same suffixes: R8_UNORM = 9 ... R64G64B64A64_SFLOAT = 121
    static const char* const eight[] = {"UNORM", "SNORM", "USCALED", "SSCALED", "UINT", "SINT", "SRGB"};
    static const char* const wide[] = {"UNORM", "SNORM", "USCALED", "SSCALED", "UINT", "SINT", "SFLOAT"};
    static const char* const ints[] = {"UINT", "SINT", "SFLOAT"};
    struct group {
        std::uint32_t first;
        const char* stem;
        const char* const* suffixes;
        std::uint32_t count;
        const char* tail;
    };
    static const group groups[] = {
        {9, "R8_", eight, 7, ""},           {16, "R8G8_", eight, 7, ""},        {23, "R8G8B8_", eight, 7, ""},
        {30, "B8G8R8_", eight, 7, ""},      {37, "R8G8B8A8_", eight, 7, ""},    {44, "B8G8R8A8_", eight, 7, ""},
        {51, "A8B8G8R8_", eight, 7, "_PACK32"}, {58, "A2R10G10B10_", eight, 6, "_PACK32"},
        {64, "A2B10G10R10_", eight, 6, "_PACK32"}, {70, "R16_", wide, 7, ""}, {77, "R16G16_", wide, 7, ""},
        {84, "R16G16B16_", wide, 7, ""},    {91, "R16G16B16A16_", wide, 7, ""}, {98, "R32_", ints, 3, ""},
        {101, "R32G32_", ints, 3, ""},      {104, "R32G32B32_", ints, 3, ""},   {107, "R32G32B32A32_", ints, 3, ""},
        {110, "R64_", ints, 3, ""},         {113, "R64G64_", ints, 3, ""},      {116, "R64G64B64_", ints, 3, ""},
        {119, "R64G64B64A64_", ints, 3, ""},
    };
    for (const auto& g : groups)
        if (vk >= g.first && vk < g.first + g.count) return std::string(g.stem) + g.suffixes[vk - g.first] + g.tail;
    static const char* const small[] = {"UNDEFINED", "R4G4_UNORM_PACK8", "R4G4B4A4_UNORM_PACK16", "B4G4R4A4_UNORM_PACK16",
                                        "R5G6B5_UNORM_PACK16", "B5G6R5_UNORM_PACK16", "R5G5B5A1_UNORM_PACK16",
                                        "B5G5R5A1_UNORM_PACK16", "A1R5G5B5_UNORM_PACK16"};
    static const char* const packed[] = {"B10G11R11_UFLOAT_PACK32", "E5B9G9R9_UFLOAT_PACK32", "D16_UNORM",
                                         "X8_D24_UNORM_PACK32", "D32_SFLOAT", "S8_UINT", "D16_UNORM_S8_UINT",
                                         "D24_UNORM_S8_UINT", "D32_SFLOAT_S8_UINT", "BC1_RGB_UNORM_BLOCK",
                                         "BC1_RGB_SRGB_BLOCK", "BC1_RGBA_UNORM_BLOCK", "BC1_RGBA_SRGB_BLOCK",
                                         "BC2_UNORM_BLOCK", "BC2_SRGB_BLOCK", "BC3_UNORM_BLOCK", "BC3_SRGB_BLOCK",
                                         "BC4_UNORM_BLOCK", "BC4_SNORM_BLOCK", "BC5_UNORM_BLOCK", "BC5_SNORM_BLOCK",
                                         "BC6H_UFLOAT_BLOCK", "BC6H_SFLOAT_BLOCK", "BC7_UNORM_BLOCK", "BC7_SRGB_BLOCK"};
    if (vk < 9) return small[vk];
    if (vk >= 122 && vk < 147) return packed[vk - 122];
    if (vk >= 147 && vk < 157) return "an ETC2 or EAC block-compressed format (vkFormat " + std::to_string(vk) + ")";
    if (vk >= 157 && vk < 185) return "an ASTC block-compressed format (vkFormat " + std::to_string(vk) + ")";
    return "vkFormat " + std::to_string(vk);
}

}  // namespace verify
