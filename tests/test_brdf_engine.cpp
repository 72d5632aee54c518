// The engine-style example (examples/brdfs/engine/, docs/brdf-code.md#an-engines-file), checked as
// an engine keeps it: the checked file includes its terms from a shared folder, a macro picks the
// quality, a mobile path, uniforms and mediump. At each quality its albedo is the built-in
// composition's it writes out, computed by the library alone (`energy --model`).
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "temp_files.hpp"

namespace {

const std::string engine = std::string(NORMZOO_SOURCE_DIR) + "/examples/brdfs/engine";

normzoo_test::run_result run_verify(const std::string& args) {
    return normzoo_test::run_shell(std::string(NORMZOO_VERIFY_BIN) + " " + args + " 2>&1");
}

// The --json document: one line, which the failures' lines on stderr may follow.
nlohmann::json records(const std::string& out) {
    const std::size_t start = out.find("{\"records\"");
    return nlohmann::json::parse(out.substr(start, out.find('\n', start) - start))["records"];
}

std::string engine_file(const std::string& defines) {
    return "--brdf '" + engine + "/specular.glsl' --include-dir '" + engine + "/common' " + defines;
}

}  // namespace

TEST_CASE("the engine-style example gives, at each quality, the albedo of the composition it writes out") {
    struct quality {
        const char* defines;
        const char* built_in;  // its G part: the height-correlated Smith term or Hammon's approximation
    };
    const auto q = GENERATE(values<quality>({{"", "ggx/smith-height-correlated"},
                                             {"--define SPECULAR_QUALITY=0", "ggx/hammon"},
                                             {"--define TARGET_MOBILE --define SPECULAR_QUALITY=1", "ggx/smith-height-correlated"}}));
    struct point {
        const char* r;      // perceptual roughness
        const char* alpha;  // its square
        const char* f0;     // one channel; Schlick's F at f0 = 1 is F = 1
        const char* f_part;
    };
    const auto p = GENERATE(values<point>({{"0.3", "0.09", "1", "one"}, {"0.8", "0.64", "0.04", "schlick --f0 0.04"}}));
    const std::string mus = "1,0.5,0.1";
    const auto code = run_verify(engine_file(q.defines) + " --param perceptualRoughness=" + p.r + " --param f0=" + p.f0 + "," + p.f0 +
                                 "," + p.f0 + " --mu " + mus + " --json");
    CAPTURE(q.defines, p.r, p.f0, code.out);
    REQUIRE(code.status == 0);
    const auto built_in = run_verify(std::string("energy --model ") + q.built_in + "/" + p.f_part + " --alpha " + p.alpha + " --mu " + mus + " --json");
    REQUIRE(built_in.status == 0);
    const auto c = records(code.out), b = records(built_in.out);
    std::size_t compared = 0;
    for (const auto& r : c) {
        if (r["table"] != "brdf") continue;
        const auto& e = b.at(compared++);
        CAPTURE(r.dump(), e.dump());
        const double diff = std::abs(r["albedo"].get<double>() - e["albedo"].get<double>());
        CHECK(diff <= r["error_estimate"].get<double>() + e["error_estimate"].get<double>());
        CHECK(r["pass"] == true);
    }
    CHECK(compared == 3);
}

TEST_CASE("the head's command holds the options that build the file, so that it runs again") {
    normzoo_test::temp_dir dir("engine-head");
    const auto r = run_verify(engine_file("--define SPECULAR_QUALITY=0") + " --theta 0 --out '" + dir.path.string() + "'");
    REQUIRE(r.status == 0);
    std::ifstream in(dir.path / "brdf.md");
    const std::string md((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(md.find("/specular.glsl --include-dir " + engine + "/common --define SPECULAR_QUALITY=0`") != std::string::npos);
}

TEST_CASE("a scene builds a material given as code as --define, --include-dir, --texture and --fixed do") {
    const auto scene = run_verify("--scene '" + std::string(NORMZOO_SOURCE_DIR) + "/scenes/engine-shader.toml' --json");
    CAPTURE(scene.out);
    // the compensated material's gains and its reciprocity fail; the two builds without pass
    REQUIRE(scene.status == 1);
    std::size_t compensated_failures = 0, texture_bounds = 0;
    for (const auto& r : records(scene.out)) {
        if (r["material"] != "desktop-compensated") {
            if (r.contains("pass") && !r["pass"].is_null()) CHECK(r["pass"] == true);
            CHECK(!r.contains("texture_storage_bound"));
            continue;
        }
        if (r.contains("pass") && r["pass"] == false) ++compensated_failures;
        if (r.contains("texture_storage_bound")) {
            // 16-bit storage, half a step of each of A and B
            CHECK(r["texture_storage_bound"].get<double>() >= 0.5 / 65535);
            ++texture_bounds;
        }
    }
    CHECK(compensated_failures >= 2);
    CHECK(texture_bounds == 8);
    // the mobile material, against the same file run directly
    const auto direct = run_verify(engine_file("--define TARGET_MOBILE --define SPECULAR_QUALITY=0") +
                                   " --fixed view --param perceptualRoughness=0.3 --param f0=1,1,1 --json");
    REQUIRE(direct.status == 0);
    const auto d = records(direct.out);
    std::size_t matched = 0;
    for (const auto& r : records(scene.out)) {
        if (r["table"] != "brdf" || r["material"] != "mobile" || r["param_perceptualRoughness"] != 0.3) continue;
        CHECK(r["fixed"] == "view");
        const auto& e = d.at(matched++);
        CHECK(r["theta_deg"] == e["theta_deg"]);
        CHECK(r["albedo"] == e["albedo"]);
    }
    CHECK(matched == 8);
}

TEST_CASE("a scene's bad build keys are exit 2 naming the key") {
    struct bad {
        const char* keys;
        const char* says;
    };
    const auto b = GENERATE(values<bad>({{"defines = [\"1X\"]", "materials[1].defines: --define 1X: '1X' is not a macro name"},
                                         {"defines = \"A\"", "materials[1].defines: must be an array of strings"},
                                         {"include_dirs = [\"no-such-folder\"]", "materials[1].include_dirs: no such folder"},
                                         {"fixed = \"normal\"", "materials[1].fixed: 'normal' is not light or view"},
                                         {"textures = { dfgLut = \"no-such.png\" }", "materials[1].textures.dfgLut: no such file"},
                                         {"textures = { 2x = \"s.toml\" }", "materials[1].textures.2x: --texture"},
                                         {"texture_layout = \"row0=high\"", "materials[1].texture_layout: a layout without textures"},
                                         {"textures = { t = \"s.toml\" }\ntexture_layout = \"rows=alpha\"", "materials[1].texture_layout: --brdf: --layout: rows"}}));
    normzoo_test::temp_dir dir("engine-scene");
    const auto scene = dir.path / "s.toml";
    std::ofstream(scene) << "[[materials]]\nname = \"m\"\nbrdf = \"" << engine << "/specular.glsl\"\n" << b.keys << "\n";
    const auto r = run_verify("--scene '" + scene.string() + "'");
    CAPTURE(r.out);
    CHECK(r.status == 2);
    CHECK(r.out.find(b.says) != std::string::npos);
}
