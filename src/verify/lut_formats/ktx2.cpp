// KTX 2.0 read and written (ktx2.hpp). Section numbers are those of the KTX 2.0 specification;
// the data format descriptor's fields those of the Khronos Data Format Specification 1.3,
// section 5 (the basic descriptor block).
#include "ktx2.hpp"

#include <zstd.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "../args.hpp"
#include "texels.hpp"

namespace verify {
namespace {

const char identifier[12] = {'\xAB', 'K', 'T', 'X', ' ', '2', '0', '\xBB', '\r', '\n', '\x1A', '\n'};
constexpr std::size_t header_bytes = 80, level_entry_bytes = 24;

// The header and index (section 3), as stored.
struct header {
    std::uint32_t vk, type_size, width, height, depth, layers, faces, levels, scheme;
    std::uint32_t dfd_offset, dfd_length, kvd_offset, kvd_length;
    std::uint64_t sgd_offset, sgd_length;
    std::size_t level_count() const { return std::max<std::uint32_t>(levels, 1); }
};

header header_of(const std::string& b) {
    header h{};
    std::uint32_t* fields[] = {&h.vk, &h.type_size, &h.width, &h.height, &h.depth, &h.layers, &h.faces, &h.levels,
                               &h.scheme, &h.dfd_offset, &h.dfd_length, &h.kvd_offset, &h.kvd_length};
    for (std::size_t k = 0; k < 13; ++k) *fields[k] = le32(b, 12 + 4 * k);
    h.sgd_offset = le64(b, 64), h.sgd_length = le64(b, 72);
    return h;
}

// What the header says against what a table is: a 2D image of one layer, one face, in a format
// read, of 1 to max_side texels a side, uncompressed or Zstandard.
const ktx2_format& check_header(const std::string& path, const header& h) {
    const auto bad = [&](const std::string& what) { return bad_input(path + ": KTX2 " + what); };
    const ktx2_format* f = ktx2_format_of(h.vk);
    if (!f)
        throw bad("format " + vk_format_name(h.vk) + " is not read; a table is R16_SFLOAT, R16G16_SFLOAT, R16G16B16_SFLOAT, "
                  "R16G16B16A16_SFLOAT, R32_SFLOAT, R32G32_SFLOAT, R32G32B32A32_SFLOAT, R8_UNORM, R8G8_UNORM, "
                  "R8G8B8A8_UNORM, R8G8B8A8_SRGB, R16_UNORM, R16G16_UNORM or R16G16B16A16_UNORM");
    if (h.type_size != value_bytes(f->encoding))
        throw bad("typeSize " + std::to_string(h.type_size) + " is not " + std::to_string(value_bytes(f->encoding)) +
                  ", the component size of " + f->name);
    if (h.height == 0) throw bad("1D texture (pixelHeight 0); a table is 2D");
    if (h.depth != 0) throw bad("3D texture (pixelDepth " + std::to_string(h.depth) + "); a table is 2D");
    if (h.width == 0 || h.width > max_side || h.height > max_side)
        throw bad("image of " + std::to_string(h.width) + " x " + std::to_string(h.height) + "; a table is 1 to " +
                  std::to_string(max_side) + " texels a side");
    if (h.layers > 1) throw bad("array of " + std::to_string(h.layers) + " layers; a table is one");
    if (h.faces != 1) throw bad("texture of " + std::to_string(h.faces) + " faces (a cube map has 6); a table is one");
    if (h.scheme != 0 && h.scheme != 2) {
        const std::string scheme = h.scheme == 1 ? "BasisLZ" : h.scheme == 3 ? "ZLIB" : "scheme " + std::to_string(h.scheme);
        throw bad("supercompression " + scheme + " is not read; a table is uncompressed or Zstandard (scheme 2)");
    }
    std::size_t most = 1;  // levels down to 1 x 1
    while ((std::max(h.width, h.height) >> most) > 0) ++most;
    if (h.level_count() > most)
        throw bad(std::to_string(h.levels) + " mip levels for " + std::to_string(h.width) + " x " + std::to_string(h.height) +
                  " (at most " + std::to_string(most) + ")");
    if (h.sgd_length != 0 || h.sgd_offset != 0) throw bad("supercompression global data, which Zstandard has none of");
    return *f;
}

// The data format descriptor (section 3.10.1; KDFS 1.3 section 5): one basic block describing
// the format: RGBSDA colour model, one texel per block, the texel's bytes, one sample per channel
// (R, G, B, A in order, each its bits in order, float where the format is); the transfer function
// sRGB for an _SRGB format, linear for the others. Returns whether it is sRGB.
bool check_dfd(const std::string& path, const std::string& b, const header& h, const ktx2_format& f) {
    const auto bad = [&](const std::string& what) { return bad_input(path + ": KTX2 data format descriptor: " + what); };
    const std::size_t at = h.dfd_offset, n = h.dfd_length;
    if (n < 4 + 24) throw bad(std::to_string(n) + " bytes, too few for a basic block");
    if (le32(b, at) != n) throw bad("dfdTotalSize " + std::to_string(le32(b, at)) + " is not dfdByteLength " + std::to_string(n));
    const std::size_t blk = at + 4, bits = 8 * value_bytes(f.encoding);
    const std::size_t block_size = le16(b, blk + 6), samples = block_size >= 24 ? (block_size - 24) / 16 : 0;
    if (le32(b, blk) != 0 || le16(b, blk + 4) != 2) throw bad("not a basic block of version 1.3 (vendor 0, type 0, version 2)");
    if (block_size < 24 || (block_size - 24) % 16 != 0 || block_size > n - 4)
        throw bad("block size " + std::to_string(block_size) + " does not fit its " + std::to_string(n - 4) + " bytes");
    const auto byte = [&](std::size_t k) { return unsigned(std::uint8_t(b[blk + k])); };
    if (byte(8) != 1) throw bad("colour model " + std::to_string(byte(8)) + " is not RGBSDA (1)");
    if (byte(12) || byte(13) || byte(14) || byte(15)) throw bad("texel blocks are not 1 x 1 (a compressed format)");
    if (byte(16) != f.channels * bits / 8) throw bad("bytesPlane0 " + std::to_string(byte(16)) + " is not the texel's size");
    for (std::size_t k = 17; k < 24; ++k)
        if (byte(k)) throw bad("more than one plane");
    if (samples != f.channels)
        throw bad(std::to_string(samples) + " samples; " + f.name + " has " + std::to_string(f.channels) + " channels");
    const unsigned ids[] = {0, 1, 2, 15};  // R, G, B, A
    const bool is_float = f.encoding == value_encoding::half || f.encoding == value_encoding::float32;
    for (std::size_t s = 0; s < samples; ++s) {
        const std::size_t p = 24 + 16 * s;
        if (le16(b, blk + p) != s * bits || byte(p + 2) + 1 != bits || (byte(p + 3) & 0xf) != ids[s] ||
            bool(byte(p + 3) & 0x80) != is_float)
            throw bad("sample " + std::to_string(s) + " does not describe channel " + "RGBA"[s] + " of " + f.name);
    }
    const unsigned transfer = byte(10);
    if (transfer != 1 && transfer != 2) throw bad("transfer function " + std::to_string(transfer) + " is neither linear (1) nor sRGB (2)");
    if ((transfer == 2) != f.srgb)
        throw bad(std::string("transfer function ") + (transfer == 2 ? "sRGB" : "linear") + " contradicts the format " + f.name);
    return transfer == 2;
}

// The key/value data (section 3.11): entries of a length, a NUL-terminated key and a value, each
// padded to 4 bytes. Returns KTXorientation's value, "rd" (its default) where absent.
std::string orientation_of(const std::string& path, const std::string& b, const header& h) {
    const auto bad = [&](const std::string& what) { return bad_input(path + ": KTX2 key/value data: " + what); };
    std::string orientation;
    const std::size_t end = std::size_t(h.kvd_offset) + h.kvd_length;
    for (std::size_t at = h.kvd_offset; at < end;) {
        if (end - at < 4) throw bad("an entry cut short at byte " + std::to_string(at));
        const std::size_t len = le32(b, at);
        if (len > end - at - 4) throw bad("an entry of " + std::to_string(len) + " bytes runs past its end");
        const std::string entry = b.substr(at + 4, len);
        const std::size_t nul = entry.find('\0');
        if (nul == std::string::npos || nul == 0) throw bad("an entry at byte " + std::to_string(at) + " has no NUL-terminated key");
        if (entry.compare(0, nul, "KTXorientation") == 0) {
            if (!orientation.empty()) throw bad("KTXorientation given twice");
            orientation = entry.substr(nul + 1);
            if (!orientation.empty() && orientation.back() == '\0') orientation.pop_back();
            if (orientation.size() != 2 || (orientation[0] != 'r' && orientation[0] != 'l') ||
                (orientation[1] != 'd' && orientation[1] != 'u'))
                throw bad("KTXorientation is not one of rd, ru, ld, lu (a 2D texture's)");
        }
        at += 4 + len;
        at += (4 - at % 4) % 4;
        if (at > end) throw bad("the last entry's padding runs past its end");
    }
    return orientation.empty() ? "rd" : orientation;
}

// Where the metadata lie: the level index after the header, the DFD right after it, the
// key/value data right after that (section 3.9's order), all within the file. Returns where
// they end.
std::uint64_t check_metadata(const std::string& b, const header& h, const std::function<bad_input(const std::string&)>& bad) {
    const auto n = [](std::uint64_t v) { return std::to_string(v); };
    const std::size_t index_end = header_bytes + level_entry_bytes * h.level_count();
    if (index_end > b.size()) throw bad("truncated: " + n(b.size()) + " bytes, the level index ends at " + n(index_end));
    if (h.dfd_offset != index_end)
        throw bad("dfdByteOffset " + n(h.dfd_offset) + " is not " + n(index_end) + ", right after the level index");
    std::uint64_t end = std::uint64_t(h.dfd_offset) + h.dfd_length;
    if (end > b.size()) throw bad("truncated: the data format descriptor runs past the end");
    if (h.kvd_length == 0 && h.kvd_offset != 0) throw bad("kvdByteOffset " + n(h.kvd_offset) + " with no key/value data");
    if (h.kvd_length != 0) {
        if (h.kvd_offset != end) throw bad("kvdByteOffset " + n(h.kvd_offset) + " is not " + n(end) + ", right after the descriptor");
        end += h.kvd_length;
        if (end > b.size()) throw bad("truncated: the key/value data runs past the end");
    }
    return end;
}

// Every level's data past the metadata, within the file, of the size its mip level takes
// (uncompressed: that size exactly, aligned to lcm(texel size, 4); section 3.9.7).
void check_levels(const std::string& path, const std::string& b, const header& h, const ktx2_format& f) {
    const auto bad = [&](const std::string& what) { return bad_input(path + ": KTX2 " + what); };
    const auto n = [](std::uint64_t v) { return std::to_string(v); };
    const std::uint64_t meta_end = check_metadata(b, h, bad);
    const std::size_t texel = f.channels * value_bytes(f.encoding), align = std::lcm(texel, std::size_t(4));
    for (std::size_t i = 0; i < h.level_count(); ++i) {
        const std::size_t entry = header_bytes + level_entry_bytes * i;
        const std::uint64_t offset = le64(b, entry), length = le64(b, entry + 8), full = le64(b, entry + 16);
        const std::uint64_t need = std::uint64_t(std::max<std::uint32_t>(h.width >> i, 1)) * std::max<std::uint32_t>(h.height >> i, 1) * texel;
        const std::string level = "level " + n(i) + ": ";
        if (full != need) throw bad(level + "uncompressedByteLength " + n(full) + " is not " + n(need) + ", the size of its texels");
        if (offset < meta_end) throw bad(level + "its data at byte " + n(offset) + " overlaps the header, descriptor or key/value data");
        if (offset > b.size() || length > b.size() - offset)
            throw bad(level + "truncated: its " + n(length) + " bytes at " + n(offset) + " run past the file's end (" + n(b.size()) + " bytes)");
        if (h.scheme == 0 && (length != full || offset % align != 0))
            throw bad(level + "uncompressed, " + n(length) + " bytes at " + n(offset) + ": not its " + n(full) + " bytes aligned to " + n(align));
        // a Zstandard block of 4 bytes (an RLE block) expands to at most 128 KiB: a level that
        // claims more is refused before its texels are allocated
        if (h.scheme == 2 && full / 32768 > length) throw bad(level + n(length) + " bytes of Zstandard cannot expand to " + n(full));
    }
}

// Level 0's bytes, decompressed where supercompressed (section 3.12.2: one or more Zstandard frames).
std::string level0(const std::string& path, const std::string& b, const header& h) {
    const std::uint64_t offset = le64(b, header_bytes), length = le64(b, header_bytes + 8);
    const std::uint64_t full = le64(b, header_bytes + 16);
    if (h.scheme == 0) return b.substr(offset, length);
    std::string out(full, '\0');
    const std::size_t got = ZSTD_decompress(out.data(), out.size(), b.data() + offset, length);
    if (ZSTD_isError(got))
        throw bad_input(path + ": KTX2 level 0: corrupt Zstandard data (" + ZSTD_getErrorName(got) + ")");
    if (got != full)
        throw bad_input(path + ": KTX2 level 0: Zstandard data of " + std::to_string(got) + " bytes, not " + std::to_string(full));
    return out;
}

std::string dfd_of(const ktx2_format& f) {
    const std::size_t bits = 8 * value_bytes(f.encoding), samples = f.channels;
    const bool is_float = f.encoding == value_encoding::half || f.encoding == value_encoding::float32;
    std::string d;
    put32(d, std::uint32_t(4 + 24 + 16 * samples));
    put32(d, 0);                                                // vendor 0, descriptor type 0
    put16(d, 2), put16(d, std::uint32_t(24 + 16 * samples));    // version 1.3, block size
    d += char(1), d += char(1), d += char(f.srgb ? 2 : 1), d += char(0);  // RGBSDA, BT.709, transfer, straight alpha
    put32(d, 0);                                                // texel block 1 x 1 x 1 x 1
    d += char(f.channels * bits / 8), d.append(7, '\0');        // bytesPlane0..7
    const unsigned ids[] = {0, 1, 2, 15};
    for (std::size_t s = 0; s < samples; ++s) {
        // float samples are signed floats in [-1, 1]; unorm ones integers in [0, 2^bits - 1];
        // alpha of an sRGB format is linear
        const unsigned qualifiers = is_float ? 0xC0 : f.srgb && ids[s] == 15 ? 0x10 : 0;
        put16(d, std::uint32_t(s * bits));
        d += char(bits - 1), d += char(ids[s] | qualifiers);
        put32(d, 0);
        put32(d, is_float ? 0xBF800000u : 0);
        put32(d, is_float ? 0x3F800000u : std::uint32_t((std::uint64_t(1) << bits) - 1));
    }
    return d;
}

}  // namespace

std::string encode_ktx2(const lut_image& im, std::uint32_t vk, bool zstd) {
    const ktx2_format* f = ktx2_format_of(vk);
    if (!f) throw std::invalid_argument("KTX2: " + vk_format_name(vk) + " is not a format normzoo writes");
    check_image(im);
    if (im.channels != f->channels)
        throw std::invalid_argument("KTX2: " + std::to_string(im.channels) + " channels in " + f->name);
    std::string texels;
    encode_values(im.data, f->encoding, texels);
    std::string level = texels;
    if (zstd) {
        level.assign(ZSTD_compressBound(texels.size()), '\0');
        const std::size_t n = ZSTD_compress(level.data(), level.size(), texels.data(), texels.size(), 19);
        if (ZSTD_isError(n)) throw std::runtime_error(std::string("KTX2: Zstandard: ") + ZSTD_getErrorName(n));
        level.resize(n);
    }
    const std::string dfd = dfd_of(*f);
    std::string kvd;
    const std::string entry = std::string("KTXwriter") + '\0' + "normzoo" + '\0';
    put32(kvd, std::uint32_t(entry.size()));
    kvd += entry;
    kvd.append((4 - kvd.size() % 4) % 4, '\0');
    const std::size_t dfd_at = header_bytes + level_entry_bytes, kvd_at = dfd_at + dfd.size(), meta_end = kvd_at + kvd.size();
    const std::size_t align = zstd ? 1 : std::lcm(f->channels * value_bytes(f->encoding), std::size_t(4));
    const std::size_t level_at = (meta_end + align - 1) / align * align;

    std::string out(identifier, 12);
    for (const std::uint32_t v : {f->vk, std::uint32_t(value_bytes(f->encoding)), std::uint32_t(im.width),
                                  std::uint32_t(im.height), 0u, 0u, 1u, 1u, zstd ? 2u : 0u, std::uint32_t(dfd_at),
                                  std::uint32_t(dfd.size()), std::uint32_t(kvd_at), std::uint32_t(kvd.size())})
        put32(out, v);
    put64(out, 0), put64(out, 0);  // no supercompression global data
    put64(out, level_at), put64(out, level.size()), put64(out, texels.size());
    out += dfd + kvd;
    out.append(level_at - out.size(), '\0');
    return out + level;
}

decoded_lut read_ktx2(const std::string& path, const std::string& b) {
    if (b.size() < 12 || std::memcmp(b.data(), identifier, 12) != 0) throw bad_input(path + ": not a KTX2 file (its identifier)");
    if (b.size() < header_bytes)
        throw bad_input(path + ": KTX2 truncated: " + std::to_string(b.size()) + " bytes, the header takes " + std::to_string(header_bytes));
    const header h = header_of(b);
    const ktx2_format& f = check_header(path, h);
    check_levels(path, b, h, f);
    const bool srgb = check_dfd(path, b, h, f);
    decoded_lut d;
    d.orientation = orientation_of(path, b, h);
    const std::string texels = level0(path, b, h);
    d.image.width = h.width, d.image.height = h.height, d.image.channels = f.channels;
    d.image.data.reserve(std::size_t(h.width) * h.height * f.channels);
    decode_values(texels.data(), std::size_t(h.width) * h.height * f.channels, f.encoding, d.image.data);
    d.format = std::string("ktx2-") + f.name;
    set_storage_tolerance(d, f.encoding);
    d.colour.declared = srgb ? colour_declaration::kind::srgb : colour_declaration::kind::linear;
    return d;
}

}  // namespace verify
