// The albedo quadrature against independent Monte Carlo (issue 3, point 6): for a few cases per
// form, the quadrature must lie within 4 standard errors of the Monte Carlo mean; and how many
// samples Monte Carlo would need to be as accurate as the quadrature.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <normzoo/albedo.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/montecarlo.hpp>
#include <normzoo/registry.hpp>

#include "../record.hpp"

namespace normzoo {

struct monte_carlo_case {
    const char* model;
    double n, theta_deg;
};

// One case per form, away from the extremes where Monte Carlo's variance explodes.
inline std::vector<monte_carlo_case> default_monte_carlo_cases() {
    return {{"lambert", 0, 60},
            {"phong", 4, 80},
            {"phong-modified", 16, 45},
            {"blinn-phong", 64, 70},
            {"blinn-phong-modified", 256, 30},
            {"blinn-phong-modified-approx", 8, 0},
            {"microfacet-blinn", 1024, 60},
            {"minimalist-cook-torrance", 16, 75},
            {"cook-torrance-ksk", 100, 85}};
}

namespace detail {
// The fields every Monte Carlo record holds after its keys: both estimates, their distance in
// standard errors, what Monte Carlo would need to match the quadrature, and the verdict.
inline void set_monte_carlo_fields(record& r, const quadrature::estimate<double>& q, const monte_carlo_estimate& mc) {
    const double deviation = std::abs(q.value - mc.mean) / mc.standard_error;
    // Samples for a standard error equal to the quadrature's error bound: N se^2 / err^2.
    // (At least one: a zero-variance estimator, like cosine sampling of Lambert, needs one.)
    auto needed = [&](double target) {
        const double ratio = mc.standard_error / target;
        return std::max(1.0, static_cast<double>(mc.samples) * ratio * ratio);
    };
    r.set("samples", static_cast<std::int64_t>(mc.samples))
        .set("mc_albedo", mc.mean)
        .set("mc_standard_error", mc.standard_error)
        .set("quadrature_albedo", q.value)
        .set("quadrature_error", q.abs_error)
        .set("deviation_in_standard_errors", deviation)
        .set("mc_samples_for_quadrature_error", needed(q.abs_error))
        .set("mc_samples_for_1e-10", needed(1e-10))
        .set("quadrature_evaluations", static_cast<std::int64_t>(q.evaluations))
        .set("pass", std::abs(q.value - mc.mean) <= 4 * mc.standard_error + q.abs_error);
}
}  // namespace detail

inline record monte_carlo_record(const monte_carlo_case& c, std::uint64_t samples, std::uint64_t seed,
                                 const albedo_settings& s) {
    record r{"energy-montecarlo", {}};
    with_brdf(c.model, [&](auto form) {
        using Model = decltype(form);
        const auto q = albedo<Model>(c.theta_deg, c.n, 1.0, s);
        const auto mc = albedo_monte_carlo<Model>(c.theta_deg, c.n, 1.0, samples, seed);
        r.set("model", std::string(c.model)).set("n", Model::has_exponent ? c.n : 0.0).set("theta_deg", c.theta_deg);
        detail::set_monte_carlo_fields(r, q, mc);
    });
    return r;
}

inline std::vector<record> monte_carlo_table(const std::vector<std::string>& models, std::uint64_t samples,
                                             unsigned jobs, const albedo_settings& s = {}) {
    std::vector<monte_carlo_case> cases;
    for (const auto& c : default_monte_carlo_cases())
        if (std::find(models.begin(), models.end(), c.model) != models.end()) cases.push_back(c);
    std::vector<record> out(cases.size());
    // A fixed seed per case: the table is the same on every run.
    detail::parallel_for(cases.size(), jobs,
                         [&](std::size_t i) { out[i] = monte_carlo_record(cases[i], samples, 20261121 + i, s); });
    return out;
}

inline table_info monte_carlo_info(std::uint64_t samples) {
    return {"energy-montecarlo",
            "Albedo by quadrature against an independent Monte Carlo estimate",
            {"Monte Carlo: " + std::to_string(samples) +
                 " samples of V per case, mixture of cosine-weighted and lobe sampling (balance heuristic), "
                 "std::mt19937_64 with a fixed seed per case",
             "pass: |quadrature - Monte Carlo| <= 4 standard errors + quadrature error",
             "mc_samples_for_quadrature_error = samples x (standard error / quadrature error)^2: what Monte "
             "Carlo would need to be as accurate as the quadrature"},
            {"model", "n", "theta_deg", "quadrature_albedo", "mc_albedo", "mc_standard_error",
             "deviation_in_standard_errors", "mc_samples_for_quadrature_error", "pass"},
            {"quadrature_albedo", "mc_albedo"}};
}

}  // namespace normzoo
