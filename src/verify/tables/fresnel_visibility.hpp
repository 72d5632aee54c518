// The comparison of "The Blinn-Phong Normalization Zoo" (its three graphs): the minimalist
// F V = k_s / (4 (L.H)^3) against Schlick's Fresnel with the Kelemen / Szirmay-Kalos visibility
// 1 / (4 (L.H)^2), for k_s = 0.02, 0.05 and 0.8, over L.H in (0, 1]; where each is larger, where
// they cross, and the albedo each model gives.
//
// The crossings in closed form: k / (4x^3) = F(k, x) / (4x^2) means k = x F(k, x), i.e.
// (1 - x) [k - (1 - k) x (1 - x)^4] = 0. So they meet at x = 1 for every k, and inside (0, 1)
// where x (1 - x)^4 = k / (1 - k): twice if k / (1 - k) < 4^4 / 5^5 (the maximum, at x = 1/5),
// never otherwise. The minimalist form is the larger where x (1 - x)^4 < k / (1 - k).
#pragma once
#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include <normzoo/albedo.hpp>
#include <normzoo/brdf/microfacet.hpp>
#include <normzoo/detail/parallel.hpp>

#include "../record.hpp"
#include "energy.hpp"
#include "grid_text.hpp"

namespace verify {

// The specular reflectances k_s the minimalist Cook-Torrance's F V is compared at ("The
// Blinn-Phong Normalization Zoo"): water and plastics (0.02, 0.05) and a metal (0.8).
inline std::vector<double> compared_specular_reflectances() { return {0.02, 0.05, 0.8}; }
// The exponents their albedos are compared at.
inline std::vector<double> compared_exponents() { return {16, 256}; }

// "k_s = 0.02, 0.05, 0.8": the reflectances compared, for the heads and the settings.
inline std::string compared_reflectances_text() { return "k_s = " + list_text(compared_specular_reflectances()); }

// Interior crossings of the two F V curves, ascending (none, or two around x = 1/5).
inline std::vector<double> fresnel_visibility_crossings(double k) {
    const double level = k / (1 - k);
    auto h = [&](double x) { return x * std::pow(1 - x, 4) - level; };
    const double peak = 0.2;
    if (!(h(peak) > 0)) return {};
    std::vector<double> roots;
    for (auto [a, b] : {std::pair{0.0, peak}, std::pair{peak, 1.0}}) {
        std::uintmax_t iterations = 200;
        const auto r = boost::math::tools::toms748_solve(h, a, b, boost::math::tools::eps_tolerance<double>(52),
                                                         iterations);
        roots.push_back((r.first + r.second) / 2);
    }
    return roots;
}

inline record fresnel_visibility_record(double k, double x) {
    const double fv_min = brdf::minimalist_cook_torrance::fresnel_visibility(k, x);
    const double fv_ksk = brdf::cook_torrance_ksk::fresnel_visibility(k, x);
    const double ratio = fv_min / fv_ksk;
    record r{"fresnel-visibility", {}};
    r.set("specular", k)
        .set("l_dot_h", x)
        .set("fv_minimalist", fv_min)
        .set("fv_schlick_ksk", fv_ksk)
        .set("ratio", ratio)
        .set("larger", std::string(ratio > 1 ? "minimalist" : ratio < 1 ? "schlick-ksk" : "equal"));
    return r;
}

// Each k over L.H = 0.01, 0.02, ..., 1 and at the crossings.
inline std::vector<record> fresnel_visibility_table() {
    std::vector<record> out;
    for (double k : compared_specular_reflectances()) {
        std::vector<double> xs;
        for (int i = 1; i <= 100; ++i) xs.push_back(i / 100.0);
        for (double c : fresnel_visibility_crossings(k)) xs.push_back(c);
        std::sort(xs.begin(), xs.end());
        for (double x : xs) out.push_back(fresnel_visibility_record(k, x));
    }
    return out;
}

// Per k: the crossings, where the minimalist form is larger, and the largest ratios.
inline std::vector<record> fresnel_visibility_summary() {
    std::vector<record> out;
    for (double k : compared_specular_reflectances()) {
        const auto c = fresnel_visibility_crossings(k);
        std::string larger, crossings;
        for (double x : c) crossings += (crossings.empty() ? "" : ", ") + detail::format_number(x);
        crossings += std::string(crossings.empty() ? "" : ", ") + "1";
        if (c.empty()) larger = "(0, 1)";
        else larger = "(0, " + detail::format_number(c[0]) + ") and (" + detail::format_number(c[1]) + ", 1)";
        // The ratio k / (x F) over the open ends: largest as x -> 0 (like k / x), smallest inside.
        double min_ratio = INFINITY, at = 1;
        for (int i = 1; i <= 10000; ++i) {
            const double x = i / 10000.0;
            const double q = k / (x * brdf::fresnel_schlick(k, x));
            if (q < min_ratio) min_ratio = q, at = x;
        }
        record r{"fresnel-visibility-summary", {}};
        r.set("specular", k)
            .set("crossings_l_dot_h", crossings)
            .set("minimalist_larger_on", larger)
            .set("schlick_ksk_larger_on", c.empty() ? std::string("nowhere")
                                                    : "(" + detail::format_number(c[0]) + ", " +
                                                          detail::format_number(c[1]) + ")")
            .set("min_ratio", min_ratio)
            .set("min_ratio_at_l_dot_h", at)
            .set("ratio_at_l_dot_h_0.1", k / (0.1 * brdf::fresnel_schlick(k, 0.1)));
        out.push_back(std::move(r));
    }
    return out;
}

// The albedo each model gives at the seed's k_s values.
inline std::vector<record> fresnel_visibility_albedo(unsigned jobs, const albedo_settings& s = {}) {
    struct point {
        double k, n, theta;
    };
    std::vector<point> points;
    for (double k : compared_specular_reflectances())
        for (double n : compared_exponents())
            for (double t : {0.0, 45.0, 70.0, 85.0, 89.0}) points.push_back({k, n, t});
    std::vector<record> out(points.size());
    detail::parallel_for(points.size(), jobs, [&](std::size_t i) {
        const auto [k, n, t] = points[i];
        const auto a = albedo<brdf::minimalist_cook_torrance>(t, n, k, s);
        const auto b = albedo<brdf::cook_torrance_ksk>(t, n, k, s);
        record r{"fresnel-visibility-albedo", {}};
        r.set("specular", k)
            .set("n", n)
            .set("theta_deg", t)
            .set("albedo_minimalist", a.value)
            .set("error_minimalist", a.abs_error)
            .set("albedo_schlick_ksk", b.value)
            .set("error_schlick_ksk", b.abs_error)
            .set("ratio", a.value / b.value)
            .set("pass", a.abs_error <= albedo_tolerance(a.value, s.tolerance) &&
                             b.abs_error <= albedo_tolerance(b.value, s.tolerance));
        out[i] = std::move(r);
    });
    return out;
}

inline std::vector<table_info> fresnel_visibility_infos() {
    const std::string src =
        "after the three graphs of \"The Blinn-Phong Normalization Zoo\" (" + compared_reflectances_text() + ")";
    std::vector<table_info> infos{
        {"fresnel-visibility",
         "F V of the minimalist Cook-Torrance against Schlick with Kelemen / Szirmay-Kalos, over L.H",
         {src, "fv_minimalist = k_s / (4 (L.H)^3); fv_schlick_ksk = (k_s + (1 - k_s)(1 - L.H)^5) / (4 (L.H)^2)",
          "rows at L.H = 0.01, 0.02, ..., 1 and at the crossings"},
         {"specular", "l_dot_h", "fv_minimalist", "fv_schlick_ksk", "ratio", "larger"}},
        {"fresnel-visibility-summary",
         "Where the minimalist F V and Schlick with Kelemen / Szirmay-Kalos cross, and which is larger",
         {src,
          "crossings: x (1 - x)^4 = k / (1 - k) (Boost toms748 to double precision) and L.H = 1 (always)",
          "ratio = minimalist / (Schlick + Kelemen) = k / (L.H F); min_ratio over L.H = 1e-4 ... 1"},
         {"specular", "crossings_l_dot_h", "minimalist_larger_on", "schlick_ksk_larger_on", "min_ratio",
          "min_ratio_at_l_dot_h", "ratio_at_l_dot_h_0.1"}},
        {"fresnel-visibility-albedo",
         "Directional albedo of the minimalist and Schlick + Kelemen / Szirmay-Kalos models at the seed's k_s",
         {src, "albedo as in energy.md (tolerance 1e-10, absolute up to 1)"},
         {"specular", "n", "theta_deg", "albedo_minimalist", "albedo_schlick_ksk", "ratio", "pass"},
         {"albedo_minimalist", "albedo_schlick_ksk"}}};
    table_info& albedo = infos[2];  // fresnel-visibility-albedo
    albedo.id_keys = {"specular", "n", "theta_deg"};
    albedo.check = {{{"albedo_minimalist", "error_minimalist", false}, {"albedo_schlick_ksk", "error_schlick_ksk", false}},
                    {"error_minimalist", "error_schlick_ksk", "ratio"}};
    return infos;
}

}  // namespace verify
