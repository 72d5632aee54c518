// DDS read and written (dds.hpp). Offsets are the file's: the 4-byte magic, the 124-byte
// DDS_HEADER (its DDS_PIXELFORMAT at 76), the 20-byte DDS_HEADER_DXT10 at 128 when the FourCC is
// "DX10", then the top level's rows, top to bottom, tightly packed.
#include "dds.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "../args.hpp"
#include "texels.hpp"

namespace verify {
namespace {

constexpr std::uint32_t fourcc_dx10 = 0x30315844;  // "DX10"
constexpr std::uint32_t pf_alpha_pixels = 0x1, pf_fourcc = 0x4, pf_rgb = 0x40;
constexpr std::size_t header_end = 128, dx10_end = 148;

// How the top level's texels are laid out: a DXGI format's packed values, or bit masks.
struct layout {
    std::string name;  // the DXGI format's name, or the masks' ("B8G8R8A8_UNORM")
    std::size_t channels = 0, texel_bytes = 0, data_at = header_end;
    value_encoding encoding = value_encoding::unorm8;
    bool srgb = false;
    std::vector<std::uint32_t> masks;  // R, G, B, A present; empty for a DXGI format's values
};

layout of_dxgi(const dds_format& f, std::size_t data_at) {
    layout l;
    l.name = f.name, l.channels = f.channels, l.encoding = f.encoding, l.srgb = f.srgb, l.data_at = data_at;
    l.texel_bytes = f.channels * value_bytes(f.encoding);
    return l;
}

// The DX10 header: a 2D texture, not a cube, one element, in a format read.
layout dx10_layout(const std::string& path, const std::string& b) {
    const auto bad = [&](const std::string& what) { return bad_input(path + ": DDS " + what); };
    if (b.size() < dx10_end) throw bad("truncated: " + std::to_string(b.size()) + " bytes, the DX10 header ends at 148");
    const std::uint32_t dxgi = le32(b, 128), dimension = le32(b, 132), misc = le32(b, 136), array = le32(b, 140);
    if (dimension != 3)
        throw bad(std::string("resource dimension ") +
                  (dimension == 2 ? "1D" : dimension == 4 ? "3D" : std::to_string(dimension).c_str()) + "; a table is 2D (3)");
    if (misc & 0x4) throw bad("cube map; a table is one 2D image");
    if (array != 1) throw bad("array of " + std::to_string(array) + " textures; a table is one");
    const dds_format* f = dds_format_of(dxgi);
    if (!f)
        throw bad("format " + dxgi_format_name(dxgi) + " is not read; a table is R16_FLOAT, R16G16_FLOAT, R16G16B16A16_FLOAT, "
                  "R32_FLOAT, R32G32_FLOAT, R32G32B32A32_FLOAT, R8_UNORM, R8G8_UNORM, R8G8B8A8_UNORM, R8G8B8A8_UNORM_SRGB, "
                  "R16_UNORM, R16G16_UNORM or R16G16B16A16_UNORM");
    return of_dxgi(*f, dx10_end);
}

// A legacy FourCC: the D3DFORMAT codes of the float formats read; another is named in the refusal.
layout fourcc_layout(const std::string& path, std::uint32_t fourcc) {
    const std::uint32_t codes[][2] = {{112, 34}, {113, 10}, {115, 16}, {116, 2}};  // D3DFMT -> DXGI
    for (const auto& c : codes)
        if (fourcc == c[0]) return of_dxgi(*dds_format_of(c[1]), header_end);
    std::string name;
    const struct { std::uint32_t code; const char* name; } d3d[] = {{36, "A16B16G16R16"}, {110, "Q16W16V16U16"}, {111, "R16F"},
                                                                   {114, "R32F"}, {117, "CxV8U8"}};
    for (const auto& d : d3d)
        if (fourcc == d.code) name = std::string("D3DFMT_") + d.name + " (" + std::to_string(fourcc) + ")";
    if (name.empty()) {
        bool printable = true;
        for (int k = 0; k < 4; ++k) printable = printable && (fourcc >> 8 * k & 0xff) >= 0x20 && (fourcc >> 8 * k & 0xff) < 0x7f;
        name = printable ? "'" + std::string{char(fourcc), char(fourcc >> 8), char(fourcc >> 16), char(fourcc >> 24)} + "'"
                         : std::to_string(fourcc);
    }
    throw bad_input(path + ": DDS FourCC " + name + " is not read; a legacy table is G16R16F (112), A16B16G16R16F (113), "
                    "G32R32F (115), A32B32G32R32F (116) or RGB bit masks");
}

std::string hex(std::uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%x", v);
    return buf;
}

// Legacy RGB bit masks: each present channel a contiguous run of 8 or 16 bits on a byte
// boundary, all of one width, not overlapping, within the texel. The name lists the fields from
// the lowest bit up, X for bits no channel uses (DXGI's naming: A8R8G8B8 is B8G8R8A8_UNORM).
layout mask_layout(const std::string& path, const std::string& b, std::uint32_t pf_flags) {
    const std::uint32_t bits = le32(b, 88);
    std::uint32_t masks[4] = {le32(b, 92), le32(b, 96), le32(b, 100), pf_flags & pf_alpha_pixels ? le32(b, 104) : 0};
    const std::string described = "RGB bit masks of " + std::to_string(bits) + " bits (R " + hex(masks[0]) + ", G " +
                                  hex(masks[1]) + ", B " + hex(masks[2]) + ", A " + hex(masks[3]) + ")";
    const auto bad = [&] {
        return bad_input(path + ": DDS " + described + " are not read; a table's masks are 8- or 16-bit channels on byte boundaries");
    };
    if (bits != 8 && bits != 16 && bits != 24 && bits != 32) throw bad();
    layout l;
    std::uint32_t width = 0, used = 0;
    char slot[4] = {'X', 'X', 'X', 'X'};  // the channel at each field, by its index from the lowest bit
    for (int c = 0; c < 4; ++c) {
        const std::uint32_t m = masks[c];
        if (!m) continue;
        int shift = 0;
        while (!(m >> shift & 1)) ++shift;
        const std::uint32_t w = std::uint32_t(__builtin_popcount(m));
        if ((w != 8 && w != 16) || (width && w != width) || shift % int(w) != 0 || (m >> shift) != (std::uint64_t(1) << w) - 1 ||
            (used & m) || shift + w > bits)
            throw bad();
        width = w, used |= m;
        slot[shift / int(w)] = "RGBA"[c];
        l.masks.push_back(m);
    }
    if (l.masks.empty()) throw bad();
    for (std::uint32_t k = 0; k < bits / width; ++k) l.name += slot[k] + std::to_string(width);
    l.name += "_UNORM";
    l.channels = l.masks.size(), l.texel_bytes = bits / 8, l.encoding = width == 8 ? value_encoding::unorm8 : value_encoding::unorm16;
    return l;
}

// The header: its sizes, a 2D texture (not a cube map, not a volume) of 1 to max_side texels a
// side, and how its texels are laid out.
layout read_header(const std::string& path, const std::string& b, std::uint32_t& width, std::uint32_t& height) {
    const auto bad = [&](const std::string& what) { return bad_input(path + ": DDS " + what); };
    if (b.size() < 4 || std::memcmp(b.data(), "DDS ", 4) != 0) throw bad_input(path + ": not a DDS file (its magic)");
    if (b.size() < header_end) throw bad("truncated: " + std::to_string(b.size()) + " bytes, the header takes 128");
    if (le32(b, 4) != 124 || le32(b, 76) != 32)
        throw bad("header size " + std::to_string(le32(b, 4)) + " and pixel format size " + std::to_string(le32(b, 76)) +
                  " are not 124 and 32");
    const std::uint32_t flags = le32(b, 8), depth = le32(b, 24), caps2 = le32(b, 112), pf_flags = le32(b, 80);
    height = le32(b, 12), width = le32(b, 16);
    if (caps2 & 0x200) throw bad("cube map; a table is one 2D image");
    if ((caps2 & 0x200000) || ((flags & 0x800000) && depth > 1)) throw bad("volume texture; a table is 2D");
    if (width == 0 || height == 0 || width > max_side || height > max_side)
        throw bad("image of " + std::to_string(width) + " x " + std::to_string(height) + "; a table is 1 to " +
                  std::to_string(max_side) + " texels a side");
    if (pf_flags & pf_fourcc) return le32(b, 84) == fourcc_dx10 ? dx10_layout(path, b) : fourcc_layout(path, le32(b, 84));
    if (pf_flags & pf_rgb) return mask_layout(path, b, pf_flags);
    throw bad("pixel format flags " + hex(pf_flags) + " name neither a FourCC nor RGB bit masks (luminance, alpha, YUV are not read)");
}

}  // namespace

std::string encode_dds(const lut_image& im, std::uint32_t dxgi) {
    const dds_format* f = dds_format_of(dxgi);
    if (!f) throw std::invalid_argument("DDS: " + dxgi_format_name(dxgi) + " is not a format normzoo writes");
    check_image(im);
    if (im.channels != f->channels) throw std::invalid_argument("DDS: " + std::to_string(im.channels) + " channels in " + f->name);
    const std::size_t pitch = im.width * f->channels * value_bytes(f->encoding);
    std::string out = "DDS ";
    // caps, height, width, pixel format, pitch; the pitch; no depth or mip levels; 11 reserved
    for (const std::uint32_t v : {124u, 0x100Fu, std::uint32_t(im.height), std::uint32_t(im.width), std::uint32_t(pitch), 0u, 0u})
        put32(out, v);
    out.append(44, '\0');
    for (const std::uint32_t v : {32u, pf_fourcc, fourcc_dx10, 0u, 0u, 0u, 0u, 0u}) put32(out, v);  // DDS_PIXELFORMAT
    for (const std::uint32_t v : {0x1000u, 0u, 0u, 0u, 0u}) put32(out, v);  // caps: a texture; caps2-4, reserved
    for (const std::uint32_t v : {f->dxgi, 3u, 0u, 1u, 0u}) put32(out, v);  // 2D, not a cube, one element, alpha mode unknown
    encode_values(im.data, f->encoding, out);
    return out;
}

decoded_lut read_dds(const std::string& path, const std::string& b) {
    std::uint32_t width = 0, height = 0;
    const layout l = read_header(path, b, width, height);
    const std::size_t need = std::size_t(width) * height * l.texel_bytes;
    if (b.size() < l.data_at || need > b.size() - l.data_at)
        throw bad_input(path + ": DDS truncated: " + std::to_string(width) + " x " + std::to_string(height) + " texels of " +
                        l.name + " take " + std::to_string(need) + " bytes, " + std::to_string(b.size() - std::min(b.size(), l.data_at)) +
                        " follow the header");
    decoded_lut d;
    d.image.width = width, d.image.height = height, d.image.channels = l.channels;
    d.image.data.reserve(std::size_t(width) * height * l.channels);
    if (l.masks.empty()) {
        decode_values(b.data() + l.data_at, std::size_t(width) * height * l.channels, l.encoding, d.image.data);
    } else {
        for (std::size_t t = 0; t < std::size_t(width) * height; ++t) {
            std::uint32_t texel = 0;
            for (std::size_t k = 0; k < l.texel_bytes; ++k) texel |= std::uint32_t(std::uint8_t(b[l.data_at + t * l.texel_bytes + k])) << 8 * k;
            for (const std::uint32_t m : l.masks) {
                int shift = 0;
                while (!(m >> shift & 1)) ++shift;
                d.image.data.push_back(double((texel & m) >> shift) / double(m >> shift));
            }
        }
    }
    d.format = "dds-" + l.name;
    set_storage_tolerance(d, l.encoding);
    if (l.srgb) d.colour.declared = colour_declaration::kind::srgb;
    return d;
}

}  // namespace verify
