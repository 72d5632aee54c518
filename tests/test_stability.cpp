// The stress table: values at the ends of each domain are checked against their references or
// refused for a reason that holds; the naive formulations break where the arithmetic says.
#include <catch2/catch.hpp>

#include <normzoo/normzoo.hpp>
#include <verify/tables/tables.hpp>

using namespace normzoo;
using namespace verify;  // the tables under test

namespace {
const field_value& get(const record& r, const char* key) {
    const auto* v = r.find(key);
    REQUIRE(v);
    return *v;
}
bool passes(const record& r) { return std::get<bool>(get(r, "pass")); }
std::string text(const record& r, const char* key) { return std::get<std::string>(get(r, key)); }
}  // namespace

TEST_CASE("zoo values to n = 1e9 are within their bounds in binary128 and double") {
    const double n = GENERATE(0.0, 1e-12, 1e9);
    CAPTURE(n);
    for (const auto& r : verify::detail::zoo_stability<zoo::blinn_phong_modified>(n)) {
        CHECK(text(r, "status") == "ok");
        CHECK(passes(r));
        CHECK(std::get<double>(get(r, "rel_error")) <= std::get<double>(get(r, "error_estimate")));
    }
}

TEST_CASE("irradiance of a subnormal ratio: kept in binary128, refused in double with the reason") {
    const double ratio = GENERATE(1e-310, 5e-324);
    CAPTURE(ratio);
    const auto rs = verify::detail::irradiance_stability(light_kind::sphere, ratio, 0);
    REQUIRE(rs.size() == 2);
    CHECK(text(rs[0], "status") == "ok");
    CHECK(passes(rs[0]));
    CHECK(text(rs[1], "status") == "refused");
    CHECK(text(rs[1], "reason").find("below the smallest normal double") != std::string::npos);
    CHECK(passes(rs[1]));
    // a ratio whose E/L a double holds is not refused
    const auto fine = verify::detail::irradiance_stability(light_kind::disk, 1e-100, 0);
    CHECK(text(fine[1], "status") == "ok");
    CHECK(passes(fine[1]));
}

TEST_CASE("albedo at 90 - 1e-6 degrees: Lambert's is 1, a lobe's agrees with a tighter run") {
    CHECK(passes(verify::detail::albedo_stability<brdf::lambert>(90 - 1e-6, 0)));
    const auto r = verify::detail::albedo_stability<brdf::phong_modified>(90 - 1e-6, 16);
    CHECK(text(r, "reference_kind") == "same integrator, tolerance 1e-12");
    CHECK(passes(r));
}

TEST_CASE("a check against a wrong reference fails") {
    record r{"stability", {}};
    verify::detail::set_checked<double>(r, 1.0, 1e-12, 1.0 + 1e-9, 0.0, "test", 17);
    CHECK_FALSE(passes(r));
    verify::detail::set_checked<double>(r, 1.0, 1e-12, std::nan(""), 0.0, "test", 17);
    CHECK_FALSE(passes(r));
}

TEST_CASE("naive formulations break where the arithmetic says") {
    std::vector<verify::detail::naive_sweep> sweeps;
    verify::detail::irradiance_naive(sweeps);
    REQUIRE(sweeps.size() == 2);
    // 1 - cos^2 b with cos b = sqrt(1 - r^2) keeps ~eps / r^2 relative error: 1e-8 is passed by r = 1e-4
    const auto cancel = verify::detail::naive_record(sweeps[0]);
    CHECK(std::get<double>(get(cancel, "breaks_at")) == 1e-4);
    // r^2 in double: subnormal from r ~ 1.5e-154, so the first grid point below that, 1e-160
    const auto range = verify::detail::naive_record(sweeps[1]);
    CHECK(std::get<double>(get(range, "breaks_at")) == 1e-160);
    // pow(cos, n): n times the cosine's rounding, above 1e-8 only at n = 1e9 on the grid
    verify::detail::zoo_naive<zoo::phong>(sweeps);
    const auto power = verify::detail::naive_record(sweeps[2]);
    CHECK(text(power, "formulation").rfind("pow(cos theta, n)", 0) == 0);
    CHECK(std::get<double>(get(power, "breaks_at")) == 1e9);
}
