// Tables laid out as engines lay theirs out (docs/lut.md, "Layouts"), made from normzoo's own
// exact values (microfacet/split_sum.hpp, split_sum_to.hpp at the edges) and written through
// normzoo's writers (16-bit PNG, float or half OpenEXR; a CSV as text) or as the engines ship them
// (tests/lut_fixtures.hpp: three.js's Uint16Array of half bits, Bevy's zstd KTX2): `verify lut
// --check --detect` names each convention, `--preset ENGINE` reads it, the plain reading fails on
// it and says to try --detect (or refuses what only the layout says), and a bad layout is exit 2
// naming its key.
#include <normzoo/microfacet/multiple_scattering.hpp>
#include <normzoo/microfacet/split_sum.hpp>
#include <normzoo/microfacet/split_sum_to.hpp>

#include <Imath/half.h>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lut_fixtures.hpp"
#include "lut_formats/ktx2.hpp"
#include "lut_image.hpp"
#include "lut_runs.hpp"
#include "temp_files.hpp"

namespace fs = std::filesystem;
namespace mf = normzoo::microfacet;
using normzoo_test::records;
using normzoo_test::run_shell;
using normzoo_test::verify_lut;

namespace {

// A convention: where the texels sit, what the channels hold, how the values are stored, the
// model baked, and what --detect must find (encodings that only round are found as linear).
struct convention {
    std::string name, kind, model;
    std::string rows, cols;  // r, alpha, mu, sqrt-mu
    bool row0_high, col0_high;
    std::string grid;                   // centres, edges, filament
    std::vector<std::string> channels;  // A, B, A+B, E; "-" a filler, "D" RGBD's divisor
    std::string encoding;               // linear, half, unorm10, srgb, rgbd
    std::string file;                   // png16, exr, exr-half
    std::size_t n;
    std::string preset;    // the engine's, or none
    std::string detected;  // the canonical layout --detect must name
    bool detect_passes;    // the check under the detected layout passes (false: a rounding it cannot see)
};

// Written from docs/lut.md's definitions, not from the command's code.
double coordinate(const std::string& grid, bool roughness, bool high, std::size_t i, std::size_t n) {
    const double t = double(high ? n - 1 - i : i);
    if (grid == "edges") return t / double(n - 1);
    if (grid == "filament" && roughness) return std::min(1.0, (t + 1.5) / double(n));  // cmgen's rows, GL order
    return (t + 0.5) / double(n);
}

double srgb_encode(double x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055; }

// The values of one texel in the convention's channels, before encoding. At r = 0 and mu = 0 a
// split-sum table holds the pair's limits (docs/lut.md, "Edges"); inside: as an engine bakes them,
// a little inside (Cycles clamps both to 1e-4), as an E table always is.
std::vector<double> texel_values(const convention& c, double mu, double alpha, double filler, bool inside) {
    const auto m = mf::composition::parse(c.model);
    const bool edge = mu == 0 || alpha == 0;
    const auto s = edge && !inside && c.kind == "dfg" ? mf::split_sum_to(m, mu, alpha, {})
                                                      : mf::split_sum(m, std::max(mu, 1e-4), std::max(alpha, 1e-8));
    std::vector<double> v;
    for (const auto& ch : c.channels)
        v.push_back(ch == "A" ? s.a.value : ch == "B" ? s.b.value : ch == "A+B" || ch == "E" ? s.a.value + s.b.value
                    : ch == "D" ? 1.0 : filler);
    return v;
}

// The values as stored: rounded to half or 10 bits, sRGB-encoded, or RGBD as Babylon's toRGBD
// writes it (D = floor(255 / max) / 255, rgb = (v D)^(1/2.2)).
void encode(const convention& c, std::vector<double>& v) {
    if (c.encoding == "half")
        for (auto& x : v) x = float(Imath::half(float(x)));
    if (c.encoding == "unorm10")
        for (auto& x : v) x = std::round(x * 1023) / 1023;
    if (c.encoding == "srgb")
        for (auto& x : v) x = srgb_encode(x);
    if (c.encoding == "rgbd") {
        const double most = std::max({v[0], v[1], v[2], 1e-7});
        const double d = std::clamp(std::floor(255 / most) / 255, 0.0, 1.0);
        for (int k = 0; k < 3; ++k) v[std::size_t(k)] = std::clamp(std::pow(v[std::size_t(k)] * d, 1 / 2.2), 0.0, 1.0);
        v[3] = d;
    }
}

std::string write_table(const convention& c, const fs::path& dir, bool inside = false) {
    verify::lut_image im{c.n, c.n, c.channels.size(), {}};
    const bool rough_rows = c.rows == "r" || c.rows == "alpha";
    for (std::size_t j = 0; j < c.n; ++j)
        for (std::size_t i = 0; i < c.n; ++i) {
            const double ur = coordinate(c.grid, rough_rows, c.row0_high, j, c.n), uc = coordinate(c.grid, !rough_rows, c.col0_high, i, c.n);
            const double rough = rough_rows ? ur : uc, mu_u = rough_rows ? uc : ur;
            const double alpha = (rough_rows ? c.rows : c.cols) == "r" ? rough * rough : rough;
            const double mu = (rough_rows ? c.cols : c.rows) == "sqrt-mu" ? mu_u * mu_u : mu_u;
            // RGBD's third channel (Babylon's sheen) beyond 1, so that D varies
            std::vector<double> v = texel_values(c, mu, alpha, c.encoding == "rgbd" ? 2 + 6 * ur : 0.25, inside);
            encode(c, v);
            im.data.insert(im.data.end(), v.begin(), v.end());
        }
    const std::string ext = c.file == "png16" ? ".png" : ".exr";
    const fs::path p = dir / (c.name + (inside ? "-inside" : "") + ext);
    std::ofstream(p, std::ios::binary) << (c.file == "png16" ? verify::encode_png16(im) : verify::encode_exr(im, c.file == "exr-half"));
    return p.string();
}

const std::string correlated = "ggx/smith-height-correlated/one", schlick = "ggx/schlick-ggx/one";

std::vector<convention> conventions() {
    const std::string rest = ",row0=low,col0=low,grid=centres,channels=";
    return {
        {"texel-centres", "dfg", correlated, "r", "mu", false, false, "centres", {"A", "B"}, "linear", "png16", 16,
         "gltf-sample-viewer", "rows=r,cols=mu" + rest + "A,B,encoding=linear", true},
        {"threejs-transposed", "dfg", correlated, "mu", "r", false, false, "centres", {"A", "B"}, "half", "exr-half", 16, "threejs",
         "rows=mu,cols=r" + rest + "A,B,encoding=linear", true},
        {"godot-flipped-schlick", "dfg", schlick, "r", "mu", true, false, "centres", {"B", "A+B", "-", "D"}, "half", "exr-half", 16,
         "godot", "rows=r,cols=mu,row0=high,col0=low,grid=centres,channels=B,A+B,encoding=linear", true},
        {"unity-edges-sqrt-mu", "dfg", correlated, "r", "sqrt-mu", false, false, "edges", {"B", "A+B", "-"}, "unorm10", "png16", 16,
         "unity-hdrp", "rows=r,cols=sqrt-mu,row0=low,col0=low,grid=edges,channels=B,A+B,encoding=linear", false},
        {"filament-shift", "dfg", correlated, "r", "mu", false, false, "filament", {"B", "A+B", "-"}, "half", "exr-half", 16, "filament",
         "rows=r,cols=mu,row0=low,col0=low,grid=filament,channels=B,A+B,encoding=linear", true},
        {"babylon-rgbd", "dfg", correlated, "r", "mu", false, false, "centres", {"B", "A+B", "-", "D"}, "rgbd", "png16", 16, "babylon",
         "rows=r,cols=mu" + rest + "B,A+B,encoding=rgbd", true},
        {"srgb", "dfg", correlated, "r", "mu", false, false, "centres", {"A", "B", "-"}, "srgb", "png16", 16, "",
         "rows=r,cols=mu" + rest + "A,B,encoding=srgb", true},
        {"learnopengl-schlick", "dfg", schlick, "r", "mu", false, false, "centres", {"A", "B"}, "half", "exr-half", 16, "learnopengl",
         "rows=r,cols=mu" + rest + "A,B,encoding=linear", true},
        {"cycles-E", "E", correlated, "mu", "r", false, false, "edges", {"E"}, "linear", "exr", 32, "cycles",
         "rows=mu,cols=r,row0=low,col0=low,grid=edges,channels=E,encoding=linear", true},
        {"alpha-rows-remapped", "dfg", "ggx/schlick-ggx-remapped/one", "alpha", "mu", false, false, "centres", {"A", "B"}, "linear",
         "exr", 16, "", "rows=alpha,cols=mu" + rest + "A,B,encoding=linear", true},
        {"separable-mu-flipped", "dfg", "ggx/smith-separable/one", "r", "mu", false, true, "centres", {"A", "B"}, "linear", "exr", 16,
         "", "rows=r,cols=mu,row0=low,col0=high,grid=centres,channels=A,B,encoding=linear", true},
    };
}

}  // namespace

TEST_CASE("lut --check --detect names each engine's convention, --preset reads it, the plain reading fails and says so") {
    const fs::path dir = normzoo_test::fresh_dir("lut-layout");
    for (const auto& c : conventions()) {
        CAPTURE(c.name);
        const std::string file = "--check '" + write_table(c, dir) + "' --kind " + c.kind;
        const auto found = records(file + " --detect");
        REQUIRE(!found.empty());
        CHECK(found[0]["layout"] == c.detected);
        CHECK(found[0]["model"] == c.model);
        REQUIRE(found[0]["candidates"].is_array());
        CHECK(found[0]["candidates"][0]["layout"] == c.detected);
        CHECK(verify_lut(file + " --detect").status == (c.detect_passes ? 0 : 1));
        if (!c.preset.empty()) {
            const auto r = verify_lut(file + " --preset " + c.preset);
            CAPTURE(r.out);
            CHECK(r.status == 0);
        }
        // the plain reading (rows r, columns mu, texel centres, A and B, linear, height-correlated)
        // fails, and names the reading that fits; the texel-centre table itself read transposed
        const auto wrong = verify_lut(file + (c.name == "texel-centres" ? " --layout rows=mu,cols=r" : ""));
        CAPTURE(wrong.out);
        CHECK(wrong.status == 1);
        CHECK(wrong.out.find("try --detect") != std::string::npos);
        // keys given that the better reading changes: --detect would keep them
        if (c.name == "texel-centres") CHECK(wrong.out.find("try --detect without --layout rows=mu --layout cols=r") != std::string::npos);
        if (c.name == "godot-flipped-schlick") {  // the report: by row and column in the table's coordinates, display steps
            CHECK(wrong.out.find("A, largest |error| by row (r): 0.0312: ") != std::string::npos);
            CHECK(wrong.out.find("A, by column (mu): 0.0312: ") != std::string::npos);
            CHECK(wrong.out.find("in 8-bit display steps (sRGB-encoded, 1/255): A ") != std::string::npos);
        }
    }
    // Unity's 10-bit codes: the layout found, the check passes once the encoding is given (kept fixed)
    const convention unity = conventions()[3];
    const std::string file = "--check '" + (dir / (unity.name + ".png")).string() + "' --kind dfg";
    const auto r = records(file + " --detect --layout encoding=unorm10");
    CHECK(r[0]["layout"] == "rows=r,cols=sqrt-mu,row0=low,col0=low,grid=edges,channels=B,A+B,encoding=unorm10");
    CHECK(r[0]["pass"] == true);
    // the edge texels at r = 0 and mu = 0 are compared with the pair's limits: all 256
    CHECK(r[0]["texels"] == 256);
    CHECK(!r[0].contains("not_compared"));
    // baked a little inside (N.V = 1e-4) as engines do, the mu = 0 column is off the grazing limit
    // by more than 10 bits hold
    const std::string inside = "--check '" + write_table(unity, dir, true) + "' --kind dfg --preset unity-hdrp";
    const auto off = records(inside);
    CHECK(off[0]["pass"] == false);
    CHECK(off[0]["at_mu"] == 0);
    CHECK(verify_lut(inside).status == 1);
    // where no limit is derived the edges are not compared: Schlick-GGX's G (31 of the 256), and
    // E (Cycles' r = 0 column and mu = 0 row, 63 of 1024)
    const auto schlick_edges = records(file + " --preset unity-hdrp --model " + schlick);
    CHECK(schlick_edges[0]["not_compared"] == 31);
    CHECK(schlick_edges[0]["texels"] == 225);
    const auto cycles = records("--check '" + (dir / "cycles-E.exr").string() + "' --kind E --preset cycles");
    CHECK(cycles[0]["not_compared"] == 63);
    CHECK(cycles[0]["texels"] == 961);
    CHECK(cycles[0]["pass"] == true);
    // E_avg of 16 roughness values, roughest first, in one row of an OpenEXR image
    verify::lut_image eavg{16, 1, 1, {}};
    for (std::size_t i = 0; i < 16; ++i) {
        const double rough = (double(15 - i) + 0.5) / 16;
        eavg.data.push_back(mf::average_albedo(mf::composition::parse(correlated), rough * rough).value);
    }
    std::ofstream(dir / "eavg.exr", std::ios::binary) << verify::encode_exr(eavg, false);
    const std::string avg = "--check '" + (dir / "eavg.exr").string() + "' --kind Eavg";
    const auto e = records(avg + " --detect");
    CHECK(e[0]["layout"] == "rows=r,row0=high,grid=centres,channels=E_avg,encoding=linear");
    CHECK(e[0]["pass"] == true);
    CHECK(verify_lut(avg).status == 1);
    CHECK(verify_lut(avg + " --layout row0=high").status == 0);
    fs::remove_all(dir);
}

TEST_CASE("lut --check: a CSV of half values holds half's step with encoding=half, size=WxH shapes a flat table") {
    const fs::path dir = normzoo_test::fresh_dir("lut-layout-csv");
    const auto c = mf::composition::parse(correlated);
    std::ofstream csv(dir / "half.csv");
    csv << "mu,r,A,B\n";
    verify::lut_image flat{256, 1, 2, {}};
    for (std::size_t j = 0; j < 16; ++j)
        for (std::size_t i = 0; i < 16; ++i) {
            const double r = (double(j) + 0.5) / 16, mu = (double(i) + 0.5) / 16;
            const auto s = mf::split_sum(c, mu, r * r);
            const float a = float(Imath::half(float(s.a.value))), b = float(Imath::half(float(s.b.value)));
            char line[128];
            std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g\n", mu, r, double(a), double(b));
            csv << line;
            flat.data.push_back(s.a.value), flat.data.push_back(s.b.value);
        }
    csv.close();
    const std::string half = "--check '" + (dir / "half.csv").string() + "' --kind dfg";
    CHECK(verify_lut(half).status == 1);  // as printed, 9 digits hold a float: half's rounding is off
    const auto ok = records(half + " --layout encoding=half");
    CHECK(ok[0]["pass"] == true);
    CHECK(ok[0]["layout"] == "encoding=half");
    // a 16 x 16 table stored as one row of 256 texels
    std::ofstream(dir / "flat.png", std::ios::binary) << verify::encode_png16(flat);
    const std::string shaped = "--check '" + (dir / "flat.png").string() + "' --kind dfg";
    CHECK(verify_lut(shaped).status == 1);
    CHECK(verify_lut(shaped + " --layout size=16x16").status == 0);
    const auto wrong_size = verify_lut(shaped + " --layout size=8x8");
    CHECK(wrong_size.status == 2);
    CHECK(wrong_size.out.find("size=8x8 is 64 texels") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("lut --check: a list's point is computed where its decimals are, and rounds only where no double holds them") {
    const fs::path dir = normzoo_test::fresh_dir("lut-layout-points");
    const auto c = mf::composition::parse(correlated);
    // r = 511/512 prints its square, 0.996097564697265625, rounded to 17 digits: the point is r's,
    // which a double holds, and so does r^2; r = 0.1 is held by no double
    auto row = [&](const char* roughness, double r) {  // mu = 0.5, then the roughness as printed
        const auto v = mf::split_sum(c, 0.5, r * r);
        char line[160];
        std::snprintf(line, sizeof line, "0.5,%s,%.17g,%.17g\n", roughness, v.a.value, v.b.value);
        return std::string(line);
    };
    std::ofstream(dir / "held.csv") << "mu,alpha,r,A,B\n" << row("0.99609756469726562,0.998046875", 0.998046875);
    std::ofstream(dir / "rounded.csv") << "mu,r,A,B\n" << row("0.1", 0.1);
    std::ofstream(dir / "r.csv") << "mu,r,A,B\n" << row("0.998046875", 0.998046875);
    const auto held = verify_lut("--check '" + (dir / "held.csv").string() + "' --kind dfg");
    CHECK(held.status == 0);
    CHECK(held.out.find("0 of 1 points with a coordinate no double holds") != std::string::npos);
    const auto by_r = verify_lut("--check '" + (dir / "r.csv").string() + "' --kind dfg");
    CHECK(by_r.out.find("0 of 1 points with a coordinate no double holds") != std::string::npos);
    const auto rounded = verify_lut("--check '" + (dir / "rounded.csv").string() + "' --kind dfg");
    CHECK(rounded.status == 0);
    CHECK(rounded.out.find("1 of 1 points with a coordinate no double holds") != std::string::npos);
    fs::remove_all(dir);
}

// n x n texels of the exact pair (height-correlated GGX) as half bits, row by row: rows mu and
// columns r (three.js), or rows r and columns mu (Bevy), at texel centres.
std::vector<std::uint16_t> exact_halves(std::size_t n, bool rows_mu, bool unorm16 = false) {
    const auto c = mf::composition::parse(correlated);
    auto code = [&](double v) { return unorm16 ? std::uint16_t(std::lround(v * 65535)) : verify::double_to_half(v); };
    std::vector<std::uint16_t> h;
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < n; ++i) {
            const double row = (double(j) + 0.5) / double(n), col = (double(i) + 0.5) / double(n);
            const double mu = rows_mu ? row : col, r = rows_mu ? col : row;
            const auto s = mf::split_sum(c, mu, r * r);
            h.push_back(code(s.a.value)), h.push_back(code(s.b.value));
        }
    return h;
}

TEST_CASE("lut --check reads three.js's Uint16Array by --preset threejs and Bevy's zstd KTX2 by --preset bevy") {
    normzoo_test::temp_dir dir{"lut-layout-engines"};
    // three.js: the half bits only encoding=half names; its size from the DataTexture call
    const std::string js = dir.file("DFGLUTData.js", lut_fixture::threejs_like(exact_halves(16, true), 16));
    const std::string three = "--check '" + js + "' --kind dfg";
    const auto t = records(three + " --preset threejs");
    CHECK(t[0]["format"] == "array-hex");
    CHECK(t[0]["layout"] == "rows=mu,cols=r,row0=low,col0=low,grid=centres,channels=A,B,encoding=half");
    CHECK(t[0]["texels"] == 256);
    CHECK(t[0]["pass"] == true);
    CHECK(verify_lut(three + " --preset threejs").status == 0);
    for (const std::string& unsaid : {std::string(""), std::string(" --layout encoding=unorm10")}) {
        const auto r = verify_lut(three + unsaid);
        CAPTURE(unsaid, r.out);
        CHECK(r.status == 2);
        CHECK(r.out.find("holds hex integers") != std::string::npos);
    }
    const auto found = records(three + " --detect --layout encoding=half");
    CHECK(found[0]["layout"] == "rows=mu,cols=r,row0=low,col0=low,grid=centres,channels=A,B,encoding=half");
    CHECK(found[0]["pass"] == true);
    // --detect alone reads the integers as half bits, unorm16 and unorm8, and keeps half's reading
    const auto guessed = records(three + " --detect");
    CHECK(guessed[0]["layout"] == "rows=mu,cols=r,row0=low,col0=low,grid=centres,channels=A,B,encoding=half");
    CHECK(guessed[0]["pass"] == true);
    // and the same table as unorm16 codes, as unorm16
    const std::string codes = dir.file("codes.js", lut_fixture::threejs_like(exact_halves(16, true, true), 16));
    const auto as_codes = records("--check '" + codes + "' --kind dfg --detect");
    CHECK(as_codes[0]["layout"] == "rows=mu,cols=r,row0=low,col0=low,grid=centres,channels=A,B,encoding=unorm16");
    CHECK(as_codes[0]["pass"] == true);
    // test_lut_formats' own 4 x 4 fixture (values that are no table): read and compared, it fails
    std::vector<std::uint16_t> made;
    for (std::size_t k = 0; k < 32; ++k) made.push_back(verify::double_to_half(k % 2 ? 0.01 * double(k) : 1 - 0.02 * double(k)));
    const std::string small = dir.file("small.js", lut_fixture::threejs_like(made, 4));
    CHECK(verify_lut("--check '" + small + "' --kind dfg --preset threejs").status == 1);

    // Bevy: a Zstandard-supercompressed KTX2 of R16G16_SFLOAT, rows r, columns mu
    const std::string ktx = dir.file("dfg.ktx2", lut_fixture::ktx2_bytes(lut_fixture::bevy_like(exact_halves(16, false), 16)));
    const auto b = records("--check '" + ktx + "' --kind dfg --preset bevy");
    CHECK(b[0]["format"] == "ktx2-R16G16_SFLOAT");
    CHECK(b[0]["layout"] == "rows=r,cols=mu,row0=low,col0=low,grid=centres,channels=A,B,encoding=half");
    CHECK(b[0]["pass"] == true);
    CHECK(verify_lut("--check '" + ktx + "' --kind dfg --preset bevy").status == 0);
    // test_lut_formats' fixture as it is (values that are no table): read and compared, it fails
    const std::string fixture = dir.file("fixture.ktx2", lut_fixture::ktx2_bytes(lut_fixture::bevy_like()));
    const auto f = records("--check '" + fixture + "' --kind dfg --preset bevy");
    CHECK(f[0]["format"] == "ktx2-R16G16_SFLOAT");
    CHECK(f[0]["pass"] == false);
    CHECK(verify_lut("--check '" + fixture + "' --kind dfg --preset bevy").status == 1);
}

// What only a layout says, said by one: a KTX2 file whose rows run up is read once row0 is named
// (rows as stored), an sRGB KTX2 once encoding=srgb decodes it, a flat array once size=WxH shapes
// it; without, exit 2.
TEST_CASE("lut --check: KTXorientation, sRGB formats and an array's size are read when the layout says them") {
    normzoo_test::temp_dir dir{"lut-layout-said"};
    const auto c = mf::composition::parse(correlated);
    verify::lut_image ab{8, 8, 2, {}}, srgb{8, 8, 4, {}};
    std::string flat = "export const lut = [";
    for (std::size_t j = 0; j < 8; ++j)
        for (std::size_t i = 0; i < 8; ++i) {
            const double r = (double(j) + 0.5) / 8, mu = (double(i) + 0.5) / 8;
            const auto s = mf::split_sum(c, mu, r * r);
            ab.data.insert(ab.data.end(), {s.a.value, s.b.value});
            srgb.data.insert(srgb.data.end(), {srgb_encode(s.a.value), srgb_encode(s.b.value), 0.0, 1.0});
            char v[64];
            std::snprintf(v, sizeof v, "%s%.9g, %.9g", j + i ? ", " : "", s.a.value, s.b.value);
            flat += v;
        }
    // a KTX2 file's KTXwriter entry (18 bytes) made KTXorientation = ru: its rows as stored are r
    // from low to high all the same
    std::string ru = verify::encode_ktx2(ab, 83, false);
    ru.replace(ru.find("KTXwriter"), 18, std::string("KTXorientation\0ru\0", 18));
    const std::string up = "--check '" + dir.file("ru.ktx2", ru) + "' --kind dfg";
    CHECK(verify_lut(up).status == 2);
    CHECK(verify_lut(up + " --layout row0=low").status == 0);
    CHECK(verify_lut(up + " --layout row0=high").status == 1);
    CHECK(verify_lut(up + " --detect").status == 0);
    // R8G8B8A8_SRGB: what a sampler decodes
    const std::string s8 = "--check '" + dir.file("srgb.ktx2", verify::encode_ktx2(srgb, 43, false)) + "' --kind dfg";
    CHECK(verify_lut(s8).status == 2);
    CHECK(verify_lut(s8 + " --layout encoding=linear").status == 2);
    CHECK(verify_lut(s8 + " --layout encoding=srgb").status == 0);
    const auto found = records(s8 + " --detect");
    CHECK(found[0]["layout"] == "rows=r,cols=mu,row0=low,col0=low,grid=centres,channels=A,B,encoding=srgb");
    // an array of 128 decimals (floats printed to 9 digits) with no size in the file
    const std::string bare = "--check '" + dir.file("bare.ts", flat + "];\n") + "' --kind dfg";
    const auto no_size = verify_lut(bare);
    CHECK(no_size.status == 2);
    CHECK(no_size.out.find("--layout size=WxH gives it") != std::string::npos);
    CHECK(verify_lut(bare + " --layout size=8x8").status == 0);
}

TEST_CASE("lut --check: a bad layout, preset or combination is exit 2 naming the key") {
    const fs::path dir = normzoo_test::fresh_dir("lut-layout-bad");
    convention c = conventions()[0];
    c.n = 4;
    const std::string png = "--check '" + write_table(c, dir) + "' ";
    std::ofstream(dir / "t.csv") << "mu,r,A,B\n0.5,0.5,0.5,0.1\n";
    const std::string csv = "--check '" + (dir / "t.csv").string() + "' ";
    const std::vector<std::pair<std::string, std::string>> bad = {
        {png + "--kind dfg --layout rows=foo", "rows 'foo' is not one of r, alpha, mu, sqrt-mu"},
        {png + "--kind dfg --layout bogus=1", "unknown key 'bogus'"},
        {png + "--kind dfg --layout rows=r,cols=alpha", "rows=r and cols=alpha"},
        {png + "--kind dfg --layout channels=A,C", "channels 'C'"},
        {png + "--kind dfg --layout channels=A,A+B,B", "channels 'A,A+B,B'"},
        {png + "--kind dfg --layout rows=r,rows=mu", "key 'rows' is given twice"},
        {png + "--kind dfg --layout grid", "'grid' is not KEY=VALUE"},
        {png + "--kind dfg --layout size=0x4", "size '0x4'"},
        {png + "--kind dfg --layout encoding=rgbd", "the layout reads 4"},
        {png + "--kind E --layout channels=A", "channels 'A'"},
        {png + "--kind Eavg --layout cols=r", "cols is not read by --kind Eavg"},
        {png + "--kind dfg --preset nope", "unknown engine 'nope'"},
        {png + "--kind dfg --preset eevee", "sqrt(1 - N.V)"},
        {png + "--kind dfg --preset cycles", "--preset cycles is a table of --kind E"},
        {png + "--kind dfg --preset filament --detect", "--preset names a layout"},
        {png + "--kind dfg --map alpha --layout rows=r", "--map is --layout rows=r"},
        {csv + "--kind dfg --layout rows=mu", "rows is for an image"},
        {csv + "--kind dfg --detect", "--detect reads an image"},
        {csv + "--kind dfg --layout encoding=srgb", "encoding=srgb decodes an image's codes"},
        {"--kind dfg --size 4 --layout encoding=rgbd --format exr", "--format exr cannot hold --layout encoding=rgbd"},
        {"--kind dfg --size 4 --detect", "--detect is for --check FILE"},
    };
    for (const auto& [args, says] : bad) {
        const auto r = verify_lut(args);
        CAPTURE(args, r.out);
        CHECK(r.status == 2);
        CHECK(r.out.find(says) != std::string::npos);
    }
    fs::remove_all(dir);
}
