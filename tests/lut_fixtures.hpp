// Files in the formats engines ship their tables in, made byte by byte by the tests (never
// copied from an engine) for tests/test_lut_formats.cpp and tests/test_lut_layout.cpp: a PNG with
// stored deflate blocks and the colour chunks chosen, base64, RGBE pixels and scanlines,
// little-endian fields; KTX2 files field by field as Bevy's dfg.ktx2 is laid out, three.js's
// Uint16Array of half bits, DDS headers, Radiance pictures.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <zstd.h>

#include "lut_formats/texels.hpp"

namespace lut_fixture {

inline void le(std::string& out, std::uint64_t v, int bytes) {
    for (int k = 0; k < bytes; ++k) out += char(v >> 8 * k & 0xff);
}
inline void be32(std::string& out, std::uint32_t v) {
    for (int k = 3; k >= 0; --k) out += char(v >> 8 * k & 0xff);
}

inline std::uint32_t crc32(const std::string& s) {
    std::uint32_t c = 0xffffffff;
    for (unsigned char b : s) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >> 1) : c >> 1;
    }
    return ~c;
}

// A zlib stream of stored (uncompressed) deflate blocks.
inline std::string zlib_stored(const std::string& data) {
    std::string z = "\x78\x01";
    std::size_t at = 0;
    do {
        const std::size_t n = std::min<std::size_t>(65535, data.size() - at);
        z += char(at + n == data.size() ? 1 : 0);
        le(z, n, 2), le(z, ~n & 0xffff, 2);
        z += data.substr(at, n);
        at += n;
    } while (at < data.size());
    std::uint32_t a = 1, b = 0;
    for (unsigned char c : data) a = (a + c) % 65521, b = (b + a) % 65521;
    be32(z, b << 16 | a);
    return z;
}

inline std::string png_chunk(const std::string& type, const std::string& data) {
    std::string c;
    be32(c, std::uint32_t(data.size()));
    c += type + data;
    be32(c, crc32(type + data));
    return c;
}

// An 8-bit PNG of `channels` (1 gray ... 4 RGBA), rows unfiltered, with `colour` chunks
// (already framed by png_chunk) before its image data.
inline std::string png8(std::uint32_t w, std::uint32_t h, int channels, const std::vector<std::uint8_t>& samples,
                        const std::string& colour = "") {
    std::string ihdr;
    be32(ihdr, w), be32(ihdr, h);
    const int type[] = {0, 0, 4, 2, 6};
    ihdr += char(8), ihdr += char(type[channels]), ihdr += std::string(3, '\0');
    std::string raw;
    for (std::uint32_t j = 0; j < h; ++j) {
        raw += '\0';  // filter: none
        for (std::uint32_t i = 0; i < w * std::uint32_t(channels); ++i) raw += char(samples[j * w * std::uint32_t(channels) + i]);
    }
    return std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr) + colour + png_chunk("IDAT", zlib_stored(raw)) +
           png_chunk("IEND", "");
}

inline std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t k = 0; k < bytes.size(); k += 3) {
        std::uint32_t v = std::uint32_t(std::uint8_t(bytes[k])) << 16;
        if (k + 1 < bytes.size()) v |= std::uint32_t(std::uint8_t(bytes[k + 1])) << 8;
        if (k + 2 < bytes.size()) v |= std::uint8_t(bytes[k + 2]);
        out += digits[v >> 18], out += digits[v >> 12 & 63];
        out += k + 1 < bytes.size() ? digits[v >> 6 & 63] : '=';
        out += k + 2 < bytes.size() ? digits[v & 63] : '=';
    }
    return out;
}

// Radiance's setcolr(): the largest of r, g, b as a mantissa in [128, 256) and an exponent.
inline void rgbe(double r, double g, double b, std::uint8_t out[4]) {
    const double d = std::max(r, std::max(g, b));
    if (d <= 1e-32) {
        out[0] = out[1] = out[2] = out[3] = 0;
        return;
    }
    int e = 0;
    const double scale = std::frexp(d, &e) * 255.9999 / d;
    out[0] = std::uint8_t(r * scale), out[1] = std::uint8_t(g * scale), out[2] = std::uint8_t(b * scale);
    out[3] = std::uint8_t(e + 128);
}

// One scanline of 4-byte pixels, run-length encoded as Radiance 2.0 writes it (fwritescan()):
// 02 02 and the width, then each component's plane in runs (128 + n, value) and literals (n, ...).
inline std::string rle_scanline(const std::vector<std::uint8_t>& pixels, std::size_t w) {
    std::string out = {2, 2, char(w >> 8), char(w & 0xff)};
    for (std::size_t c = 0; c < 4; ++c) {
        for (std::size_t x = 0; x < w;) {
            std::size_t run = 1;
            while (x + run < w && run < 127 && pixels[4 * (x + run) + c] == pixels[4 * x + c]) ++run;
            if (run >= 3) {
                out += char(128 + run), out += char(pixels[4 * x + c]);
                x += run;
                continue;
            }
            std::size_t n = 0;  // a literal up to the next run of 3
            while (x + n < w && n < 128 &&
                   !(x + n + 2 < w && pixels[4 * (x + n) + c] == pixels[4 * (x + n + 1) + c] &&
                     pixels[4 * (x + n) + c] == pixels[4 * (x + n + 2) + c]))
                ++n;
            if (n == 0) n = 1;
            out += char(n);
            for (std::size_t k = 0; k < n; ++k) out += char(pixels[4 * (x + k) + c]);
            x += n;
        }
    }
    return out;
}

// A KTX2 file field by field, as `ktx create --format R16G16_SFLOAT --zstd 22` lays one out (the
// layout of Bevy's dfg.ktx2: docs/lut.md): header, one level's index entry, the DFD right after,
// the key/value data right after that, the level's data right after them.
struct ktx2_parts {
    std::uint32_t vk = 83, type_size = 2, width = 16, height = 16, depth = 0, layers = 0, faces = 1, levels = 1, scheme = 2;
    std::string dfd, kvd, level;
    std::uint64_t uncompressed = 0;
};

inline std::string kvd_entry(const std::string& key, const std::string& value) {
    std::string e;
    le(e, key.size() + value.size() + 2, 4);
    e += key + '\0' + value + '\0';
    e.append((4 - e.size() % 4) % 4, '\0');
    return e;
}

// The basic descriptor block of R16G16_SFLOAT: RGBSDA, BT.709, linear (transfer 2: sRGB), 4 bytes
// a texel, samples R and G of 16 bits, signed floats in [-1, 1].
inline std::string rg16f_dfd(int transfer = 1) {
    std::string d;
    le(d, 60, 4), le(d, 0, 4), le(d, 2, 2), le(d, 56, 2);
    d += char(1), d += char(1), d += char(transfer), d += char(0);
    le(d, 0, 4);
    d += char(4), d += std::string(7, '\0');
    for (int c = 0; c < 2; ++c) {
        le(d, 16 * c, 2), d += char(15), d += char(0xC0 | c);
        le(d, 0, 4), le(d, 0xBF800000, 4), le(d, 0x3F800000, 4);
    }
    return d;
}

inline std::string ktx2_bytes(const ktx2_parts& p) {
    std::string out("\xAB" "KTX 20\xBB\r\n\x1A\n", 12);
    const std::size_t dfd_at = 80 + 24, kvd_at = dfd_at + p.dfd.size(), level_at = kvd_at + p.kvd.size();
    for (std::uint32_t v : {p.vk, p.type_size, p.width, p.height, p.depth, p.layers, p.faces, p.levels, p.scheme,
                            std::uint32_t(dfd_at), std::uint32_t(p.dfd.size()), std::uint32_t(p.kvd.empty() ? 0 : kvd_at),
                            std::uint32_t(p.kvd.size())})
        le(out, v, 4);
    le(out, 0, 8), le(out, 0, 8);
    le(out, level_at, 8), le(out, p.level.size(), 8), le(out, p.uncompressed, 8);
    return out + p.dfd + p.kvd + p.level;
}

// A 16 x 16 table of (A, B) as half bits: A falls with roughness and rises with mu, B is small.
inline std::vector<std::uint16_t> dfg_halves(std::size_t n) {
    std::vector<std::uint16_t> h;
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < n; ++i) {
            const double mu = (i + 0.5) / double(n), r = (j + 0.5) / double(n);
            h.push_back(verify::double_to_half(mu * (1 - 0.5 * r)));
            h.push_back(verify::double_to_half(0.1 * r * (1 - mu)));
        }
    return h;
}

// Bevy's dfg.ktx2 as `ktx create --zstd 22` lays it out: n x n texels of two half values (halves:
// row by row, by default dfg_halves(16)).
inline ktx2_parts bevy_like(const std::vector<std::uint16_t>& halves = dfg_halves(16), std::uint32_t n = 16) {
    ktx2_parts p;
    p.width = p.height = n;
    std::string texels;
    for (std::uint16_t v : halves) le(texels, v, 2);
    p.level.assign(ZSTD_compressBound(texels.size()), '\0');
    p.level.resize(ZSTD_compress(&p.level[0], p.level.size(), texels.data(), texels.size(), 22));
    p.uncompressed = texels.size();
    p.dfd = rg16f_dfd();
    p.kvd = kvd_entry("KTXwriter", "tests/test_lut_formats.cpp") + kvd_entry("KTXwriterScParams", "--zstd 22");
    return p;
}

// three.js's DFGLUTData.js as it ships its table: an n x n table of two half values (bits: row by
// row) as a Uint16Array of hex literals, eight a line, whose size is handed on to a DataTexture.
inline std::string threejs_like(const std::vector<std::uint16_t>& bits, std::size_t n) {
    const std::string side = std::to_string(n);
    std::string js = "/**\n * A DFG table for a test: " + side + " x " + side + ", (scale, bias) as half floats.\n * Resolution: " + side +
                     "x" + side + "\n */\n\nimport { DataTexture } from '../../textures/DataTexture.js';\n\nconst DATA = new Uint16Array( [\n";
    for (std::size_t k = 0; k < bits.size(); ++k) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%04x", unsigned(bits[k]));
        js += (k % 8 ? " " : "\t") + std::string(hex) + (k + 1 < bits.size() ? "," : "") + (k % 8 == 7 ? "\n" : "");
    }
    return js + "] );\n\nlet lut = null;\n\nexport function getDFGLUT() {\n\n\tif ( lut === null ) {\n\n\t\tlut = new DataTexture( DATA, " +
           side + ", " + side + ", RGFormat, HalfFloatType );\n\t}\n\n\treturn lut;\n\n}\n";
}

inline std::string dds_header(std::uint32_t w, std::uint32_t h, std::uint32_t pf_flags, std::uint32_t fourcc, std::uint32_t bits,
                       std::vector<std::uint32_t> masks = {0, 0, 0, 0}, std::uint32_t caps2 = 0) {
    std::string out = "DDS ";
    for (std::uint32_t v : {124u, 0x1007u, h, w, 0u, 0u, 0u}) le(out, v, 4);
    out += std::string(44, '\0');
    for (std::uint32_t v : {32u, pf_flags, fourcc, bits, masks[0], masks[1], masks[2], masks[3]}) le(out, v, 4);
    for (std::uint32_t v : {0x1000u, caps2, 0u, 0u, 0u}) le(out, v, 4);
    return out;
}

inline std::string dx10(std::uint32_t dxgi, std::uint32_t dimension = 3, std::uint32_t misc = 0, std::uint32_t array = 1) {
    std::string out;
    for (std::uint32_t v : {dxgi, dimension, misc, array, 0u}) le(out, v, 4);
    return out;
}

// A Radiance picture: its header lines, the resolution line, and the pixels (r, g, b) of each row
// as setcolr() encodes them, run-length encoded (w in [8, 0x7fff]) or flat.
inline std::string hdr_file(std::size_t w, std::size_t h, const std::vector<double>& rgb, const std::string& header = "FORMAT=32-bit_rle_rgbe\n",
                     const std::string& resolution = "") {
    std::string f = "#?RADIANCE\n# made by tests/test_lut_formats.cpp\n" + header + "\n" +
                    (resolution.empty() ? "-Y " + std::to_string(h) + " +X " + std::to_string(w) : resolution) + "\n";
    for (std::size_t y = 0; y < h; ++y) {
        std::vector<std::uint8_t> row(4 * w);
        for (std::size_t x = 0; x < w; ++x) rgbe(rgb[3 * (y * w + x)], rgb[3 * (y * w + x) + 1], rgb[3 * (y * w + x) + 2], &row[4 * x]);
        if (w >= 8) f += rle_scanline(row, w);
        else f.append(row.begin(), row.end());
    }
    return f;
}

inline std::vector<double> hdr_values(std::size_t w, std::size_t h) {
    std::vector<double> v;
    for (std::size_t y = 0; y < h; ++y)
        for (std::size_t x = 0; x < w; ++x) {
            v.push_back((x + 0.5) / double(w));
            v.push_back(y < h / 2 ? 0.25 : 0.01 * double(x));  // runs in the upper half, literals below
            v.push_back(0);
        }
    return v;
}

}  // namespace lut_fixture
