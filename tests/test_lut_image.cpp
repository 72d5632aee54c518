// The baked tables' image formats (src/verify/lut_image.cpp): round trips through PNG and
// OpenEXR, the C header as C, and bad files refused as bad input naming the file.
#include <png.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <Imath/half.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "args.hpp"
#include "lut_image.hpp"
#include "temp_files.hpp"

using normzoo_test::temp_dir;
using verify::bad_input;
using verify::decoded_lut;
using verify::lut_image;

namespace {

// A 5 x 3 image whose values run over [0, 1], 0 and 1 included.
lut_image sample(std::size_t channels, bool unit = true) {
    lut_image im{5, 3, channels, {}};
    for (std::size_t k = 0; k < 15 * channels; ++k)
        im.data.push_back(k == 0 ? 0.0 : k == 1 ? 1.0 : std::fmod(0.123456789 * double(k * k), 1.0));
    if (!unit) im.data[2] = 2.5, im.data.back() = -0.75;  // OpenEXR holds any real
    return im;
}

decoded_lut round_trip(const temp_dir& dir, const std::string& name, const std::string& bytes) {
    return verify::read_lut_image(dir.file(name, bytes));
}

// A PNG written by libpng itself, as an engine would: `rows` packed at `depth` bits.
bool write_png(const char* path, png_uint_32 w, png_uint_32 h, int depth, int color, bool interlace, png_bytepp rows) {
    std::FILE* f = std::fopen(path, "wb");
    if (!f) return false;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info || setjmp(png_jmpbuf(png))) {  // nothing with a destructor in this frame
        png_destroy_write_struct(&png, &info);
        std::fclose(f);
        return false;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, depth, color, interlace ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (interlace) png_set_interlace_handling(png);
    png_color palette[2] = {{0, 0, 0}, {255, 255, 255}};
    if (color == PNG_COLOR_TYPE_PALETTE) png_set_PLTE(png, info, palette, 2);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return std::fclose(f) == 0;
}

std::string png_file(const temp_dir& dir, const std::string& name, png_uint_32 w, png_uint_32 h, int depth, int color,
                     std::vector<png_byte> bytes, bool interlace = false) {
    const std::size_t row = bytes.size() / h;
    std::vector<png_bytep> rows;
    for (std::size_t j = 0; j < h; ++j) rows.push_back(bytes.data() + j * row);
    const std::string p = (dir.path / name).string();
    REQUIRE(write_png(p.c_str(), w, h, depth, color, interlace, rows.data()));
    return p;
}

// A 2 x 2 OpenEXR file with the given channels, its data window at `origin`; each sample the
// float (or unsigned) 1 + its index in the channel.
std::string exr_file(const temp_dir& dir, const std::string& name, const std::vector<std::pair<const char*, Imf::PixelType>>& chans,
                     Imath::V2i origin = {0, 0}) {
    const std::string p = (dir.path / name).string();
    const Imath::Box2i window(origin, origin + Imath::V2i(1, 1));
    Imf::Header header(window, window);
    Imf::FrameBuffer fb;
    std::vector<std::array<char, 16>> store(chans.size());  // 4 samples of 4 bytes, whatever the type
    for (std::size_t c = 0; c < chans.size(); ++c) {
        const auto [name, type] = chans[c];
        header.channels().insert(name, Imf::Channel(type));
        for (std::size_t k = 0; k < 4; ++k) {
            const float f = float(k + 1);
            const Imath::half h(f);
            const unsigned u = unsigned(k + 1);
            const void* v = type == Imf::HALF ? static_cast<const void*>(&h) : type == Imf::FLOAT ? static_cast<const void*>(&f) : &u;
            std::memcpy(&store[c][4 * k], v, type == Imf::HALF ? 2 : 4);
        }
        fb.insert(name, Imf::Slice::Make(type, store[c].data(), window, 4));
    }
    Imf::OutputFile out(p.c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(2);
    return p;
}

std::string message_of(const std::string& path) {
    try {
        verify::read_lut_image(path);
    } catch (const bad_input& e) {
        return e.what();
    }
    return "(no bad_input)";
}

}  // namespace

TEST_CASE("16-bit PNG round trip, 1 to 4 channels") {
    const std::size_t channels = GENERATE(1, 2, 3, 4);
    CAPTURE(channels);
    temp_dir dir{"lut-image"};
    const lut_image im = sample(channels);
    const decoded_lut d = round_trip(dir, "t.png", verify::encode_png16(im));
    CHECK(d.format == "png16");
    CHECK(d.absolute == 0.5 / 65535);
    CHECK(d.relative == 0);
    REQUIRE(d.image.width == 5);
    REQUIRE(d.image.height == 3);
    // the reader returns what the file holds: (A, B) was written as RGB with B = 0
    REQUIRE(d.image.channels == (channels == 2 ? 3 : channels));
    for (std::size_t j = 0; j < 3; ++j)
        for (std::size_t i = 0; i < 5; ++i) {
            for (std::size_t c = 0; c < channels; ++c) CHECK(std::abs(d.image.at(j, i, c) - im.at(j, i, c)) <= 0.5 / 65535);
            if (channels == 2) CHECK(d.image.at(j, i, 2) == 0);
        }
}

TEST_CASE("8-bit PNG round trip, 1 to 4 channels: each value the nearest of 255 steps") {
    const std::size_t channels = GENERATE(1, 2, 3, 4);
    CAPTURE(channels);
    temp_dir dir{"lut-image"};
    lut_image im = sample(channels);
    im.data[2] = -0.5, im.data[3] = std::nan("");  // clamped, 0
    const decoded_lut d = round_trip(dir, "t8.png", verify::encode_png8(im));
    CHECK(d.format == "png8");
    CHECK(d.absolute == 0.5 / 255);
    REQUIRE(d.image.channels == (channels == 2 ? 3 : channels));
    for (std::size_t j = 0; j < 3; ++j)
        for (std::size_t i = 0; i < 5; ++i)
            for (std::size_t c = 0; c < channels; ++c) {
                const double v = im.at(j, i, c), unit = std::isnan(v) ? 0 : std::clamp(v, 0.0, 1.0);
                CHECK(d.image.at(j, i, c) == double(std::lround(unit * 255)) / 255);
            }
}

TEST_CASE("16-bit PNG clamps to [0, 1] and writes 0 for NaN") {
    temp_dir dir{"lut-image"};
    const lut_image im{4, 1, 1, {-0.5, 1.5, std::nan(""), 0.5}};
    const decoded_lut d = round_trip(dir, "c.png", verify::encode_png16(im));
    REQUIRE(d.image.data.size() == 4);
    CHECK(d.image.data[0] == 0);
    CHECK(d.image.data[1] == 1);
    CHECK(d.image.data[2] == 0);
    CHECK(d.image.data[3] == 32768 / 65535.0);  // lround(0.5 * 65535) = 32768
}

TEST_CASE("OpenEXR round trip, half and float, 1 to 4 channels") {
    const bool half = GENERATE(false, true);
    const std::size_t channels = GENERATE(1, 2, 3, 4);
    CAPTURE(half, channels);
    temp_dir dir{"lut-image"};
    const lut_image im = sample(channels, false);
    const decoded_lut d = round_trip(dir, "t.exr", verify::encode_exr(im, half));
    CHECK(d.format == (half ? "exr-half" : "exr-float"));
    CHECK(d.relative == (half ? std::ldexp(1.0, -11) : std::ldexp(1.0, -24)));
    REQUIRE(d.image.width == 5);
    REQUIRE(d.image.height == 3);
    REQUIRE(d.image.channels == channels);  // 2 channels are R, G: no B invented
    const double tol = half ? std::ldexp(1.0, -11) : 1e-7;
    for (std::size_t k = 0; k < im.data.size(); ++k) {
        CAPTURE(k, im.data[k]);
        CHECK(std::abs(d.image.data[k] - im.data[k]) <= tol * std::abs(im.data[k]));
        CHECK(std::abs(d.image.data[k] - im.data[k]) <= d.absolute + d.relative * std::abs(im.data[k]));
    }
}

TEST_CASE("8-bit PNG from libpng reads as png8") {
    struct layout {
        int color;
        std::size_t channels;
    };
    const layout l = GENERATE(layout{PNG_COLOR_TYPE_GRAY, 1}, layout{PNG_COLOR_TYPE_GRAY_ALPHA, 2},
                              layout{PNG_COLOR_TYPE_RGB, 3}, layout{PNG_COLOR_TYPE_RGB_ALPHA, 4});
    const bool interlace = GENERATE(false, true);
    CAPTURE(l.channels, interlace);
    temp_dir dir{"lut-image"};
    std::vector<png_byte> bytes;
    for (std::size_t k = 0; k < 4 * 3 * l.channels; ++k) bytes.push_back(png_byte(k * 37 % 256));
    const decoded_lut d = verify::read_lut_image(png_file(dir, "e.png", 4, 3, 8, l.color, bytes, interlace));
    CHECK(d.format == "png8");
    CHECK(d.absolute == 0.5 / 255);
    CHECK(d.relative == 0);
    CHECK(d.image.width == 4);
    CHECK(d.image.height == 3);
    REQUIRE(d.image.channels == l.channels);
    for (std::size_t k = 0; k < bytes.size(); ++k) CHECK(d.image.data[k] == bytes[k] / 255.0);
}

TEST_CASE("OpenEXR: the data window gives the size, wherever it lies") {
    temp_dir dir{"lut-image"};
    const decoded_lut d = verify::read_lut_image(exr_file(dir, "w.exr", {{"R", Imf::HALF}, {"G", Imf::HALF}}, {-7, 100}));
    CHECK(d.format == "exr-half");
    REQUIRE(d.image.width == 2);
    REQUIRE(d.image.height == 2);
    REQUIRE(d.image.channels == 2);
    CHECK(d.image.data == std::vector<double>{1, 1, 2, 2, 3, 3, 4, 4});
}

TEST_CASE("OpenEXR: a tall image, read in strips") {
    temp_dir dir{"lut-image"};
    lut_image im{3, 150, 2, {}};
    for (std::size_t k = 0; k < 900; ++k) im.data.push_back(double(k) / 1024);  // halves hold these exactly
    const decoded_lut d = round_trip(dir, "tall.exr", verify::encode_exr(im, true));
    REQUIRE(d.image.height == 150);
    CHECK(d.image.data == im.data);
}

TEST_CASE("C header") {
    lut_image im = sample(2);
    im.data[3] = 1e-10, im.data[4] = 0.1;  // an exponent, and a value no float holds exactly
    // a line ending in a backslash must not join the declaration to the comment
    const std::string h = verify::encode_c_header(im, "normzoo_dfg_5", "made by a test\n\nrows: roughness\nC:\\");
    CHECK(h.rfind("#pragma once\n// made by a test\n//\n// rows: roughness\n// C:\\.\n", 0) == 0);
    CHECK(h.find("static const float normzoo_dfg_5[3][5][2] = {\n") != std::string::npos);
    CHECK(h.size() > 3);
    CHECK(h.substr(h.size() - 3) == "};\n");

    // every literal is a C float literal ("1.f", not "1f") naming the value's float
    std::vector<float> values;
    for (std::size_t b = h.find("= {"); (b = h.find_first_of("-0123456789", b)) != std::string::npos;) {
        const std::size_t e = h.find('f', b);
        const std::string lit = h.substr(b, e - b);
        CAPTURE(lit);
        CHECK(lit.find_first_of(".e") != std::string::npos);
        CHECK(lit.find_first_not_of("-+.e0123456789") == std::string::npos);
        values.push_back(std::strtof(lit.c_str(), nullptr));
        b = e + 1;
    }
    REQUIRE(values.size() == im.data.size());
    for (std::size_t k = 0; k < values.size(); ++k) CHECK(values[k] == float(im.data[k]));
    CHECK(h.find("{0.f, 1.f}") != std::string::npos);

    SECTION("compiles as C") {
        if (std::system("command -v cc >/dev/null 2>&1") != 0) {
            WARN("no cc: the header is not compiled");
            return;
        }
        temp_dir dir{"lut-image"};
        dir.file("lut.h", h);
        const std::string src = dir.file("lut.c", "#include \"lut.h\"\nconst float *first = &normzoo_dfg_5[0][0][0];\n");
        const std::string cmd = "cc -std=c99 -pedantic -Wall -Werror -c -x c '" + src + "' -o '" + (dir.path / "lut.o").string() + "'";
        CHECK(std::system(cmd.c_str()) == 0);
    }
    SECTION("the name must be a C identifier") {
        const std::string name = GENERATE("", "1abc", "a-b", "a b", "int", "caf\xc3\xa9");
        CAPTURE(name);
        CHECK_THROWS_AS(verify::encode_c_header(im, name, ""), std::invalid_argument);
    }
}

TEST_CASE("the encoders refuse a malformed image") {
    const lut_image bad = GENERATE(lut_image{0, 1, 1, {}}, lut_image{2, 1, 5, {0, 0, 0, 0, 0, 0, 0, 0, 0, 0}},
                                   lut_image{2, 2, 1, {0, 0, 0}});
    CHECK_THROWS_AS(verify::encode_png16(bad), std::invalid_argument);
    CHECK_THROWS_AS(verify::encode_exr(bad, true), std::invalid_argument);
    CHECK_THROWS_AS(verify::encode_c_header(bad, "x", ""), std::invalid_argument);
}

TEST_CASE("bad files are bad input naming the file") {
    temp_dir dir{"lut-image"};
    const std::string png = verify::encode_png16(sample(3)), exr = verify::encode_exr(sample(4), false);
    struct bad_case {
        const char* name;
        const char* says;
    };
    const bad_case c = GENERATE(bad_case{"missing", "cannot be read"}, bad_case{"text", "not a PNG or OpenEXR image"},
                                bad_case{"empty", "not a PNG or OpenEXR image"}, bad_case{"half-png", "truncated or corrupt PNG"},
                                bad_case{"half-exr", "truncated or corrupt OpenEXR"}, bad_case{"palette", "palette"},
                                bad_case{"gray4", "4-bit"}, bad_case{"uint-exr", "channel Y"},
                                bad_case{"mixed-exr", "channel R"}, bad_case{"rb-exr", "{B, R}"},
                                bad_case{"directory", "cannot be read"}, bad_case{"wide-exr", "too few for 82 texels"},
                                bad_case{"wide-png", "4096 texels a side"});
    CAPTURE(c.name);
    const std::string name = c.name;
    std::string path;
    if (name == "missing") path = (dir.path / "no-such.png").string();
    else if (name == "text") path = dir.file("t.png", "mu,alpha,A,B\n0.5,0.5,0.1,0.2\n");
    else if (name == "empty") path = dir.file("e.exr", "");
    else if (name == "half-png") path = dir.file("h.png", png.substr(0, png.size() / 2));
    else if (name == "half-exr") path = dir.file("h.exr", exr.substr(0, exr.size() / 2));
    else if (name == "palette") path = png_file(dir, "p.png", 8, 2, 8, PNG_COLOR_TYPE_PALETTE, std::vector<png_byte>(16, 1));
    else if (name == "wide-png") path = png_file(dir, "w.png", 4097, 1, 16, PNG_COLOR_TYPE_GRAY, std::vector<png_byte>(2 * 4097, 0x5a));
    else if (name == "gray4") path = png_file(dir, "g.png", 8, 2, 4, PNG_COLOR_TYPE_GRAY, std::vector<png_byte>(8, 0x5a));
    else if (name == "uint-exr") path = exr_file(dir, "u.exr", {{"Y", Imf::UINT}});
    else if (name == "mixed-exr") path = exr_file(dir, "m.exr", {{"R", Imf::HALF}, {"G", Imf::FLOAT}});
    else if (name == "rb-exr") path = exr_file(dir, "rb.exr", {{"R", Imf::FLOAT}, {"B", Imf::FLOAT}});
    else if (name == "wide-exr") {  // the data window says 82 texels a row; the scanlines hold 5
        std::string e = exr;
        const std::string key("dataWindow\0box2i\0", 17);
        e[e.find(key) + key.size() + 4 + 8] = 81;  // after the size: xMin, yMin, then xMax (little-endian)
        path = dir.file("w.exr", e);
    } else path = dir.path.string();
    const std::string m = message_of(path);
    CHECK_THAT(m, Catch::Matchers::StartsWith(path + ": ") && Catch::Matchers::Contains(c.says));
}

TEST_CASE("every truncation and every flipped byte is read or refused, never a crash") {
    temp_dir dir{"lut-image"};
    const std::string png = verify::encode_png16(sample(2));
    const bool half = GENERATE(false, true);
    const std::string exr = verify::encode_exr(sample(3), half);
    for (const std::string* file : {&png, &exr}) {
        const std::string path = (dir.path / (file == &png ? "t.png" : "t.exr")).string();
        for (std::size_t n = 0; n < file->size(); ++n) {
            CAPTURE(n);
            dir.file(path, file->substr(0, n));  // an absolute path replaces the folder
            CHECK_THROWS_AS(verify::read_lut_image(path), bad_input);
            std::string flipped = *file;
            flipped[n] = char(flipped[n] ^ 0x55);
            dir.file(path, flipped);
            try {
                verify::read_lut_image(path);
            } catch (const bad_input&) {
            }
        }
    }
}
