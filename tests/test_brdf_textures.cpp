// verify --brdf --texture end to end (docs/brdf-code.md#textures): an energy-compensated GGX
// lobe that divides by the split-sum table's A + B, sampled from tables `verify lut` bakes (8-bit
// PNG, float OpenEXR, the OpenEXR with its rows flipped). With V held, the lobe's albedo is
// E(mu) / E_table(mu): 1 where the table's value is exact, so each table's albedo is held to 1
// within its error bound, storage included, and the bound shrinks from 8 bits to float. Between
// texel centres the sampler's value is the bilinear mean of the two texels, which the test
// computes from the exact pair (`verify lut --json`): sampling half a texel off fails it. One
// GLSL file (the example's) and one HLSL file, each compiled once, serve every case; the engine
// example (examples/brdfs/engine/) with its energy compensation is a third.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "brdf_runs.hpp"
#include "temp_files.hpp"

namespace fs = std::filesystem;
using normzoo_test::run_shell;

namespace {

// examples/brdfs/energy-compensated-ggx.glsl, and the same in HLSL: GGX with Smith's
// height-correlated masking as Filament writes them (brdf.fs: D_GGX, V_SmithGGXCorrelated),
// F = 1, over the table's E = A + B at (N.V, r): the composition ggx/smith-height-correlated/one
// that `verify lut` bakes by default.
const char* header = R"(// [brdf]
// [parameters.r]
// range = [0.05, 1]
// default = 0.515625
//
)";
const char* lobe = R"(
const float PI = 3.14159265358979323846;

float D_GGX(float NoH, float a) {
    float ratio = a / (1.0 - NoH * NoH + NoH * NoH * a * a);
    return ratio * ratio / PI;
}

float V_SmithGGXCorrelated(float NoV, float NoL, float a) {
    float a2 = a * a;
    float lightTerm = NoV * sqrt((NoL - NoL * a2) * NoL + a2);
    float viewTerm = NoL * sqrt((NoV - NoV * a2) * NoV + a2);
    return 0.5 / (viewTerm + lightTerm);
}
)";
// The HLSL: a Texture2D<float2> and its SamplerState, Sample and SampleLevel.
const char* hlsl_body = R"(
Texture2D<float2> dfg : register(t0);
SamplerState dfgSampler : register(s0);

float3 BRDF(float3 L, float3 V, float3 N, float3 X, float3 Y) {
    float NoV = dot(N, V), NoL = dot(N, L);
    if (NoL <= 0.0 || NoV <= 0.0) return 0;
    float3 H = normalize(L + V);
    float a = r * r;
    float2 ab = 0.5 * (dfg.Sample(dfgSampler, float2(NoV, r)) + dfg.SampleLevel(dfgSampler, float2(NoV, r), 0));
    return D_GGX(dot(N, H), a) * V_SmithGGXCorrelated(NoV, NoL, a) / (ab.x + ab.y);
}
)";

std::string zeros(std::size_t n) {
    std::string s = "0";
    for (std::size_t i = 1; i < n; ++i) s += ",0";
    return s;
}

struct fixture {
    normzoo_test::temp_dir dir{"brdf-textures"};
    std::string glsl = NORMZOO_SOURCE_DIR "/examples/brdfs/energy-compensated-ggx.glsl";
    std::string hlsl = dir.file("lobe.hlsl", std::string(header) + lobe + hlsl_body);
    std::string tables = (dir.path / "tables").string();
    // one texel over the cap, a C header's array of zeros shaped [1024][1025][1]
    std::string big = dir.file("big.h", "static const float big[1024][1025][1] = {" + zeros(1024 * 1025) + "};\n");
    fixture() {
        // 32 x 32 split-sum tables at texel centres (i + 0.5)/32 in mu and r, rows r, columns mu
        const std::pair<const char*, const char*> made[] = {{"plain", "--format png8"},
                                                            {"plain", "--format exr"},
                                                            {"flipped", "--format exr --layout row0=high"},
                                                            {"srgb", "--format ktx2 --layout encoding=srgb"}};
        for (const auto& [folder, how] : made) {
            const std::string out = tables + "/" + folder;
            const auto r = run_shell(std::string(NORMZOO_VERIFY_BIN) + " lut --kind dfg --size 32 " + how + " --out '" + out + "' >/dev/null 2>&1");
            REQUIRE(r.status == 0);
        }
    }
    std::string table(const char* which, const char* ext) const {
        for (const auto& e : fs::directory_iterator(fs::path(tables) / which))
            if (e.path().extension() == ext && e.path().string().find("8bit") == std::string::npos) return e.path().string();
        for (const auto& e : fs::directory_iterator(fs::path(tables) / which))
            if (e.path().extension() == ext) return e.path().string();
        FAIL("no " << ext << " table in " << which);
        return {};
    }
};

const fixture& files() {
    static const fixture f;
    return f;
}

using normzoo_test::run;

nlohmann::json albedo_record(const std::string& json) {
    const auto doc = nlohmann::json::parse(json);
    for (const auto& r : doc["records"])
        if (r["table"] == "brdf") return r;
    FAIL("no brdf record");
    return {};
}

// The exact E = A + B at (mu, r) and its bound, from `verify lut`.
std::pair<double, double> exact_e(double mu, double r) {
    const auto out = run("lut --kind dfg --mu " + std::to_string(mu) + " --r " + std::to_string(r) + " --json");
    REQUIRE(out.status == 0);
    const auto doc = nlohmann::json::parse(out.out);
    for (const auto& rec : doc["records"])
        if (rec.contains("A") && rec.contains("B"))
            return {rec["A"].get<double>() + rec["B"].get<double>(), rec["A_error_estimate"].get<double>() + rec["B_error_estimate"].get<double>()};
    FAIL("no lut record: " << out.out);
    return {};
}

// mu at texel i's centre, r at row j's: the sampler returns the stored texel there.
constexpr double centre_mu = 20.5 / 32, centre_r = 16.5 / 32;

}  // namespace

TEST_CASE("verify --brdf --texture: a lobe over an 8-bit and a float DFG table, its albedo 1 within the storage bound") {
    const auto& f = files();
    double bound_8bit = 0, bound_float = 0;
    struct row {
        const char* name;
        std::string table, layout;
        double* bound;
    };
    const std::vector<row> rows = {{"png8", f.table("plain", ".png"), "", &bound_8bit},
                                   {"exr", f.table("plain", ".exr"), "", &bound_float},
                                   {"exr flipped", f.table("flipped", ".exr"), " --layout row0=high", nullptr},
                                   // an sRGB format: decoded before filtering, as its sampler decodes it, unasked
                                   {"ktx2 srgb", f.table("srgb", ".ktx2"), "", nullptr}};
    for (const auto& [name, table, layout, bound] : rows) {
        const auto r = run("--brdf '" + f.glsl + "' --texture 'dfg=" + table + "'" + layout + " --fixed view --mu " +
                           std::to_string(centre_mu) + " --json");
        REQUIRE((r.status == 0 || r.status == 1));
        const auto a = albedo_record(r.out);
        CAPTURE(name, a.dump());
        REQUIRE(a["albedo"].is_number());
        CHECK(a["texture_storage_bound"].get<double>() > 0);
        CHECK(a["error_estimate"].get<double>() >= a["texture_storage_bound"].get<double>());
        CHECK(std::abs(a["albedo"].get<double>() - 1) <= a["error_estimate"].get<double>());
        if (bound) *bound = a["texture_storage_bound"];
    }
    // 8 bits hold a value to half of 1/255, a float to half an ulp: A and B move together, so
    // the bound is about 2 (0.5/255) / E at E ~ 0.8, and 2^-24 relative in float
    CAPTURE(bound_8bit, bound_float);
    CHECK(bound_8bit > 1e-3);
    CHECK(bound_8bit < 1e-2);
    CHECK(bound_float < 1e-6);
    // the flipped file read without its layout takes the roughness 1 - r: the albedo is far from 1
    const auto wrong = run("--brdf '" + f.glsl + "' --texture 'dfg=" + f.table("flipped", ".exr") + "' --fixed view --mu " +
                           std::to_string(centre_mu) + " --json");
    const auto w = albedo_record(wrong.out);
    CHECK(std::abs(w["albedo"].get<double>() - 1) > 100 * w["error_estimate"].get<double>());
}

TEST_CASE("verify --brdf --texture: the engine example's energy compensation, unedited, at F0 = 1") {
    // examples/brdfs/engine/specular.glsl with ENERGY_COMPENSATION: textureLod of dfgLut in GLSL
    // ES 3.00, times 1 + F0 (1/E - 1), which is 1/E at F0 = 1: its albedo with V held is 1 where
    // the table's E is exact
    const auto& f = files();
    const std::string engine = NORMZOO_SOURCE_DIR "/examples/brdfs/engine";
    const auto r = run("--brdf '" + engine + "/specular.glsl' --include-dir '" + engine + "/common' --define ENERGY_COMPENSATION" +
                       " --texture 'dfgLut=" + f.table("plain", ".exr") + "' --param perceptualRoughness=" + std::to_string(centre_r) +
                       " --param f0=1,1,1 --fixed view --mu " + std::to_string(centre_mu) + " --json");
    REQUIRE((r.status == 0 || r.status == 1));
    const auto a = albedo_record(r.out);
    CAPTURE(a.dump());
    CHECK(std::abs(a["albedo"].get<double>() - 1) <= a["error_estimate"].get<double>());
    CHECK(a["texture_storage_bound"].get<double>() < 1e-6);
}

TEST_CASE("verify --brdf --texture: between texel centres the sampler is the bilinear mean, as the HLSL Sample") {
    const auto& f = files();
    // mu at the edge between columns 19 and 20, r at row 16's centre: the sampler's E is the mean
    // of the two texels'; half a texel off (corners for centres) it would be one texel's
    const double mu = 20.0 / 32;
    const auto [e_mu, b_mu] = exact_e(mu, centre_r);
    const auto [e19, b19] = exact_e(19.5 / 32, centre_r);
    const auto [e20, b20] = exact_e(20.5 / 32, centre_r);
    const double expected = e_mu / (0.5 * (e19 + e20));
    const double slack = (b_mu + b19 + b20) * 4;  // the exact values' bounds, through the quotient (E ~ 0.8)
    for (const std::string& file : {f.glsl, f.hlsl}) {
        const auto r = run("--brdf '" + file + "' --texture 'dfg=" + f.table("plain", ".exr") + "' --fixed view --mu " +
                           std::to_string(mu) + " --json");
        REQUIRE((r.status == 0 || r.status == 1));
        const auto a = albedo_record(r.out);
        CAPTURE(file, a.dump(), expected, e_mu, e19, e20);
        CHECK(std::abs(a["albedo"].get<double>() - expected) <= a["error_estimate"].get<double>() + slack);
        // the same point is not the one texel's (what sampling at corners gives)
        CHECK(std::abs(a["albedo"].get<double>() - e_mu / e20) > 100 * (a["error_estimate"].get<double>() + slack));
    }
}

TEST_CASE("verify --brdf --texture: what does not bind is exit 2, named, with nothing written") {
    const auto& f = files();
    const std::string out = (f.dir.path / "out").string();
    const std::string exr = f.table("plain", ".exr");
    const std::string bad = f.dir.file("bad.png", "\x89PNG\r\n\x1a\nnot a png");
    struct refusal {
        std::string args, says;
    };
    const std::vector<refusal> cases = {
        {"", "sampler2D dfg is not bound to a table: --texture dfg=FILE binds it"},
        {"--texture 'dfg=" + exr + "' --texture 'env=" + exr + "'", "--texture env: " + f.glsl + " declares no texture env"},
        {"--texture 'dfg=" + bad + "'", "--texture dfg: " + bad},
        {"--texture 'dfg=" + (f.dir.path / "none.exr").string() + "'", "--texture dfg: " + (f.dir.path / "none.exr").string()},
        {"--texture 'dfg=" + f.dir.file("points.csv", "mu,r,A,B\n0.5,0.5,0.8,0.05\n") + "'", "table holds points"},
        {"--texture dfg", "--texture: 'dfg' is not NAME=FILE"},
        {"--texture '1x=" + exr + "'", "is not NAME=FILE"},
        {"--texture 'dfg=" + exr + "' --texture 'dfg=" + exr + "'", "--texture: dfg is bound twice"},
        {"--texture 'dfg=" + exr + "' --layout grid=edges", "--layout: grid says what a table's texels mean"},
        {"--texture 'dfg=" + exr + "' --layout encoding=rgbd", "encoding=rgbd is decoded by the shader's own code"},
        {"--layout row0=high", "no --texture is given"},
        {"--texture 'dfg=" + f.big + "'", "is 1025 x 1024 texels; --texture binds at most 1048576"},
    };
    for (const auto& c : cases) {
        const auto r = run("--brdf '" + f.glsl + "' " + c.args + " --theta 0 --out '" + out + "'", true);
        CAPTURE(c.args, r.out);
        CHECK(r.status == 2);
        CHECK(r.out.find(c.says) != std::string::npos);
        CHECK(!fs::exists(out));
    }
}
