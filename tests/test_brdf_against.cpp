// verify --brdf FILE --against MATERIAL (docs/materials.md, "A shader's conformance to a
// material"): the example GGX file against the composition it writes out passes to rounding; against
// the separable Smith G, which it does not write, it fails, naming where f differs and by how much
// the albedo does; the parameters bind by name or by --map, and bad input is exit 2 naming it.
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <string>

#include "brdf_runs.hpp"
#include "temp_files.hpp"

namespace {

using normzoo_test::records_of;
using normzoo_test::run;

std::string ggx_file() { return std::string(NORMZOO_SOURCE_DIR) + "/examples/brdfs/ggx-smith-schlick.brdf"; }

std::string against(const std::string& reference, const std::string& more = "") {
    return "--brdf '" + ggx_file() + "' --param roughness=0.3..0.9 --steps 3 --param f0=0.04 --theta 0,60,85 --json --against " +
           reference + " --map roughness=r" + more;
}

}  // namespace

TEST_CASE("verify --brdf --against: the code that writes a composition out conforms to it to rounding") {
    const auto r = run(against("ggx/smith-height-correlated/schlick"));
    REQUIRE(r.status == 0);
    const auto rows = records_of(r.out, "brdf-conformance");
    REQUIRE(rows.size() == 3);
    for (const auto& row : rows) {
        INFO(row.dump());
        CHECK(row["pass"] == true);
        CHECK(row["max_relative_f"].get<double>() < 1e-12);  // the same arithmetic in double, but for pow's
        CHECK(row["albedo_difference"].get<double>() <= row["albedo_bound"].get<double>());
        CHECK(row["directions"].get<long>() == 3 * 20 * 24);  // each incidence, L on 20 polar angles and 24 azimuths
    }
}

TEST_CASE("verify --brdf --against: against the separable Smith G it fails, where and by how much") {
    const auto r = run(against("ggx/smith-separable/schlick"));
    REQUIRE(r.status == 1);
    const auto rows = records_of(r.out, "brdf-conformance");
    REQUIRE(rows.size() == 3);
    for (const auto& row : rows) {
        INFO(row.dump());
        CHECK(row["pass"] == false);
        // the two G agree at N.L = 1 or N.V = 1 and part most at grazing: 0.2 to 4 here
        CHECK(row["max_relative_f"].get<double>() > 0.1);
        CHECK(row["where"].get<std::string>().find("theta_l 89.9") == 0);
        CHECK(row["albedo_difference"].get<double>() > 1e-3);
        CHECK(row["reason"].get<std::string>().find("f differs by") == 0);
    }
    // a tolerance above the largest difference passes
    CHECK(run(against("ggx/smith-separable/schlick", " --against-tolerance 10")).status == 0);
}

TEST_CASE("verify --brdf --against: bad input is exit 2 naming it") {
    const std::string c = "--against ggx/smith-height-correlated/schlick ";
    const auto [args, named] = GENERATE_COPY(table<std::string, std::string>({
        {"--map roughness=r", "--map is read with --against"},
        {c + "--map roughness", "--map roughness: not SHADER_PARAM=MATERIAL_PARAM"},
        {c + "--map shine=r", "the code has no parameter shine"},
        {c + "--map roughness=sheen", "has no parameter sheen"},
        {"--against no-such-material", "unknown material 'no-such-material'"},
        {c + "--against-tolerance -1", "--against-tolerance"},
    }));
    const auto r = run("--brdf '" + ggx_file() + "' --theta 0 " + args, true);
    CAPTURE(args, r.out);
    CHECK(r.status == 2);
    CHECK(r.out.find(named) != std::string::npos);
}

// The glTF example (the specification's Appendix B) against the material gltf; and the same file
// with the mix its older sample code made (F0 mixed first; KhronosGroup/glTF, number 2386): the specular lobe is
// the same (Schlick's F is linear in F0), but the diffuse is weighted by 1 - F of the mixed F0
// instead of 1 - F of 0.04, which agrees with the specification at metallic 0 and 1 only.
TEST_CASE("verify --brdf --against gltf: the specification's code conforms, and mixing F0 first does not between 0 and 1") {
    const std::string gltf = std::string(NORMZOO_SOURCE_DIR) + "/examples/brdfs/gltf.brdf";
    const std::string args = " --param roughness=0.2,0.8 --param metallic=0,0.5,1 --theta 0,70 --json --against gltf";
    const auto good = run("--brdf '" + gltf + "'" + args);
    REQUIRE((good.status == 0 || good.status == 1));  // 1: glTF's dielectric gains energy at grazing (the brdf table)
    for (const auto& row : records_of(good.out, "brdf-conformance")) {
        INFO(row.dump());
        CHECK(row["pass"] == true);
        CHECK(row["max_relative_f"].get<double>() < 1e-12);
    }
    std::ifstream in(gltf);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string mixed = "return mix(dielectric, metal, metallic);";
    REQUIRE(text.find(mixed) != std::string::npos);
    text.replace(text.find(mixed), mixed.size(),
                 "vec3 f0 = mix(vec3(0.04), baseColor, metallic);\n"
                 "    vec3 F = f0 + (vec3(1.0) - f0) * s;\n"
                 "    return (1.0 - metallic) * (vec3(1.0) - F) * baseColor / PI + F * specular;");
    normzoo_test::temp_dir dir("against-f0-first");
    const auto path = dir.path / "f0-first.brdf";
    std::ofstream(path) << text;
    const auto bad = run("--brdf '" + path.string() + "'" + args);
    REQUIRE(bad.status == 1);
    for (const auto& row : records_of(bad.out, "brdf-conformance")) {
        INFO(row.dump());
        const double m = row["param_metallic"].get<double>();
        CHECK(row["pass"] == (m == 0 || m == 1));
        if (m == 0.5) CHECK(row["max_relative_f"].get<double>() > 1e-3);
    }
}
