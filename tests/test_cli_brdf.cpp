// The command end to end: verify --brdf's files, bad input and limits, and options tables do not read.
#include "cli_helpers.hpp"

using namespace cli_test;

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
