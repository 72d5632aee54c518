// The energy tables: records and verdicts, the summary, the seed's claims, the seed 000 F V
// comparison (crossings in closed form against the curves).
#include <catch2/catch.hpp>

#include <cmath>

#include <verify/tables/energy.hpp>
#include <verify/tables/energy_claims.hpp>
#include <verify/tables/fresnel_visibility.hpp>

using namespace normzoo;

namespace {
double number(const record& r, const char* key) { return std::get<double>(*r.find(key)); }
std::string text(const record& r, const char* key) { return std::get<std::string>(*r.find(key)); }
}  // namespace

TEST_CASE("verdicts: gains, conserves, and equality within error") {
    CHECK(std::string(energy_verdict(1.075, 1e-14)) == "gains");
    CHECK(std::string(energy_verdict(0.999, 1e-14)) == "conserves");
    CHECK(std::string(energy_verdict(1 + 1e-15, 1e-14)) == "equal within error");
}

TEST_CASE("energy records carry the SPEC keys and check the closed form at normal incidence") {
    const auto records = energy_table({"phong-modified", "blinn-phong-modified-approx", "lambert"}, {1, 8},
                                      {0, 45, 89.99}, 2);
    REQUIRE(records.size() == 2 * 2 * 3 + 3);
    for (const auto& r : records) {
        for (const char* k : {"model", "n", "theta_deg", "albedo", "error_estimate", "conserving", "pass"})
            CHECK(r.find(k));
        CHECK_FALSE(r.failed());
        if (number(r, "theta_deg") == 0) CHECK(r.find("albedo_closed_form"));
    }
    // (n+8)/(8 pi) at n = 8 and normal incidence: 16/(8 pi) / norm_bpm(8) = 1.075 exactly.
    const auto& approx = records[2 * 3 + 3];
    CHECK(text(approx, "model") == "blinn-phong-modified-approx");
    CHECK(number(approx, "theta_deg") == 0);
    CHECK(number(approx, "albedo") == Approx(1.075).epsilon(1e-13));
    CHECK(text(approx, "verdict") == "gains");
    CHECK(std::get<bool>(*approx.find("conserving")) == false);
}

TEST_CASE("summary: the largest albedo, where, and the verdict per form and exponent") {
    const auto sweep = energy_table({"phong", "phong-modified", "lambert"}, {16}, {0, 30, 60, 85, 89}, 2);
    const auto summary = energy_summary(sweep, 2);
    REQUIRE(summary.size() == 3);
    // phong rises towards grazing incidence: maximum at the last angle, gains.
    CHECK(text(summary[0], "verdict") == "gains");
    CHECK(number(summary[0], "argmax_theta_deg") == 89);
    CHECK(std::get<bool>(*summary[0].find("rising_at_last_angle")));
    CHECK(number(summary[0], "first_gain_theta_deg") == 85);
    // modified Phong: 1 at normal incidence and below elsewhere.
    CHECK(text(summary[1], "verdict") == "equal within error");
    CHECK(number(summary[1], "argmax_theta_deg") == 0);
    // Lambert: 1 everywhere; ties go to the first angle, no refinement.
    CHECK(number(summary[2], "argmax_theta_deg") == 0);
    CHECK_FALSE(std::get<bool>(*summary[2].find("refined")));
}

TEST_CASE("refining an interior maximum finds at least the grid's value") {
    // ksk at n = 16 rises from 85 to 89 degrees: Brent on the bracket returns the larger end.
    const auto albedo_at = [](double theta) { return albedo<brdf::cook_torrance_ksk>(theta, 16); };
    const auto [t, e] = detail::refine_maximum(albedo_at, 85, 89);
    const double at_89 = albedo<brdf::cook_torrance_ksk>(89, 16).value;
    CHECK(t == Approx(89).margin(1e-3));
    CHECK(e.value >= at_89 - 1e-9);
}

TEST_CASE("claims: the identities hold and the approximate factor's gain peaks at 7.52%") {
    const auto sweep = energy_table({"phong-modified", "blinn-phong-modified", "blinn-phong-modified-approx"},
                                    {1, 8, 64}, {0, 45, 89}, 2);
    const auto claims = energy_claims(sweep, energy_summary(sweep, 2));
    REQUIRE(claims.size() == 3);
    CHECK(std::get<bool>(*claims[0].find("pass")));
    CHECK(std::get<bool>(*claims[1].find("pass")));
    CHECK(std::get<bool>(*claims[2].find("holds")));
    CHECK(text(claims[2], "detail").find("peaks at 0.0752012") != std::string::npos);
}

TEST_CASE("F V crossings: the closed-form roots are where the two curves meet") {
    const double k = GENERATE(0.02, 0.05, 0.8);
    const auto roots = fresnel_visibility_crossings(k);
    CHECK(roots.size() == (k < 0.5 ? 2u : 0u));
    for (double x : roots) {
        const double a = brdf::minimalist_cook_torrance::fresnel_visibility(k, x);
        const double b = brdf::cook_torrance_ksk::fresnel_visibility(k, x);
        CHECK(a == Approx(b).epsilon(1e-12));
    }
    // Both equal k/4 at L.H = 1; the minimalist form is larger outside the roots, smaller between.
    CHECK(brdf::minimalist_cook_torrance::fresnel_visibility(k, 1.0) == Approx(k / 4));
    CHECK(brdf::cook_torrance_ksk::fresnel_visibility(k, 1.0) == Approx(k / 4));
    for (const auto& r : fresnel_visibility_table()) {
        if (number(r, "specular") != k) continue;
        const double x = number(r, "l_dot_h");
        const bool between = roots.size() == 2 && x > roots[0] * (1 + 1e-9) && x < roots[1] * (1 - 1e-9);
        const bool outside =
            x < 1 && (roots.empty() || x < roots[0] * (1 - 1e-9) || x > roots[1] * (1 + 1e-9));
        if (between) CHECK(text(r, "larger") == "schlick-ksk");
        if (outside) CHECK(text(r, "larger") == "minimalist");
    }
}
