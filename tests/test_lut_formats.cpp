// The files engines ship their tables in (src/verify/lut_formats/, docs/lut.md "Files it reads"):
// KTX2 and DDS round trips through normzoo's writers; fixtures in the engines' formats made byte
// by byte here (tests/lut_fixtures.hpp), never copied from an engine: a zstd KTX2 of
// R16G16_SFLOAT as Bevy ships its dfg.ktx2, a DX10 DDS of R16G16_FLOAT, a 16 x 16 RGBE .hdr, a
// three.js-style Uint16Array of half bits, a Babylon-style base64 PNG in a .js string, C, WGSL
// and GLSL arrays; PNG colour chunks; malformed files refused as bad input naming the culprit.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "args.hpp"
#include "lut_fixtures.hpp"
#include "lut_formats/dds.hpp"
#include "lut_formats/hdr.hpp"
#include "lut_formats/ktx2.hpp"
#include "lut_formats/png.hpp"
#include "lut_formats/read.hpp"
#include "lut_formats/source_array.hpp"
#include "lut_formats/texels.hpp"
#include "lut_image.hpp"
#include "temp_files.hpp"

using namespace lut_fixture;
using normzoo_test::temp_dir;
using verify::bad_input;
using verify::decoded_lut;
using verify::lut_image;
using verify::value_encoding;

namespace {

// A w x h image of `channels` whose values run over [0, 1], 0 and 1 included.
lut_image sample(std::size_t w, std::size_t h, std::size_t channels) {
    lut_image im{w, h, channels, {}};
    for (std::size_t k = 0; k < w * h * channels; ++k)
        im.data.push_back(k == 0 ? 0.0 : k == 1 ? 1.0 : std::fmod(0.123456789 * double(k * k), 1.0));
    return im;
}

std::string message_of(const std::string& path) {
    try {
        verify::read_lut_file(path, {});
    } catch (const bad_input& e) {
        return e.what();
    }
    return "(no bad_input)";
}

// What a value becomes when stored in e and read back.
double stored(double v, value_encoding e) {
    switch (e) {
        case value_encoding::unorm8: return std::round(v * 255) / 255;
        case value_encoding::unorm16: return std::round(v * 65535) / 65535;
        case value_encoding::half: return verify::half_to_double(verify::double_to_half(v));
        default: return double(float(v));
    }
}

void check_values(const decoded_lut& d, const lut_image& im, value_encoding e) {
    REQUIRE(d.image.width == im.width);
    REQUIRE(d.image.height == im.height);
    REQUIRE(d.image.channels == im.channels);
    CHECK(d.encoding == e);
    for (std::size_t k = 0; k < im.data.size(); ++k) {
        CAPTURE(k, im.data[k]);
        CHECK(d.image.data[k] == stored(im.data[k], e));
        CHECK(std::abs(d.image.data[k] - im.data[k]) <= d.tolerance(k));
    }
}

}  // namespace

TEST_CASE("binary16 conversions: exact one way, to nearest even the other") {
    CHECK(verify::double_to_half(1.0) == 0x3c00);
    CHECK(verify::double_to_half(0.5) == 0x3800);
    CHECK(verify::double_to_half(65504) == 0x7bff);
    CHECK(verify::double_to_half(65520) == 0x7c00);  // the midpoint to 2^16 rounds to even: infinity
    CHECK(verify::double_to_half(std::ldexp(1.0, -24)) == 0x0001);
    CHECK(verify::double_to_half(std::ldexp(1.0, -25)) == 0x0000);  // a tie, to even
    CHECK(verify::double_to_half(std::ldexp(3.0, -26)) == 0x0001);
    CHECK(verify::double_to_half(-2.0) == 0xc000);
    CHECK(verify::double_to_float(1e300) == 0x7f800000u);  // infinity, not undefined behaviour
    CHECK(verify::double_to_float(-double(std::numeric_limits<float>::max())) == 0xff7fffffu);
    for (std::uint32_t bits = 0; bits < 0x10000; ++bits) {
        if ((bits & 0x7c00) == 0x7c00 && (bits & 0x3ff)) continue;  // NaN
        CHECK(verify::double_to_half(verify::half_to_double(std::uint16_t(bits))) == bits);
    }
}

TEST_CASE("KTX2 round trip through normzoo's writer, every format, uncompressed and zstd") {
    const std::uint32_t vk = GENERATE(9u, 16u, 37u, 43u, 70u, 76u, 77u, 83u, 90u, 91u, 97u, 100u, 103u, 109u);
    const bool zstd = GENERATE(false, true);
    const verify::ktx2_format* f = verify::ktx2_format_of(vk);
    REQUIRE(f);
    CAPTURE(f->name, zstd);
    temp_dir dir{"lut-formats"};
    const lut_image im = sample(7, 5, f->channels);
    const std::string bytes = verify::encode_ktx2(im, vk, zstd);
    const decoded_lut d = verify::read_lut_file(dir.file("t.ktx2", bytes), {});
    CHECK(d.format == std::string("ktx2-") + f->name);
    CHECK(d.orientation == "rd");
    CHECK(d.colour.declared == (f->srgb ? verify::colour_declaration::kind::srgb : verify::colour_declaration::kind::linear));
    check_values(d, im, f->encoding);
    CHECK(verify::le32(bytes, 44) == (zstd ? 2u : 0u));  // supercompressionScheme
}

TEST_CASE("DDS round trip through normzoo's writer, every format") {
    const std::uint32_t dxgi = GENERATE(2u, 10u, 11u, 16u, 28u, 29u, 34u, 35u, 41u, 49u, 54u, 56u, 61u);
    const verify::dds_format* f = verify::dds_format_of(dxgi);
    REQUIRE(f);
    CAPTURE(f->name);
    temp_dir dir{"lut-formats"};
    const lut_image im = sample(6, 9, f->channels);
    const decoded_lut d = verify::read_lut_file(dir.file("t.dds", verify::encode_dds(im, dxgi)), {});
    CHECK(d.format == std::string("dds-") + f->name);
    CHECK(d.orientation.empty());
    CHECK(d.colour.declared == (f->srgb ? verify::colour_declaration::kind::srgb : verify::colour_declaration::kind::none));
    check_values(d, im, f->encoding);
}


TEST_CASE("a zstd KTX2 of R16G16_SFLOAT laid out as Bevy's dfg.ktx2") {
    temp_dir dir{"lut-formats"};
    const decoded_lut d = verify::read_lut_file(dir.file("dfg.ktx2", ktx2_bytes(bevy_like())), {});
    CHECK(d.format == "ktx2-R16G16_SFLOAT");
    CHECK(d.encoding == value_encoding::half);
    CHECK(d.orientation == "rd");  // no KTXorientation: the default
    CHECK(d.colour.declared == verify::colour_declaration::kind::linear);
    REQUIRE(d.image.width == 16);
    REQUIRE(d.image.height == 16);
    REQUIRE(d.image.channels == 2);
    const auto halves = dfg_halves(16);
    for (std::size_t k = 0; k < halves.size(); ++k) CHECK(d.image.data[k] == verify::half_to_double(halves[k]));
    CHECK(d.relative == std::ldexp(1.0, -11));
}

TEST_CASE("KTX2: what a table is not, refused naming the culprit") {
    struct bad_case {
        const char* what;
        const char* says;
    };
    const bad_case c = GENERATE(bad_case{"bc7", "BC7_SRGB_BLOCK is not read"}, bad_case{"b10g11r11", "B10G11R11_UFLOAT_PACK32"},
                                bad_case{"cube", "6 faces"}, bad_case{"basis", "BasisLZ"}, bad_case{"zlib", "ZLIB"},
                                bad_case{"3d", "3D texture"}, bad_case{"layers", "array of 3 layers"},
                                bad_case{"wide", "4097 x 16; a table is 1 to 4096"}, bad_case{"1d", "1D texture"},
                                bad_case{"type-size", "typeSize 4"}, bad_case{"srgb-dfd", "contradicts the format R16G16_SFLOAT"},
                                bad_case{"length", "uncompressedByteLength"}, bad_case{"corrupt", "Zstandard"},
                                bad_case{"orientation", "KTXorientation is not one of"}, bad_case{"expand", "cannot expand"},
                                bad_case{"dfd-size", "dfdTotalSize"}, bad_case{"levels", "40 mip levels"});
    CAPTURE(c.what);
    const std::string what = c.what;
    ktx2_parts p = bevy_like();
    if (what == "bc7") p.vk = 146;
    if (what == "b10g11r11") p.vk = 122;
    if (what == "cube") p.faces = 6;
    if (what == "basis") p.scheme = 1;
    if (what == "zlib") p.scheme = 3;
    if (what == "3d") p.depth = 4;
    if (what == "layers") p.layers = 3;
    if (what == "wide") p.width = 4097;
    if (what == "1d") p.height = 0;
    if (what == "type-size") p.type_size = 4;
    if (what == "srgb-dfd") p.dfd = rg16f_dfd(2);
    if (what == "length") p.uncompressed += 4;
    if (what == "corrupt") p.level.resize(p.level.size() - 5);  // the frame cut short
    if (what == "orientation") p.kvd += kvd_entry("KTXorientation", "rdi");
    if (what == "expand") p.width = p.height = 4096, p.vk = 109, p.type_size = 4, p.uncompressed = 4096ull * 4096 * 16;
    if (what == "dfd-size") p.dfd[0] = 61;
    if (what == "levels") p.levels = 40;
    temp_dir dir{"lut-formats"};
    const std::string path = dir.file("bad.ktx2", ktx2_bytes(p));
    const std::string m = message_of(path);
    CHECK_THAT(m, Catch::Matchers::StartsWith(path + ": ") && Catch::Matchers::Contains(c.says));
}

TEST_CASE("KTX2: KTXorientation is reported, not applied") {
    ktx2_parts p = bevy_like();
    p.kvd += kvd_entry("KTXorientation", "ru");
    temp_dir dir{"lut-formats"};
    CHECK(verify::read_lut_file(dir.file("ru.ktx2", ktx2_bytes(p)), {}).orientation == "ru");
}


TEST_CASE("a DX10 DDS of R16G16_FLOAT made by hand") {
    temp_dir dir{"lut-formats"};
    std::string f = dds_header(16, 16, 0x4, 0x30315844, 0) + dx10(34);
    const auto halves = dfg_halves(16);
    for (std::uint16_t v : halves) le(f, v, 2);
    const decoded_lut d = verify::read_lut_file(dir.file("dfg.dds", f), {});
    CHECK(d.format == "dds-R16G16_FLOAT");
    REQUIRE(d.image.channels == 2);
    REQUIRE(d.image.width == 16);
    for (std::size_t k = 0; k < halves.size(); ++k) CHECK(d.image.data[k] == verify::half_to_double(halves[k]));
}

TEST_CASE("DDS legacy headers: bit masks and float FourCCs, channels in R, G, B, A order") {
    temp_dir dir{"lut-formats"};
    const std::vector<std::uint8_t> texel = {10, 20, 30, 40};  // the bytes of the one texel, lowest first
    struct legacy {
        const char* name;
        std::uint32_t flags, bits;
        std::vector<std::uint32_t> masks;
        std::vector<double> rgba;  // what the texel's bytes are
    };
    const legacy l = GENERATE(legacy{"B8G8R8A8_UNORM", 0x41, 32, {0xff0000, 0xff00, 0xff, 0xff000000}, {30, 20, 10, 40}},
                              legacy{"R8G8B8A8_UNORM", 0x41, 32, {0xff, 0xff00, 0xff0000, 0xff000000}, {10, 20, 30, 40}},
                              legacy{"B8G8R8X8_UNORM", 0x40, 32, {0xff0000, 0xff00, 0xff, 0xff000000}, {30, 20, 10}},
                              legacy{"B8G8R8_UNORM", 0x40, 24, {0xff0000, 0xff00, 0xff, 0}, {30, 20, 10}});
    CAPTURE(l.name);
    std::string f = dds_header(1, 1, l.flags, 0, l.bits, l.masks);
    for (std::uint32_t k = 0; k < l.bits / 8; ++k) f += char(texel[k]);
    const decoded_lut d = verify::read_lut_file(dir.file("l.dds", f), {});
    CHECK(d.format == std::string("dds-") + l.name);
    CHECK(d.encoding == value_encoding::unorm8);
    REQUIRE(d.image.data.size() == l.rgba.size());
    for (std::size_t c = 0; c < l.rgba.size(); ++c) CHECK(d.image.data[c] == l.rgba[c] / 255);

    SECTION("G16R16 masks") {
        std::string g = dds_header(1, 1, 0x40, 0, 32, {0xffff, 0xffff0000, 0, 0});
        le(g, 0x8000ffff, 4);
        const decoded_lut e = verify::read_lut_file(dir.file("g.dds", g), {});
        CHECK(e.format == "dds-R16G16_UNORM");
        CHECK(e.image.data == std::vector<double>{1.0, 32768 / 65535.0});
    }
    SECTION("FourCC 112, G16R16F") {
        std::string g = dds_header(1, 1, 0x4, 112, 0);
        le(g, 0x3c00, 2), le(g, 0x3800, 2);
        const decoded_lut e = verify::read_lut_file(dir.file("h.dds", g), {});
        CHECK(e.format == "dds-R16G16_FLOAT");
        CHECK(e.image.data == std::vector<double>{1.0, 0.5});
    }
}

TEST_CASE("DDS: what a table is not, refused naming the culprit") {
    struct bad_case {
        const char* what;
        const char* says;
    };
    const bad_case c = GENERATE(bad_case{"dxt5", "FourCC 'DXT5'"}, bad_case{"bc7", "BC7_UNORM is not read"},
                                bad_case{"r32f", "D3DFMT_R32F (114)"}, bad_case{"565", "RGB bit masks of 16 bits"},
                                bad_case{"cube", "cube map"}, bad_case{"volume", "3D"}, bad_case{"array", "array of 2"},
                                bad_case{"wide", "4097 x 1; a table is 1 to 4096"}, bad_case{"short", "truncated"},
                                bad_case{"header-size", "header size 100"}, bad_case{"luminance", "neither a FourCC nor RGB"});
    CAPTURE(c.what);
    const std::string what = c.what;
    std::string f;
    if (what == "dxt5") f = dds_header(4, 4, 0x4, 0x35545844, 0) + std::string(16, '\0');
    if (what == "bc7") f = dds_header(4, 4, 0x4, 0x30315844, 0) + dx10(98) + std::string(16, '\0');
    if (what == "r32f") f = dds_header(1, 1, 0x4, 114, 0) + std::string(4, '\0');
    if (what == "565") f = dds_header(1, 1, 0x40, 0, 16, {0xf800, 0x7e0, 0x1f, 0}) + std::string(2, '\0');
    if (what == "cube") f = dds_header(1, 1, 0x40, 0, 32, {0xff, 0xff00, 0xff0000, 0}, 0x200) + std::string(24, '\0');
    if (what == "volume") f = dds_header(1, 1, 0x4, 0x30315844, 0) + dx10(34, 4) + std::string(4, '\0');
    if (what == "array") f = dds_header(1, 1, 0x4, 0x30315844, 0) + dx10(34, 3, 0, 2) + std::string(8, '\0');
    if (what == "wide") f = dds_header(4097, 1, 0x4, 0x30315844, 0) + dx10(34) + std::string(4 * 4097, '\0');
    if (what == "short") f = dds_header(16, 16, 0x4, 0x30315844, 0) + dx10(34) + std::string(1023, '\0');
    if (what == "header-size") (f = dds_header(1, 1, 0x4, 112, 0) + std::string(4, '\0'))[4] = 100;
    if (what == "luminance") f = dds_header(1, 1, 0x20000, 0, 8, {0xff, 0, 0, 0}) + std::string(1, '\0');
    temp_dir dir{"lut-formats"};
    const std::string path = dir.file("bad.dds", f);
    CHECK_THAT(message_of(path), Catch::Matchers::StartsWith(path + ": ") && Catch::Matchers::Contains(c.says));
}


TEST_CASE("a 16 x 16 RGBE .hdr, run-length encoded, and a flat one") {
    const std::size_t w = GENERATE(16, 5);
    CAPTURE(w);
    temp_dir dir{"lut-formats"};
    const std::vector<double> v = hdr_values(w, 16);
    const std::string f = hdr_file(w, 16, v, "FORMAT=32-bit_rle_rgbe\nEXPOSURE=2\nGAMMA=2.2\nSOFTWARE=test\n");
    const decoded_lut d = verify::read_lut_file(dir.file("t.hdr", f), {});
    CHECK(d.format == "hdr");
    CHECK(d.encoding == value_encoding::rgbe);
    CHECK(d.orientation == "-Y H +X W");
    CHECK(d.exposure == 2);
    CHECK(d.colour.declared == verify::colour_declaration::kind::gamma);
    CHECK(*d.colour.gamma == Approx(1 / 2.2));
    REQUIRE(d.image.width == w);
    REQUIRE(d.image.height == 16);
    REQUIRE(d.image.channels == 3);
    REQUIRE(d.precision.size() == v.size());
    for (std::size_t k = 0; k < v.size(); ++k) {
        CAPTURE(k, v[k]);
        std::uint8_t px[4];
        rgbe(v[k - k % 3], v[k - k % 3 + 1], v[k - k % 3 + 2], px);
        // Radiance's colr_color(): (c + 0.5) 2^(E - 136)
        CHECK(d.image.data[k] == (px[3] ? (px[k % 3] + 0.5) * std::ldexp(1.0, px[3] - 136) : 0.0));
        CHECK(std::abs(d.image.data[k] - v[k]) <= d.tolerance(k));
    }
}

TEST_CASE("Radiance HDR: what a table is not, refused naming the culprit") {
    struct bad_case {
        const char* what;
        const char* says;
    };
    const bad_case c = GENERATE(bad_case{"flipped", "'+Y 16 +X 16' orders its pixels otherwise"},
                                bad_case{"mirrored", "'-Y 16 -X 16' orders"}, bad_case{"transposed", "'+X 16 -Y 16' orders"},
                                bad_case{"xyze", "32-bit_rle_xyze (CIE XYZ)"}, bad_case{"old-rle", "old run-length encoding"},
                                bad_case{"short", "scanline 15: truncated"}, bad_case{"trailing", "3 bytes follow the last scanline"},
                                bad_case{"huge", "16 x 4097; a table is 1 to 4096"}, bad_case{"no-end", "has no end"},
                                bad_case{"width", "run-length encoded for 17 pixels, the width is 16"},
                                bad_case{"garbled", "is not of the form -Y H +X W"}, bad_case{"many", "cannot fit"});
    CAPTURE(c.what);
    const std::string what = c.what;
    const std::vector<double> v = hdr_values(16, 16);
    std::string f = hdr_file(16, 16, v);
    if (what == "flipped") f = hdr_file(16, 16, v, "FORMAT=32-bit_rle_rgbe\n", "+Y 16 +X 16");
    if (what == "mirrored") f = hdr_file(16, 16, v, "FORMAT=32-bit_rle_rgbe\n", "-Y 16 -X 16");
    if (what == "transposed") f = hdr_file(16, 16, v, "FORMAT=32-bit_rle_rgbe\n", "+X 16 -Y 16");
    if (what == "xyze") f = hdr_file(16, 16, v, "FORMAT=32-bit_rle_xyze\n");
    if (what == "old-rle") f = hdr_file(4, 1, {0.5, 0.5, 0.5, 0, 0, 0, 0, 0, 0, 0, 0, 0}), f.replace(f.size() - 12, 4, "\x01\x01\x01\x02");
    if (what == "short") f.resize(f.size() - 3);
    if (what == "trailing") f += "abc";
    if (what == "huge") f = hdr_file(16, 1, hdr_values(16, 1), "FORMAT=32-bit_rle_rgbe\n", "-Y 4097 +X 16");
    if (what == "no-end") f = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n";
    if (what == "width") f[f.find("+X 16\n") + 9] = 17;
    if (what == "garbled") f = hdr_file(16, 16, v, "FORMAT=32-bit_rle_rgbe\n", "-Y  16 +X 16");
    if (what == "many") f = hdr_file(16, 1, hdr_values(16, 1), "FORMAT=32-bit_rle_rgbe\n", "-Y 4000 +X 16");
    temp_dir dir{"lut-formats"};
    const std::string path = dir.file("bad.hdr", f);
    CHECK_THAT(message_of(path), Catch::Matchers::StartsWith(path + ": ") && Catch::Matchers::Contains(c.says));
}

TEST_CASE("PNG colour chunks are reported as the file declares them") {
    temp_dir dir{"lut-formats"};
    const std::vector<std::uint8_t> px = {0, 64, 128, 255};
    using kind = verify::colour_declaration::kind;
    SECTION("none") {
        const decoded_lut d = verify::read_lut_file(dir.file("n.png", png8(2, 2, 1, px)), {});
        CHECK(d.format == "png8");
        CHECK(d.colour.declared == kind::none);
        CHECK(!d.colour.gamma);
        CHECK(d.image.data == std::vector<double>{0, 64 / 255.0, 128 / 255.0, 1});
    }
    SECTION("sRGB, with the gAMA and cHRM that go with it") {
        std::string gama, chrm;
        be32(gama, 45455);
        for (std::uint32_t v : {31270u, 32900u, 64000u, 33000u, 30000u, 60000u, 15000u, 6000u}) be32(chrm, v);
        const std::string chunks = png_chunk("sRGB", std::string(1, '\1')) + png_chunk("gAMA", gama) + png_chunk("cHRM", chrm);
        const decoded_lut d = verify::read_lut_file(dir.file("s.png", png8(2, 2, 1, px, chunks)), {});
        CHECK(d.colour.declared == kind::srgb);
        CHECK(d.colour.srgb_intent == 1);
        CHECK(*d.colour.gamma == 0.45455);
        REQUIRE(d.colour.chromaticities);
        CHECK((*d.colour.chromaticities)[0] == 0.3127);
        CHECK((*d.colour.chromaticities)[7] == 0.06);
    }
    SECTION("gAMA alone") {
        std::string gama;
        be32(gama, 100000);
        const decoded_lut d = verify::read_lut_file(dir.file("g.png", png8(2, 2, 1, px, png_chunk("gAMA", gama))), {});
        CHECK(d.colour.declared == kind::gamma);
        CHECK(*d.colour.gamma == 1.0);
    }
    SECTION("iCCP: the profile's name and bytes") {
        std::string profile;  // an ICC header of 128 bytes and an empty tag table
        be32(profile, 132), be32(profile, 0), be32(profile, 0x02100000);
        profile += "mntrRGB XYZ ";
        profile += std::string(12, '\0') + "acsp" + std::string(24, '\0');
        be32(profile, 0);  // intent
        be32(profile, 0xF6D6), be32(profile, 0x10000), be32(profile, 0xD32D);  // D50
        profile += std::string(48, '\0');
        be32(profile, 0);  // no tags
        REQUIRE(profile.size() == 132);
        const std::string chunk = png_chunk("iCCP", std::string("a test profile") + '\0' + '\0' + zlib_stored(profile));
        const decoded_lut d = verify::read_lut_file(dir.file("i.png", png8(2, 2, 3, std::vector<std::uint8_t>(12, 7), chunk)), {});
        CHECK(d.colour.declared == kind::icc);
        CHECK(d.colour.icc_name == "a test profile");
        CHECK(d.colour.icc_profile == profile);
    }
}

TEST_CASE("a three.js-style Uint16Array of half bits in a .js file") {
    std::vector<double> values;
    std::vector<std::uint16_t> bits;
    for (std::size_t k = 0; k < 32; ++k) {
        bits.push_back(verify::double_to_half(k % 2 ? 0.01 * double(k) : 1 - 0.02 * double(k)));
        values.push_back(verify::half_to_double(bits.back()));
    }
    const std::string js = threejs_like(bits, 4);
    temp_dir dir{"lut-formats"};
    const std::string path = dir.file("DFGLUTData.js", js);
    decoded_lut d = verify::read_lut_file(path, {});
    CHECK(d.format == "array-hex");
    CHECK(d.encoding == value_encoding::hex_integer);
    CHECK(d.array_name == "DATA");
    CHECK(d.element_type == "Uint16Array");
    CHECK(d.shaped);
    CHECK_THAT(d.shape_from, Catch::Matchers::EndsWith("hands 'DATA' on with 4, 4"));
    REQUIRE(d.image.width == 4);
    REQUIRE(d.image.height == 4);
    REQUIRE(d.image.channels == 2);
    CHECK(d.image.data[0] == 0x3c00);
    verify::interpret_hex(path, d, verify::hex_meaning::binary16);
    CHECK(d.encoding == value_encoding::half);
    CHECK(d.image.data == values);
    CHECK(d.tolerance(0) == std::ldexp(1.0, -25) + std::ldexp(1.0, -11));

    SECTION("read as unorm8, an integer over 255 is refused") {
        decoded_lut e = verify::read_lut_file(path, {});
        CHECK_THROWS_WITH(verify::interpret_hex(path, e, verify::hex_meaning::unorm8), Catch::Matchers::Contains("more than an 8-bit"));
    }
    SECTION("the caller's size") {
        const decoded_lut e = verify::read_lut_file(path, {"DATA", 8, 2});
        CHECK(e.image.width == 8);
        CHECK(e.image.channels == 2);
        CHECK(e.shape_from == "size=8x2, given");
        CHECK_THROWS_WITH(verify::read_lut_file(path, {"", 3, 3}), Catch::Matchers::Contains("not a 3 x 3 table"));
    }
}

TEST_CASE("a Babylon-style base64 PNG in a .js string, plain and as a data: URI") {
    std::vector<std::uint8_t> px;
    for (std::size_t k = 0; k < 4 * 4 * 4; ++k) px.push_back(std::uint8_t(k * 37 % 256));
    const std::string png = png8(4, 4, 4, px), b64 = base64(png);
    const std::string js = "import { Texture } from \"../Materials/Textures/texture\";\n"
                           "const note = \"plain words, not base64\";\n"
                           "const _environmentBRDFBase64Texture = \"" + b64 + "\";\n"
                           "const _otherTexture = \"data:image/png;base64," + b64 + "\";\n";
    temp_dir dir{"lut-formats"};
    const std::string path = dir.file("brdfTextureTools.js", js);
    const std::string name = GENERATE("", "_otherTexture");
    const decoded_lut d = verify::read_lut_file(path, {name, 0, 0});
    CHECK(d.format == "base64-png8");
    CHECK(d.array_name == (name.empty() ? "_environmentBRDFBase64Texture" : name));
    REQUIRE(d.image.channels == 4);
    for (std::size_t k = 0; k < px.size(); ++k) CHECK(d.image.data[k] == px[k] / 255.0);
    CHECK_THAT(message_of(dir.file("cut.js", "const t = \"" + base64(png.substr(0, 60)) + "\";\n")),
               Catch::Matchers::Contains("cut.js:1: the base64 PNG 't': truncated or corrupt PNG"));
}

TEST_CASE("normzoo's own C header read back as an array") {
    lut_image im = sample(5, 3, 2);
    im.data[3] = 1e-10;
    temp_dir dir{"lut-formats"};
    const std::string path = dir.file("lut.h", verify::encode_c_header(im, "normzoo_dfg_5", "made by a test\n{1, 2, 3} = not it"));
    const decoded_lut d = verify::read_lut_file(path, {});
    CHECK(d.format == "array-decimal");
    CHECK(d.encoding == value_encoding::decimal_text);
    CHECK(d.array_name == "normzoo_dfg_5");
    CHECK(d.element_type == "float");
    CHECK(d.shape_from == "declared [3][5][2]");
    REQUIRE(d.image.width == 5);
    REQUIRE(d.image.height == 3);
    REQUIRE(d.image.channels == 2);
    for (std::size_t k = 0; k < im.data.size(); ++k) {
        CHECK(float(d.image.data[k]) == float(im.data[k]));
        CHECK(std::abs(d.image.data[k] - im.data[k]) <= d.tolerance(k));  // 9 digits: a float's, 2^-24 relative
    }
}

TEST_CASE("arrays in C, WGSL and GLSL: comments skipped, shapes from the file") {
    temp_dir dir{"lut-formats"};
    SECTION("C: a size constant in the dimensions, comments that look like arrays") {
        const std::string c = "/* lut = {9, 9}; */\n#include <stdint.h>\n#define LUT_SIZE 2 // the side\n"
                              "static const char* name = \"not it\";\nint n = f(3, 4);\n"
                              "static const float lut[LUT_SIZE][LUT_SIZE][2] = {\n  {{0.5f, 1e-3f}, {.25F, 2.5E-1}}, // row 0\n"
                              "  {{-0.0f, 1.f}, /* a comment */ {0.125, 0x1}}};\n";
        const std::string path = dir.file("lut.inc", c);
        CHECK_THAT(message_of(path), Catch::Matchers::StartsWith(path + ":7: '0.5f' in an array of hex integers ('0x1')"));
        const decoded_lut d = verify::read_lut_file(dir.file("ok.inc", c.substr(0, c.find("0x1")) + "1.0}}};\n"), {});
        CHECK(d.shape_from == "declared [LUT_SIZE][LUT_SIZE][2]");
        CHECK(d.image.data == std::vector<double>{0.5, 1e-3, 0.25, 0.25, -0.0, 1.0, 0.125, 1.0});
        CHECK(d.tolerance(0) == Approx(0.5e-3));  // column A is printed to 3 decimals at most (0.125)
    }
    SECTION("WGSL: array<f32, N>(...), its size given") {
        const std::string w = "// a table\nconst lut = array<f32, 8>(0.5, 0.25, 0.125, 1.0, 0.0, 1e-2, 0.75f, 1.5h);\n";
        const decoded_lut d = verify::read_lut_file(dir.file("lut.wgsl", w), {"lut", 2, 2});
        CHECK(d.element_type == "f32");
        CHECK(d.image.channels == 2);
        CHECK(d.image.data.back() == 1.5);
        const decoded_lut u = verify::read_lut_file(dir.file("lut.wgsl", w), {});
        CHECK(!u.shaped);
        CHECK(u.image.width == 8);
    }
    SECTION("GLSL: vec2[](vec2(...), ...), a size constant") {
        const std::string g = "#version 300 es\nconst int LUT_SIZE = 2;\n"
                              "const vec2 lut[4] = vec2[](vec2(0.1, 0.2), vec2(0.3, 0.4), vec2(0.5, 0.6), vec2(0.7, 0.8));\n";
        const decoded_lut d = verify::read_lut_file(dir.file("lut.glsl", g), {});
        CHECK(d.element_type == "vec2");
        CHECK(d.shape_from == "LUT_SIZE = 2");
        CHECK(d.image.width == 2);
        CHECK(d.image.channels == 2);
    }
    SECTION("refused, naming the file and the line") {
        struct bad_case {
            const char* name;
            const char* text;
            const char* says;
        };
        const bad_case b = GENERATE(bad_case{"a.ts", "let x = 1;\n", "a.ts: no declaration initialises an array"},
                                    bad_case{"b.c", "/* open\n", "b.c:1: a comment that never ends"},
                                    bad_case{"c.c", "float a[2][2][2] = {1.0, 2.0};\n", "c.c:1: 'a' holds 2 values; it is declared [2][2][2]"},
                                    bad_case{"d.js", "const d = [1.5, 010];\n", "d.js:1: '010' is octal"},
                                    bad_case{"e.js", "const d = [-0x10];\n", "e.js:1: '-0x10' is a negative hex"},
                                    bad_case{"f.js", "const d = [1.5.5];\n", "f.js:1: '1.5.5' is not a number"},
                                    bad_case{"g.js", "const s = 'never ends;\n", "g.js:1: a string that never ends"},
                                    bad_case{"h.js", "const s = \"not a png\";\n", "h.js: no declaration"},
                                    bad_case{"i.js", "const d = [0x1, 99999999999];\n", "i.js:1: '99999999999' in an array of hex"});
        CAPTURE(b.name);
        const std::string path = dir.file(b.name, b.text);
        CHECK_THAT(message_of(path), Catch::Matchers::StartsWith((dir.path / b.says).string()));
    }
    SECTION("a name asked for that the file does not initialise so") {
        const std::string path = dir.file("n.js", "const x = 1;\nconst y = [1, 2];\n");
        CHECK_THROWS_WITH(verify::read_lut_file(path, {"x", 0, 0}), Catch::Matchers::Contains("n.js:1: 'x' is not initialised by an array"));
        CHECK_THROWS_WITH(verify::read_lut_file(path, {"z", 0, 0}), Catch::Matchers::Contains("nothing named 'z'"));
    }
}

TEST_CASE("every truncation of every binary format is refused, every flipped byte read or refused") {
    const std::string which = GENERATE("ktx2", "ktx2-zstd", "dds", "dds-legacy", "hdr", "hdr-flat");
    CAPTURE(which);
    std::string f;
    if (which == "ktx2") f = verify::encode_ktx2(sample(3, 2, 2), 83, false);
    if (which == "ktx2-zstd") f = ktx2_bytes(bevy_like());
    if (which == "dds") f = verify::encode_dds(sample(3, 2, 4), 10);
    if (which == "dds-legacy") f = dds_header(2, 2, 0x41, 0, 32, {0xff0000, 0xff00, 0xff, 0xff000000}) + std::string(16, '\x11');
    if (which == "hdr") f = hdr_file(16, 3, hdr_values(16, 3));
    if (which == "hdr-flat") f = hdr_file(3, 2, hdr_values(3, 2));
    temp_dir dir{"lut-formats"};
    const std::string ext = which.substr(0, which.find('-'));
    const std::string path = (dir.path / ("t." + ext)).string();
    for (std::size_t n = 0; n < f.size(); ++n) {
        CAPTURE(n);
        dir.file(path, f.substr(0, n));
        CHECK_THAT(message_of(path), Catch::Matchers::StartsWith(path + ": "));
        std::string flipped = f;
        flipped[n] = char(flipped[n] ^ 0x55);
        dir.file(path, flipped);
        try {
            verify::read_lut_file(path, {});
        } catch (const bad_input& e) {
            CHECK_THAT(std::string(e.what()), Catch::Matchers::StartsWith(path + ": "));
        }
    }
}
