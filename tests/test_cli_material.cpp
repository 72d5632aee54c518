// The command end to end: energy --material (docs/materials.md), its records and bad input.
#include "cli_helpers.hpp"

using namespace cli_test;

TEST_CASE("materials: energy --material gltf records, per lobe and whole, with verdicts") {
    const auto r = run("energy --material gltf --param baseColor=0.8,0.4,0.2 --param metallic=0.5 --param roughness=0.5 "
                       "--mu 0.1,1 --json");
    REQUIRE(r.status == 0);
    const auto doc = nlohmann::json::parse(r.out);
    REQUIRE(doc["records"].size() == 2);
    for (const auto& rec : doc["records"]) {
        CHECK(rec["table"] == "material");
        CHECK(rec["material"] == "gltf");
        CHECK(rec["param_baseColor"] == nlohmann::json::array({0.8, 0.4, 0.2}));
        CHECK(rec["param_masking"] == "smith-separable");
        CHECK(rec["albedo"].get<double>() == rec["albedo_rgb"][0].get<double>());  // red is the largest
        CHECK(rec["error_estimate"].get<double>() <= 1e-10);
        CHECK(rec["lobes"].size() == 5);  // diffuse, specular, metal; sheen and clearcoat (0 here)
        CHECK(rec["preserving"].is_null());  // a plain gltf claims nothing
        CHECK(rec["reciprocal"]["holds"] == true);
    }
    // a white metal with a compensation claims 1, and gets it
    for (const char* comp : {"kulla-conty", "turquin"}) {
        const auto w = nlohmann::json::parse(run(std::string("energy --material gltf/") + comp + " --param roughness=0.75 --mu 0.5 --json").out);
        CAPTURE(comp);
        REQUIRE(w["records"].size() == 1);
        CHECK(w["records"][0]["preserving"] == true);
        CHECK(std::abs(w["records"][0]["albedo"].get<double>() - 1) <= w["records"][0]["error_estimate"].get<double>());
    }
    // a range sweeps in 5 values, as --brdf's do; --theta instead of --mu
    const auto swept = nlohmann::json::parse(run("energy --material gltf --param metallic=0..1 --theta 60 --json").out);
    REQUIRE(swept["records"].size() == 5);
    CHECK(swept["records"][2]["param_metallic"].get<double>() == 0.5);
}

TEST_CASE("materials: bad input to energy --material is exit 2 naming the culprit") {
    const std::pair<const char*, const char*> bad[] = {
        {"energy --material plastic", "'plastic'"},
        {"energy --material gltf/fdez", "'fdez'"},
        {"energy --material gltf --param shininess=3", "'shininess'"},
        {"energy --material gltf --param metallic=2", "metallic"},
        {"energy --material gltf --param roughness=abc", "roughness"},
        {"energy --material gltf --param baseColor=0.5,0.5", "baseColor"},
        {"energy --material gltf --param masking=smith", "masking"},
        {"energy --material gltf --param ior=0.5", "ior"},
        {"energy --material gltf --param baseColor=0..1", "baseColor"},
        {"energy --material gltf --mu 0", "--mu"},
        {"energy --material gltf --mu 0.5 --theta 10", "--theta"},
        {"zoo --material gltf", "zoo"},
        {"energy --material gltf --n 3", "--n"},
        {"energy --material gltf --param sheenColor=1", "sheenRoughness"},
        {"energy --material gltf --param sheenColor=1.5", "sheenColor"},
        {"energy --material gltf --param sheenColor=1 --param sheenRoughness=2", "sheenRoughness"},
        {"energy --material gltf --param clearcoat=1", "clearcoatRoughness"},
        {"energy --material gltf --param clearcoat=-1", "clearcoat"},
        {"energy --material gltf/turquin --param sheenColor=1 --param sheenRoughness=0.5", "sheen"},
    };
    for (const auto& [args, named] : bad) check_refused(args, named);
}

// KHR_materials_sheen and _clearcoat through the same command: their lobes and parameters appended,
// a white sheen over a white metal below the core (the base scaled by 1 - max(E_v, E(N.L))), a coat
// not reciprocal (its Fresnel reads N.V).
TEST_CASE("materials: energy --material gltf with a sheen and with a clearcoat") {
    const auto sheen = nlohmann::json::parse(
        run("energy --material gltf --param sheenColor=1 --param sheenRoughness=0.5 --mu 0.5 --json").out);
    REQUIRE(sheen["records"].size() == 1);
    const auto& s = sheen["records"][0];
    CHECK(s["param_sheenColor"] == nlohmann::json::array({1, 1, 1}));
    CHECK(s["lobes"].size() == 5);
    CHECK(s["lobes"]["sheen"].get<double>() > 0.18);  // E(0.5) at alpha 0.25 is 0.18785
    CHECK(s["error_estimate"].get<double>() <= 1e-10);
    CHECK(s["reciprocal"]["holds"] == true);  // min(.., ..) is symmetric in L and V
    const auto coat = nlohmann::json::parse(
        run("energy --material gltf --param clearcoat=1 --param clearcoatRoughness=0.25 --mu 0.5 --json").out);
    const auto& c = coat["records"][0];
    CHECK(c["lobes"]["clearcoat"].get<double>() > 0);
    CHECK(c["lobes"]["sheen"].get<double>() == 0);
    CHECK(c["reciprocal"]["holds"] == false);
}
