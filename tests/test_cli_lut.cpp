// The command end to end: verify lut, writing its formats and checking engines' tables.
#include "cli_helpers.hpp"

using namespace cli_test;

TEST_CASE("verify lut: a table in each format is written and checked back, an edited table fails, a bad file is exit 2") {
    const auto dir = normzoo_test::fresh_dir("lut");
    const std::string bin = NORMZOO_VERIFY_BIN;
    for (const char* format : {"csv", "png16", "exr", "exr-half", "h", "json"}) {
        const auto w = run_shell(bin + " lut --kind dfg --size 4 --format " + format + " --out '" + dir.string() + "' 2>&1");
        CAPTURE(format, w.out);
        CHECK(w.status == 0);
    }
    CHECK(fs::exists(dir / "lut-dfg-4.h"));
    CHECK(normzoo_test::slurp(dir / "lut-dfg-4.h").find("[4][4][2]") != std::string::npos);
    // exr-half beside the float exr, not over it
    CHECK(fs::exists(dir / "lut-dfg-4-half.exr"));
    for (const char* file : {"lut-dfg-4.csv", "lut-dfg-4.png", "lut-dfg-4.exr", "lut-dfg-4-half.exr"}) {
        const auto c = run_shell(bin + " lut --check '" + (dir / file).string() + "' --kind dfg --json 2>&1");
        CAPTURE(file, c.out);
        CHECK(c.status == 0);
    }
    // the records' JSON: one per texel with A, B and their bounds
    const auto j = nlohmann::json::parse(run("lut --kind dfg --size 2 --json").out);
    REQUIRE(j["records"].size() == 4);
    for (const char* key : {"alpha", "mu", "A", "A_error_estimate", "B", "B_error_estimate"}) CHECK(j["records"][0].contains(key));
    // --f0: E of a Schlick model at F0 = 0.04 is F0 A + B of the split-sum pair, computed apart
    const auto e = nlohmann::json::parse(run("lut --kind E --model ggx/smith-height-correlated/schlick --f0 0.04 --alpha 0.3 --mu 0.5 --json").out);
    const auto ab = nlohmann::json::parse(run("lut --kind dfg --alpha 0.3 --mu 0.5 --json").out);
    REQUIRE(e["records"].size() == 1);
    REQUIRE(ab["records"].size() == 1);
    const auto& er = e["records"][0];
    const auto& abr = ab["records"][0];
    CHECK((er["f0"].get<double>() == 0.04 && er["f0_input"] == "0.04"));
    const double split = 0.04 * abr["A"].get<double>() + abr["B"].get<double>();
    CHECK(std::abs(er["E"].get<double>() - split) <=
          er["error_estimate"].get<double>() + 0.04 * abr["A_error_estimate"].get<double>() + abr["B_error_estimate"].get<double>());
    // two integrals, not one number twice: E's bound is its own, not the pair's (both integrals are
    // accurate to ~1e-16 here, so their values may agree to the bit)
    CHECK(er["error_estimate"].get<double>() != 0.04 * abr["A_error_estimate"].get<double>() + abr["B_error_estimate"].get<double>());
    for (const char* bad : {"lut --kind dfg --size 2 --f0 0.5", "lut --kind E --size 2 --f0 1.5", "lut --kind E --size 2 --f0 0.1,0.2"})
        check_refused(bad, "--f0");
    // an engine's table with a wrong value: exit 1, FAIL on the console
    std::string csv = normzoo_test::slurp(dir / "lut-dfg-4.csv");
    const auto line = csv.find("\nlut,");
    const auto header = csv.substr(csv.find("table,"), csv.find('\n', csv.find("table,")) - csv.find("table,"));
    std::ofstream(dir / "edited.csv") << header << "\nlut,dfg,ggx/smith-height-correlated/one,0.015625,0.125,0.125,0.5,0,0.1,0\n";
    const auto edited = run_shell(bin + " lut --check '" + (dir / "edited.csv").string() + "' --kind dfg 2>&1");
    CAPTURE(edited.out, line);
    CHECK(edited.status == 1);
    CHECK(edited.out.find("FAIL") != std::string::npos);
    // a NaN or an Inf a baker wrote into a float EXR (uncompressed: the last 4 bytes are the last
    // texel's last channel) fails, where the format's precision, relative to the value, would not
    const std::string exr = normzoo_test::slurp(dir / "lut-dfg-4.exr");
    for (const auto& [name, bits] : {std::pair{"nan.exr", std::string("\x00\x00\xc0\x7f", 4)}, std::pair{"inf.exr", std::string("\x00\x00\x80\x7f", 4)}}) {
        std::ofstream(dir / name, std::ios::binary) << exr.substr(0, exr.size() - 4) + bits;
        const auto r = run_shell(bin + " lut --check '" + (dir / name).string() + "' --kind dfg 2>&1");
        CAPTURE(name, r.out);
        CHECK(r.status == 1);
        CHECK(r.out.find("FAIL") != std::string::npos);
    }
    // not an image, a truncated PNG, a 3 x 4 image
    std::ofstream(dir / "text.png") << "hello";
    const std::string png = normzoo_test::slurp(dir / "lut-dfg-4.png");
    std::ofstream(dir / "short.png", std::ios::binary) << png.substr(0, png.size() / 2);
    for (const char* file : {"text.png", "short.png", "missing.exr"}) check_refused("lut --check '" + (dir / file).string() + "' --kind dfg", file);
    fs::remove_all(dir);
}

// The files engines ship (docs/lut.md, "Files it reads"), laid out as normzoo writes its own
// tables (rows r, columns mu, texel centres, channels A, B): normzoo's float table converted into
// each by lut_formats/'s writers (or, for RGBE, tests/lut_fixtures.hpp) and checked; what the check
// does not read is exit 2, naming the file.
TEST_CASE("verify lut --check reads KTX2, DDS, Radiance HDR and source arrays") {
    const auto dir = normzoo_test::fresh_dir("lut-files");
    const std::string bin = NORMZOO_VERIFY_BIN;
    REQUIRE(run_shell(bin + " lut --kind dfg --size 8 --format exr --out '" + dir.string() + "' 2>&1").status == 0);
    const verify::lut_image ab = verify::read_lut_image((dir / "lut-dfg-8.exr").string()).image;
    verify::lut_image rgba{ab.width, ab.height, 4, {}}, rgb{ab.width, ab.height, 3, {}};
    for (std::size_t k = 0; k < ab.width * ab.height; ++k) {
        rgba.data.insert(rgba.data.end(), {ab.data[2 * k], ab.data[2 * k + 1], 0.0, 1.0});
        rgb.data.insert(rgb.data.end(), {ab.data[2 * k], ab.data[2 * k + 1], 0.0});
    }
    const std::string hdr = lut_fixture::hdr_file(8, 8, rgb.data);
    const std::vector<std::pair<std::string, std::string>> files = {
        {"ktx2-R32G32_SFLOAT", verify::encode_ktx2(ab, 103, false)}, {"ktx2-R16G16_SFLOAT", verify::encode_ktx2(ab, 83, true)},
        {"ktx2-R16G16B16A16_SFLOAT", verify::encode_ktx2(rgba, 97, true)}, {"ktx2-R16G16_UNORM", verify::encode_ktx2(ab, 77, false)},
        {"dds-R16G16_FLOAT", verify::encode_dds(ab, 34)}, {"dds-R32G32B32A32_FLOAT", verify::encode_dds(rgba, 2)},
        {"dds-R8G8_UNORM", verify::encode_dds(ab, 49)}, {"hdr", hdr}};
    for (const auto& [format, bytes] : files) {
        const std::string path = (dir / ("t-" + format + (format == "hdr" ? ".hdr" : format[0] == 'k' ? ".ktx2" : ".dds"))).string();
        std::ofstream(path, std::ios::binary) << bytes;
        const auto c = run_shell(bin + " lut --check '" + path + "' --kind dfg --json 2>&1");
        CAPTURE(format, c.out);
        CHECK(c.status == 0);
        CHECK(c.out.find("\"format\":\"" + format + "\"") != std::string::npos);
    }
    const auto h = run_shell(bin + " lut --kind dfg --size 8 --format h --out '" + dir.string() + "' 2>&1");
    REQUIRE(h.status == 0);
    const auto c = run_shell(bin + " lut --check '" + (dir / "lut-dfg-8.h").string() + "' --kind dfg --json 2>&1");
    CAPTURE(c.out);
    CHECK(c.status == 0);
    CHECK(c.out.find("\"format\":\"array-decimal\"") != std::string::npos);
    // a texel off by 1e-3 in a half KTX2 fails
    verify::lut_image off = ab;
    off.data[10] += 1e-3;
    std::ofstream(dir / "off.ktx2", std::ios::binary) << verify::encode_ktx2(off, 83, true);
    CHECK(run_shell(bin + " lut --check '" + (dir / "off.ktx2").string() + "' --kind dfg 2>&1").status == 1);

    std::string ru = verify::encode_ktx2(ab, 83, false);  // its KTXwriter entry, 18 bytes, made KTXorientation = ru
    ru.replace(ru.find("KTXwriter"), 18, std::string("KTXorientation\0ru\0", 18));
    const std::vector<std::pair<std::string, std::string>> refused = {
        {"hex.js", "const DATA = new Uint16Array([0x3c00, 0x0000]);\nnew DataTexture(DATA, 1, 1, RGFormat, HalfFloatType);\n"},
        {"bare.ts", "export const lut = [0.5, 0.25, 0.125, 1.0];\n"},
        {"srgb.ktx2", verify::encode_ktx2(rgba, 43, false)},
        {"bc7.dds", verify::encode_dds(ab, 34).replace(128, 1, std::string(1, char(98)))},
        {"short.ktx2", verify::encode_ktx2(ab, 83, true).substr(0, 200)}, {"ru.ktx2", ru}};
    for (const auto& [name, bytes] : refused) {
        std::ofstream(dir / name, std::ios::binary) << bytes;
        check_refused("lut --check '" + (dir / name).string() + "' --kind dfg", name);
    }
    fs::remove_all(dir);
}

// A CSV holds what its column prints: a value cut to 2 decimals among values printed to 17
// digits is off (its tolerance is that of the 17 digits), and every value printed "%.2f" passes at
// 0.005. Its coordinates are refused out of range, alpha and r where they disagree; the making
// options beside --check and --tolerance without it are refused.
TEST_CASE("verify lut --check: a CSV's tolerance is what its column prints, bad rows and options are exit 2") {
    const auto dir = normzoo_test::fresh_dir("lut-csv");
    const std::string bin = NORMZOO_VERIFY_BIN;
    auto check = [&](const std::string& file, const std::string& rows) {
        std::ofstream(dir / file) << "mu,r,E\n" << rows;
        const auto r = run_shell(bin + " lut --check '" + (dir / file).string() + "' --kind E 2>&1");
        CAPTURE(file, rows, r.out);
        return r.status;
    };
    const auto exact = nlohmann::json::parse(run("lut --kind E --r 0.25,0.5 --mu 0.5 --json").out)["records"];
    REQUIRE(exact.size() == 2);
    const double e0 = exact[0]["E"].get<double>(), e1 = exact[1]["E"].get<double>();
    char shortest[64], cut[32], fixed0[32], fixed1[32];
    std::snprintf(shortest, sizeof shortest, "%.17g", e0);
    std::snprintf(cut, sizeof cut, "%.2f", e1);
    std::snprintf(fixed0, sizeof fixed0, "%.2f", e0);
    std::snprintf(fixed1, sizeof fixed1, "%.2f", e1);
    CHECK(check("full.csv", std::string("0.5,0.25,") + shortest + "\n") == 0);
    CHECK(check("cut.csv", std::string("0.5,0.25,") + shortest + "\n0.5,0.5," + cut + "\n") == 1);
    CHECK(check("fixed.csv", std::string("0.5,0.25,") + fixed0 + "\n0.5,0.5," + fixed1 + "\n") == 0);
    // a float table printed shortest, alpha = r^2 formed in float beside r: it holds a float's 2^-24
    const float rf = 0.3f, af = rf * rf;
    char alpha_text[32], r_text[32], e_text[32] = "";
    std::snprintf(alpha_text, sizeof alpha_text, "%.9g", double(af));
    std::snprintf(r_text, sizeof r_text, "%.9g", double(rf));
    const float ef = float(nlohmann::json::parse(run(std::string("lut --kind E --alpha ") + alpha_text + " --mu 0.5 --json").out)["records"][0]["E"].get<double>());
    for (int digits = 1; digits <= 9; ++digits) {
        std::snprintf(e_text, sizeof e_text, "%.*g", digits, double(ef));
        if (std::strtof(e_text, nullptr) == ef) break;
    }
    std::ofstream(dir / "float.csv") << "mu,alpha,r,E\n0.5," << alpha_text << "," << r_text << "," << e_text << "\n";
    const auto floats = run_shell(bin + " lut --check '" + (dir / "float.csv").string() + "' --kind E 2>&1");
    CAPTURE(alpha_text, r_text, e_text, floats.out);
    CHECK(floats.status == 0);
    const std::pair<const char*, const char*> bad_rows[] = {
        {"mu,alpha,E\n0.5,200,0.9\n", ":2: alpha 200 is not in (0, 100]"},
        {"mu,r,E\n0.5,11,0.9\n", ":2: r 11 is not in (0, 10]"},
        {"mu,alpha,E\n1e-9,0.5,0.9\n", ":2: mu = 1e-9"},
        {"mu,alpha,E\n0.5,0x1p-2,0.9\n", ":2: alpha '0x1p-2' is not a decimal number"},
        {"mu,r,E\n0.5,0.5,0x1p-1\n", ":2: a value '0x1p-1' is not a decimal number"},
        {"mu,r,E\n0.5,0.5,nan\n", ":2: a value 'nan' is not a decimal number"},
        {"mu,alpha,r,E\n0.5,0.2,0.3,0.9\n", ":2: alpha 0.2 and r 0.3 disagree"},
    };
    for (const auto& [text, says] : bad_rows) {
        std::ofstream(dir / "bad.csv") << text;
        check_refused("lut --check '" + (dir / "bad.csv").string() + "' --kind E", std::string("bad.csv") + says);
    }
    for (const std::string& making : {std::string("--size 8"), std::string("--alpha 0.5 --mu 0.5"), std::string("--format png16")})
        check_refused("lut --kind E --check '" + (dir / "full.csv").string() + "' " + making, "is for making a table");
    // --out takes an image's error map; a CSV's points have none
    check_refused("lut --kind E --check '" + (dir / "full.csv").string() + "' --out '" + dir.string() + "'", "a CSV, is points");
    check_refused("lut --kind E --size 2 --tolerance 0.1", "--tolerance is for --check");
    check_refused("lut --kind E --check '" + (dir / "full.csv").string() + "' --tolerance ''", "--tolerance: an empty value");
    check_refused("lut --kind E --check '" + (dir / "full.csv").string() + "' --f0 ''", "--f0: an empty value");
    // listed values are points: no image or header of texel centres; Eavg reads no mu
    for (const char* format : {"png16", "exr", "exr-half", "h"})
        check_refused(std::string("lut --kind dfg --r 0.5,0.7 --mu 0.2,1 --format ") + format + " --out '" + dir.string() + "'",
                      "listed values (--alpha or --r with --mu) are points");
    check_refused("lut --kind Eavg --r 0.5 --mu 0.2", "--mu is not read by --kind Eavg");
    // a Monte Carlo table's head says so
    REQUIRE(run_shell(bin + " lut --kind dfg --size 2 --monte-carlo 16 --out '" + dir.string() + "' 2>&1").status == 0);
    const std::string mc = normzoo_test::slurp(dir / "lut-dfg-2.csv");
    CHECK(mc.find("by Monte Carlo as engines bake it") != std::string::npos);
    CHECK(mc.find("at tolerance 1e-10") == std::string::npos);
    // a row cut short or run on, a header naming a column twice: exit 2 at the line; a byte order mark is read past
    const std::string rows = std::string("mu,r,E\n0.5,0.25,") + shortest + "\n";
    const std::pair<std::string, const char*> ragged[] = {{"mu,r,E\n0.5,0.25\n", ":2: 2 cells, the header has 3"},
                                                          {rows + "0.5,0.5,0.9,7\n", ":3: 4 cells, the header has 3"},
                                                          {"mu,r,E,E\n0.5,0.25,0.9,0.9\n", ":1: the header names 'E' twice"}};
    for (const auto& [text, says] : ragged) {
        std::ofstream(dir / "ragged.csv") << text;
        check_refused("lut --check '" + (dir / "ragged.csv").string() + "' --kind E", std::string("ragged.csv") + says);
    }
    std::ofstream(dir / "image.csv") << "\x89PNG\r\n\x1a\n and so on";
    check_refused("lut --check '" + (dir / "image.csv").string() + "' --kind E", "image.csv: holds a PNG or OpenEXR image");
    std::ofstream(dir / "bom2.csv") << "\xEF\xBB\xBF" << rows;
    CHECK(run_shell(bin + " lut --check '" + (dir / "bom2.csv").string() + "' --kind E 2>&1").status == 0);
    // a table `verify lut` wrote names what it was made with: a check of another is refused
    const std::string made = "--kind E --model ggx/smith-height-correlated/dielectric --eta 1.5";
    REQUIRE(run_shell(bin + " lut " + made + " --size 2 --out '" + dir.string() + "' 2>&1").status == 0);
    const std::string own = "lut --check '" + (dir / "lut-E-2.csv").string() + "' ";
    CHECK(run_shell(bin + " " + own + made + " 2>&1").status == 0);
    check_refused(own + "--kind E --model ggx/smith-height-correlated/dielectric", "made with eta = 1.5, the check is of eta not given");
    check_refused(own + "--kind E --model ggx/smith-height-correlated/dielectric --eta 1.6", "the check is of eta = 1.6");
    check_refused(own + "--kind E --model ggx/smith-separable/dielectric --eta 1.5", "the check is of model = ggx/smith-separable");
    // made from F0 (no eta written), checked with an eta: refused as well, not a bare exit 1
    REQUIRE(run_shell(bin + " lut --kind E --model ggx/smith-height-correlated/dielectric --f0 0.04 --size 2 --out '" + dir.string() + "' 2>&1").status == 0);
    CHECK(run_shell(bin + " " + own + "--kind E --model ggx/smith-height-correlated/dielectric --f0 0.04 2>&1").status == 0);
    check_refused(own + "--kind E --model ggx/smith-height-correlated/dielectric --eta 1.5", "made with eta not given, the check is of eta = 1.5");
    check_refused(own + "--kind E --model ggx/smith-height-correlated/dielectric --f0 0.05", "made with f0 = 0.04");
    // the compensation changes E, not E_avg: an Eavg table checks as the compensated model's too
    REQUIRE(run_shell(bin + " lut --kind Eavg --size 4 --out '" + dir.string() + "' 2>&1").status == 0);
    const std::string eavg = "lut --check '" + (dir / "lut-Eavg-4.csv").string() + "' --kind Eavg --model ";
    CHECK(run_shell(bin + " " + eavg + "ggx/smith-height-correlated/one/kulla-conty 2>&1").status == 0);
    check_refused(eavg + "ggx/smith-separable/one/kulla-conty", "the check is of model = ggx/smith-separable/one/kulla-conty");
    fs::remove_all(dir);
}


TEST_CASE("verify lut --check: a split-sum CSV's edges (mu = 0, r = 0) are checked against the pair's limits") {
    // docs/lut.md, "Edges": the mirror's (1 - (1 - mu)^5, (1 - mu)^5), the height-correlated G's
    // A + B = 1 at grazing (20/21 and 1/21 at alpha = 1), and the corner's A = 0, B in [0, 1]
    const auto dir = normzoo_test::fresh_dir("lut-edges");
    const std::string bin = NORMZOO_VERIFY_BIN;
    auto check = [&](const std::string& rows, const std::string& kind = "dfg", const std::string& model = "") {
        std::ofstream(dir / "edges.csv") << "mu,r," << (kind == "dfg" ? "A,B" : "E") << "\n" << rows;
        const auto r = run_shell(bin + " lut --check '" + (dir / "edges.csv").string() + "' --kind " + kind + model + " 2>&1");
        CAPTURE(rows, r.out);
        return r.status;
    };
    const std::string limits = "0.5,0,0.96875,0.03125\n0,1,0.952380952380952,0.0476190476190476\n0,0,0,0.7\n";
    CHECK(check(limits) == 0);
    CHECK(check(limits + "0,1,0.9,0.1\n") == 1);  // off by 0.05 at grazing
    CHECK(check(limits, "dfg", " --model ggx/smith-separable/one") == 1);  // the separable G loses energy there
    // a G whose limits are not derived, and E, refuse the edges (exit 2, the file named)
    check_refused("lut --check '" + (dir / "edges.csv").string() + "' --kind dfg --model ggx/schlick-ggx/one", "edges.csv: lut:");
    CHECK(check("0,0.5,0.5\n", "E") == 2);
}

TEST_CASE("verify lut --check FILE --junit: one test case per channel, a texel off fails it") {
    const auto dir = fresh_dir("lut-junit");
    REQUIRE(run("lut --kind dfg --size 4 --out '" + dir.string() + "'").status == 0);
    struct checked {
        std::string table;  // written by lut, or edited
        int status;
        const char* failures;
    };
    std::string csv = slurp(dir / "lut-dfg-4.csv");
    std::ofstream(dir / "edited.csv") << csv.substr(0, csv.find("\nlut,"))
                                      << "\nlut,dfg,ggx/smith-height-correlated/one,0.015625,0.125,0.125,0.5,0,0.1,0\n";
    const auto c = GENERATE(values<checked>({{"lut-dfg-4.csv", 0, "failures=\"0\""}, {"edited.csv", 1, "failures=\"1\""}}));
    const fs::path junit = dir / ("j-" + c.table + ".xml");
    const auto r = run("lut --check '" + (dir / c.table).string() + "' --kind dfg --junit '" + junit.string() + "'");
    CAPTURE(c.table, r.out);
    CHECK(r.status == c.status);
    CHECK(r.out.find("lut-check " + (dir / c.table).string() + " (csv), A: max |error|") != std::string::npos);
    const std::string xml = slurp(junit);
    CHECK(xml.find("<testsuite name=\"normzoo.lut-check\" tests=\"2\"") != std::string::npos);
    CHECK(xml.find(c.failures) != std::string::npos);
    fs::remove_all(dir);
}

// The sheen's E (docs/lut.md#sheen-tables): --kind sheen-E is E of charlie/charlie-sheen/one, the
// same value energy computes; the two sheen presets bake and check back; the composition takes
// the new parts and compensation as any other; charlie-sheen above its fit's alpha = 1 is exit 2.
TEST_CASE("verify lut --kind sheen-E and the sheen presets, and energy --model with the sheen parts") {
    const auto s = nlohmann::json::parse(run("lut --kind sheen-E --r 0.5 --mu 0.3 --json").out);
    REQUIRE(s["records"].size() == 1);
    const auto& sr = s["records"][0];
    CHECK((sr["kind"] == "E" && sr["model"] == "charlie/charlie-sheen/one"));
    const auto e = nlohmann::json::parse(run("energy --model charlie/charlie-sheen/one --r 0.5 --mu 0.3 --json").out);
    REQUIRE(e["records"].size() == 1);
    CHECK(std::abs(sr["E"].get<double>() - e["records"][0]["albedo"].get<double>()) <=
          sr["error_estimate"].get<double>() + e["records"][0]["error_estimate"].get<double>());
    const auto dir = normzoo_test::fresh_dir("lut-sheen");
    const std::string bin = NORMZOO_VERIFY_BIN;
    struct sheen_preset {
        const char *kind, *preset, *format;
    };
    for (const auto& [kind, preset, format] : {sheen_preset{"sheen-E", "gltf-sample-viewer-sheen", "exr"}, sheen_preset{"E", "filament-cloth", "exr-half"},
                                               sheen_preset{"E", "babylon-sheen", "png16"}}) {
        const std::string sub = (dir / preset).string();
        const auto w = run_shell(bin + " lut --kind " + kind + " --size 8 --preset " + preset + " --format " + format + " --out '" + sub + "' 2>&1");
        CAPTURE(preset, w.out);
        REQUIRE(w.status == 0);
        const auto file = fs::directory_iterator(sub)->path().string();
        const auto c = run_shell(bin + " lut --check '" + file + "' --kind " + kind + " --preset " + preset + " 2>&1");
        CAPTURE(c.out);
        CHECK(c.status == 0);
        // --detect finds the channel (the third, beside a split-sum pair) with the model given
        const auto d = run_shell(bin + " lut --check '" + file + "' --kind " + kind + " --detect --model charlie/" +
                                 (std::string(kind) == "E" ? "ashikhmin" : "charlie-sheen") + "/one 2>&1");
        CAPTURE(d.out);
        CHECK(d.status == 0);
        CHECK(d.out.find(std::string(kind) == "E" ? "channels=-,-,E," : "channels=E,") != std::string::npos);
    }
    // an 8-bit PNG cannot hold the cloth's E above 1 near grazing (1.41 at r = mu = 1/16): clamped, and said
    const auto clamped = run_shell(bin + " lut --kind E --model charlie/ashikhmin/one --size 8 --format png8 --out '" + (dir / "png8").string() + "' 2>&1");
    CAPTURE(clamped.out);
    CHECK(clamped.status == 0);
    CHECK(clamped.out.find("2 values beyond what --format png8 with encoding=linear holds are clamped (the largest 1.40") != std::string::npos);
    for (const char* model : {"charlie/neubelt/one", "charlie/ashikhmin/one", "ggx/smith-height-correlated/schlick/fdez-aguera"}) {
        const auto j = nlohmann::json::parse(run(std::string("energy --model ") + model + " --alpha 0.3 --mu 0.5 --json").out);
        REQUIRE(j["records"].size() == 1);
        CHECK(j["records"][0]["model"] == model);
        CHECK(j["records"][0]["error_estimate"].get<double>() <= 1e-10);
    }
    check_refused("energy --model charlie/charlie-sheen/one --alpha 2 --mu 1", "fitted Lambda");
}

// A check computes E and E_avg to a hundredth of each texel's tolerance (docs/lut.md, "How a check
// chooses its accuracy") and settles at 1e-10 a texel whose verdict the looser bound could flip:
// each value 5e-10 beyond --tolerance 0.05, above or below the exact value, fails; each 5e-10
// within it passes. At 5e-4 the exact values err by up to 1e-7 or so (the exact Fresnel factor):
// settled only beyond the tolerance, values below it pass wrongly.
TEST_CASE("verify lut --check: E and E_avg texels just beyond their tolerance fail, as at 1e-10") {
    const auto dir = normzoo_test::fresh_dir("lut-settle");
    const std::string model = " --model ggx/smith-separable/dielectric --eta 1.5";
    struct kind_case {
        const char *kind, *value, *points, *header;
    };
    const kind_case kinds[] = {{"E", "E", " --r 0.2,0.45 --mu 0.15,0.5", "mu,r,E\n"}, {"Eavg", "E_avg", " --r 0.2,0.45", "r,E_avg\n"}};
    const double tolerance = 0.05;
    for (const kind_case& k : kinds) {
        const auto exact = nlohmann::json::parse(run(std::string("lut --kind ") + k.kind + model + k.points + " --json").out)["records"];
        REQUIRE(exact.size() >= 2);
        for (const double shift : {tolerance + 5e-10, -(tolerance + 5e-10), tolerance - 5e-10, -(tolerance - 5e-10)}) {
            const bool beyond = std::abs(shift) > tolerance;
            std::ostringstream rows;
            rows.precision(17);
            rows << k.header;
            for (const auto& e : exact) {
                if (std::string(k.kind) == "E") rows << e["mu"].get<double>() << ",";
                rows << e["r"].get<double>() << "," << e[k.value].get<double>() + shift << "\n";
            }
            const auto file = dir / (std::string(k.kind) + (beyond ? "-beyond" : "-within") + (shift > 0 ? "-above.csv" : "-below.csv"));
            std::ofstream(file) << rows.str();
            const auto r = run("lut --check '" + file.string() + "' --kind " + k.kind + model + " --tolerance 0.05 --json");
            CAPTURE(k.kind, shift, rows.str(), r.out);
            const auto rec = nlohmann::json::parse(r.out)["records"][0];
            CHECK(rec["above_tolerance"].get<std::size_t>() == (beyond ? exact.size() : 0));
            CHECK(r.status == (beyond ? 1 : 0));
        }
    }
}

// The interface that transmits (docs/lut.md, "openpbr-bsdf-ideal-dielectric"): at eta = 1 its E is
// 1 / (1 + Lambda(V)) in closed form; a table of it is written and checked back, a texel moved
// by 1e-4 fails; where it is no table (the split-sum pair, Monte Carlo baking, a scene, another G)
// exit 2.
TEST_CASE("verify lut: the transmitting interface's E and E_avg, written and checked, refused where it is no table") {
    const std::string model = " --model ggx/smith-separable/dielectric/transmission";
    const auto one = nlohmann::json::parse(run("lut --kind E" + model + " --eta 1 --alpha 0.25 --mu 0.5 --json").out);
    REQUIRE(one["records"].size() == 1);
    const double lambda = (-1 + std::sqrt(1 + 0.0625 * 3)) / 2;  // alpha^2 tan^2 = 0.0625 x 0.75 / 0.25
    CHECK(std::abs(one["records"][0]["E"].get<double>() - 1 / (1 + lambda)) <= one["records"][0]["error_estimate"].get<double>());
    const auto dir = normzoo_test::fresh_dir("lut-transmission");
    const std::string bin = NORMZOO_VERIFY_BIN;
    // E below eta = 1 (total internal reflection), E_avg above it (a tenth of the time)
    for (const auto& [kind, eta] : {std::pair<std::string, std::string>{"E", " --eta 0.6667"}, {"Eavg", " --eta 1.5"}}) {
        const std::string sub = (dir / kind).string();
        const auto w = run_shell(bin + " lut --kind " + kind + model + eta + " --size 3 --format csv --out '" + sub + "' 2>&1");
        CAPTURE(kind, w.out);
        REQUIRE(w.status == 0);
        const fs::path file = fs::directory_iterator(sub)->path();
        const auto c = run_shell(bin + " lut --check '" + file.string() + "' --kind " + kind + model + eta + " 2>&1");
        CAPTURE(c.out);
        CHECK(c.status == 0);
        // the last row's value (before its bound) moved by 1e-4 fails
        std::string text = normzoo_test::slurp(file);
        const std::size_t bound = text.rfind(',', text.size() - 2), value = text.rfind(',', bound - 1) + 1;
        const double v = std::stod(text.substr(value, bound - value));
        char moved[64];
        std::snprintf(moved, sizeof moved, "%.17g", v + 1e-4);
        text.replace(value, bound - value, moved);
        std::ofstream(file, std::ios::binary) << text;
        const auto m = run_shell(bin + " lut --check '" + file.string() + "' --kind " + kind + model + eta + " 2>&1");
        CAPTURE(m.out);
        CHECK(m.status == 1);
    }
    check_refused("lut --kind dfg" + model + " --size 2", "the split-sum pair is a reflection's");
    // no index: F0's default 1 is a mirror; alpha above 1, where the integral was not made for
    check_refused("energy" + model + " --alpha 0.5 --mu 0.5", "needs the interface's index, --eta");
    check_refused("lut --kind E" + model + " --size 2", "needs the interface's index, --eta");
    check_refused("energy" + model + " --eta 1.5 --alpha 1.5 --mu 0.5", "alpha in (0, 1]");
    check_refused("lut --kind Eavg" + model + " --eta 1.5 --r 1.1", "alpha in (0, 1]");
    check_refused("lut --kind E" + model + " --size 2 --monte-carlo 64", "--monte-carlo");
    check_refused("lut --kind E --model ggx/smith-height-correlated/dielectric/transmission --size 2", "Smith's separable G");
    check_refused("--brdf /dev/null --theta 0 --against ggx/smith-separable/dielectric/transmission", "drop /transmission");
    check_scene_refused(dir, "model = \"ggx/smith-separable/dielectric/transmission\"\nr = [0.1, 0.5]\n", "a scene lights the reflection",
                        "microfacet-energy.md");
}
