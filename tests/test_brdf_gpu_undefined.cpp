// verify --brdf's report of the operations a GPU leaves undefined
// (docs/brdf-code.md#gpu-undefined-operations): each operation of tests/shaders/gpu-undefined.glsl
// found, named, with the directions where, even where the CPU's result is a number; none on a
// well-defined lobe or on the examples. One shader file, compiled once (then cached), serves the
// cases.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "brdf_runs.hpp"
#include "temp_files.hpp"

using normzoo_test::run_shell;

namespace {

const std::string shader = NORMZOO_SOURCE_DIR "/tests/shaders/gpu-undefined.glsl";

using normzoo_test::run;

std::vector<nlohmann::json> albedos(const std::string& json) { return normzoo_test::records_of(json, "brdf"); }

// The z of a direction written x,y,z
double z_of(const std::string& xyz) {
    std::istringstream in(xyz);
    double x = 0, y = 0, z = 0;
    char comma = 0;
    in >> x >> comma >> y >> comma >> z;
    return z;
}

}  // namespace

TEST_CASE("verify --brdf: each operation a GPU leaves undefined is reported, named, with where") {
    struct expected {
        int op;
        const char* name;
        double z_low, z_high;  // where it is undefined: the cosine of the direction integrated over
    };
    const auto e = GENERATE(expected{1, "pow of a negative base", 0, 0.2887}, expected{2, "sqrt of a negative", 0, 0.2887},
                            expected{3, "inversesqrt of a value <= 0", 0, 0.2887}, expected{4, "log of a value <= 0", 0, 0.2887},
                            expected{5, "asin or acos outside [-1, 1]", 0.6735, 1}, expected{6, "atan(y, x) with x = y = 0", 0, 1},
                            expected{7, "normalize of a zero vector", 0, 1}, expected{8, "division by zero", 0, 1});
    for (const char* fixed : {"light", "view"}) {
        const auto out = run("--brdf '" + shader + "' --param op=" + std::to_string(e.op) + " --theta 30 --json --fixed " + fixed);
        CAPTURE(e.op, fixed);
        CHECK(out.status == 1);
        const auto a = albedos(out.out);
        REQUIRE(a.size() == 1);
        const auto& r = a[0];
        CAPTURE(r.dump());
        CHECK(r["values"] == "gpu-undefined");
        CHECK(r["pass"] == false);
        CHECK(r["albedo"].is_number());  // the CPU's numbers, finite here
        CHECK(r["problem_count"].get<long>() > 0);
        const double z = z_of(r["problem_V"]);
        CHECK(z >= e.z_low);
        CHECK(z <= e.z_high);
        const std::string reason = r["reason"];
        CHECK(reason.find(std::string("undefined on a GPU: ") + e.name) != std::string::npos);
        CHECK(reason.find(" at L=") != std::string::npos);
        // only the one operation
        CHECK(reason.find("undefined on a GPU") == reason.rfind("undefined on a GPU"));
    }
}

TEST_CASE("verify --brdf: no operation undefined on a GPU on a well-defined lobe or on the examples") {
    const auto out = run("--brdf '" + shader + "' --param op=0 --theta 0,60 --json");
    CHECK(out.status == 0);
    for (const auto& r : albedos(out.out)) {
        CHECK(r["values"] == "reflectance");
        CHECK(r["reason"].is_null());
    }
    std::vector<std::string> examples;
    for (const auto& f : std::filesystem::directory_iterator(NORMZOO_SOURCE_DIR "/examples/brdfs"))
        if (f.is_regular_file() && normzoo_test::slurp(f.path()).find("sampler2D") == std::string::npos)  // a texture's: below
            examples.push_back("'" + f.path().string() + "'");
    const std::string engine = NORMZOO_SOURCE_DIR "/examples/brdfs/engine";
    examples.push_back("'" + engine + "/specular.glsl' --include-dir '" + engine + "/common'");
    for (const auto& args : examples) {
        CAPTURE(args);
        const auto ex = run("--brdf " + args + " --theta 0,45,89 --json");
        REQUIRE((ex.status == 0 || ex.status == 1));
        for (const auto& r : albedos(ex.out)) {
            CAPTURE(r.dump());
            CHECK(r["values"] != "gpu-undefined");
            CHECK((r["reason"].is_null() || r["reason"].get<std::string>().find("undefined on a GPU") == std::string::npos));
        }
    }
}
