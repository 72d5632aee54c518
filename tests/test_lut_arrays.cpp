// The tables engines keep in source files and text (src/verify/lut_formats/source_array.hpp,
// docs/lut.md "Files it reads"): a three.js-style Uint16Array of half bits, a Babylon-style base64
// PNG in a .js string, C, WGSL and GLSL arrays, normzoo's own C header; and every truncation and
// flipped byte of every binary format refused or read.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
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
#include "lut_formats/printed.hpp"
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

// A column of floats printed shortest (at most 9 digits) holds what a float holds: 2^-24
// relative, and below a float's normal range its spacing, 2^-149 (half of it the rounding), a
// value that underflowed printing 0. Tolerances from 2^-24 |v| alone failed normzoo's own header
// of the sheen's E, whose smallest values are subnormal floats.
TEST_CASE("a float printed shortest holds what a float holds, down to its subnormals") {
    const verify::printed_digits column = verify::digits_of("4.53848343e-40");  // the header's finest cell
    for (const double exact : {0.3, 1e-30, 4.5384835e-40, 1.6959355e-40, 3e-45, 1.14e-46}) {
        char text[32];
        std::snprintf(text, sizeof text, "%.9g", double(float(exact)));
        const double stored = std::strtod(text, nullptr);
        INFO("exact " << exact << " printed " << text);
        CHECK(std::abs(stored - exact) <= verify::printed_precision(stored, column));
    }
}
