// The command end to end: JSON on stdout, files in --out, exit statuses, and bad input that
// leaves the output folder untouched.
#include "cli_helpers.hpp"

using namespace cli_test;

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
