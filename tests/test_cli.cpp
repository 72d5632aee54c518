// The command end to end: JSON on stdout, files in --out, exit statuses, and bad input that
// leaves the output folder untouched.
#include <catch2/catch.hpp>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <normzoo/version.hpp>
#include <normzoo/wide.hpp>

#include <boost/math/constants/constants.hpp>

#include "args.hpp"
#include "lut_fixtures.hpp"
#include "lut_formats/dds.hpp"
#include "lut_formats/ktx2.hpp"
#include "lut_image.hpp"
#include "temp_files.hpp"

namespace fs = std::filesystem;

namespace {
using normzoo_test::run_result;
using normzoo_test::run_shell;

run_result run(const std::string& args) {
    return run_shell(std::string(NORMZOO_VERIFY_BIN) + " " + args + " 2>/dev/null");
}

// The command with `args` exits 2, and its message names `named`.
void check_refused(const std::string& args, const std::string& named) {
    const auto b = run_shell(std::string(NORMZOO_VERIFY_BIN) + " " + args + " 2>&1");
    CAPTURE(args, b.out);
    CHECK(b.status == 2);
    CHECK(b.out.find(named) != std::string::npos);
}

// A scene in `dir` of one material `body` exits 2, its message names `named`, and `unwritten`
// (under dir/out) is not made.
void check_scene_refused(const fs::path& dir, const std::string& body, const std::string& named, const fs::path& unwritten) {
    std::ofstream(dir / "s.toml") << "[[materials]]\nname = \"m\"\n" << body;
    const auto b = run_shell(std::string(NORMZOO_VERIFY_BIN) + " --scene '" + (dir / "s.toml").string() + "' --out '" +
                             (dir / "out").string() + "' 2>&1");
    CAPTURE(body, b.out);
    CHECK(b.status == 2);
    CHECK(b.out.find(named) != std::string::npos);
    CHECK(!fs::exists(dir / "out" / unwritten));
}

// stdout and stderr together, run from `cwd` without NORMZOO_RESULTS_DIR: a default output
// folder lands in cwd, never in the project's results/.
run_result run_in(const fs::path& cwd, const std::string& args) {
    return run_shell("cd '" + cwd.string() + "' && env -u NORMZOO_RESULTS_DIR " + NORMZOO_VERIFY_BIN + " " + args +
                     " 2>&1");
}

// The lines of a text that begin with `prefix`.
std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.rfind(prefix, 0) == 0) out.push_back(line);
    return out;
}

std::string xml_unescaped(std::string s) {
    const std::pair<std::string, std::string> entities[] = {{"&quot;", "\""}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}};
    for (const auto& [from, to] : entities)
        for (std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size()))
            s.replace(p, from.size(), to);
    return s;
}

// The text of attribute `name` in the first element at or after `from`.
std::string xml_attribute(const std::string& xml, const std::string& name, std::size_t from) {
    const std::size_t at = xml.find(" " + name + "=\"", from);
    if (at == std::string::npos) return {};
    const std::size_t start = at + name.size() + 3;
    return xml_unescaped(xml.substr(start, xml.find('"', start) - start));
}

using normzoo_test::fresh_dir;
using normzoo_test::slurp;
}  // namespace

TEST_CASE("parameter lists") {
    const auto list = verify::parse_decimal_list("--n", "0,2.5,1e6,0.37", "0", "1e9");
    REQUIRE(list.size() == 4);
    CHECK(list[3].text() == "0.37");  // the input as typed, beside its value
    CHECK(list[3] == normzoo::decimal("37e-2"));
    CHECK(list[1].to<double>() == 2.5);
    // The bounds are compared exactly: a value just inside an open bound stays, whatever its double.
    CHECK(verify::parse_decimal_list("--theta", "89.99999999999999999999", "0", "90", true).size() == 1);
    CHECK_THROWS_AS(verify::parse_decimal_list("--theta", "90.000000000000000000001", "0", "90", false), verify::bad_input);
    const std::string bad = GENERATE("-1", "nan", "NaN", "abc", "1e400", "", "1,,2", "1,", ",1", "inf", "2x", "1 ", "1e-400",
                                     "2e9", "0x10", "1e", "1.2.3", "+", ".");
    CAPTURE(bad);
    CHECK_THROWS_AS(verify::parse_decimal_list("--n", bad, "0", "1e9"), verify::bad_input);
    try {
        verify::parse_decimal_list("--n", bad, "0", "1e9");
    } catch (const verify::bad_input& e) {
        CHECK(std::string(e.what()).find("--n") != std::string::npos);  // names the option
    }
}

TEST_CASE("counts: decimal digits only, in range") {
    CHECK(verify::parse_count("--seed", "0", 0, 10) == 0);
    CHECK(verify::parse_count("--seed", "18446744073709551615", 0, UINT64_MAX) == UINT64_MAX);
    const std::string bad = GENERATE("", "-1", "+1", "1e3", " 1", "1 ", "0x10", "11", "18446744073709551616");
    CAPTURE(bad);
    CHECK_THROWS_AS(verify::parse_count("--cases", bad, 1, 10), verify::bad_input);
}

TEST_CASE("verify zoo --json: one JSON document with the documented keys") {
    const auto dir = fresh_dir("json");
    const auto r = run("zoo --json --n 0,2.5,1e6 --out " + dir.string());
    REQUIRE(r.status == 0);
    const auto doc = nlohmann::json::parse(r.out);
    REQUIRE(doc.contains("records"));
    REQUIRE(doc["skipped"].is_array());
    int zoo = 0;
    for (const auto& rec : doc["records"]) {
        if (rec["table"] != "zoo") continue;
        ++zoo;
        for (const char* k : {"row", "n", "norm_quadrature", "norm_closed_form", "norm_quadrature_2d", "rel_error",
                              "error_estimate", "pass"})
            CHECK(rec.contains(k));
        CHECK(rec["norm_quadrature"].is_string());
        CHECK(rec["n"].is_number());
        CHECK(rec["pass"] == true);
        // >= 32 digits: the quadrature string and the closed form agree in their first 32.
        CHECK(rec["norm_quadrature"].get<std::string>().substr(0, 33) == rec["norm_closed_form"].get<std::string>().substr(0, 33));
    }
    CHECK(zoo == 1 + 6 * 3);
    for (const char* f : {"zoo.md", "zoo.csv", "zoo.json", "zoo-constants.md", "gloss-8bit.csv"}) CHECK(fs::exists(dir / f));
    fs::remove_all(dir);
}

TEST_CASE("verify shader-precision --json: both precisions of every formula, with the issue's keys") {
    const auto dir = fresh_dir("shader-precision");
    const auto r = run("shader-precision --json --out " + dir.string());
    REQUIRE(r.status == 0);
    const auto doc = nlohmann::json::parse(r.out);
    std::set<std::string> fp16, fp32;
    for (const auto& rec : doc["records"]) {
        REQUIRE(rec["table"] == "shader-precision");
        for (const char* k : {"precision", "formula", "max_rel_error", "at_n", "breaks_at_n", "breaks_because"})
            CHECK(rec.contains(k));
        CHECK(rec["max_rel_error"].is_number());
        CHECK((rec["breaks_at_n"].is_null() || rec["breaks_at_n"].is_number()));
        (rec["precision"] == "fp16" ? fp16 : fp32).insert(rec["formula"].get<std::string>());
        if (rec["formula"] == "blinn-phong-modified" && rec["precision"] == "fp16") CHECK(rec["breaks_at_n"] == 252.9375);
    }
    CHECK(fp16 == fp32);
    CHECK(fp16.size() >= 10);
    for (const char* f : {"shader-precision.md", "shader-precision.csv", "shader-precision.json", "shader-precision.svg"})
        CHECK(fs::exists(dir / f));
    fs::remove_all(dir);
}

TEST_CASE("verify energy --json: records with the documented keys, every table and plot written") {
    const auto dir = fresh_dir("energy");
    const auto r = run("energy --json --model lambert,phong-modified,minimalist-cook-torrance --n 1,16 --theta 0,45,89.99 --out " +
                       dir.string());
    REQUIRE(r.status == 0);
    const auto doc = nlohmann::json::parse(r.out);
    int energy = 0, summary = 0;
    for (const auto& rec : doc["records"]) {
        if (rec["table"] == "energy") {
            ++energy;
            for (const char* k : {"model", "parameter", "value", "theta_deg", "albedo", "error_estimate", "conserving"})
                CHECK(rec.contains(k));
            CHECK(rec["albedo"].is_number());
            CHECK(rec["conserving"].is_boolean());
        }
        if (rec["table"] == "energy-summary") {
            ++summary;
            for (const char* k : {"model", "parameter", "value", "max_albedo", "argmax_theta_deg", "conserving"})
                CHECK(rec.contains(k));
        }
    }
    CHECK(energy == 3 + 2 * 2 * 3);
    CHECK(summary == 1 + 2 * 2);
    for (const char* f : {"energy.md", "energy.csv", "energy.json", "energy-summary.md", "energy-claims.md",
                          "fresnel-visibility.csv", "fresnel-visibility-summary.md", "energy-montecarlo.json"})
        CHECK(fs::exists(dir / f));
    fs::remove_all(dir);
}

TEST_CASE("verify irradiance --json: records with the documented keys, values beyond a double as strings") {
    const auto dir = fresh_dir("irradiance");
    const auto r = run("irradiance --json --light sphere,disk --ratio 1e-1,1e-300 --tilt 0,89.9,95 --model lambert,phong --out " +
                       dir.string());
    REQUIRE(r.status == 0);
    const auto doc = nlohmann::json::parse(r.out);
    int irradiance = 0;
    for (const auto& rec : doc["records"]) {
        if (rec["table"] != "irradiance") continue;
        ++irradiance;
        for (const char* k : {"light", "ratio", "tilt_deg", "E_quadrature", "E_closed_form", "E_point", "rel_error"})
            CHECK(rec.contains(k));
        CHECK(rec["E_quadrature"].is_string());
        CHECK(rec["pass"] == true);
        // >= 30 digits at every ratio, 1e-300 included (E ~ 3e-600 is beyond a double: a string)
        CHECK(rec["E_quadrature"].get<std::string>().substr(0, 31) == rec["E_closed_form"].get<std::string>().substr(0, 31));
        if (rec["ratio"] == 1e-300 && rec["tilt_deg"] == 0) CHECK(rec["E_point"].get<std::string>().find("e-6") != std::string::npos);
    }
    CHECK(irradiance == 2 * 2 * 3);
    for (const char* f : {"irradiance.md", "irradiance-limit.csv", "punctual-limit.json", "irradiance-limit.svg"})
        CHECK(fs::exists(dir / f));
    CHECK(run("irradiance --light disk --ratio 2 --tilt 0 --model lambert --out " + dir.string()).status == 0);
    fs::remove_all(dir);
}

TEST_CASE("verify --scene: only what the scene needs, the rest under skipped") {
    const auto dir = fresh_dir("scene");
    const auto r = run("--scene " + std::string(NORMZOO_SOURCE_DIR) + "/scenes/single-material.toml --json --out " + dir.string());
    REQUIRE(r.status == 0);
    const auto doc = nlohmann::json::parse(r.out);
    std::set<std::string> tables;
    for (const auto& rec : doc["records"]) tables.insert(rec["table"].get<std::string>());
    CHECK(tables == std::set<std::string>{"zoo", "energy", "energy-summary", "shader-normalization"});
    bool bounds_skipped = false, irradiance_skipped = false;
    for (const auto& k : doc["skipped"]) {
        CHECK(k.contains("reason"));
        bounds_skipped = bounds_skipped || k["table"] == "bounds";
        irradiance_skipped = irradiance_skipped || k["table"] == "irradiance";
    }
    CHECK(bounds_skipped);
    CHECK(irradiance_skipped);
    for (const auto& rec : doc["records"])
        if (rec["table"] == "shader-normalization") {
            for (const char* k : {"material", "model", "expression", "max_rel_error", "at_n", "max_albedo", "conserving"})
                CHECK(rec.contains(k));
            CHECK(std::abs(rec["max_rel_error"].get<double>()) < 1e-15);
        }
    // The (n+8)/(8 pi) scene fails on purpose: 7.5 % off and gaining energy.
    CHECK(run("--scene " + std::string(NORMZOO_SOURCE_DIR) + "/scenes/rtr-approximation.toml --out " + dir.string()).status == 1);
    fs::remove_all(dir);
}

TEST_CASE("bad scenes: exit 2, the message names the file, the line and the key, nothing written") {
    struct bad {
        const char* toml;
        const char* key;  // must appear in the message with the line
        int line;
    };
    const auto b = GENERATE(values<bad>({
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\nexponent = [1, 2\n", "malformed TOML", 4},
        {"[[materials]]\nname = 'a'\nmodel = 'phnog'\nexponent = [1, 2]\n", "materials[1].model", 3},
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\nexponent = [1, 2]\ncolour = 3\n", "materials[1].colour", 5},
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\nexponent = []\n", "materials[1].exponent", 4},
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\nexponent = [5, 2]\n", "materials[1].exponent", 4},
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\nexponent = [1, 2]\nnormalization = '(n+1/(2*pi)'\n", "materials[1].normalization", 5},
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\nexponent = [1, 2]\nnormalization = '(n+1)/(2*tau)'\n", "materials[1].normalization", 5},
        {"[[lights]]\nname = 's'\ntype = 'sphere'\nradius = -1.0\ndistance = 1.0\n", "lights[1].radius", 4},
        {"[[lights]]\nname = 's'\ntype = 'sphere'\nradius = 2.0\ndistance = 1.0\n", "lights[1].radius", 4},
        {"[[lights]]\nname = 's'\ntype = 'lamp'\nradius = 0.1\ndistance = 1.0\n", "lights[1].type", 3},
        {"[tolerance]\ndigits = 40\n", "tolerance.digits", 2},
        {"[tolerance]\nalbedo = 1.0\n", "tolerance.albedo: must be in", 2},
        {"[tolerance]\nnormalization = 0.0\n", "tolerance.normalization: must be > 0", 2},
        {"[tolerance]\nallow_energy_gain = 1\n", "tolerance.allow_energy_gain: must be true or false", 2},
        {"[scene]\nname = 7\n", "scene.name: must be a string", 2},
        {"[scene]\nname = \"a\\tb\"\n", "scene.name: must not hold control characters", 2},
        {"[[materials]]\nname = ''\nmodel = 'phong'\nexponent = [1, 2]\n", "materials[1].name: must not be empty", 2},
        {"[[lights]]\nname = 's'\ntype = 'disk'\nradius = 1.0\ndistance = 1.0\n[[lights]]\nname = 's'\ntype = 'disk'\n"
         "radius = 2.0\ndistance = 1.0\n",
         "lights[2].name: 's' names two lights", 7},
        {"[scene]\nname = '\xff'\n", "byte 0xff is not ASCII", 2},
        {"x = 1\nlights \xc8\xa0[1, 2]\n", "byte 0xc8 is not ASCII", 2},       // fuzz/corpus/scene/finding-toml-unreachable-*
        {"s = \"\"\"\\\n\xc2\xa7\"\"\"\n", "byte 0xc2 is not ASCII", 2},  // toml++ issue #190
        {"colour = 1\n", "colour: unknown key", 1},
        {"materials = 3\n", "materials: must be an array of tables", 1},
        {"", "the scene has no materials and no lights", 1},
        {"[[materials]]\nmodel = 'phong'\nexponent = [1, 2]\n", "materials[1]: missing key 'name'", 1},
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\nexponent = [1, 2]\ngloss = [0, 1]\n", "materials[1]: give exactly one", 1},
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\nexponent = 'big'\n", "materials[1].exponent: must be a range", 4},
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\nexponent = [nan, inf]\n", "materials[1].exponent: must be a finite number", 4},
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\nexponent = [1, 2e9]\n", "materials[1].exponent: exponents must be in", 4},
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\ngloss = [0, 2]\n", "materials[1].gloss: gloss must be in", 4},
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\ngloss = [0, 1]\nspecular = 2.0\n", "materials[1].specular", 5},
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\nexponent = [1, 2]\nnormalization = 'n/0'\n", "materials[1].normalization: the expression 'n/0' is inf", 5},
        {"[[materials]]\nname = 'a'\nmodel = 'phong'\nexponent = [0, 2]\nnormalization = 'sqrt(n-1)'\n", "materials[1].normalization: the expression 'sqrt(n-1)' is", 5},
        {"[[lights]]\nname = 'd'\ntype = 'disk'\nradius = 1.0\n", "lights[1]: missing key 'distance'", 1},
        {"[[lights]]\nname = 'd'\ntype = 'disk'\nradius = 1e300\ndistance = 1e-300\n", "lights[1].radius: radius / distance = inf", 4},
        {"[[lights]]\nname = 'd'\ntype = 'disk'\nradius = 1e-300\ndistance = 1e300\n", "lights[1].radius: radius / distance = 0", 4},
        {"[[lights]]\nname = 'd'\ntype = 'disk'\nradius = 1.0\ndistance = 1.0\ntilt_deg = [0.0, 200.0]\n", "lights[1].tilt_deg", 6},
    }));
    const auto dir = fresh_dir("badscene");
    const fs::path file = dir / "scene.toml";
    std::ofstream(file) << b.toml;
    const auto out = dir / "out";
    fs::create_directories(out);
    const std::string cmd = std::string(NORMZOO_VERIFY_BIN) + " --scene " + file.string() + " --out " + out.string() + " 2>&1 >/dev/null";
    const auto [status, err] = run_shell(cmd);
    CAPTURE(b.toml, err);
    CHECK(status == 2);
    CHECK(err.find(file.string() + ":" + std::to_string(b.line)) != std::string::npos);
    CHECK(err.find(b.key) != std::string::npos);
    CHECK(fs::is_empty(out));
    fs::remove_all(dir);
}

TEST_CASE("check: a hand edit beyond the error bound is reported and exits 1, and the JUnit XML shows it") {
    const auto dir = fresh_dir("check");
    REQUIRE(run("zoo --n 1,8 --out " + dir.string()).status == 0);
    CHECK(run("zoo --n 1,8 --check --out " + dir.string()).status == 0);
    // Change the 31st digit of one normalization: far beyond its bound of ~1e-33.
    std::string js = slurp(dir / "zoo.json");
    const std::string key = "\"norm_quadrature\":\"";
    const std::size_t at = js.find(key, js.find("\"row\":\"phong\"")) + key.size() + 31;
    js[at] = js[at] == '9' ? '8' : static_cast<char>(js[at] + 1);
    std::ofstream(dir / "zoo.json", std::ios::binary) << js;
    const auto before = fs::last_write_time(dir / "zoo.md");
    const auto r = run("zoo --n 1,8 --check --junit " + (dir / "junit.xml").string() + " --out " + dir.string());
    CHECK(r.status == 1);
    CHECK(r.out.find("zoo: DIFFERS") != std::string::npos);
    CHECK(r.out.find("norm_quadrature") != std::string::npos);
    CHECK(fs::last_write_time(dir / "zoo.md") == before);  // --check writes no table
    const std::string xml = slurp(dir / "junit.xml");
    CHECK(xml.find("<testsuite name=\"normzoo.check\"") != std::string::npos);
    CHECK(xml.find("<failure") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("junit: one test case per check record") {
    const auto dir = fresh_dir("junit");
    const auto r = run("zoo --n 1,8 --json --junit " + (dir / "j.xml").string() + " --out " + dir.string());
    REQUIRE(r.status == 0);
    std::size_t checks = 0;
    const auto doc = nlohmann::json::parse(r.out);
    for (const auto& rec : doc["records"]) checks += rec.contains("pass");
    const std::string xml = slurp(dir / "j.xml");
    std::size_t cases = 0;
    for (std::size_t p = xml.find("<testcase"); p != std::string::npos; p = xml.find("<testcase", p + 1)) ++cases;
    CHECK(checks >= 13);
    CHECK(cases == checks);
    CHECK(xml.find("<failure") == std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("reruns write byte-identical tables") {
    const auto dir = fresh_dir("rerun");
    REQUIRE(run("zoo bounds --n 1,1e7 --out " + dir.string()).status == 0);
    const std::string md = slurp(dir / "zoo.md"), csv = slurp(dir / "bounds.csv"), js = slurp(dir / "zoo.json");
    REQUIRE(run("zoo bounds --n 1,1e7 --jobs 1 --out " + dir.string()).status == 0);
    CHECK(slurp(dir / "zoo.md") == md);
    CHECK(slurp(dir / "bounds.csv") == csv);
    CHECK(slurp(dir / "zoo.json") == js);
    fs::remove_all(dir);
}

TEST_CASE("bad input: exit 2, a message naming what is wrong, and the output folder untouched") {
    struct bad {
        const char* args;
        const char* named;  // the message must contain it: the option, the value or the key
    };
    const auto b = GENERATE(values<bad>({
        {"zoo --n -1", "--n: bad value '-1'"}, {"zoo --n nan", "--n: bad value 'nan'"}, {"zoo --n abc", "'abc'"},
        {"zoo --n 1e400", "'1e400'"}, {"zoo --n 1,,2", "empty item"}, {"zoo --n ''", "--n"}, {"bounds --n 1,", "--n"},
        {"zoo --n 1e-310", "underflow"}, {"zoo --n ' 1'", "white space"},
        {"nosuchtable", "unknown table 'nosuchtable'"}, {"zoo --frobnicate", "--frobnicate"}, {"--jobs 0", "--jobs"},
        {"--jobs x", "--jobs"}, {"--jobs 257", "--jobs"}, {"zoo --n", "--n"}, {"zoo --n 1 --n 2", "--n"},
        {"energy --model nosuchmodel", "--model: unknown name 'nosuchmodel'"}, {"energy --model lambert,", "--model"},
        {"energy --theta 90", "--theta: bad value '90'"}, {"energy --theta -1", "--theta"}, {"energy --theta nan", "--theta"},
        {"energy --theta 91", "--theta"}, {"energy --theta ''", "--theta"}, {"energy --n -1", "--n"},
        {"energy --n NaN", "'NaN'"}, {"energy --theta 45,89.99,90", "'90'"}, {"irradiance --ratio 0", "--ratio"},
        {"irradiance --ratio -1e-3", "--ratio"}, {"irradiance --ratio nan", "--ratio"}, {"irradiance --ratio 1", "--ratio"},
        {"irradiance --light sphere --ratio 1.5", "--ratio: bad value '1.5'"}, {"irradiance --light disk --ratio 1e101", "--ratio"},
        {"irradiance --tilt 181", "--tilt"}, {"irradiance --tilt -1", "--tilt"}, {"irradiance --tilt nan", "--tilt"},
        {"irradiance --light lamp", "--light: unknown name 'lamp'"}, {"irradiance --ratio 1e-400", "--ratio"},
        {"--scene ''", "--scene: the path is empty"}, {"zoo --junit ''", "--junit: the path is empty"},
        {"--scene nosuch.toml", "nosuch.toml: cannot read the scene"}, {"--scene .", ".: cannot read the scene"},
        {"--scene x.toml zoo", "tables are not named with --scene"}, {"--scene x.toml --n 1", "--n does not go with --scene"},
        {"--scene x.toml --light disk", "--light does not go with --scene"},
    }));
    const auto dir = fresh_dir("bad");
    std::ofstream(dir / "zoo.md") << "committed table\n";
    const std::string cmd = std::string(NORMZOO_VERIFY_BIN) + " " + b.args + " --out " + dir.string() + " 2>&1 >/dev/null";
    const auto [status, err] = run_shell(cmd);
    CAPTURE(b.args, err);
    CHECK(status == 2);
    CHECK(err.rfind("verify: ", 0) == 0);
    CHECK(err.find(b.named) != std::string::npos);
    CHECK(slurp(dir / "zoo.md") == "committed table\n");
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 1);
    fs::remove_all(dir);
}

TEST_CASE("verify audit: only when named, and a small audit writes its tables and plot and passes") {
    const auto dir = fresh_dir("audit");
    const auto r = run("audit --cases 120 --seed 3 --json --out " + dir.string());
    REQUIRE(r.status == 0);
    const auto doc = nlohmann::json::parse(r.out);
    int summaries = 0;
    for (const auto& rec : doc["records"]) {
        if (rec["table"] != "error-audit") continue;
        ++summaries;
        for (const char* k : {"family", "number_type", "cases", "exact", "failures", "min_ratio", "ratio_q01",
                              "ratio_q50", "ratio_q99", "max_ratio", "max_pessimism", "pessimistic", "pass"})
            CHECK(rec.contains(k));
        CHECK(rec["pass"] == true);
    }
    CHECK(summaries == 8);
    for (const char* f : {"error-audit.md", "error-audit.csv", "error-audit.json", "error-audit-histogram.csv",
                          "error-audit-extremes.md", "error-audit.svg"})
        CHECK(fs::exists(dir / f));
    CHECK(slurp(dir / "error-audit.md").find("seed 3") != std::string::npos);
    const std::string help = run("--help").out;
    CHECK(help.find("audit") != std::string::npos);
    for (const char* bad : {"audit --cases 0", "audit --cases -5", "audit --cases x", "audit --cases 1e4",
                            "audit --cases 20000000", "audit --seed -1", "audit --seed x", "audit --seed ''",
                            "audit --seed 18446744073709551616"}) {
        CAPTURE(bad);
        CHECK(run(std::string(bad) + " --out " + dir.string()).status == 2);
    }
    fs::remove_all(dir);
}

TEST_CASE("the library's version is the project's") { CHECK(std::string(NORMZOO_VERSION) == NORMZOO_PROJECT_VERSION); }

TEST_CASE("the committed results/ were produced by this version's tables") {
    // Every committed JSON table names the normzoo version that wrote it.
    const fs::path results = fs::path(NORMZOO_SOURCE_DIR) / "results";
    for (const char* name : {"zoo.json", "bounds.json", "zoo-constants.json", "energy.json", "energy-summary.json"}) {
        CAPTURE(name);
        REQUIRE(fs::exists(results / name));
        const auto doc = nlohmann::json::parse(slurp(results / name));
        CHECK(doc["normzoo"] == NORMZOO_VERSION);
    }
}

TEST_CASE("verify proofs enclosures --json: the claims proved, the controls refuted, the enclosures hold") {
    const auto dir = fresh_dir("certify");
    const auto r = run("proofs enclosures --n 0.5,2048 --json --out " + dir.string());
    REQUIRE(r.status == 0);
    const auto doc = nlohmann::json::parse(r.out);
    std::size_t proofs = 0, enclosures = 0;
    for (const auto& rec : doc["records"]) {
        CHECK(rec["pass"] == true);
        CHECK(rec["seconds"].is_number());
        if (rec["table"] == "proofs") {
            ++proofs;
            for (const char* k : {"claim", "method", "boxes", "max_depth", "smallest_box", "result"}) CHECK(rec.contains(k));
            CHECK(rec["result"].get<std::string>().rfind(rec["expected"].get<std::string>(), 0) == 0);
        } else {
            REQUIRE(rec["table"] == "enclosures");
            ++enclosures;
            CHECK(rec["enclosure_mid"].is_string());
            CHECK(rec["closed_form_inside"] == true);
            CHECK(rec["quadrature_inside"] == true);
        }
    }
    CHECK(proofs == 8);
    CHECK(enclosures == 1 + 6 * 2);  // lambert once, the six rows with an exponent at two n
    for (const char* f : {"proofs.md", "proofs.csv", "proofs.json", "enclosures.md", "enclosures.csv", "enclosures.json"})
        CHECK(fs::exists(dir / f));
    fs::remove_all(dir);
}

TEST_CASE("an option's value that is itself an option is refused: exit 2, both named, nothing written") {
    struct bad {
        const char* args;
        const char* named;
    };
    const auto b = GENERATE(values<bad>({
        {"zoo --n 1 --out --json", "--out: missing its value ('--json'"},
        {"--out --json", "--out: missing its value ('--json'"},
        {"zoo --n 1 --out -h", "--out: missing its value ('-h'"},
        {"zoo --n 1 --out --check", "--out: missing its value ('--check'"},
        {"zoo --n 1 --out results --junit --json", "--junit: missing its value ('--json'"},
        {"zoo --n 1 --out results --junit --out", "--junit: missing its value ('--out'"},
        {"audit --seed --json --out results", "--seed: missing its value ('--json'"},
    }));
    const auto dir = fresh_dir("option-value");
    const auto r = run_in(dir, b.args);
    CAPTURE(b.args, r.out);
    CHECK(r.status == 2);
    CHECK(r.out.rfind("verify: ", 0) == 0);
    CHECK(r.out.find(b.named) != std::string::npos);
    CHECK(fs::is_empty(dir));  // no folder named "--json", no results/
    fs::remove_all(dir);
}

TEST_CASE("an output path that cannot be written is bad input: exit 2, the path named, nothing written") {
    const auto dir = fresh_dir("unwritable");
    std::ofstream(dir / "file") << "not a folder\n";
    const std::string out = " --out " + (dir / "out").string();
    struct bad {
        std::string args, named;
    };
    const auto b = GENERATE_COPY(values<bad>({
        {"zoo --n 1 --out /proc/normzoo-out", "--out: '/proc/normzoo-out'"},
        {"zoo --n 1 --out " + (dir / "file" / "sub").string(), "--out: '" + (dir / "file" / "sub").string() + "'"},
        {"zoo --n 1 --out " + (dir / "file").string(), "is not a folder"},
        {"zoo --n 1 --junit /proc/normzoo-out/j.xml" + out, "--junit: '/proc/normzoo-out/j.xml'"},
        {"zoo --n 1 --junit " + (dir / "nosuch" / "j.xml").string() + out, (dir / "nosuch" / "j.xml").string()},
        {"zoo --n 1 --junit " + dir.string() + out, "--junit: '" + dir.string() + "' is a folder"},
    }));
    const auto r = run_in(dir, b.args);
    CAPTURE(b.args, r.out);
    CHECK(r.status == 2);
    CHECK(r.out.rfind("verify: ", 0) == 0);
    CHECK(r.out.find(b.named) != std::string::npos);
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 1);  // only "file"
    CHECK(slurp(dir / "file") == "not a folder\n");
    CHECK(!fs::exists("/proc/normzoo-out"));
    fs::remove_all(dir);
}

TEST_CASE("verify --scene: the bounds of the Blinn-Phong rows its materials use, and no other") {
    const auto dir = fresh_dir("scene-bounds");
    // rtr-approximation.toml: one material, blinn-phong-modified over [1, 256]
    const auto r = run("--scene " + std::string(NORMZOO_SOURCE_DIR) + "/scenes/rtr-approximation.toml --json --out " +
                       dir.string());
    REQUIRE(r.status == 1);
    const auto doc = nlohmann::json::parse(r.out);
    std::size_t bounds = 0;
    for (const auto& rec : doc["records"])
        if (rec["table"] == "bounds") {
            ++bounds;
            CHECK(rec["row"] == "blinn-phong-modified");
            CHECK(rec["n"].get<double>() >= 1);
            CHECK(rec["n"].get<double>() <= 256);
        }
    CHECK(bounds > 2);
    bool skipped = false;
    for (const auto& k : doc["skipped"]) skipped = skipped || k["table"] == "bounds: blinn-phong";
    CHECK(skipped);
    fs::remove_all(dir);
}

TEST_CASE("a failing check says why on the console: one line per record, at most 20 per table") {
    const auto dir = fresh_dir("verdicts");
    const auto r = run("--scene " + std::string(NORMZOO_SOURCE_DIR) + "/scenes/rtr-approximation.toml --out " + dir.string());
    CHECK(r.status == 1);
    const auto lines = lines_starting(r.out, "  shader-normalization: ");
    REQUIRE(lines.size() == 1);
    CAPTURE(lines[0]);
    CHECK(lines[0].find("material \"plastic\" (blinn-phong-modified, n in [1, 256], (n+8)/(8*pi))") != std::string::npos);
    CHECK(lines[0].find("relative error") != std::string::npos);
    CHECK(lines[0].find("above the tolerance 0.001") != std::string::npos);
    CHECK(lines[0].find("gains energy") != std::string::npos);

    // Two forms that gain energy at every exponent: 28 failing summaries, 20 lines and the count of the rest.
    const fs::path scene = dir / "gains.toml";
    std::ofstream(scene) << "[[materials]]\nname = 'p'\nmodel = 'phong'\nexponent = [1.0, 1e5]\n"
                            "[[materials]]\nname = 'm'\nmodel = 'minimalist-cook-torrance'\nexponent = [1.0, 1e5]\n";
    const auto g = run("--scene " + scene.string() + " --out " + (dir / "out").string());
    CHECK(g.status == 1);
    const auto head = lines_starting(g.out, "energy-summary: ");
    REQUIRE(head.size() == 1);
    const std::size_t failing = std::stoul(head[0].substr(head[0].find("records, ") + 9));
    CAPTURE(g.out);
    REQUIRE(failing > 20);
    const auto shown = lines_starting(g.out, "  energy-summary: material ");
    CHECK(shown.size() == 20);
    for (const auto& l : shown) CHECK(l.find("gains energy, which the scene does not allow") != std::string::npos);
    CHECK(lines_starting(g.out, "  ... and " + std::to_string(failing - 20) + " more failing energy-summary").size() == 1);
    fs::remove_all(dir);
}

TEST_CASE("junit: test names from ids and inputs only, a failure keeps its whole verdict, the scene names its suites") {
    const auto dir = fresh_dir("junit-names");
    REQUIRE(run("zoo --n 1,8 --junit " + (dir / "j.xml").string() + " --out " + dir.string()).status == 0);
    const std::string xml = slurp(dir / "j.xml");
    std::set<std::string> names;
    for (std::size_t p = xml.find("<testcase"); p != std::string::npos; p = xml.find("<testcase", p + 1))
        if (xml_attribute(xml, "classname", p) == "normzoo.zoo") names.insert(xml_attribute(xml, "name", p));
    std::set<std::string> expected{"row = lambert, n = 0"};
    for (const char* row : {"phong", "phong-modified", "blinn-phong", "blinn-phong-modified", "blinn-phong-heightfield",
                            "blinn-phong-ndf"})
        for (const char* n : {"1", "8"}) expected.insert(std::string("row = ") + row + ", n = " + n);
    CAPTURE(xml.substr(0, 2000));
    CHECK(names == expected);  // no computed value in a name

    // compositions (the white furnace of a compensated one is a check): named by their inputs as
    // typed, one name per (model, roughness, incidence)
    REQUIRE(run("energy --model ggx/smith-height-correlated/one/turquin --alpha 0.3,0.5 --mu 0.5,1 --json --junit " +
                (dir / "c.xml").string()).status == 0);
    const std::string cx = slurp(dir / "c.xml");
    std::set<std::string> composition_names;
    for (std::size_t p = cx.find("<testcase"); p != std::string::npos; p = cx.find("<testcase", p + 1))
        composition_names.insert(xml_attribute(cx, "name", p));
    std::set<std::string> composition_expected;
    for (const char* alpha : {"0.3", "0.5"})
        for (const char* mu : {"0.5", "1"})
            composition_expected.insert(std::string("model = ggx/smith-height-correlated/one/turquin, alpha_input = ") + alpha +
                                        ", mu_input = " + mu);  // no f0: no part of it reads one
    CAPTURE(cx.substr(0, 2000));
    CHECK(composition_names == composition_expected);

    const auto r = run("--scene " + std::string(NORMZOO_SOURCE_DIR) + "/scenes/rtr-approximation.toml --junit " +
                       (dir / "scene.xml").string() + " --out " + (dir / "scene").string());
    REQUIRE(r.status == 1);
    const auto lines = lines_starting(r.out, "  shader-normalization: ");
    REQUIRE(lines.size() == 1);
    const std::string verdict = lines[0].substr(2);
    const std::string sx = slurp(dir / "scene.xml");
    CAPTURE(sx);
    CHECK(sx.find("<testsuite name=\"normzoo.(n+8)/(8 pi) shader.shader-normalization\"") != std::string::npos);
    const std::size_t f = sx.find("<failure");
    REQUIRE(f != std::string::npos);
    const std::string message = xml_attribute(sx, "message", f);
    const std::size_t body = sx.find('>', f) + 1;
    CHECK(xml_unescaped(sx.substr(body, sx.find("</failure>", f) - body)).find(verdict) != std::string::npos);
    // The message is the verdict, or its start cut between words.
    if (message != verdict) {
        REQUIRE(message.size() > 4);
        REQUIRE(message.compare(message.size() - 4, 4, " ...") == 0);
        const std::string kept = message.substr(0, message.size() - 4);
        CHECK(verdict.rfind(kept, 0) == 0);
        CHECK(verdict[kept.size()] == ' ');
    }
    fs::remove_all(dir);
}

namespace {
// The command with its stderr after its stdout, and NORMZOO_RESULTS_DIR set when `results` is
// given (as ./verify sets it to the checkout's results/).
run_result run_with_stderr(const std::string& args, const fs::path& results = {}) {
    const std::string env = results.empty() ? std::string() : "NORMZOO_RESULTS_DIR='" + results.string() + "' ";
    return run_shell(env + NORMZOO_VERIFY_BIN + " " + args + " 2>&1");
}

// Every file under `dir` by its path relative to it, with its bytes.
std::map<std::string, std::string> tree(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = slurp(e.path());
    return files;
}

// The files added, removed or changed from `before` to `after`.
std::vector<std::string> changed(const std::map<std::string, std::string>& before,
                                 const std::map<std::string, std::string>& after) {
    std::vector<std::string> names;
    for (const auto& [name, text] : after)
        if (!before.count(name) || before.at(name) != text) names.push_back(name);
    for (const auto& [name, text] : before)
        if (!after.count(name)) names.push_back(name + " (removed)");
    return names;
}
}  // namespace

TEST_CASE("check: a number or a word edited in the Markdown, the CSV or the JSON's head fails, naming the file") {
    struct edit {
        const char* file;
        const char* from;
        const char* to;
    };
    const auto e = GENERATE(values<edit>({
        // phong at n = 8, 7 % off: the file people cite, and the one programs read
        {"zoo.md", "| 1.432394487827058021919953870352630e+00 |", "| 1.532394487827058021919953870352630e+00 |"},
        {"zoo.csv", ",1.432394487827058021919953870352630e+00,", ",1.532394487827058021919953870352630e+00,"},
        {"zoo.csv", "phong,8.0,", "phong,8,"},  // the same number written otherwise
        {"zoo.md", "| phong | 8 |", "| Phong | 8 |"},
        {"zoo.csv", "# 1D: reduced integrand", "# 1D: reduced integral"},
        {"zoo-constants.md", "Produced by normzoo", "Made by normzoo"},
        {"gloss-8bit.csv", "\ngloss-8bit,", "\ngloss-8-bit,"},
        {"zoo.json", "\"title\": \"The normalization zoo", "\"title\": \"The normalisation zoo"},
    }));
    CAPTURE(e.file, e.from);
    const auto dir = fresh_dir("check-formats");
    REQUIRE(run("zoo --n 1,8 --out " + dir.string()).status == 0);
    REQUIRE(run("zoo --n 1,8 --check --out " + dir.string()).status == 0);
    std::string text = slurp(dir / e.file);
    const std::size_t at = text.find(e.from);
    REQUIRE(at != std::string::npos);
    text.replace(at, std::string(e.from).size(), e.to);
    std::ofstream(dir / e.file, std::ios::binary) << text;
    const auto r = run_with_stderr("zoo --n 1,8 --check --out " + dir.string());
    CAPTURE(r.out);
    CHECK(r.status == 1);
    CHECK(r.out.find("DIFFERS") != std::string::npos);
    CHECK(r.out.find((dir / e.file).string() + ":") != std::string::npos);  // FILE:LINE:COLUMN
    fs::remove_all(dir);
}

TEST_CASE("check: a value moved within its error bound in every file alike still matches") {
    // What another platform may compute: phong at n = 8 one unit off in its 34th digit (bound ~6e-33).
    const auto dir = fresh_dir("check-within");
    REQUIRE(run("zoo --n 1,8 --out " + dir.string()).status == 0);
    for (const char* file : {"zoo.json", "zoo.md", "zoo.csv"}) {
        std::string text = slurp(dir / file);
        const std::string from = "1.432394487827058021919953870352630e+00";
        const std::size_t at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), "1.432394487827058021919953870352631e+00");
        std::ofstream(dir / file, std::ios::binary) << text;
    }
    const auto r = run_with_stderr("zoo --n 1,8 --check --out " + dir.string());
    CAPTURE(r.out);
    CHECK(r.status == 0);
    CHECK(r.out.find("zoo: matches") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("check: the figures a checked table draws are compared byte for byte") {
    const auto dir = fresh_dir("check-figure");
    REQUIRE(run("bounds --n 1,1e7 --out " + dir.string()).status == 0);
    if (!fs::exists(dir / "bounds.svg")) {
        WARN("gnuplot is missing: no figure to compare");
        return;
    }
    const auto ok = run_with_stderr("bounds --n 1,1e7 --check --out " + dir.string());
    CAPTURE(ok.out);
    REQUIRE(ok.status == 0);
    CHECK(ok.out.find("bounds.svg") != std::string::npos);  // named among the files compared
    std::string svg = slurp(dir / "bounds.svg");
    const std::size_t at = svg.find("<title>Gnuplot</title>");
    REQUIRE(at != std::string::npos);
    svg.replace(at, 22, "<title>gnuplot</title>");
    std::ofstream(dir / "bounds.svg", std::ios::binary) << svg;
    const auto r = run_with_stderr("bounds --n 1,1e7 --check --out " + dir.string());
    CAPTURE(r.out);
    CHECK(r.status == 1);
    CHECK(r.out.find((dir / "bounds.svg").string() + ":") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("runs on custom grids and --json leave results/ and the docs alone, a canonical run writes them") {
    // A copy of the project's results and docs: ./verify names its results/ by NORMZOO_RESULTS_DIR
    // and refreshes the docs beside it.
    const auto root = fresh_dir("project");
    const fs::path source(NORMZOO_SOURCE_DIR);
    fs::copy(source / "results", root / "results", fs::copy_options::recursive);
    fs::copy(source / "docs", root / "docs", fs::copy_options::recursive);
    fs::copy_file(source / "README.md", root / "README.md");
    const auto results = root / "results";
    const auto before = tree(root);
    for (const char* args : {"zoo --n 3,0.37", "zoo --n 3 --json", "zoo --json", "bounds --n 2",
                             "energy --model lambert --theta 0,45", "audit --cases 40 --seed 3"}) {
        CAPTURE(args);
        const auto r = run_with_stderr(args, results);
        CAPTURE(r.out);
        CHECK(r.status == 0);
        CHECK(r.out.find("nothing written") != std::string::npos);
        CHECK(r.out.find("--out DIR") != std::string::npos);
        CHECK(changed(before, tree(root)).empty());
    }
    // Named as --out, the project's results/ still takes no custom grid: exit 2 before any work.
    const auto refused = run_with_stderr("zoo --n 3 --out " + results.string(), results);
    CAPTURE(refused.out);
    CHECK(refused.status == 2);
    CHECK(refused.out.find("--n") != std::string::npos);
    CHECK(changed(before, tree(root)).empty());
    // On its canonical grid a table is written to results/.
    fs::remove(results / "zoo.csv");
    CHECK(run_with_stderr("zoo", results).status == 0);
    CHECK(fs::exists(results / "zoo.csv"));
    fs::remove_all(root);
}

TEST_CASE("progress: a line rewritten on a terminal's stderr, nothing of it in a pipe or a file or with --json") {
    // Long enough (with one thread) that a terminal shows the line: it appears after a second.
    const std::string audit = std::string(NORMZOO_VERIFY_BIN) + " audit --cases 5000 --jobs 1";
    const auto dir = fresh_dir("progress");
    const auto err = dir / "stderr.txt";
    // stderr a file, stdout a pipe: no carriage return, no progress text.
    const auto r = run_shell(audit + " 2>'" + err.string() + "'");
    CHECK(r.status == 0);
    const std::string text = slurp(err);
    CHECK(text.find('\r') == std::string::npos);
    CHECK(text.find(" left") == std::string::npos);
    CHECK(text.find("verify: audit ") == std::string::npos);
    CHECK(r.out.find('\r') == std::string::npos);
    // A terminal, through script(1) (util-linux), when it is there: the line shows, counting cases,
    // and is cleared; with --json it does not.
    if (run_shell("command -v script >/dev/null 2>&1").status == 0) {
        const auto pty = run_shell("script -qec '" + audit + "' /dev/null");
        CHECK(pty.status == 0);
        CHECK(pty.out.find("\rverify: audit ") != std::string::npos);
        CHECK(pty.out.find(" cases") != std::string::npos);
        CHECK(pty.out.find("/5,0") != std::string::npos);  // "1,234/5,0xx cases": thousands separated
        const auto json = run_shell("script -qec '" + audit + " --json' /dev/null");
        CHECK(json.status == 0);
        CHECK(json.out.find("\rverify: audit ") == std::string::npos);
        CHECK(json.out.find(" left") == std::string::npos);
    } else {
        WARN("script(1) is not installed: the terminal half of this test is skipped");
    }
    fs::remove_all(dir);
}

TEST_CASE("a table's head: the command as typed, and nothing that changes with a commit alone") {
    const auto dir = fresh_dir("head");
    REQUIRE(run("zoo --n 1,8 --out " + dir.string()).status == 0);
    const std::string md = slurp(dir / "zoo.md");
    CHECK(md.find("Produced by normzoo " + std::string(NORMZOO_VERSION) + ", `./verify zoo --n 1,8`, n = 1,8.") !=
          std::string::npos);
    CHECK(md.find("- `phong`: (R.V)^n (an RDF, V = N); normalization (n+1)/(2 pi)") != std::string::npos);
    // A commit that moves no value leaves the committed tables byte-identical (docs/reference.md,
    // "The head of a table"): no head names the source commit.
    CHECK(md.find("ommit") == std::string::npos);
    CHECK(slurp(dir / "zoo.csv").find("ommit") == std::string::npos);
    const auto doc = nlohmann::json::parse(slurp(dir / "zoo.json"));
    CHECK(!doc.contains("commit"));
    CHECK(run("zoo --n 1,8 --check --out " + dir.string()).status == 0);
    // An edit of the head is an edit of that file.
    std::string md_text = slurp(dir / "zoo.md");
    md_text.replace(md_text.find("Produced by"), 11, "Made by");
    std::ofstream(dir / "zoo.md", std::ios::binary) << md_text;
    CHECK(run("zoo --n 1,8 --check --out " + dir.string()).status == 1);
    fs::remove_all(dir);
}

TEST_CASE("inputs are the decimals typed, end to end: the command line and a scene") {
    using normzoo::wide;
    const wide pi = boost::math::constants::pi<wide>();
    // The relative difference of a record's decimal string from a value in 50 digits.
    auto off = [](const nlohmann::json& text, const wide& truth) {
        return static_cast<double>(abs(wide(text.get<std::string>()) - truth) / truth);
    };
    {
        const auto r = run("zoo --json --n 0.37,2.000000000000000001");
        REQUIRE(r.status == 0);
        int phong = 0;
        const auto doc = nlohmann::json::parse(r.out);
        for (const auto& rec : doc["records"]) {
            if (rec["table"] != "zoo" || rec["row"] != "phong") continue;
            ++phong;
            const std::string typed = rec["n_input"];
            CAPTURE(typed);
            CHECK((typed == "0.37" || typed == "2.000000000000000001"));
            // (n + 1) / (2 pi) at the decimal typed, in 50 digits: within the record's own estimate
            CHECK(off(rec["norm_quadrature"], (wide(typed) + 1) / (2 * pi)) <= rec["error_estimate"].get<double>());
        }
        CHECK(phong == 2);
    }
    {
        const auto r = run("irradiance --json --light sphere --ratio 0.1,3e-4 --tilt 0 --model lambert");
        REQUIRE(r.status == 0);
        int irradiance = 0;
        const auto doc = nlohmann::json::parse(r.out);
        for (const auto& rec : doc["records"]) {
            if (rec["table"] != "irradiance") continue;
            ++irradiance;
            const wide ratio(rec["ratio_input"].get<std::string>());
            CHECK(off(rec["E_quadrature"], pi * ratio * ratio) <= rec["error_estimate"].get<double>());
        }
        CHECK(irradiance == 2);
    }
    {
        const auto dir = fresh_dir("scene-decimals");
        const auto scene = dir / "decimals.toml";
        std::ofstream(scene) << "[[materials]]\nname = \"m\"\nmodel = \"phong-modified\"\nexponent = [0.37, 0.37]\n"
                             << "[[lights]]\nname = \"l\"\ntype = \"sphere\"\nradius = 0.1\ndistance = 3\n";
        const auto r = run("--scene " + scene.string() + " --json --out " + (dir / "out").string());
        REQUIRE(r.status == 0);
        int zoo = 0, irradiance = 0;
        const auto doc = nlohmann::json::parse(r.out);
        for (const auto& rec : doc["records"]) {
            if (rec["table"] == "zoo" && rec["row"] == "phong-modified") {
                ++zoo;
                CHECK(rec["n_input"] == "0.37");
                CHECK(off(rec["norm_quadrature"], (wide("0.37") + 2) / (2 * pi)) <= rec["error_estimate"].get<double>());
            }
            if (rec["table"] == "irradiance") {
                ++irradiance;
                CHECK(rec["ratio_input"] == "0.1/3");
                // E = pi (r0/r)^2 with r0/r = 1/30 exactly, which no binary type holds
                CHECK(off(rec["E_quadrature"], pi / 900) <= rec["error_estimate"].get<double>());
            }
        }
        CHECK(zoo == 1);
        CHECK(irradiance == 1);
        fs::remove_all(dir);
    }
}

TEST_CASE("microfacet compositions: energy --model D/G/F records, and bad input naming the value") {
    const auto r = run("energy --model ggx/smith-height-correlated/one --alpha 1 --mu 0.1,0.5,1 --json");
    REQUIRE(r.status == 0);
    const auto doc = nlohmann::json::parse(r.out);
    REQUIRE(doc["records"].size() == 3);
    for (const auto& rec : doc["records"]) {
        for (const char* key : {"model", "alpha", "mu", "albedo", "error_estimate"}) CHECK(rec.contains(key));
        const double mu = rec["mu"].get<double>();
        const double exact = 1 - mu * std::log1p(1 / mu);  // docs/microfacet.md, alpha = 1
        CHECK(std::abs(rec["albedo"].get<double>() - exact) <= rec["error_estimate"].get<double>());
    }
    // --r: alpha = r^2; --theta instead of --mu
    const auto by_r = nlohmann::json::parse(run("energy --model ggx/smith-separable/one --r 0.5 --theta 60 --json").out);
    REQUIRE(by_r["records"].size() == 1);
    CHECK(by_r["records"][0]["alpha"].get<double>() == 0.25);
    // F0 = 1 (the default) is an infinite index for the exact Fresnel parts: F = 1, their limit,
    // not NaN, so their albedo is the white furnace's
    for (const char* f : {"dielectric", "conductor"}) {
        const auto exact_f = nlohmann::json::parse(
            run(std::string("energy --model ggx/smith-height-correlated/") + f + " --alpha 0.5 --mu 0.5 --json").out);
        const auto one = nlohmann::json::parse(run("energy --model ggx/smith-height-correlated/one --alpha 0.5 --mu 0.5 --json").out);
        CAPTURE(f);
        REQUIRE(exact_f["records"][0]["albedo"].is_number());
        CHECK(exact_f["records"][0]["albedo"].get<double>() == one["records"][0]["albedo"].get<double>());
        CHECK(exact_f["records"][0]["conserving"].get<bool>());
    }
    const std::pair<const char*, const char*> bad[] = {
        {"energy --model ggx/smith-separable/one --alpha 0.3 --mu 1e-9", "1e-9"},
        {"energy --model beckmann/smith-separable/one --alpha 0.3 --theta 89.99999999", "89.99999999"},
        {"lut --kind E --alpha 0.3 --mu 1e-160", "1e-160"},
        {"energy --model ggx/smith/one --alpha 0.5", "'smith'"},
        {"energy --model ggx/smith-separable/one --alpha 0", "'0'"},
        {"energy --model ggx/smith-separable/one --alpha nan", "'nan'"},
        // below the smallest roughness taken (alpha 1e-8, r 1e-4): at 1e-100 GGX's integral gave NaN
        {"energy --model ggx/smith-height-correlated/one --alpha 1e-100 --mu 1", "'1e-100'"},
        {"lut --kind E --r 1e-5 --mu 1", "'1e-5'"},
        {"lut --kind dfg --alpha 1e-9 --mu 0.5", "'1e-9'"},
        {"lut --kind E --alpha --mu 1", "--alpha: missing its value"},
        {"energy --model ggx/smith-separable/one --mu 1.5", "'1.5'"},
        {"energy --model ggx/smith-separable/one --f0 -1", "'-1'"},
        {"energy --model ggx/implicit/one/multiple", "'multiple'"},
        {"energy --model ward --alpha 0.3", "--alpha"},
        {"lut --kind dfg --size 4 --model ggx/smith-separable/fresnel", "'fresnel'"},
        {"lut --kind XYZ --size 4", "'XYZ'"},
        {"energy --model ggx/smith-separable/one --alpha 0.3 --mu 0.5 --n 5", "--n is the exponent of the BRDF forms"},
        {"energy --model ggx/smith-separable/one,ggx --alpha 0.3 --mu 0.5", "unknown name 'ggx'"},
        {"energy --model ggx/smith-separable/one,ward --alpha 0.3 --mu 0.5", "'ward' is a BRDF form and the others are compositions"}};
    for (const auto& [args, named] : bad) check_refused(args, named);
    // scenes: a composition's keys checked, the file and line named, exit 2
    const auto dir = normzoo_test::fresh_dir("composition-scenes");
    const std::pair<const char*, const char*> scenes[] = {
        {"model = \"ggx/smith-height-correlated/one\"\nr = [0.1, 0.5]\nf0 = 1.5\n", "f0"},
        {"model = \"ggx/smith-height-correlated/one\"\nalpha = [0, 0.5]\n", "alpha"},
        {"model = \"ggx/smith-height-correlated/one\"\nalpha = [1e-9, 0.5]\n", "alpha: must be in [1e-8, 100]"},
        {"model = \"ggx/smith-height-correlated/one\"\nalpha = [1e-400, 0.5]\n", "s.toml:4: materials[1].alpha: '1e-400' is too small to hold in a double"},
        {"model = \"ggx/smith/one\"\nr = [0.1, 0.5]\n", "'smith'"},
        {"model = \"ggx/smith-separable/one\"\nexponent = [1, 2]\n", "exponent"},
        {"model = \"ggx/smith-separable/one\"\nr = [0.1, 0.5]\nlut = \"missing.png\"\n", "s.toml:5: materials[1].lut: '"},
        {"model = \"ggx/smith-separable/one\"\nr = [0.1, 0.5]\nlut_kind = \"E\"\n", "lut_kind: it describes the table of 'lut'"},
        {"model = \"ggx/smith-separable/one\"\nr = [0.1, 0.5]\nlut_map = \"alpha\"\n", "lut_map: it describes the table of 'lut'"},
        // a part parameter the composition does not read: at its own line, not the material's
        {"model = \"ggx/smith-height-correlated/one\"\nr = [0.2, 1.0]\nf0 = 0.04\n", "s.toml:5: materials[1].f0: f0"},
        // the table's own complaint, at the scene's line that names it
        {"model = \"ggx/smith-separable/one\"\nr = [0.1, 0.5]\nlut = \"text.png\"\n", "s.toml:5: materials[1].lut: "}};
    std::ofstream(dir / "text.png") << "not an image\n";
    for (const auto& [body, named] : scenes) check_scene_refused(dir, body, named, "microfacet-energy.md");
    fs::remove_all(dir);
}

TEST_CASE("microfacet compositions: the parts' own parameters from the command line and scenes, and bad ones named") {
    auto albedo = [](const std::string& args) {
        const auto r = run("energy " + args + " --json");
        CAPTURE(args);
        REQUIRE(r.status == 0);
        const auto rec = nlohmann::json::parse(r.out)["records"][0];
        return std::make_pair(rec["albedo"].get<double>(), rec["error_estimate"].get<double>());
    };
    auto same = [](std::pair<double, double> a, std::pair<double, double> b) { return std::abs(a.first - b.first) <= a.second + b.second; };
    const std::string at = " --alpha 0.3 --mu 0.5";
    // F90 = F0 makes schlick-f90 the constant F0: F0 times the white furnace's albedo
    const auto one = albedo("--model ggx/smith-height-correlated/one" + at);
    const auto flat = albedo("--model ggx/smith-height-correlated/schlick-f90 --f0 0.25 --f90 0.25" + at);
    CHECK(std::abs(flat.first - 0.25 * one.first) <= flat.second + 0.25 * one.second);
    CHECK(!same(flat, albedo("--model ggx/smith-height-correlated/schlick --f0 0.25" + at)));
    // eta = 1.5 is F0 = 0.04 exactly ((1.5 - 1)/(1.5 + 1))^2; a conductor with k = 0 is that dielectric
    const auto glass = albedo("--model ggx/smith-height-correlated/dielectric --eta 1.5" + at);
    CHECK(same(glass, albedo("--model ggx/smith-height-correlated/dielectric --f0 0.04" + at)));
    CHECK(same(glass, albedo("--model ggx/smith-height-correlated/conductor --eta 1.5 --k 0" + at)));
    const auto metal = run("energy --model ggx/smith-height-correlated/conductor --eta 0.18 --k 3.42" + at + " --json");
    REQUIRE(metal.status == 0);
    const auto m = nlohmann::json::parse(metal.out)["records"][0];
    CHECK(m["eta"].get<double>() == 0.18);
    CHECK(m["k"].get<double>() == 3.42);
    CHECK(!m.contains("f90"));
    // the inputs as typed beside the doubles; no F0 where eta replaces it, nor where no part reads it
    CHECK((m["eta_input"] == "0.18" && m["k_input"] == "3.42"));
    CHECK(!m.contains("f0"));
    const auto white = nlohmann::json::parse(run("energy --model ggx/smith-height-correlated/one" + at + " --json").out)["records"][0];
    CHECK(!white.contains("f0"));
    const auto schlick = nlohmann::json::parse(run("energy --model ggx/smith-height-correlated/schlick --f0 .040" + at + " --json").out)["records"][0];
    CHECK((schlick["f0"] == 0.04 && schlick["f0_input"] == ".040"));
    // a sweep that mixes them: the CSV's f0 columns stay among the inputs, before the results
    const auto mixed = normzoo_test::fresh_dir("mixed-f0");
    REQUIRE(run("energy --model ggx/smith-height-correlated/one,ggx/smith-height-correlated/schlick --f0 0.04" + at + " --out '" +
                mixed.string() + "'").status == 0);
    const std::string table = normzoo_test::slurp(mixed / "energy.csv");
    const auto head = table.find("\ntable,");
    REQUIRE(head != std::string::npos);
    const std::string columns = table.substr(head + 1, table.find('\n', head + 1) - head - 1);
    CAPTURE(columns);
    CHECK(columns.find(",mu_input,f0,f0_input,albedo,") != std::string::npos);
    fs::remove_all(mixed);
    CHECK(m["albedo"].get<double>() > glass.first + 0.5);  // gold-like: most of what one bounce keeps
    CHECK(m["albedo"].get<double>() < one.first);
    // an anisotropic D with aspect 1 is the isotropic one; at normal incidence its axes can swap
    CHECK(same(albedo("--model ggx-aniso/smith-height-correlated/one --aspect 1" + at), one));
    const auto wide = albedo("--model ggx-aniso/smith-height-correlated/one --aspect 4 --alpha 0.2 --mu 1");
    CHECK(same(wide, albedo("--model ggx-aniso/smith-height-correlated/one --aspect 0.25 --alpha 0.8 --mu 1")));
    CHECK(!same(wide, albedo("--model ggx/smith-height-correlated/one --alpha 0.2 --mu 1")));
    // the compensations read the index too: Turquin's F0 is F(1), Kulla-Conty's F_avg the part's
    for (const char* compensation : {"turquin", "kulla-conty"}) {
        CAPTURE(compensation);
        CHECK(same(albedo(std::string("--model ggx/smith-height-correlated/dielectric/") + compensation + " --eta 1.5" + at),
                   albedo(std::string("--model ggx/smith-height-correlated/dielectric/") + compensation + " --f0 0.04" + at)));
    }
    // GTR near gamma = 1 is continuous (its constant's 1 - a^(2 (1 - gamma)) is not left to cancel)
    const auto berry = albedo("--model gtr/implicit/one --gamma 1" + at);
    const auto near_berry = albedo("--model gtr/implicit/one --gamma 1.000000000001" + at);
    CHECK(std::abs(berry.first - near_berry.first) <= berry.second + near_berry.second + 1e-11);
    // GTR at gamma = 2 is GGX
    const auto ggx = albedo("--model ggx/implicit/one" + at);
    CHECK(same(albedo("--model gtr/implicit/one --gamma 2" + at), ggx));
    CHECK(!same(albedo("--model gtr/implicit/one --gamma 1.5" + at), ggx));
    const std::pair<const char*, const char*> bad[] = {
        {"energy --model ggx/smith-separable/dielectric --eta 0", "'0'"},
        {"energy --model ggx/smith-separable/dielectric --eta -1.5", "'-1.5'"},
        {"energy --model ggx/smith-separable/dielectric --eta nan", "'nan'"},
        {"energy --model ggx/smith-separable/dielectric --eta 1.5,2", "one value"},
        {"energy --model ggx/smith-separable/conductor --k -1", "'-1'"},
        {"energy --model ggx/smith-separable/schlick-f90 --f90 1.5", "'1.5'"},
        {"energy --model ggx-aniso/smith-separable/one --aspect 0.001", "'0.001'"},
        {"energy --model gtr/implicit/one --gamma 11", "'11'"},
        {"energy --model ggx/smith-separable/schlick --eta 1.5", "eta = 1.5: no part of 'ggx/smith-separable/schlick' reads it (the parts that do: dielectric, conductor)"},
        {"energy --model ggx/smith-separable/dielectric --k 2", "k = 2"},
        {"energy --model ggx/smith-separable/conductor --k 3.42", "k = 3.42: a conductor's k goes with its index, --eta"},
        {"energy --model ggx/smith-separable/one --f0 0.5", "f0 = 0.5: no part of 'ggx/smith-separable/one' reads it"},
        {"energy --model ggx/smith-separable/dielectric --f0 0.04 --eta 1.5", "f0 and --eta"},
        {"energy --model ward --eta 1.5", "--eta applies to microfacet compositions"},
        {"lut --kind dfg --size 4 --eta 1.5", "--eta is for --kind E and Eavg"},
        {"lut --kind E --size 4 --aspect 2", "aspect = 2: no part"},
        {"lut --kind dfg --size 4 --out --json", "--out: missing its value"},
        {"lut --kind dfg --size 4 --out ''", "--out: the path is empty"},
        {"lut --kind dfg --check --json", "--check: missing its value"}};
    for (const auto& [args, named] : bad) check_refused(args, named);
    const auto dir = normzoo_test::fresh_dir("part-parameter-scenes");
    const std::pair<const char*, const char*> scenes[] = {
        {"model = \"ggx/smith-height-correlated/dielectric\"\nr = [0.1, 0.5]\neta = 0\n", "s.toml:5"},
        {"model = \"ggx/smith-height-correlated/schlick\"\nr = [0.1, 0.5]\neta = 1.5\n", "eta = 1.5: no part"},
        {"model = \"ggx/smith-height-correlated/one\"\nr = [0.1, 0.5]\nf90 = 0.5\n", "f90 = 0.5"},
        {"model = \"blinn-phong\"\nexponent = [1, 2]\ngamma = 1.5\n", "gamma"}};
    for (const auto& [body, named] : scenes) check_scene_refused(dir, body, named, "");
    // a scene's parameters reach the sweep: the records carry them
    std::ofstream(dir / "s.toml") << "[[materials]]\nname = \"gold\"\nmodel = \"ggx/smith-height-correlated/conductor\"\n"
                                     "alpha = [0.3, 0.3]\neta = 0.18\nk = 3.42\n";
    const auto g = run_shell(std::string(NORMZOO_VERIFY_BIN) + " --scene '" + (dir / "s.toml").string() + "' --json");
    REQUIRE(g.status == 0);
    const auto gold = nlohmann::json::parse(g.out);
    std::size_t swept = 0;
    for (const auto& rec : gold["records"])
        if (rec["table"] == "microfacet-energy") {
            CHECK((rec["eta"].get<double>() == 0.18 && rec["k"].get<double>() == 3.42));
            ++swept;
        }
    CHECK(swept == 8);  // one alpha, eight mu
    // a scene's E table is checked at the material's F0
    REQUIRE(run("lut --kind E --model ggx/smith-height-correlated/schlick --f0 0.04 --size 4 --map alpha --out '" + dir.string() + "'").status == 0);
    std::ofstream(dir / "s.toml") << "[[materials]]\nname = \"plastic\"\nmodel = \"ggx/smith-height-correlated/schlick\"\n"
                                     "alpha = [0.3, 0.3]\nf0 = 0.04\nlut = \"lut-E-4.csv\"\nlut_kind = \"E\"\n";
    const auto e = run_shell(std::string(NORMZOO_VERIFY_BIN) + " --scene '" + (dir / "s.toml").string() + "' --json");
    CHECK(e.status == 0);
    std::size_t checked = 0;
    const auto plastic = nlohmann::json::parse(e.out);
    for (const auto& rec : plastic["records"])
        if (rec["table"] == "lut-check") {
            CHECK(rec["max_abs_error"].get<double>() < 1e-12);
            ++checked;
        }
    CHECK(checked == 1);
    // a CSV's header names its roughness: lut_map beside one is refused, as --map is
    check_scene_refused(dir, "model = \"ggx/smith-height-correlated/schlick\"\nalpha = [0.3, 0.3]\nlut = \"lut-E-4.csv\"\n"
                             "lut_kind = \"E\"\nlut_map = \"alpha\"\n", "s.toml:7: materials[1].lut_map: it is for an image", "");
    check_refused("lut --kind E --check '" + (dir / "lut-E-4.csv").string() + "' --map alpha", "lut: --map is for an image");
    fs::remove_all(dir);
}

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

TEST_CASE("verify --brdf: a BRDF Explorer file's albedo, verdicts and records") {
    const std::string ward = std::string(NORMZOO_SOURCE_DIR) + "/examples/brdfs/ward.brdf";
    const auto r = run("--brdf '" + ward + "' --param alpha=0.3 --theta 0,60 --json");
    REQUIRE(r.status == 0);
    const auto doc = nlohmann::json::parse(r.out);
    int albedos = 0;
    for (const auto& rec : doc["records"]) {
        if (rec["table"] != "brdf") continue;
        ++albedos;
        CHECK(rec["param_alpha"] == 0.3);
        CHECK(rec["values"] == "reflectance");
        CHECK(rec["conserving"] == true);
        CHECK(rec["error_estimate"].get<double>() <= 1e-10);
    }
    CHECK(albedos == 2);
    // Disney's diffuse gains energy (its albedo exceeds 1): exit 1, conserving false
    const auto d = run("--brdf '" + std::string(NORMZOO_SOURCE_DIR) + "/examples/brdfs/disney-diffuse.brdf' --theta 60 --json");
    CHECK(d.status == 1);
    CHECK(nlohmann::json::parse(d.out)["records"][0]["conserving"] == false);
}

TEST_CASE("verify --brdf: bad files and bad parameters exit 2, naming the file and line, nothing written") {
    const auto dir = fresh_dir("bad-brdf");
    const std::string good_shader =
        "::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(k / 3.14159); }\n::end shader\n";
    struct bad {
        const char* text;
        const char* says;  // in the message, after the file name
        const char* file = "bad.brdf";
    };
    const auto b = GENERATE_COPY(values<bad>({
        {"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\n{\n  return vec3(k +);\n}\n::end shader\n",
         ":7: GLSL error"},
        {"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\nvec3 Brdf(vec3 L) { return L; }\n::end shader\n",
         ": no function BRDF"},
        {"::begin parameters\ndouble k 0 1 0.5\n::end parameters\n", ":2: unknown parameter type 'double'"},
        {"::begin parameters\nfloat k 0 1 2\n::end parameters\n", ":2: parameter k: its default 2 is outside its range"},
        {"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\n#include \"/etc/passwd\"\n::end shader\n",
         ":5: #include \"/etc/passwd\" leaves the include folders"},
        // directives the preprocessor sees that a line-by-line reading would not (fuzz/corpus/shader/hidden-*)
        {"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\n/**/#include \"/etc/passwd\"\n::end shader\n",
         ":5: #include \"/etc/passwd\" leaves the include folders"},
        {"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\n%:include </etc/passwd>\n::end shader\n",
         ":5: the digraph %: (another spelling of #) is refused"},
        {"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\n#define A 1 /*\n%:include </etc/passwd>\n*/\n::end shader\n",
         ":5: a comment that begins on a directive's line must end on it"},
        {"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\n#define S(x) #x\nfloat s = S(k);\n::end shader\n",
         ":6: a string after preprocessing (the # operator, __FILE__ or __DATE__ made it)"},
        {"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\n#define ## //\n::end shader\n",
         ":5: preprocessor error"},
        {"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\nfloat x;\r#include </etc/passwd>\n::end shader\n",
         ":5: control character 0x0d refused"},
        {"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\nfloat x; // \"\n/* \"\n*/ #pragma once\n::end shader\n",
         ":7: a # after a comment that spans lines is refused"},
        {"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\nfloat x = '/*';\n::end shader\n",
         ":5: string and character literals are refused"},
        // assigning to a swizzle is supported (tests/test_shader_language.cpp); passing several of its
        // components as an out argument is not
        {"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\nvoid g(out vec2 p) { p = vec2(k); }\n"
         "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\n{\n  vec3 v = L;\n  g(v.xy);\n  return v;\n}\n::end shader\n",
         ":9: a swizzle of several components as an out or inout argument (.xy) is outside what normzoo runs"},
        {"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(k); }\n",
         ":5: the shader block has no '::end shader'"},
        // toml++ 3.3.0 reaches __builtin_unreachable on some non-ASCII text (fuzz/corpus/shader/finding-*)
        {"// [brdf]\n// function = \"f\"\n// x \xc8\xa0= 1\n//\nvec3 f(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return L; }\n",
         ":3: byte 0xc8 is not ASCII: a shader file's TOML header is plain ASCII", "bad.glsl"},
    }));
    const fs::path file = dir / b.file;
    std::ofstream(file) << b.text;
    const auto r = run_in(dir, std::string("--brdf ") + b.file);
    CAPTURE(b.text, r.out);
    CHECK(r.status == 2);
    CHECK(r.out.find(b.file + std::string(b.says)) != std::string::npos);
    // a good file with bad parameters
    std::ofstream(dir / "good.brdf") << "::begin parameters\nfloat k 0 1 0.5\n::end parameters\n" << good_shader;
    const auto unknown = run_in(dir, "--brdf good.brdf --param q=1");
    CHECK(unknown.status == 2);
    CHECK(unknown.out.find("declares no parameter q (it declares k)") != std::string::npos);
    const auto outside = run_in(dir, "--brdf good.brdf --param k=2");
    CHECK(outside.status == 2);
    CHECK(outside.out.find("--param k: 2 is outside its range") != std::string::npos);
    // nothing but the two files
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
    CHECK(files == 2);
}

TEST_CASE("verify --brdf: a #define before a prototype reaches the compiler") {
    // the translation drops prototypes (C++ needs none); the #define before one stays
    const auto dir = fresh_dir("translate-brdf");
    std::ofstream(dir / "t.brdf") << "::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\n"
                                     "#define INV_PI 0.31830988618379067\nvoid lambert(out float v);\n"
                                     "void lambert(out float v) { v = k * INV_PI; }\n"
                                     "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {\n  float v;\n  lambert(v);\n  return vec3(v);\n}\n"
                                     "::end shader\n";
    const auto r = run("--brdf '" + (dir / "t.brdf").string() + "' --theta 0 --json");
    CAPTURE(r.out);
    REQUIRE(r.status == 0);
    const auto rec = nlohmann::json::parse(r.out)["records"][0];
    CHECK(std::abs(rec["albedo"].get<double>() - 0.5) <= rec["error_estimate"].get<double>() + 1e-15);  // k/pi over the hemisphere
}

TEST_CASE("verify --brdf: a shader that loops forever is stopped, exit 2 with the reason") {
    const auto dir = fresh_dir("loop-brdf");
    std::ofstream(dir / "loop.brdf") << "::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\n"
                                        "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {\n"
                                        "  float s = 0.0;\n  while (k > 0.0) { s += 1.0; }\n  return vec3(s);\n}\n::end shader\n";
    const auto r = run_in(dir, "--brdf loop.brdf --time-limit 2 --theta 0");
    CAPTURE(r.out);
    CHECK(r.status == 2);
    CHECK(r.out.find("loop.brdf: evaluation stopped after 2 s") != std::string::npos);
}

TEST_CASE("verify --brdf --out: its tables written like any table's, nothing in results/ without it") {
    const auto dir = fresh_dir("brdf-out");
    const std::string lambert = std::string(NORMZOO_SOURCE_DIR) + "/examples/brdfs/lambert.brdf";
    const auto r = run_in(dir, "--brdf '" + lambert + "' --theta 30 --out out --junit j.xml");
    CAPTURE(r.out);
    REQUIRE(r.status == 0);
    for (const char* f : {"brdf.md", "brdf.csv", "brdf.json", "brdf-checks.md", "brdf-checks.csv", "brdf-checks.json"})
        CHECK(fs::exists(dir / "out" / f));
    CHECK(slurp(dir / "out" / "brdf.md").find("./verify --brdf " + lambert) != std::string::npos);
    CHECK(r.out.find("brdf: 1 records, 0 failing -> out/brdf.md") != std::string::npos);
    CHECK(slurp(dir / "j.xml").find("testsuite name=\"normzoo." + lambert + ".brdf\"") != std::string::npos);
    // without --out it prints its Markdown and writes nothing (no results/ in cwd)
    const auto printed = run_in(dir, "--brdf '" + lambert + "' --theta 30");
    CHECK(printed.status == 0);
    CHECK(printed.out.find("# brdf: A BRDF given as code") != std::string::npos);
    CHECK(!fs::exists(dir / "results"));
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

TEST_CASE("an option the tables planned do not read is refused: exit 2, the option named, nothing written") {
    struct bad {
        const char* args;
        const char* named;
    };
    const auto b = GENERATE(values<bad>({
        {"lut --kind dfg --size 4 --n 3", "lut: --n is not read by lut"},
        {"lut --kind dfg --size 4 --light disk", "lut: --light is not read by lut (irradiance reads it)"},
        {"zoo --kind dfg", "--kind is not read by zoo (lut reads it)"},
        {"energy --size 4", "--size is not read by energy (lut reads it)"},
        {"--param k=1", "--param is not read by zoo, bounds"},
        {"--brdf x.brdf --n 3", "--n is not read by --brdf"},
        {"--brdf x.brdf --kind dfg", "--kind is not read by --brdf (lut reads it)"},
        {"lut --kind dfg --size 4 zoo", "lut runs alone"},
        {"--brdf x.brdf zoo", "tables are not named with --brdf"},
        {"lut --check", "lut: --check: missing its value"},
        {"--check lut --kind dfg", "lut: --check needs the FILE to check"},
    }));
    const auto dir = fresh_dir("unread-option");
    const auto r = run_in(dir, std::string(b.args) + " --out out");
    CAPTURE(b.args, r.out);
    CHECK(r.status == 2);
    CHECK(r.out.rfind("verify: ", 0) == 0);
    CHECK(r.out.find(b.named) != std::string::npos);
    CHECK(fs::is_empty(dir));
    fs::remove_all(dir);
    // the results' --check with --brdf compares the tables it wrote: only to a folder named
    check_refused("--brdf x.brdf --check", "--check with --brdf compares the tables it wrote to a folder");
}
