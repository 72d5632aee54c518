// verify --brdf's binary16 program (docs/brdf-code.md#precision): the values a shader declares
// mediump, lowp, half or min16float rounded to binary16. A value computed by it is checked
// against a binary16 rounding written here bit by bit (not the compiler's _Float16, which the
// program uses); GGX's D written as engines warn against (1 - (N.H)^2 in mediump) breaks down
// where the form from Lagrange's identity does not; a file without reduced precision has no
// albedo_fp16. Two shader files (tests/shaders/ggx-mediump.glsl), each compiled once (then
// cached), serve every case.
#include <catch2/catch.hpp>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "brdf_runs.hpp"
#include "temp_files.hpp"

using normzoo_test::run_shell;

namespace {

const double pi = std::acos(-1.0);

// c = a * b + r with a, b, r mediump: each value and each operation rounded to binary16; the
// BRDF is c everywhere, whose albedo is pi c.
const char* expression_shader = R"(// [brdf]
// [parameters.p]
// range = [0, 1000]
// default = 0.1
// [parameters.q]
// range = [0, 1000]
// default = 3.3
// [parameters.r]
// range = [0, 1000]
// default = 0
//
vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)
{
    mediump float a = p;
    mediump float b = q;
    mediump float c = a * b + r;
    return vec3(c);
}
)";

struct fixture {
    normzoo_test::temp_dir dir{"brdf-fp16"};
    std::string expression = dir.file("expression.glsl", expression_shader);
};

const fixture& files() {
    static const fixture f;
    return f;
}

const std::string ggx_file = NORMZOO_SOURCE_DIR "/tests/shaders/ggx-mediump.glsl";

using normzoo_test::run;

std::vector<nlohmann::json> albedos(const std::string& json) { return normzoo_test::records_of(json, "brdf"); }

// x rounded to binary16 bit by bit: 11 significant bits (the unit of the last place 2^(e - 11)
// for x in [2^(e-1), 2^e), never below the subnormals' 2^-24), to nearest with ties to even
// (nearbyint in the default rounding mode), and Inf from 65520 up (65504 + half its ulp rounds to
// the even 2^16, out of range).
double binary16(double x) {
    if (x == 0 || !std::isfinite(x)) return x;
    int e = 0;
    std::frexp(std::abs(x), &e);
    const double ulp = std::ldexp(1.0, std::max(e - 11, -24));
    const double r = std::nearbyint(x / ulp) * ulp;
    return std::abs(r) >= 65536 ? std::copysign(HUGE_VAL, x) : r;
}

}  // namespace

TEST_CASE("binary16 as written here: ties to even, subnormals, overflow") {
    CHECK(binary16(1 + 0x1p-11) == 1);
    CHECK(binary16(1 + 3 * 0x1p-11) == 1 + 0x1p-9);
    CHECK(binary16(0.1) == 0x1.998p-4);
    CHECK(binary16(0x1p-25) == 0);
    CHECK(binary16(3 * 0x1p-26) == 0x1p-24);
    CHECK(binary16(65519.99) == 65504);
    CHECK(std::isinf(binary16(65520)));
}

TEST_CASE("verify --brdf: a mediump expression's value is the binary16 rounding of each value and operation") {
    struct values {
        double p, q, r;
    };
    // a rounding of each step; a product in the subnormals; a sum that rounds to even
    const auto v = GENERATE(values{0.1, 2.5, 0}, values{1e-3, 1e-3, 0}, values{0.1, 0.2, 0.25}, values{0.07, 0.11, 0.0625});
    const auto out = run("--brdf '" + files().expression + "' --param p=" + std::to_string(v.p) + " --param q=" + std::to_string(v.q) +
                         " --param r=" + std::to_string(v.r) + " --theta 30 --json");
    REQUIRE(out.status == 0);
    const auto a = albedos(out.out);
    REQUIRE(a.size() == 1);
    CAPTURE(v.p, v.q, v.r, a[0].dump());
    auto input = [](double x) { return binary16(static_cast<float>(x)); };  // a float parameter made mediump
    const double expected = binary16(binary16(input(v.p) * input(v.q)) + input(v.r));
    const double in_double = v.p * v.q + v.r;
    REQUIRE(a[0]["albedo_fp16"].is_number());
    CHECK(std::abs(a[0]["albedo_fp16"].get<double>() / pi / expected - 1) < 1e-6);
    CHECK(std::abs(a[0]["albedo"].get<double>() / pi / in_double - 1) < 1e-12);
    CHECK(a[0]["fp16_breakdown"] == false);
}

TEST_CASE("verify --brdf: a mediump value past binary16's range is Inf, a breakdown with where and by how much") {
    const auto out = run("--brdf '" + files().expression + "' --param p=300 --param q=300 --theta 30 --json");
    CHECK(out.status == 1);
    const auto a = albedos(out.out);
    REQUIRE(a.size() == 1);
    CAPTURE(a[0].dump());
    CHECK(a[0]["values"] == "reflectance");  // double's verdict: 90000 everywhere
    CHECK(a[0]["albedo_fp16"].is_null());
    CHECK(a[0]["fp16_breakdown"] == true);
    CHECK(a[0]["pass"] == false);  // for the gain (pi 90000): a breakdown in fp16 alone does not fail
    CHECK(a[0]["reason"].get<std::string>().find("fp16 breaks down (reported, not failed): binary16 inf against double 9e+04") != std::string::npos);
}

TEST_CASE("verify --brdf: GGX's D from 1 - (N.H)^2 in mediump breaks down at low roughness, from |N x H|^2 it does not") {
    const auto out = run("--brdf '" + ggx_file + "' --param roughness=0.1,0.5 --param robust=false,true --theta 0,60 --json");
    REQUIRE((out.status == 0 || out.status == 1));
    const auto a = albedos(out.out);
    REQUIRE(a.size() == 8);
    for (const auto& r : a) {
        const double roughness = r["param_roughness"], theta = r["theta_deg"];
        const bool robust = r["param_robust"];
        CAPTURE(roughness, robust, theta, r.dump());
        REQUIRE(r["albedo_fp16"].is_number());
        const double err16 = std::abs(r["albedo_fp16"].get<double>() - r["albedo"].get<double>());
        if (robust) {
            CHECK(r["fp16_breakdown"] == false);
            CHECK(r["pass"] == true);
            CHECK(err16 < 0.01);
            CHECK(r["fp32_breakdown"] == false);
        } else if (roughness == 0.1) {
            // 1 - (N.H)^2 from N.H rounded to 2^-11 where alpha^2 is 1e-4: D many times too large
            CHECK(r["fp16_breakdown"] == true);
            CHECK(err16 > 1);
            CHECK(r["reason"].get<std::string>().find("fp16 breaks down (reported, not failed): binary16 ") != std::string::npos);
        }
    }
}

TEST_CASE("verify --brdf: a file without reduced precision has no albedo_fp16") {
    const auto out = run("--brdf '" + std::string(NORMZOO_SOURCE_DIR) + "/examples/brdfs/ggx-smith-schlick.brdf' --param roughness=0.5 --theta 30 --json");
    REQUIRE(out.status == 0);
    const auto a = albedos(out.out);
    REQUIRE(a.size() == 1);
    CHECK_FALSE(a[0].contains("albedo_fp16"));
    CHECK_FALSE(a[0].contains("fp16_breakdown"));
}
