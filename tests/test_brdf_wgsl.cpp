// `verify --brdf` on WGSL (docs/brdf-code.md#wgsl): a BRDF written as Bevy keeps its lighting
// functions, held to the built-in composition's albedo; WGSL's semantics where GLSL's and C++'s
// differ, checked at run time (tests/wgsl/semantics.wgsl); programs of the subset translated into
// GLSL that glslangValidator accepts, line for line; what WGSL refuses and what lies outside the
// subset refused with the file, the line and a WGSL programmer's words; a .wgsl file never read
// as GLSL. Shader compilations are two (each first one costs seconds; they are cached by
// content); the rest runs the translator in this process.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "args.hpp"
#include "brdf_file/brdf_file.hpp"
#include "brdf_file/wgsl.hpp"
#include "temp_files.hpp"

namespace fs = std::filesystem;
using normzoo_test::run_shell;
using normzoo_test::temp_dir;

namespace {

const std::string source_dir = NORMZOO_SOURCE_DIR;

const char* header = "// [brdf]\n// function = \"BRDF\"\n// [parameters.k]\n// type = \"float\"\n// range = [0, 1]\n// default = 0.5\n"
                     "// [parameters.flag]\n// type = \"bool\"\n// default = true\n// [parameters.tint]\n// type = \"color\"\n"
                     "// default = [1, 0.5, 0.25]\n//\n";

const char* signature = "fn BRDF(L: vec3<f32>, V: vec3<f32>, N: vec3<f32>, X: vec3<f32>, Y: vec3<f32>) -> vec3<f32>";

nlohmann::json records(const std::string& out) { return nlohmann::json::parse(out.substr(out.find("{\"records\""))); }

normzoo_test::run_result run_verify(const std::string& args) { return run_shell(std::string(NORMZOO_VERIFY_BIN) + " " + args + " 2>&1"); }

// A file's text read and, if it is WGSL, translated: what --brdf does before preprocessing,
// which a .wgsl file's translation replaces (preprocess.cpp).
verify::shader_source translated(const std::string& file, const std::string& text) {
    verify::shader_source s = verify::parse_shader_text(file, text);
    if (s.lang == verify::shader_source::language::wgsl) verify::translate_wgsl(s);
    return s;
}

// The message of the bad_input that reading `text` as FILE throws ("" if none).
std::string refusal(const std::string& file, const std::string& text) {
    try {
        translated(file, text);
    } catch (const verify::bad_input& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("verify --brdf: WGSL as Bevy writes its lighting functions gives the built-in composition's albedo") {
    const std::string file = source_dir + "/examples/brdfs/ggx-smith-schlick.wgsl";
    struct point {
        const char* r;      // the perceptual roughness
        const char* alpha;  // its square, the composition's alpha
        const char* f0;
        const char* built_in;  // Schlick's F at f0 = 1 is 1: the composition of F = 1 (f0 takes [0, 1))
    };
    const auto p = GENERATE(values<point>({{"0.3", "0.09", "1", "ggx/smith-height-correlated/one"},
                                           {"0.5", "0.25", "0.04", "ggx/smith-height-correlated/schlick --f0 0.04"},
                                           {"1", "1", "0.04", "ggx/smith-height-correlated/schlick --f0 0.04"}}));
    const std::string mus = "1,0.5,0.2,0.05";
    const auto code = run_verify("--brdf '" + file + "' --param perceptual_roughness=" + p.r + " --param f0=" + p.f0 + " --mu " + mus + " --json");
    CAPTURE(p.r, p.f0, code.out);
    REQUIRE(code.status == 0);
    const auto built_in = run_verify(std::string("energy --model ") + p.built_in + " --alpha " + p.alpha + " --mu " + mus + " --json");
    REQUIRE(built_in.status == 0);
    const auto c = records(code.out)["records"], b = records(built_in.out)["records"];
    int compared = 0;
    for (const auto& r : c) {
        if (r["table"] == "brdf-checks") {
            CHECK(r["pass"] == true);  // reciprocity
            continue;
        }
        const auto& e = b.at(static_cast<std::size_t>(compared++));
        const double diff = std::abs(r["albedo"].get<double>() - e["albedo"].get<double>());
        CAPTURE(r.dump(), e.dump());
        CHECK(diff <= 1e-9);
        CHECK(diff <= r["error_estimate"].get<double>() + e["error_estimate"].get<double>());
        CHECK(r["values"] == "reflectance");
    }
    CHECK(compared == 4);
}

TEST_CASE("verify --brdf: WGSL's semantics where GLSL's and C++'s differ hold in the double and float programs") {
    // the BRDF is 1/pi when every check of tests/wgsl/semantics.wgsl holds, else 0
    const auto r = run_verify("--brdf '" + source_dir + "/tests/wgsl/semantics.wgsl' --theta 0 --json");
    CAPTURE(r.out);
    REQUIRE(r.status == 0);
    const auto rec = records(r.out)["records"][0];
    CHECK(std::abs(rec["albedo"].get<double>() - 1) <= rec["error_estimate"].get<double>() + 1e-15);
    CHECK(std::abs(rec["albedo_fp32"].get<double>() - 1) <= 1e-6);
}

TEST_CASE("WGSL: programs of the subset become GLSL that glslangValidator accepts, each statement on its line") {
    const std::string sig = signature;
    const auto body = GENERATE_COPY(values<std::string>({
        // parameters of every kind, read as module-scope names; a uniform declaring one
        "@group(0) @binding(0) var<uniform> k: f32;\n" + sig + " {\n    if flag {\n        return tint * k;\n    }\n    return vec3f(k);\n}",
        // declarations in any order, aliases, a concrete and an abstract const, a struct by value
        sig + " {\n    let s = make(k);\n    return s.c * HALF * TWO;\n}\nalias Color = vec3<f32>;\nconst HALF: f32 = 0.5;\nconst TWO = 2;\n"
              "struct S {\n    c: Color,\n    w: f32,\n}\nfn make(x: f32) -> S {\n    return S(Color(x), 1.0);\n}",
        // loops, else if, compound assignment, ++, u32 and hexadecimal literals, phony assignment
        sig + " {\n    var acc = 0.0;\n    var n = 0u;\n    for (var i = 0; i < 0x4; i++) {\n        acc += f32(i) * k;\n        n++;\n    }\n"
              "    if acc > 10.0 {\n        acc = 10.0;\n    } else if acc < 0.0 {\n        acc = 0.0;\n    } else {\n        acc *= 0.5;\n    }\n"
              "    _ = clamp(acc, 0.0, 1.0);\n    while n > 2u {\n        n -= 1u;\n    }\n    return vec3(acc, f32(n), 0.0);\n}",
        // matrices, swizzles of rgba, the shorthands, built-ins written out or added as helpers
        sig + " {\n    let m = mat3x3f(X, Y, N);\n    let t = transpose(m) * L;\n    let c = vec4f(t, 1.0).rgb;\n"
              "    let d = determinant(m) + round(k) + trunc(-k) + fma(k, k, k) + select(0.0, 1.0, flag);\n"
              "    return c * saturate(d) + vec3(k % 0.3, f32(7 / i32(k + 1.0)), f32(-7 % 3));\n}",
        // a local shadowing a module fn and a built-in, a module fn shadowing a built-in, @must_use
        "diagnostic(off, derivative_uniformity);\n@must_use\nfn sqrt(x: f32) -> f32 {\n    return x;\n}\nfn g() -> f32 {\n    return 1.0;\n}\n" + sig +
            " {\n    let g = 2.0;\n    let max = 3.0;\n    return vec3(sqrt(g) * max);\n}",
        // a material's uniform structure, read member by member: each member read is a parameter
        "struct Material {\n    tint: vec3<f32>,\n    k: f32,\n    emissive: vec4<f32>,\n}\n@group(2) @binding(0) var<uniform> material: Material;\n" + sig +
            " {\n    return material.tint * material.k;\n}",
        // a loop with a continuing block and break if; a BRDF of one channel
        "fn BRDF(L: vec3<f32>, V: vec3<f32>, N: vec3<f32>, X: vec3<f32>, Y: vec3<f32>) -> f32 {\n    var i = 0;\n    loop {\n"
            "        i++;\n        continuing {\n            break if i >= 3;\n        }\n    }\n    return f32(i) * k;\n}",
    }));
    temp_dir d("wgsl-glsl");
    const std::string text = header + body + "\n";
    verify::shader_source s;
    REQUIRE_NOTHROW(s = translated((d.path / "t.wgsl").string(), text));
    CAPTURE(body, s.code);
    CHECK(s.lang == verify::shader_source::language::glsl);
    // line for line: as many lines, and each return on its own
    auto lines = [](const std::string& t) {
        std::vector<std::string> l;
        std::istringstream in(t);
        for (std::string x; std::getline(in, x);) l.push_back(x);
        return l;
    };
    const auto wgsl = lines(text), glsl = lines(s.code);
    REQUIRE(glsl.size() == wgsl.size());
    for (std::size_t i = text.find("fn BRDF") == std::string::npos ? 0 : static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(text.find("fn BRDF")), '\n'));
         i < wgsl.size(); ++i)
        if (wgsl[i].find_first_not_of(' ') != std::string::npos && wgsl[i].compare(wgsl[i].find_first_not_of(' '), 7, "return ") == 0)
            CHECK(glsl[i].find("return") != std::string::npos);
    // the validation's form of compiled_shader.cpp: parameters as uniforms, a main that calls the BRDF
    const std::string frag = d.file("t.frag", "#version 120\nuniform float k;\nuniform bool flag;\nuniform vec3 tint;\n#line 0\n" + s.code +
                                                  "void main() { gl_FragColor = vec4(" + s.function +
                                                  "(vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0), "
                                                  "vec3(0.0, 1.0, 0.0)), 1.0); }\n");
    const auto v = run_shell("glslangValidator -S frag '" + frag + "' 2>&1");
    CAPTURE(v.out);
    CHECK(v.status == 0);
}

TEST_CASE("WGSL: what WGSL refuses, and what lies outside the subset, is refused with the file, the line and WGSL's words") {
    struct bad {
        std::string code;  // after the header; its first line is the file's line 14
        const char* says;  // after "t.wgsl:"
    };
    const std::string sig = signature;
    const auto b = GENERATE_COPY(values<bad>({
        // WGSL's strictness: no conversion between concrete types, abstract literals, scopes, behaviours
        {sig + " {\n    let i: i32 = 1;\n    return vec3(k * i);\n}", "16: '*' cannot take an f32 and an i32: WGSL converts neither"},
        {sig + " {\n    let i: i32 = 1.5;\n    return vec3(k);\n}", "15: let i: i32 cannot hold an AbstractFloat (a float literal"},
        {sig + " {\n    return clamp(L, 0.0, 1.0);\n}", "15: clamp takes arguments of one type, not a vec3<f32> and an AbstractFloat"},
        {sig + " {\n    if k > 0.5 {\n        return L;\n    }\n}", "18: fn BRDF returns a vec3<f32>, but the end of its body is reachable"},
        {sig + " {\n    let x = k;\n    x = 2.0;\n    return L;\n}", "16: cannot assign: 'x' is a let or a parameter, which is immutable"},
        {sig + " {\n    var v = L;\n    v.xy = vec2(1.0);\n    return v;\n}", "16: cannot assign: a swizzle of several components is no reference"},
        {sig + " {\n    let x = 1.0;\n    let x = 2.0;\n    return L;\n}", "16: 'x' is declared twice in the same scope (first on line 15)"},
        {"fn f(x: f32) -> f32 {\n    return g(x);\n}\nfn g(x: f32) -> f32 {\n    return f(x);\n}\n" + sig + " {\n    return vec3(f(k));\n}",
         "18: fn f calls itself, directly or through another function: WGSL refuses recursion"},
        {sig + " {\n    loop {\n    }\n}", "15: this loop never ends: it has no break and no return"},
        {sig + " {\n    return vec3(f32(1 / 0));\n}", "15: division by zero in a const-expression"},
        {sig + " {\n    return vec3(float(k));\n}", "15: 'float' is not declared (WGSL writes f32)"},
        {sig + " {\n    max(k, 1.0);\n    return L;\n}", "15: the value of max(...) is unused"},
        // outside the subset, by name
        {sig + " {\n    let p: ptr<function, f32> = &k;\n    return L;\n}", "15: pointers (unary &) are outside the subset normzoo runs"},
        {"@group(0) @binding(1) var t: texture_2d<f32>;\n" + sig + " {\n    return textureLoad(t, vec2i(0), 0).rgb;\n}",
         "14: var t (a texture or a sampler: a module-scope var without an address space) is outside the subset normzoo runs: a BRDF reads the header's parameters, and const values (docs/brdf-code.md#wgsl); read on line 16"},
        {"override q: f32 = 1.0;\n" + sig + " {\n    return vec3(q);\n}", "16: override q (line 14): pipeline-overridable constants are outside"},
        {"var<workgroup> w: f32;\n" + sig + " {\n    return vec3(w);\n}", "14: var<workgroup> w is outside the subset normzoo runs"},
        {"var<uniform> q: f32;\n" + sig + " {\n    return vec3(q);\n}", "14: var<uniform> q is not a parameter of the header: add [parameters.q]"},
        {"struct M {\n    k: f32,\n    e: f32,\n}\nvar<uniform> m: M;\n" + sig + " {\n    return vec3(m.k * m.e);\n}",
         "20: m.e is not a parameter of the header: add [parameters.e]"},
        {"enable f16;\n" + sig + " {\n    return L;\n}", "14: enable f16: f16 is outside the subset normzoo runs"},
        {sig + " {\n    let v = vec3(1, 2, 3);\n    return L;\n}", "15: let v is a vec3<i32>: outside the subset normzoo runs"},
        {sig + " {\n    switch 1 {\n        default: {}\n    }\n    return L;\n}", "15: switch is outside the subset normzoo runs"},
        {sig + " {\n    return select(L, V, L < V);\n}", "15: '<' on vectors gives a vector of bool, outside the subset"},
        {sig + " {\n    return vec3(L[i32(k)]);\n}", "15: an index known only at run time is outside the subset"},
        // a file of GLSL, and a preprocessor, in a .wgsl file
        {"vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {\n    return vec3(k);\n}", "14: 'vec3' begins no WGSL declaration"},
        {"#define PI 3.14159\n" + sig + " {\n    return L;\n}", "14: '#' is not WGSL: WGSL has no preprocessor"},
        {"fn brdf(L: vec3<f32>, V: vec3<f32>, N: vec3<f32>, X: vec3<f32>, Y: vec3<f32>) -> f32 {\n    return k;\n}", " no fn BRDF(L: vec3<f32>"},
        {"fn BRDF(L: vec3<f32>, V: vec3<f32>) -> f32 {\n    return k;\n}", "14: the BRDF must be fn BRDF(L: vec3<f32>"},
    }));
    const std::string m = refusal("t.wgsl", header + b.code + "\n");
    CAPTURE(b.code, m);
    CHECK(m.find("t.wgsl:" + std::string(b.says)) == 0);
}

TEST_CASE("verify --brdf: a .wgsl file is never read as GLSL, and its refusal is exit 2 with nothing written") {
    temp_dir d("wgsl-cli");
    const std::string glsl = std::string(header) + "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {\n    return vec3(k / 3.14159);\n}\n";
    d.file("glsl.wgsl", glsl);
    const auto r = run_shell("cd '" + d.path.string() + "' && " + NORMZOO_VERIFY_BIN + " --brdf glsl.wgsl --theta 0 --out out 2>&1");
    CAPTURE(r.out);
    CHECK(r.status == 2);
    CHECK(r.out.find("glsl.wgsl:14: 'vec3' begins no WGSL declaration") != std::string::npos);
    CHECK(r.out.find("a .wgsl file holds WGSL") != std::string::npos);
    CHECK(!fs::exists(d.path / "out"));
    // language = "glsl" in a .wgsl file is refused; in a .glsl file, the same text is GLSL's
    std::string said = glsl;
    said.insert(said.find("// function"), "// language = \"glsl\"\n");
    CHECK(refusal("said.wgsl", said).find("said.wgsl:1: language 'glsl' in a .wgsl file: a .wgsl file holds WGSL") == 0);
    CHECK(refusal("said.glsl", said).empty());
}

TEST_CASE("verify --brdf: a .wgsl file takes no --define or --include-dir, and its translation's caps are named") {
    temp_dir d("wgsl-caps");
    const std::string brdf = std::string(signature) + " {\n    return vec3(k);\n}\n";
    d.file("ok.wgsl", std::string(header) + brdf);
    auto run = [&](const std::string& env, const std::string& args) {
        return run_shell("cd '" + d.path.string() + "' && " + env + " " + NORMZOO_VERIFY_BIN + " --brdf " + args + " --theta 0 --out out 2>&1");
    };
    const auto define = run("", "ok.wgsl --define Q=1");
    CHECK(define.status == 2);
    CHECK(define.out.find("ok.wgsl: --define and --include-dir have no meaning for WGSL, which has no preprocessor") != std::string::npos);
    // 16 MB holds 32768 tokens (512 bytes each); 40000 empty statements at module scope are more
    d.file("tokens.wgsl", std::string(header) + std::string(40000, ';') + "\n" + brdf);
    const auto tokens = run("NORMZOO_SHADER_MEMORY_MB=16", "tokens.wgsl");
    CAPTURE(tokens.out);
    CHECK(tokens.status == 2);
    CHECK(tokens.out.find("tokens.wgsl:14: the code holds more than the 32768 tokens its translation may hold (16 MB, NORMZOO_SHADER_MEMORY_MB)") !=
          std::string::npos);
    d.file("text.wgsl", std::string(header) + "// " + std::string(1100000, 'x') + "\n" + brdf);
    const auto text = run("NORMZOO_SHADER_TEXT_MB=1", "text.wgsl");
    CHECK(text.status == 2);
    CHECK(text.out.find("text.wgsl: the code exceeds the cap of 1 MB (NORMZOO_SHADER_TEXT_MB)") != std::string::npos);
    CHECK(!fs::exists(d.path / "out"));
}
