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
#include "lut_format_checks.hpp"
#include "temp_files.hpp"

using namespace lut_fixture;
using lut_format_checks::message_of;
using lut_format_checks::sample;
using normzoo_test::temp_dir;
using verify::bad_input;
using verify::decoded_lut;
using verify::lut_image;
using verify::value_encoding;

namespace {

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
