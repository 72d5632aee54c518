// The shading languages as engines write them (docs/brdf-code.md#what-is-supported): the
// constructs of tests/shaders/constructs.glsl and .hlsl run end to end, each file compiled once;
// what normzoo refuses, with the file, the line and a shader programmer's words (never the C++
// compiler's); the analysis (reduced precision) and the compiler's messages mapped, alone.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "args.hpp"
#include "brdf_file/brdf_file.hpp"
#include "brdf_file/shader_analysis.hpp"
#include "brdf_file/shader_messages.hpp"
#include "brdf_file/shader_translate.hpp"
#include "temp_files.hpp"

namespace {

using normzoo_test::run_shell;

// Each value of `construct` in a constructs file, the value its code returns (its albedo is
// value / 16), at two incidences.
void check_constructs(const std::string& file, const std::vector<double>& values) {
    const std::string path = std::string(NORMZOO_SOURCE_DIR) + "/tests/shaders/" + file;
    // a cache of its own: each run validates and compiles (a second run would load the library)
    const normzoo_test::temp_dir cache("shader-cache");
    const auto r = run_shell("NORMZOO_CACHE_DIR='" + cache.path.string() + "' " + NORMZOO_VERIFY_BIN + " --brdf '" + path + "' --param construct=0.." +
                             std::to_string(values.size() - 1) + " --steps " + std::to_string(values.size()) + " --theta 0,60 --json 2>&1");
    CAPTURE(file, r.out.substr(0, 2000));
    REQUIRE(r.status == 0);
    const auto doc = nlohmann::json::parse(r.out.substr(r.out.find('{')));
    std::size_t seen = 0;
    for (const auto& rec : doc["records"]) {
        if (rec["table"] != "brdf") continue;
        const auto c = static_cast<std::size_t>(rec["param_construct"].get<double>());
        REQUIRE(c < values.size());
        CAPTURE(c, rec["theta_deg"].get<double>());
        CHECK(rec["values"] == "reflectance");
        CHECK(std::abs(16 * rec["albedo"].get<double>() - values[c]) <= 1e-9 * values[c]);
        ++seen;
    }
    CHECK(seen == 2 * values.size());
}

}  // namespace

TEST_CASE("GLSL: float returns, uniforms, precision, swizzles, arrays, structs, in/out/inout, end to end") {
    // construct: 0 a uniform; 1 uniform vec3 and bool; 2 precision qualifiers, a scalar's .x;
    // 3 x.xxx, f.rrr; 4 assignment to swizzles (=, *=, ++, v.yx = v.xy, v.xy[1]); 5 array
    // constructors, sized, unsized and by initializer list; 6 const arrays, global and local, an
    // array returned and compared; 7 a struct in and out, inout; 8 swizzles as out arguments,
    // declarators with arrays; 9 struct fields named like swizzles; 10 swizzles and mat3 of the
    // direction V against component code; 11 names C++ reserves; 12 mod and fract (floored);
    // 13 an overloaded call that is no recursion; 14 a #define with a swizzle; 15 a loop, an
    // array sized by a constant of constants, a constant computed when it runs
    check_constructs("constructs.glsl", {0.5, 1.75, 0.25, 0.5, 14.25, 4.875, 7.625, 3.75, 5.25, 7.25, 1, 0.875, 2.25, 0.75, 0.34375, 7});
}

TEST_CASE("HLSL: cbuffer, plain globals, intrinsics with HLSL's semantics, swizzles, arrays, structs, end to end") {
    // construct: 0 a cbuffer's member; 1 rcp, saturate; 2 lerp; 3 rsqrt, frac; 4 mad; 5 fmod
    // truncates (GLSL's mod would give 4.5); 6 sincos, into swizzles too; 7 x.xxx, x.rrr; 8
    // assignment to swizzles; 9 arrays by initializer list, a static const array; 10 (S)0, out
    // and inout; 11 mul with a float3x3 of rows; 12 [unroll]; 13 half, min16float; 14 v.xy =
    // -v.yx; 15 (float3) casts
    check_constructs("constructs.hlsl", {0.5, 1.25, 1.5, 1.75, 1.75, 0.5, 2, 0.375, 13.75, 6.875, 2.75, 1, 7, 0.75, 1, 1});
}

TEST_CASE("what a GPU compiler refuses, or normzoo cannot bind or run, exits 2 with the file, the line and the construct") {
    const std::string glsl = "// [brdf]\n// function = \"BRDF\"\n// [parameters.k]\n// type = \"float\"\n// range = [0, 1]\n// default = 0.5\n//\n";
    const std::string hlsl = "// [brdf]\n// function = \"BRDF\"\n// [parameters.k]\n// type = \"float\"\n// range = [0, 1]\n// default = 0.5\n//\n";
    const std::string entry = "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(f(k)); }\n";
    const std::string hentry = "float3 BRDF(float3 L, float3 V, float3 N, float3 X, float3 Y) { return f(k); }\n";
    struct bad {
        const char* name;
        std::string text;
        const char* says;  // after the file's name
    };
    const auto b = GENERATE_COPY(values<bad>({
        {"direct.glsl", glsl + "float f(float x) {\n  return x < 1.0 ? x : f(x - 1.0);\n}\n" + entry,
         ":8: recursion: f calls itself (direct.glsl:9). A shader's functions may not call themselves"},
        {"mutual.glsl", glsl + "float g(float x);\nfloat f(float x) { return g(x); }\nfloat g(float x) {\n  return f(x * 0.5);\n}\n" + entry,
         ":9: recursion: f calls g (mutual.glsl:9), which calls f (mutual.glsl:11)"},
        // an overloaded name: the call is resolved by glslangValidator's own check
        {"overloaded.glsl", glsl + "float f(float x) { return f(x); }\nvec3 f(vec3 v) { return v; }\n" + entry,
         ":8: GLSL error: recursion: f calls f"},
        {"mutual.hlsl", hlsl + "float g(float x);\nfloat f(float x) { return g(x); }\nfloat g(float x) { return f(x); }\n" + hentry,
         ":9: recursion: f calls g (mutual.hlsl:9), which calls f (mutual.hlsl:10)"},
        {"unbound.glsl", glsl + "uniform float gloss;\nfloat f(float x) { return x * gloss; }\n" + entry,
         ":8: uniform gloss is not a parameter of the file; add it to the file's TOML header, e.g.\n// [parameters.gloss]\n// "
         "type = \"float\"\n// range = [0, 1]\n// default = 0.5"},
        {"unbound.brdf", "::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\nuniform vec3 base;\nfloat f(float x) { return x; }\n" +
                             entry + "::end shader\n",
         ":5: uniform base is not a parameter of the file; add it to the ::begin parameters block, e.g.\n  color base 1 1 1"},
        {"mistyped.glsl", glsl + "uniform vec3 k;\nfloat f(vec3 x) { return x.x; }\n" + entry,
         ":8: uniform k is a vec3 here, but the header declares a float (mistyped.glsl:3): the two must agree"},
        {"unbound.hlsl", hlsl + "cbuffer Material : register(b0)\n{\n    float k;\n    float gloss;\n};\nfloat f(float x) { return x; }\n" + hentry,
         ":11: uniform gloss is not a parameter of the file"},
        {"global.hlsl", hlsl + "float4x4 World;\nfloat f(float x) { return x; }\n" + hentry,
         ":8: uniform World (a float4x4): the header's parameters are a float, a bool or a color"},
        {"texture.glsl", glsl + "uniform sampler2D dfg;\nfloat f(float x) { return x; }\n" + entry,
         ":8: sampler2D dfg is not bound to a table: --texture dfg=FILE binds it"},
        {"cube.glsl", glsl + "uniform samplerCube env;\nfloat f(float x) { return x; }\n" + entry,
         ":8: uniform env (a samplerCube): of the textures and samplers, normzoo binds a sampler2D or a Texture2D"},
        {"block.glsl", glsl + "uniform Material {\n  float k;\n};\nfloat f(float x) { return x; }\n" + entry, ":8: a uniform block"},
        {"varying.glsl", glsl + "varying vec3 normal;\nfloat f(float x) { return x; }\n" + entry, ":8: a shader input (varying)"},
        {"returns.glsl", glsl + "vec2 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec2(k); }\n",
         ":8: BRDF returns vec2; normzoo takes a BRDF that returns a float or a vec3"},
        {"takes.glsl", glsl + "vec3 BRDF(vec3 L, vec3 V) { return vec3(k); }\n",
         ":8: BRDF takes (vec3 L, vec3 V); normzoo calls it with five vectors"},
        {"swizzle-out.glsl", glsl + "void g(out vec2 p) { p = vec2(k); }\nfloat f(float x) {\n  vec3 v = vec3(x);\n  g(v.xy);\n  return v.x;\n}\n" + entry,
         ":11: a swizzle of several components as an out or inout argument (.xy)"},
        // found by the shader fuzzer: the analysis looked for its members past the file's end
        {"braceless.hlsl", hlsl + "cbuffer Material : B;\nfloat f(float x) { return x; }\n" + hentry, ":8: HLSL error"},
        {"bracket.glsl", glsl + "float f(float x) { return x); }\n" + entry, ":8: this ) closes nothing"},
        // valid GLSL that reaches the C++ compiler, whose error is said in shading terms
        {"builtin.glsl", glsl + "float f(float x) {\n  return x * gl_FragCoord.x;\n}\n" + entry,
         ":9: valid GLSL, but outside what normzoo runs on the CPU (docs/brdf-code.md#what-is-supported): gl_FragCoord is no "
         "function or variable normzoo knows (its built-in functions are listed in docs/brdf-code.md), in: return x * gl_FragCoord.x;"},
    }));
    const normzoo_test::temp_dir dir("shader-refusals");
    const std::string file = dir.file(b.name, b.text);
    const auto r = run_shell("cd '" + dir.path.string() + "' && " + NORMZOO_VERIFY_BIN + " --brdf " + b.name + " --theta 0 2>&1");
    CAPTURE(b.name, r.out);
    CHECK(r.status == 2);
    CHECK(r.out.find(std::string(b.name) + b.says) != std::string::npos);
    for (const char* compiler : {"normzoo_", "glm::", "->*", "aka", "operator->", "In member function", "required from"})
        CHECK(r.out.find(compiler) == std::string::npos);
}

TEST_CASE("the analysis records where reduced precision is declared, per function and for the file") {
    struct text {
        const char* name;
        std::string code;
        bool file;
        int line;                       // the first line that declares it
        std::vector<bool> functions;    // each function's
    };
    const auto t = GENERATE(values<text>({
        {"a.glsl", "float f(float x) { return x; }\nprecision mediump float;\nfloat g(float x) { return x; }\n", true, 2, {false, true}},
        {"b.glsl", "float f(mediump float x) { return x; }\nhighp float g(highp float x) { return x; }\n", true, 1, {true, false}},
        {"c.glsl", "precision highp float;\nfloat f(float x) { return x; }\n", false, 0, {false}},
        {"d.hlsl", "float f(float x) { return x; }\nfloat g(float x) {\n  half h = x;\n  return h;\n}\n", true, 3, {false, true}},
        {"e.hlsl", "float f(float x) { min16float y = x; return y; }\n", true, 1, {true}},
    }));
    verify::shader_source s;
    s.path = t.name;
    const bool hlsl = std::string(t.name).find(".hlsl") != std::string::npos;
    s.lang = hlsl ? verify::shader_source::language::hlsl : verify::shader_source::language::glsl;
    s.code = t.code;
    const verify::token_list tokens(verify::tokenize(s.code), 1);
    const auto a = verify::analyze_shader(s, tokens);
    CAPTURE(t.name);
    CHECK(a.reduced_precision == t.file);
    CHECK(a.reduced_precision_line == t.line);
    REQUIRE(a.functions.size() == t.functions.size());
    for (std::size_t k = 0; k < t.functions.size(); ++k) CHECK(a.functions[k].reduced_precision == t.functions[k]);
}

TEST_CASE("the C++ compiler's errors said in shading terms, with the file's line and code, none of its text") {
    verify::shader_source s;
    s.path = "brdf.glsl";
    s.first_line = 1;
    s.code = "float f(vec3 v) {\n  return v.xxy.w;\n}\nfloat g(float x) { return x % 2.0; }\n";
    struct output {
        std::string compiler;  // what g++ printed
        int line;
        const char* says;
    };
    const auto o = GENERATE(values<output>({
        {"brdf.glsl: In member function 'double normzoo_double::normzoo_program::f(vec3)':\nbrdf.glsl:2:15: error: request for member 'xxx' in "
         "'normzoo_double::normzoo_program::v', which is of non-class type 'double'\n",
         2, ".xxx is read from a value that has no such field or swizzle, in: return v.xxy.w;"},
        {"prelude.hpp: In instantiation of 'static auto normzoo_glsl::library<real>::pow(const A&, const B&)':\nbrdf.glsl:2:20:   required from "
         "here\nprelude.hpp:80:5: error: no matching function for call to 'pow(glm::vec<2, double>, double)'\n",
         2, "no version of pow that normzoo runs takes these arguments, in: return v.xxy.w;"},
        {"brdf.glsl:4:30: error: invalid operands of types 'normzoo_double::real' {aka 'double'} and 'double' to binary 'operator%'\n", 4,
         "the operator % does not apply to these operands on the CPU"},
        {"brdf.glsl:4:20: error: 'normzoo_id_new' was not declared in this scope\n", 4, "new is no function or variable normzoo knows"},
        {"shader.cpp:900:1: error: something in the wrapper\n", 0, "a construct normzoo does not run"},
    }));
    int line = -1;
    const std::string m = verify::compiler_message(o.compiler, s, line);
    CAPTURE(o.compiler, m);
    CHECK(line == o.line);
    CHECK(m.find(o.says) != std::string::npos);
    for (const char* compiler : {"normzoo_", "error:", "glm", "aka", "instantiation", "double"}) CHECK(m.find(compiler) == std::string::npos);
}

TEST_CASE("the translation makes no trigraph of the ? the code holds (fuzz/corpus/shader/finding-trigraph-*)") {
    const std::string header = "// [brdf]\n// function = \"BRDF\"\n//\n";
    const auto code = GENERATE(as<std::string>{}, "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {\n  vec3 v = L;\n  ??v.xy = L.yx;\n  return v;\n}\n",
                               "struct S { float w[2??]; };\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return L; }\n");
    const std::string t = verify::translate_shader(verify::parse_shader_text("t.glsl", header + code), "prelude.hpp");
    CAPTURE(code, t);
    for (std::size_t at = t.find("??"); at != std::string::npos; at = t.find("??", at + 1))
        CHECK(std::string("=/'()!<>-").find(t[at + 2]) == std::string::npos);
    CHECK(t.find("??") != std::string::npos);
}
