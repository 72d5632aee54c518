// `verify --brdf` on shader code kept as engines keep it (docs/brdf-code.md#the-preprocessor):
// helpers in included files behind include guards and #pragma once, a quality macro switched by
// --define, #version 300 es with a precision statement, an HLSL file with #include; includes that
// leave their folders, bad --define values and the caps on each step refused with exit 2. The
// fixtures are this project's own. Shader compilations are few (three): each first one costs
// seconds, and they are cached by content.
#include <catch2/catch.hpp>
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "args.hpp"
#include "brdf_file/shader_screen.hpp"
#include "temp_files.hpp"

namespace fs = std::filesystem;
using normzoo_test::run_shell;
using normzoo_test::temp_dir;

namespace {

const char* header = "// [brdf]\n// function = \"BRDF\"\n// [parameters.roughness]\n// type = \"float\"\n// range = [0.05, 1]\n"
                     "// default = 0.5\n//\n";

// Shared helpers behind an include guard.
const char* common_glsl = R"(// helpers every lobe uses
#ifndef COMMON_GLSL
#define COMMON_GLSL
#define PI 3.14159265358979
#define SATURATE(x) clamp((x), 0.0, 1.0)
#define SQR(x) ((x) * (x))
#endif
)";

// GGX's D and a visibility term whose exact form (height-correlated Smith, Heitz 2014) a quality
// macro switches on; else Hammon's approximation, as mobile paths take.
const char* ggx_glsl = R"(#pragma once
float D_GGX(float NoH, float a) {
    float a2 = a * a;
    float f = (NoH * a2 - NoH) * NoH + 1.0;
    return a2 / (PI * f * f);
}
float V_Smith(float NoV, float NoL, float a) {
#if QUALITY >= 2
    float a2 = a * a;
    float lv = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);
    float ll = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
    return 0.5 / (lv + ll);
#else
    return 0.5 / mix(2.0 * NoL * NoV, NoL + NoV, a);
#endif
}
)";

const char* spec_glsl = R"(#version 300 es
#extension GL_GOOGLE_include_directive : require
precision mediump float;
#include "include/common.glsl"
#include "include/common.glsl"
#include <ggx.glsl>
#include <ggx.glsl>
#ifndef QUALITY
#define QUALITY 1
#endif
#if 0
#include "../../../etc/passwd"
#endif
vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {
    vec3 H = normalize(L + V);
    float NoL = SATURATE(dot(N, L)), NoV = SATURATE(dot(N, V)), NoH = SATURATE(dot(N, H));
    float a = SQR(roughness);
    return vec3(D_GGX(NoH, a) * V_Smith(NoV, NoL, a));
}
)";

// The same lobe in HLSL, its helpers in an include folder.
const char* brdf_common_hlsl = R"(#ifndef BRDF_COMMON_HLSL
#define BRDF_COMMON_HLSL
static const float PI = 3.14159265358979;
#define SQR(x) ((x) * (x))
#endif
)";

const char* spec_hlsl = R"(#include "common/brdf_common.hlsl"
#include <brdf_common.hlsl>
float3 BRDF(float3 L, float3 V, float3 N, float3 X, float3 Y)
{
    float3 H = normalize(L + V);
    float a = SQR(roughness), a2 = a * a;
    float NoH = saturate(dot(N, H)), NoL = saturate(dot(N, L)), NoV = saturate(dot(N, V));
    float d = (NoH * a2 - NoH) * NoH + 1;
    float Vis = 0.5 / (NoL * sqrt(NoV * NoV * (1 - a2) + a2) + NoV * sqrt(NoL * NoL * (1 - a2) + a2));
    return a2 / (PI * d * d) * Vis;
}
)";

// The engine's folder: eng/spec.glsl with eng/include/, eng/h/ for HLSL, and outside/ beside it.
void write_engine(const temp_dir& d) {
    fs::create_directories(d.path / "eng" / "include");
    fs::create_directories(d.path / "eng" / "h" / "common");
    fs::create_directories(d.path / "outside");
    d.file("eng/include/common.glsl", common_glsl);
    d.file("eng/include/ggx.glsl", ggx_glsl);
    d.file("eng/spec.glsl", std::string(header) + spec_glsl);
    d.file("eng/h/common/brdf_common.hlsl", brdf_common_hlsl);
    d.file("eng/h/spec.hlsl", std::string(header) + spec_hlsl);
    d.file("outside/x.glsl", "float leaked;\n");
    fs::create_symlink("../outside/x.glsl", d.path / "eng" / "link.glsl");
}

normzoo_test::run_result verify_in(const temp_dir& d, const std::string& args, const std::string& env = "") {
    return run_shell("cd '" + d.path.string() + "' && " + env + " " + NORMZOO_VERIFY_BIN + " " + args + " 2>&1");
}

double albedo_of(const std::string& json_text) {
    const auto doc = nlohmann::json::parse(json_text.substr(json_text.find("{\"records\"")));
    return doc["records"][0]["albedo"].get<double>();
}

}  // namespace

TEST_CASE("verify --brdf: an engine's GLSL and HLSL files, preprocessed, give the built-in composition's albedo") {
    temp_dir d("brdf-engine");
    write_engine(d);
    // the built-in GGX with height-correlated Smith, F = 1, at alpha = 0.5^2 and normal incidence
    const auto built_in = verify_in(d, "energy --model ggx/smith-height-correlated/one --alpha 0.25 --mu 1 --json");
    REQUIRE(built_in.status == 0);
    const double exact = albedo_of(built_in.out);
    const auto q2 = verify_in(d, "--brdf eng/spec.glsl --include-dir eng/include --define QUALITY=2 --theta 0 --json");
    CAPTURE(q2.out);
    REQUIRE(q2.status == 0);
    CHECK(std::abs(albedo_of(q2.out) - exact) < 1e-9);
    // QUALITY 1 (the file's default) takes the approximation: another albedo
    const auto q1 = verify_in(d, "--brdf eng/spec.glsl --include-dir eng/include --theta 0 --json");
    CAPTURE(q1.out);
    REQUIRE(q1.status == 0);
    CHECK(std::abs(albedo_of(q1.out) - exact) > 1e-4);
    const auto hlsl = verify_in(d, "--brdf eng/h/spec.hlsl --include-dir eng/h/common --theta 0 --json");
    CAPTURE(hlsl.out);
    REQUIRE(hlsl.status == 0);
    CHECK(std::abs(albedo_of(hlsl.out) - exact) < 1e-9);
}

TEST_CASE("verify --brdf: an error inside an included file names that file and its line") {
    temp_dir d("brdf-included-error");
    write_engine(d);
    struct bad {
        const char* included;
        const char* says;
    };
    const auto b = GENERATE(values<bad>({
        {"#define K 2.0\n\nfloat f(float x) {\n    return x * K +;\n}\n", "eng/include/bad.glsl:4: GLSL error"},
        // assigning to a swizzle is supported (tests/test_shader_language.cpp); recursion is not
        {"float f(float x) {\n    vec3 v = vec3(x);\n    return f(v.x);\n}\n",
         "eng/include/bad.glsl:1: recursion: f calls itself (eng/include/bad.glsl:3)"},
        {"\n\n#include \"../../outside/x.glsl\"\n", "eng/include/bad.glsl:3: #include \"../../outside/x.glsl\" leaves the include folders"},
    }));
    d.file("eng/include/bad.glsl", b.included);
    d.file("eng/e.glsl", std::string(header) + "#include \"include/bad.glsl\"\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(f(roughness)); }\n");
    const auto r = verify_in(d, "--brdf eng/e.glsl --theta 0");
    CAPTURE(b.included, r.out);
    CHECK(r.status == 2);
    CHECK(r.out.find(b.says) != std::string::npos);
}

TEST_CASE("verify --brdf: includes that leave their folders or are unknown and bad --define values are exit 2 with nothing written") {
    temp_dir d("brdf-refused");
    write_engine(d);
    struct bad {
        std::string code;  // after the header, in eng/t.glsl
        std::string args;
        std::string says;
    };
    const std::string outside = (d.path / "outside" / "x.glsl").string();
    const auto b = GENERATE_COPY(values<bad>({
        {"#include \"../outside/x.glsl\"\n", "", "eng/t.glsl:8: #include \"../outside/x.glsl\" leaves the include folders (eng)"},
        {"#include \"" + outside + "\"\n", "", "eng/t.glsl:8: #include \"" + outside + "\" leaves the include folders"},
        {"#include \"link.glsl\"\n", "", "eng/t.glsl:8: #include \"link.glsl\" leaves the include folders"},
        {"#include <ggx.glsl>\n", "", "eng/t.glsl:8: #include <ggx.glsl> is not found in the include folders (eng;"},
        {"#include \"include/nope.glsl\"\n", "--include-dir eng/include", "eng/t.glsl:8: #include \"include/nope.glsl\" is not found in the include folders (eng, eng/include;"},
        {"\n#if QUALITY > 1\nfloat x;\n", "", "preprocessor error: End of input within #if (#ifdef) section started at line 9"},
        {"#include MACRO_NAME\n", "", "eng/t.glsl:8: #include MACRO_NAME: #include takes \"FILE\" or <FILE>"},
        {"#line 40\n", "", "eng/t.glsl:8: #line is refused"},
        {"#error the mobile path is not written\n", "", "eng/t.glsl:8: preprocessor error: #error the mobile path is not written"},
        {"", "--define 1X", "--define 1X: '1X' is not a macro name"},
        {"", "--define 'X=\"s\"'", "--define X=\"s\": a value holds no string"},
        {"", "--define 'X=a\\b'", "--define X=a\\b: a value holds printable ASCII but"},
        {"", "--define normzoo_x=1", "--define normzoo_x=1: names holding normzoo_ are reserved"},
        {"", "--define __VERSION__=100", "--define __VERSION__=100: __VERSION__ is reserved"},
        {"", "--include-dir no-such-folder", "--include-dir no-such-folder: not a folder"},
    }));
    d.file("eng/t.glsl", std::string(header) + b.code + "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(0.5); }\n");
    const auto before = std::distance(fs::recursive_directory_iterator(d.path), fs::recursive_directory_iterator());
    const auto r = verify_in(d, "--brdf eng/t.glsl --theta 0 --out out " + b.args);
    CAPTURE(b.code, b.args, r.out);
    CHECK(r.status == 2);
    CHECK(r.out.find(b.says) != std::string::npos);
    CHECK(std::distance(fs::recursive_directory_iterator(d.path), fs::recursive_directory_iterator()) == before);
}

TEST_CASE("verify --define and --include-dir without --brdf: exit 2 naming the option") {
    temp_dir d("brdf-options-alone");
    for (const char* args : {"--define X=1", "--include-dir .", "zoo --define X"}) {
        const auto r = verify_in(d, args);
        CAPTURE(args, r.out);
        CHECK(r.status == 2);
        CHECK(r.out.find(std::string(args).find("define") != std::string::npos ? "--define is not read by" : "--include-dir is not read by") !=
              std::string::npos);
    }
}

// A file whose macros double thirty times: 2^30 tokens, were they expanded. Before the
// preprocessor ran as a capped child, shader validation took 15.6 GB and 121 s on it.
std::string define_bomb(int depth, const std::string& use) {
    std::string s = std::string(header) + "#define A0 x+\n";
    for (int i = 1; i <= depth; ++i) s += "#define A" + std::to_string(i) + " A" + std::to_string(i - 1) + " A" + std::to_string(i - 1) + "\n";
    return s + use + "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { float x = 1.0; return vec3(0.5); }\n";
}

TEST_CASE("verify --brdf: the nested-#define bomb is stopped in seconds under the memory cap with exit 2 and the reason") {
    temp_dir d("brdf-bomb");
    d.file("bomb.glsl", define_bomb(29, "float y = A29 1.0;\n"));
    const auto start = std::chrono::steady_clock::now();
    const auto r = verify_in(d, "--brdf bomb.glsl --theta 0");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rusage children{};
    ::getrusage(RUSAGE_CHILDREN, &children);
    CAPTURE(r.out, seconds, children.ru_maxrss);
    CHECK(r.status == 2);
    CHECK(r.out.find("bomb.glsl:") != std::string::npos);
    CHECK((r.out.find("preprocessor error") != std::string::npos || r.out.find("preprocessing stopped") != std::string::npos));
    CHECK(seconds < 12);                                 // the default time cap is 10 s
    CHECK(children.ru_maxrss < 2048L * 1024);            // kB: under the default memory cap
}

TEST_CASE("verify --brdf: each cap lowered trips and is named with its variable") {
    temp_dir d("brdf-caps");
    write_engine(d);
    std::string lines;
    for (int i = 0; i < 40; ++i) lines += "float y" + std::to_string(i) + " = A14 1.0;\n";
    d.file("slow.glsl", define_bomb(14, lines));
    std::string plain;  // under 1 MB of code, which the expansions push over it
    while (plain.size() < 1000000) plain += "float aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa;\n";
    for (int i = 0; i < 60; ++i) plain += "A9\n";
    d.file("big.glsl", define_bomb(9, plain));
    d.file("eng/huge.glsl", std::string(header) + "#include \"include/huge.glsl\"\n");
    d.file("eng/include/huge.glsl", std::string(1100000, '\n'));
    struct cap {
        const char* env;
        const char* file;
        const char* says;
    };
    const auto c = GENERATE(values<cap>({
        {"NORMZOO_SHADER_SECONDS=1", "slow.glsl", "slow.glsl: preprocessing stopped: it took longer than its cap of 1 s (NORMZOO_SHADER_SECONDS)"},
        {"NORMZOO_SHADER_TEXT_MB=1", "big.glsl", "big.glsl: preprocessing stopped: it wrote more than its cap of 1 MB (NORMZOO_SHADER_TEXT_MB)"},
        {"NORMZOO_SHADER_TEXT_MB=1", "eng/huge.glsl", "eng/include/huge.glsl: the code and the files it includes exceed the cap of 1 MB (NORMZOO_SHADER_TEXT_MB)"},
        {"NORMZOO_SHADER_MEMORY_MB=64 NORMZOO_CACHE_DIR=fresh-cache", "eng/h/spec.hlsl", "memory cap of 64 MB (NORMZOO_SHADER_MEMORY_MB)"},
        {"NORMZOO_SHADER_SECONDS=abc", "eng/h/spec.hlsl", "NORMZOO_SHADER_SECONDS: 'abc' is not a number"},
    }));
    const auto r = verify_in(d, std::string("--brdf ") + c.file + " --include-dir eng/h/common --theta 0", c.env);
    CAPTURE(c.env, r.out);
    CHECK(r.status == 2);
    CHECK(r.out.find(c.says) != std::string::npos);
}

TEST_CASE("the screening going in finds the directives as the preprocessor does and keeps the line numbers") {
    // a splice joins two lines; the next directive keeps its own line number
    const auto s = verify::screen_input("f.glsl", "float a = \\\n  1.0;\n/* x */ # define B 2 // c\n#include \"a//b.glsl\"\n", false);
    REQUIRE(s.directives.size() == 2);
    CHECK(s.directives[0].line == 3);
    CHECK(s.directives[0].name == "define");
    CHECK(s.directives[1].rest.find("\"a//b.glsl\"") != std::string::npos);
    CHECK(std::count(s.text.begin(), s.text.end(), '\n') == 4);
    struct refused {
        const char* text;
        const char* says;
    };
    const auto r = GENERATE(values<refused>({
        {"float x;\r#define A\n", "f.glsl:1: control character 0x0d"},
        {"float x = 1.0; \\ \n", "f.glsl:1: a backslash that does not end a line"},
        {"/* a\n */ #define A\n", "f.glsl:2: a # after a comment that spans lines"},
        {"#define A 1 /*\n*/\n", "f.glsl:1: a comment that begins on a directive's line must end on it"},
        {"float x; # define A\n", "f.glsl:1: a # that does not begin a directive"},
        {"%:include <x>\n", "f.glsl:1: the digraph %:"},
        {"float normzoo_x;\n", "f.glsl:1: names holding normzoo_"},
        {"#import <x>\n", "f.glsl:1: '#import' is not a directive"},
        {"\n#version 300 es\n", "f.glsl:2: #version is GLSL's: an HLSL file has none"},
        {"float c = 'a';\n", "f.glsl:1: string and character literals are refused"},
        {"/* open\n", "f.glsl:1: a comment that does not end"},
    }));
    CAPTURE(r.text);
    REQUIRE_THROWS_AS(verify::screen_input("f.glsl", r.text, true), verify::bad_input);
    try {
        verify::screen_input("f.glsl", r.text, true);
    } catch (const verify::bad_input& e) {
        CHECK(std::string(e.what()).find(r.says) != std::string::npos);
    }
}
