// The albedo quadrature against independent Monte Carlo (docs/energy.md): one case per form (the
// form's monte_carlo_case), where the quadrature must lie within 4 standard errors of the Monte
// Carlo mean; and how many samples Monte Carlo would need to be as accurate as the quadrature.
// The lobe proposal of the Ward forms is the Blinn-Phong half-vector lobe at the Phong-Beckmann
// exponent of alpha (mixed with cosine sampling, so any proposal is valid; a closer one only
// lowers the variance).
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include <normzoo/albedo.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/montecarlo.hpp>
#include <normzoo/registry.hpp>

#include "../record.hpp"

namespace verify {

struct monte_carlo_case {
    std::string_view model;  // a form's id
    double value, theta_deg;  // its swept parameter's value (0 for none) and the incident angle
};

// Each form's own case (brdf::check_point), in registry order.
inline std::vector<monte_carlo_case> default_monte_carlo_cases() {
    std::vector<monte_carlo_case> cases;
    for_each_brdf([&](auto form) {
        using Form = decltype(form);
        cases.push_back({Form::id, Form::monte_carlo_case.value, Form::monte_carlo_case.theta_deg});
    });
    return cases;
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
        using Form = decltype(form);
        const brdf::params<double> p = brdf::params_at<Form>(c.value);
        const auto q = albedo<Form>(c.theta_deg, p.n, 1.0, s, p.roughness);
        const auto mc = albedo_monte_carlo<Form>(c.theta_deg, p.n, 1.0, samples, seed, p.roughness);
        r.set("model", std::string(c.model))
            .set("parameter", std::string(brdf::swept_parameter_name<Form>()))
            .set("value", brdf::has_swept_parameter<Form>() ? c.value : 0.0)
            .set("theta_deg", c.theta_deg);
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
    table_info info{
        "energy-montecarlo",
        "Albedo by quadrature against an independent Monte Carlo estimate",
        {"Monte Carlo: " + std::to_string(samples) +
             " samples of V per case, mixture of cosine-weighted and lobe sampling (balance heuristic), "
             "std::mt19937_64 with a fixed seed per case",
         "pass: |quadrature - Monte Carlo| <= 4 standard errors + quadrature error",
         "mc_samples_for_quadrature_error = samples x (standard error / quadrature error)^2: what Monte "
         "Carlo would need to be as accurate as the quadrature",
         "lobe proposal of the Ward forms: the Blinn-Phong half-vector lobe at n = 2/alpha^2 - 2 (0 for alpha >= 1); "
         "Ashikhmin-Shirley: at n (n_u); Disney and the diffuse terms: cosine only"},
        {"model", "parameter", "value", "theta_deg", "quadrature_albedo", "mc_albedo", "mc_standard_error",
         "deviation_in_standard_errors", "mc_samples_for_quadrature_error", "pass"},
        {"quadrature_albedo", "mc_albedo"}};
    info.id_keys = {"model", "parameter", "value", "theta_deg"};
    info.check = {{{"quadrature_albedo", "quadrature_error", false}},
                  {"quadrature_error", "quadrature_evaluations", "deviation_in_standard_errors",
                   "mc_samples_for_quadrature_error"}};
    return info;
}

}  // namespace verify
