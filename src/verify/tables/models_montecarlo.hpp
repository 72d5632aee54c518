// The modern forms' albedo quadrature against independent Monte Carlo (issue 8), as
// tables/montecarlo.hpp does for the zoo's forms: one case per form, away from the extremes
// where Monte Carlo's variance explodes. The lobe proposal of the Ward forms is the Blinn-Phong
// half-vector lobe at the Phong-Beckmann exponent of alpha (mixed with cosine sampling, so any
// proposal is valid; a closer one only lowers the variance).
#pragma once
#include <string>
#include <vector>

#include <normzoo/detail/parallel.hpp>

#include "models_energy.hpp"
#include "montecarlo.hpp"

namespace normzoo {

struct models_monte_carlo_case {
    const char* model;
    double parameter, theta_deg;
};

inline std::vector<models_monte_carlo_case> default_models_monte_carlo_cases() {
    return {{"ward", 0.3, 60},
            {"ward-aniso", 0.5, 45},
            {"ward-duer", 0.3, 70},
            {"ward-gmd", 0.5, 80},
            {"ward-gmd-aniso", 0.3, 30},
            {"ashikhmin-shirley", 100, 30},
            {"ashikhmin-shirley-aniso", 10, 60},
            {"ashikhmin-shirley-diffuse", 0, 45},
            {"disney-diffuse", 1, 80},
            {"disney-diffuse-renormalized", 0.5, 0}};
}

inline record models_monte_carlo_record(const models_monte_carlo_case& c, std::uint64_t samples, std::uint64_t seed,
                                        double tolerance) {
    record r{"models-montecarlo", {}};
    with_modern_brdf(c.model, [&](auto form) {
        using Form = decltype(form);
        const auto in = inputs_of<Form>(c.parameter);
        const auto q = models_albedo<Form>(c.parameter, c.theta_deg, tolerance);
        const auto mc = albedo_monte_carlo<Form>(c.theta_deg, in.n, 1.0, samples, seed, in.roughness);
        r.set("model", std::string(c.model))
            .set("parameter", parameter_name<Form>())
            .set("value", c.parameter)
            .set("theta_deg", c.theta_deg);
        detail::set_monte_carlo_fields(r, q, mc);
    });
    return r;
}

inline std::vector<record> models_monte_carlo_table(std::uint64_t samples, unsigned jobs, double tolerance = 1e-10) {
    const auto cases = default_models_monte_carlo_cases();
    std::vector<record> out(cases.size());
    // A fixed seed per case: the table is the same on every run.
    detail::parallel_for(cases.size(), jobs, [&](std::size_t i) {
        out[i] = models_monte_carlo_record(cases[i], samples, 20261121 + i, tolerance);
    });
    return out;
}

inline table_info models_monte_carlo_info(std::uint64_t samples) {
    auto info = monte_carlo_info(samples);
    info.name = "models-montecarlo";
    info.title = "Albedo of the modern forms by quadrature against an independent Monte Carlo estimate";
    info.settings.push_back("lobe proposal of the Ward forms: the Blinn-Phong half-vector lobe at n = 2/alpha^2 - 2 "
                         "(0 for alpha >= 1); Ashikhmin-Shirley: at n (n_u); Disney and the diffuse term: cosine only");
    info.md_columns = {"model", "parameter", "value", "theta_deg", "quadrature_albedo", "mc_albedo", "mc_standard_error",
                    "deviation_in_standard_errors", "mc_samples_for_quadrature_error", "pass"};
    return info;
}

}  // namespace normzoo
