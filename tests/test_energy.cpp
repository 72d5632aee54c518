// The energy tables: records and verdicts, the summary, the seed's claims, the seed 000 F V
// comparison (crossings in closed form against the curves).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <string_view>

#include <verify/tables/energy.hpp>
#include <verify/tables/energy_claims.hpp>
#include <verify/tables/fresnel_visibility.hpp>
#include <verify/tables/montecarlo.hpp>

using namespace normzoo;
using namespace verify;  // the tables under test

namespace {
double number(const record& r, const char* key) { return std::get<double>(*r.find(key)); }
std::string text(const record& r, const char* key) { return std::get<std::string>(*r.find(key)); }
}  // namespace

TEST_CASE("verdicts: gains, conserves, and equality within error") {
    CHECK(std::string(energy_verdict_text(1.075, 1e-14)) == "gains");
    CHECK(std::string(energy_verdict_text(0.999, 1e-14)) == "conserves");
    CHECK(std::string(energy_verdict_text(1 + 1e-15, 1e-14)) == "equal within error");
}

TEST_CASE("energy records carry the table's keys and check the closed form at normal incidence") {
    const auto records = energy_table({"phong-modified", "blinn-phong-modified-approx", "lambert"}, shortest_decimals({1, 8}),
                                      shortest_decimals({0, 45, 89.99}), 2);
    REQUIRE(records.size() == 2 * 2 * 3 + 3);
    for (const auto& r : records) {
        for (const char* k : {"model", "parameter", "value", "theta_deg", "albedo", "error_estimate", "conserving", "pass"})
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
    const auto sweep = energy_sweep({"phong", "phong-modified", "lambert"}, shortest_decimals({16}), shortest_decimals({0, 30, 60, 85, 89}), 2);
    const auto summary = energy_summary_table(energy_summary(sweep, 2));
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
    const auto [t, e] = verify::detail::refine_maximum(albedo_at, 85, 89);
    const double at_89 = albedo<brdf::cook_torrance_ksk>(89, 16).value;
    CHECK(t == Approx(89).margin(1e-3));
    CHECK(e.value >= at_89 - 1e-9);
}

TEST_CASE("claims: the identities hold and the approximate factor's gain peaks at 7.52%") {
    const auto sweep = energy_sweep({"phong-modified", "blinn-phong-modified", "blinn-phong-modified-approx"},
                                    shortest_decimals({1, 8, 64}), shortest_decimals({0, 45, 89}), 2);
    const auto claims = energy_claims(sweep, energy_summary(sweep, 2));
    REQUIRE(claims.size() == 3);
    CHECK(std::get<bool>(*claims[0].find("pass")));
    CHECK(std::get<bool>(*claims[1].find("pass")));
    CHECK(std::get<bool>(*claims[2].find("holds")));
    CHECK(text(claims[2], "detail").find("peaks at 0.0752012") != std::string::npos);
}

namespace {
// A form no table knows of: the concept of brdf/brdf.hpp is all the energy table needs.
struct half_lambert {
    static constexpr const char* id = "half-lambert";
    static constexpr const char* formula = "k/pi";
    static constexpr const char* literature = "none: a test form";
    static constexpr double grid[] = {0.25, 0.5};
    static constexpr std::array<brdf::parameter, 1> parameters{brdf::parameter{"k", "the scale", 0, 1, grid}};
    static constexpr bool has_exponent = false;
    static constexpr bool has_specular = false;
    static constexpr bool reciprocal = true;
    static constexpr brdf::lobe_kind lobe = brdf::lobe_kind::normal;
    static constexpr int inverse_lh_power = 0;
    static constexpr bool fresnel = false;
    static constexpr brdf::check_point monte_carlo_case{0.5, 30};
    template <class T>
    static T f(const vec3<T>& /*l*/, const vec3<T>& /*v*/, const brdf::params<T>& p) { return p.roughness / pi<T>(); }
    template <class T>
    static T albedo_at(const T& /*cos_t*/) { return T(0); }  // no closed form: k is in no signature
};
}  // namespace

TEST_CASE("every form of the registry appears in the energy tables, with its declared parameter and grid") {
    std::vector<std::string> ids;
    for (auto id : brdf_ids()) ids.emplace_back(id);
    const auto sweep = energy_sweep(ids, shortest_decimals({0}), 2);
    std::vector<std::string_view> seen;
    for (const auto& a : sweep)
        if (seen.empty() || seen.back() != a.model) seen.push_back(a.model);
    const auto all = brdf_ids();
    CHECK(seen == std::vector<std::string_view>(all.begin(), all.end()));
    for_each_brdf([&](auto form) {
        using Form = decltype(form);
        std::vector<double> values;
        for (const auto& a : sweep)
            if (a.model == Form::id) {
                CHECK(a.parameter == brdf::swept_parameter_name<Form>());
                values.push_back(a.value);
            }
        std::vector<double> declared{0};
        if constexpr (brdf::has_swept_parameter<Form>()) declared = doubles_of(declared_grid(brdf::swept_parameter<Form>()));
        CAPTURE(Form::id);
        CHECK(values == declared);
        CHECK(!energy_record(sweep.front()).failed());
    });
    const auto summary = energy_summary(sweep, 2);
    CHECK(summary.size() == sweep.size());  // one angle: one group per point
    std::vector<std::string> mc;
    for (const auto& c : default_monte_carlo_cases()) mc.emplace_back(c.model);
    CHECK(mc == ids);
}

TEST_CASE("a form the tables do not name is swept from what it declares") {
    const auto a = energy_point<half_lambert>(decimal("0.5"), decimal("60"), {});
    CHECK(a.parameter == "k");
    CHECK(a.value == 0.5);
    CHECK(a.albedo.value == Approx(0.5).epsilon(1e-12));
    CHECK(a.closed_form);  // albedo_at is detected: here it disagrees, so the point is not trusted
    CHECK_FALSE(a.trusted);
    CHECK(a.verdict == albedo_verdict::conserves);
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
