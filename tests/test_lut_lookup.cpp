// What `verify lut --check` measures beside its verdict (docs/lut.md, "The lookup's error", "The
// error map"): a shader's bilinear lookup of the table against the exact values, checked against a
// lookup computed here from the stored texels as docs/lut.md defines it, and the error map --out
// draws. The tables are normzoo's own exact ones (`verify lut --size N`), stored as the command
// writes them (float OpenEXR) or as three.js ships its table (tests/lut_fixtures.hpp).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "lut_fixtures.hpp"
#include "lut_runs.hpp"
#include "temp_files.hpp"

namespace fs = std::filesystem;
using normzoo_test::records;
using normzoo_test::run_shell;

namespace {

const std::string bin = NORMZOO_VERIFY_BIN;

std::string text(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

// The exact split-sum pair at (mu, r), mu = 0 and r = 0 included (the pair's limits, docs/lut.md
// "Edges"): a CSV point storing 0 and 0 is off by exactly A and B.
std::pair<double, double> exact_pair(const normzoo_test::temp_dir& dir, double mu, double r) {
    const auto p = records("--check '" + dir.file("point.csv", "mu,r,A,B\n" + text(mu) + "," + text(r) + ",0,0\n") + "' --kind dfg");
    return {p[0]["max_abs_error"].get<double>(), p[1]["max_abs_error"].get<double>()};
}

// A table as stored: values[(row * n + column) * channels + c], rows and columns at texel centres.
struct stored {
    std::size_t n, channels;
    std::vector<double> values;
};

// Linear between texel centres (i + 0.5)/n, held at the outermost beyond them: a shader's
// bilinear fetch with clamp to edge at texture coordinates (u along the columns, v the rows).
double bilinear(const stored& t, double u, double v, std::size_t c) {
    auto place = [&](double x, std::size_t& k, double& w) {
        const double p = std::clamp(x * double(t.n) - 0.5, 0.0, double(t.n - 1));
        k = std::min(std::size_t(p), t.n - 2), w = p - double(k);
    };
    std::size_t i = 0, j = 0;
    double wu = 0, wv = 0;
    place(u, i, wu), place(v, j, wv);
    auto at = [&](std::size_t row, std::size_t col) { return t.values[(row * t.n + col) * t.channels + c]; };
    return (1 - wv) * ((1 - wu) * at(j, i) + wu * at(j, i + 1)) + wv * ((1 - wu) * at(j + 1, i) + wu * at(j + 1, i + 1));
}

// The exact (A, B) table at texel centres, rows r and columns mu, as the command makes it.
std::vector<double> exact_table(std::size_t n) {
    std::vector<double> v;
    for (const auto& r : records("--kind dfg --size " + std::to_string(n)))
        v.push_back(r["A"].get<double>()), v.push_back(r["B"].get<double>());
    return v;
}

}  // namespace

TEST_CASE("lut --check: a table exact at texel centres has no storage error but a lookup error, of second order between the texels") {
    const normzoo_test::temp_dir dir("lut-lookup-order");
    std::vector<nlohmann::json> eavg;
    for (std::size_t n : {16, 32}) {
        REQUIRE(run_shell(bin + " lut --kind Eavg --format exr --size " + std::to_string(n) + " --out '" + dir.path.string() + "' 2>&1").status == 0);
        eavg.push_back(records("--check '" + (dir.path / ("lut-Eavg-" + std::to_string(n) + ".exr")).string() + "' --kind Eavg")[0]);
        const auto& r = eavg.back();
        CAPTURE(n, r.dump());
        CHECK(r["above_tolerance"] == 0);
        CHECK(r["max_abs_error"].get<double>() < 1e-7);  // a float's rounding
        CHECK(r["max_interpolation_error"].get<double>() > 1e-5);
        CHECK(r["lookup_points"] == n + 3);  // a middle per cell, two points in each band
    }
    // between the texels the error is the interpolation's, h^2 f''/8: a quarter at twice the
    // texels; clamped beyond the outermost (r = 1 here), it is h/2 f': a half
    const double second = eavg[0]["max_interpolation_error"].get<double>() / eavg[1]["max_interpolation_error"].get<double>();
    const double first = eavg[0]["max_lookup_error"].get<double>() / eavg[1]["max_lookup_error"].get<double>();
    CHECK((second > 3.7 && second < 4.3));
    CHECK((first > 1.8 && first < 2.2));
    CHECK(eavg[1]["lookup_at_r"] == 1.0);
    // the split-sum pair likewise: exact texels, a lookup error where the table is clamped and between
    REQUIRE(run_shell(bin + " lut --kind dfg --format exr --size 16 --out '" + dir.path.string() + "' 2>&1").status == 0);
    const auto dfg = records("--check '" + (dir.path / "lut-dfg-16.exr").string() + "' --kind dfg");
    for (const auto& r : dfg) {
        CAPTURE(r.dump());
        CHECK(r["pass"] == true);
        CHECK(r["max_abs_error"].get<double>() < 1e-7);
        CHECK(r["max_lookup_error"].get<double>() > 0.01);
        CHECK(r["lookup_points"] == 35 * 35 - 16 * 16);  // each axis' 35 positions crossed, but texel with texel
        CHECK(r["max_lookup_error_dielectric"].get<double>() > 0.01);
    }
}

TEST_CASE("lut --check: the lookup's error at its worst point is a bilinear lookup of the stored texels against the exact pair") {
    const normzoo_test::temp_dir dir("lut-lookup-worst");
    const std::size_t n = 16;
    const std::vector<double> exact = exact_table(n);
    REQUIRE(run_shell(bin + " lut --kind dfg --format exr --size 16 --out '" + dir.path.string() + "' 2>&1").status == 0);
    // as written (float OpenEXR, rows r, columns mu), and as three.js ships it (half bits, rows mu)
    stored as_float{n, 2, {}}, as_half{n, 2, {}};
    std::vector<std::uint16_t> bits(exact.size());
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t c = 0; c < 2; ++c) {
                const double v = exact[(j * n + i) * 2 + c];
                as_float.values.push_back(double(float(v)));
                bits[(i * n + j) * 2 + c] = verify::double_to_half(v);  // three.js: row mu_i, column r_j
            }
    for (std::uint16_t b : bits) as_half.values.push_back(verify::half_to_double(b));
    const std::string exr = "--check '" + (dir.path / "lut-dfg-16.exr").string() + "' --kind dfg";
    const std::string js = "--check '" + dir.file("DFGLUTData.js", lut_fixture::threejs_like(bits, n)) + "' --kind dfg --preset threejs";
    // the exact values at the fine points are computed to a hundredth of the storage's tolerance
    // (docs/lut.md, "How a check chooses its accuracy"): 2^-24 |v| / 100 is below 1e-10, half's up to 5e-6
    for (const auto& [args, table, mu_rows, near] : {std::make_tuple(exr, &as_float, false, 1e-8), std::make_tuple(js, &as_half, true, 1e-5)}) {
        const auto recs = records(args);
        REQUIRE(recs.size() == 2);
        for (std::size_t c = 0; c < 2; ++c) {
            const auto& r = recs[c];
            const double mu = r["lookup_at_mu"].get<double>(), rough = r["lookup_at_r"].get<double>();
            CAPTURE(args, r.dump(), mu, rough);
            const auto [a, b] = exact_pair(dir, mu, rough);
            const double looked = mu_rows ? bilinear(*table, rough, mu, c) : bilinear(*table, mu, rough, c);
            CHECK(std::abs(std::abs(looked - (c == 0 ? a : b)) - r["max_lookup_error"].get<double>()) < near);
        }
        // E = F0 A + B at F0 = 1, where it is worst
        const double mu = recs[0]["lookup_metal_at_mu"].get<double>(), rough = recs[0]["lookup_metal_at_r"].get<double>();
        const auto [a, b] = exact_pair(dir, mu, rough);
        auto looked = [&](std::size_t c) { return mu_rows ? bilinear(*table, rough, mu, c) : bilinear(*table, mu, rough, c); };
        CHECK(std::abs(std::abs(looked(0) + looked(1) - a - b) - recs[0]["max_lookup_error_metal"].get<double>()) < 2 * near);
    }
}

TEST_CASE("lut --check --out draws the error map as SVG, and writes nothing without --out or for a bad file") {
    const normzoo_test::temp_dir dir("lut-lookup-map");
    REQUIRE(run_shell(bin + " lut --kind dfg --format exr --size 8 --out '" + dir.path.string() + "' 2>&1").status == 0);
    const fs::path out = dir.path / "maps", svg = out / "lut-check-lut-dfg-8.svg";
    const std::string table = (dir.path / "lut-dfg-8.exr").string();
    // without --out: a report, no file (here or in the folder run from)
    const auto plain = run_shell("cd '" + dir.path.string() + "' && " + bin + " lut --check '" + table + "' --kind dfg 2>&1");
    CHECK(plain.status == 0);
    CHECK(plain.out.find("A, looked up max |error| ") != std::string::npos);
    CHECK(!fs::exists(out));
    for (const auto& e : fs::directory_iterator(dir.path)) CHECK(e.path().extension() != ".svg");
    const auto drawn = run_shell(bin + " lut --check '" + table + "' --kind dfg --out '" + out.string() + "' 2>&1");
    CAPTURE(drawn.out);
    CHECK(drawn.status == 0);
    CHECK(drawn.out.find("error map -> " + svg.string()) != std::string::npos);
    REQUIRE(fs::exists(svg));
    const std::string s = normzoo_test::slurp(svg);
    CHECK(s.rfind("<?xml", 0) == 0);
    CHECK(s.find("<svg") != std::string::npos);
    CHECK(s.find("</svg>") != std::string::npos);
    CHECK(s.find("<image") != std::string::npos);  // the maps, one image each
    CHECK(s.find("mu = N.V") != std::string::npos);
    CHECK(std::distance(fs::directory_iterator(out), fs::directory_iterator{}) == 1);  // the map alone, nothing staged left
    // a truncated file: exit 2, nothing written
    const std::string png = lut_fixture::png8(8, 8, 3, std::vector<std::uint8_t>(8 * 8 * 3, 128));
    const fs::path bad_out = dir.path / "bad";
    const auto bad = run_shell(bin + " lut --check '" + dir.file("bad.png", png.substr(0, png.size() / 2)) + "' --kind dfg --out '" +
                               bad_out.string() + "' 2>&1");
    CHECK(bad.status == 2);
    CHECK((!fs::exists(bad_out) || fs::is_empty(bad_out)));
}
