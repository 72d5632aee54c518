// The DXGI formats of DDS files: those read, and the names of the others (the DXGI_FORMAT
// enumeration's values), so that a refusal names what the file holds.
#include <string>

#include "dds.hpp"

namespace verify {

namespace {

using e = value_encoding;
// One-channel formats for E and E_avg, four-channel ones for three or four (docs/lut.md, "Formats").
const dds_format formats[] = {
    {2, "R32G32B32A32_FLOAT", 4, e::float32, false}, {10, "R16G16B16A16_FLOAT", 4, e::half, false},
    {11, "R16G16B16A16_UNORM", 4, e::unorm16, false}, {16, "R32G32_FLOAT", 2, e::float32, false},
    {28, "R8G8B8A8_UNORM", 4, e::unorm8, false},     {29, "R8G8B8A8_UNORM_SRGB", 4, e::unorm8, true},
    {34, "R16G16_FLOAT", 2, e::half, false},         {35, "R16G16_UNORM", 2, e::unorm16, false},
    {41, "R32_FLOAT", 1, e::float32, false},         {49, "R8G8_UNORM", 2, e::unorm8, false},
    {54, "R16_FLOAT", 1, e::half, false},            {56, "R16_UNORM", 1, e::unorm16, false},
    {61, "R8_UNORM", 1, e::unorm8, false},
};

}  // namespace

const dds_format* dds_format_of(std::uint32_t dxgi) {
    for (const auto& f : formats)
        if (f.dxgi == dxgi) return &f;
    return nullptr;
}

const dds_format* dds_format_with(std::size_t channels, value_encoding encoding, bool srgb) {
    for (const auto& f : formats)
        if (f.channels == channels && f.encoding == encoding && f.srgb == srgb) return &f;
    return nullptr;
}

std::string dxgi_format_name(std::uint32_t dxgi) {
    static const char* const names[] = {
        "UNKNOWN", "R32G32B32A32_TYPELESS", "R32G32B32A32_FLOAT", "R32G32B32A32_UINT", "R32G32B32A32_SINT",
        "R32G32B32_TYPELESS", "R32G32B32_FLOAT", "R32G32B32_UINT", "R32G32B32_SINT", "R16G16B16A16_TYPELESS",
        "R16G16B16A16_FLOAT", "R16G16B16A16_UNORM", "R16G16B16A16_UINT", "R16G16B16A16_SNORM", "R16G16B16A16_SINT",
        "R32G32_TYPELESS", "R32G32_FLOAT", "R32G32_UINT", "R32G32_SINT", "R32G8X24_TYPELESS", "D32_FLOAT_S8X24_UINT",
        "R32_FLOAT_X8X24_TYPELESS", "X32_TYPELESS_G8X24_UINT", "R10G10B10A2_TYPELESS", "R10G10B10A2_UNORM",
        "R10G10B10A2_UINT", "R11G11B10_FLOAT", "R8G8B8A8_TYPELESS", "R8G8B8A8_UNORM", "R8G8B8A8_UNORM_SRGB",
        "R8G8B8A8_UINT", "R8G8B8A8_SNORM", "R8G8B8A8_SINT", "R16G16_TYPELESS", "R16G16_FLOAT", "R16G16_UNORM",
        "R16G16_UINT", "R16G16_SNORM", "R16G16_SINT", "R32_TYPELESS", "D32_FLOAT", "R32_FLOAT", "R32_UINT", "R32_SINT",
        "R24G8_TYPELESS", "D24_UNORM_S8_UINT", "R24_UNORM_X8_TYPELESS", "X24_TYPELESS_G8_UINT", "R8G8_TYPELESS",
        "R8G8_UNORM", "R8G8_UINT", "R8G8_SNORM", "R8G8_SINT", "R16_TYPELESS", "R16_FLOAT", "D16_UNORM", "R16_UNORM",
        "R16_UINT", "R16_SNORM", "R16_SINT", "R8_TYPELESS", "R8_UNORM", "R8_UINT", "R8_SNORM", "R8_SINT", "A8_UNORM",
        "R1_UNORM", "R9G9B9E5_SHAREDEXP", "R8G8_B8G8_UNORM", "G8R8_G8B8_UNORM", "BC1_TYPELESS", "BC1_UNORM",
        "BC1_UNORM_SRGB", "BC2_TYPELESS", "BC2_UNORM", "BC2_UNORM_SRGB", "BC3_TYPELESS", "BC3_UNORM", "BC3_UNORM_SRGB",
        "BC4_TYPELESS", "BC4_UNORM", "BC4_SNORM", "BC5_TYPELESS", "BC5_UNORM", "BC5_SNORM", "B5G6R5_UNORM",
        "B5G5R5A1_UNORM", "B8G8R8A8_UNORM", "B8G8R8X8_UNORM", "R10G10B10_XR_BIAS_A2_UNORM", "B8G8R8A8_TYPELESS",
        "B8G8R8A8_UNORM_SRGB", "B8G8R8X8_TYPELESS", "B8G8R8X8_UNORM_SRGB", "BC6H_TYPELESS", "BC6H_UF16", "BC6H_SF16",
        "BC7_TYPELESS", "BC7_UNORM", "BC7_UNORM_SRGB", "AYUV", "Y410", "Y416", "NV12", "P010", "P016", "420_OPAQUE",
        "YUY2", "Y210", "Y216", "NV11", "AI44", "IA44", "P8", "A8P8", "B4G4R4A4_UNORM"};
    if (dxgi < sizeof names / sizeof names[0]) return names[dxgi];
    return "DXGI format " + std::to_string(dxgi);
}

}  // namespace verify
