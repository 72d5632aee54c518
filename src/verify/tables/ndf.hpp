// The microfacet NDF tables (docs/models.md): Beckmann and GGX, indexed by roughness alpha.
//   ndf          per NDF and alpha: the projected integral of D(h) (N.h) (= 1, the normalization)
//                and the non-projected integral of D(h), by quadrature against the closed forms
//   ndf-furnace  per NDF, alpha and view angle t_v: Smith's G1 in closed form against G1 from
//                the masking equation by quadrature, and the weak white furnace test of Heitz 2014,
//                integral over L of G1(V) D(h) / (4 |N.V|) = 1
//   phong-beckmann  the Phong-Beckmann mapping n = 2/alpha^2 - 2 (Walter et al. 2007): the
//                normalized Blinn-Phong NDF against Beckmann at mapped parameters
// Every integral is over the polar angle of h in the log-slope variable of quadrature/slope.hpp,
// in long double, with D evaluated from the vector h; closed forms in 50 digits (wide).
//
// The furnace in h: with L = 2 (V.h) h - V, d(omega_L) = 4 |V.h| d(omega_h), and L over the whole
// sphere covers h over V.h > 0 once, so
//     integral G1(V) D(h) / (4 |N.V|) d(omega_L) = G1(V) / (N.V) * integral D(h) max(V.h, 0) d(omega_h).
// The azimuth of h is integrated in closed form: with a = sin t sin t_v, b = cos t cos t_v,
//     integral_0^2pi max(a cos p + b, 0) dp = 2 pi b (b >= a), else 2 (b p0 + a sin p0), p0 = acos(-b/a),
// which leaves a kink at t = 90 deg - t_v (a breakpoint of the polar integral). The masking
// equation (Heitz 2014) says the last integral is N.V / G1(V): G1 "by quadrature" is N.V over it.
#pragma once
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <normzoo/decimal.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/geometry.hpp>
#include <normzoo/ndf_integrals.hpp>
#include <normzoo/quadrature/slope.hpp>
#include <normzoo/real.hpp>
#include <normzoo/wide.hpp>
#include <normzoo/registry.hpp>

#include "../record.hpp"
#include "grid.hpp"

namespace verify {

// The roughness grid: narrow lobes to 1e-4, wide ones to 10 (as written, for the head's text).
inline std::vector<decimal> default_ndf_alphas() {
    return decimals({"1e-4", "1e-3", "1e-2", "0.05", "0.1", "0.2", "0.3", "0.5", "0.7", "1", "2", "5", "10"});
}
inline std::vector<double> default_furnace_angles() { return {0, 30, 60, 80, 85, 89, 89.9}; }
inline std::vector<decimal> default_mapping_exponents() {
    return decimals({"1", "2", "4", "8", "16", "32", "64", "128", "512", "2048", "1e4", "1e5"});
}

template <class Ndf>
record ndf_record(double alpha) {
    using std::abs;
    const auto projected = ndf_integral<Ndf>(alpha, 1);
    const auto plain = ndf_integral<Ndf>(alpha, 0);
    const wide closed = Ndf::non_projected(wide(alpha));
    const long double closed_ld = static_cast<long double>(closed);
    const long double proj_err = abs(projected.value - 1), plain_err = abs(plain.value - closed_ld);
    // the closed form is rounded to long double: one ulp more
    const bool ok_proj = detail::usable(projected) && proj_err <= projected.abs_error + 2 * eps<long double>() &&
                         projected.abs_error < 1e-15L;
    const bool ok_plain = detail::usable(plain) && plain_err <= plain.abs_error + 2 * eps<long double>() * closed_ld &&
                          plain.abs_error < 1e-15L * closed_ld;
    record r{"ndf", {}};
    r.set("ndf", std::string(Ndf::id))
        .set("alpha", alpha)
        .set("exponent_equivalent", exponent_of_beckmann_alpha(alpha))
        .set("projected_quadrature", to_decimal(projected.value, 20))
        .set("projected_error_estimate", static_cast<double>(projected.abs_error))
        .set("projected_rel_error", static_cast<double>(proj_err))
        .set("non_projected_quadrature", to_decimal(plain.value, 20))
        .set("non_projected_closed_form", to_decimal(closed, 20))
        .set("non_projected_rel_error", static_cast<double>(plain_err / closed_ld))
        .set("non_projected_error_estimate", static_cast<double>(plain.abs_error / closed_ld))
        .set("digits", digits_of(static_cast<double>(plain_err / closed_ld)))
        .set("evaluations", static_cast<std::int64_t>(projected.evaluations + plain.evaluations))
        .set("pass", ok_proj && ok_plain);
    return r;
}

template <class Ndf>
record furnace_record(double alpha, double theta_v) {
    using std::abs;
    using R = long double;
    const degrees_angle<R> v(theta_v);
    const auto area = visible_projected_area<Ndf>(alpha, theta_v);
    const degrees_angle<wide> vw(theta_v);
    const vec3<wide> w(vw.sin_t, 0, vw.cos_t);
    const microfacet::ndf_params<wide> pw{wide(alpha), wide(alpha)};
    const wide g1_closed = microfacet::smith_g1<Ndf>(w, pw);
    const R g1c = static_cast<R>(g1_closed);
    const R g1q = v.cos_t / area.value;
    const R rel_area = area.abs_error / area.value;
    const R furnace = g1c * area.value / v.cos_t;
    const R furnace_error = g1c * area.abs_error / v.cos_t;
    // G1 is rounded once to long double, the furnace a few more times: 8 ulps
    const bool ok = detail::usable(area) && abs(furnace - 1) <= furnace_error + 8 * eps<R>() && rel_area < 1e-15L;
    record r{"ndf-furnace", {}};
    r.set("ndf", std::string(Ndf::id))
        .set("alpha", alpha)
        .set("theta_v_deg", theta_v)
        .set("g1_closed_form", static_cast<double>(g1c))
        .set("g1_quadrature", static_cast<double>(g1q))
        .set("g1_rel_difference", static_cast<double>((g1q - g1c) / g1c))
        .set("lambda", static_cast<double>(Ndf::lambda(w, pw)))
        .set("furnace", to_decimal(furnace, 20))
        .set("furnace_minus_one", static_cast<double>(furnace - 1))
        .set("error_estimate", static_cast<double>(furnace_error))
        .set("evaluations", static_cast<std::int64_t>(area.evaluations))
        .set("pass", ok);
    return r;
}

inline std::vector<record> ndf_table(const std::vector<double>& alphas, unsigned jobs) {
    std::vector<std::function<record()>> tasks;
    for_each_ndf([&](auto ndf) {
        using Ndf = decltype(ndf);
        for (double a : alphas) tasks.push_back([a] { return ndf_record<Ndf>(a); });
    });
    std::vector<record> out(tasks.size());
    detail::parallel_for(tasks.size(), jobs, [&](std::size_t i) { out[i] = tasks[i](); });
    return out;
}

inline std::vector<record> furnace_table(const std::vector<double>& alphas, const std::vector<double>& angles,
                                         unsigned jobs) {
    std::vector<std::function<record()>> tasks;
    for_each_ndf([&](auto ndf) {
        using Ndf = decltype(ndf);
        for (double a : alphas)
            for (double t : angles) tasks.push_back([a, t] { return furnace_record<Ndf>(a, t); });
    });
    std::vector<record> out(tasks.size());
    detail::parallel_for(tasks.size(), jobs, [&](std::size_t i) { out[i] = tasks[i](); });
    return out;
}

// ---- The Phong-Beckmann mapping --------------------------------------------------------------

namespace detail {

// ln(D_blinn / D_beckmann) at angle t for alpha = sqrt(2/(n+2)): the peaks are equal
// ((n+2)/(2 pi) = 1/(pi alpha^2)), and with c = cos t,
//     ln r(c) = (n+4) ln c + (n+2) (1 - c^2) / (2 c^2),
// whose derivative (n+4)/c - (n+2)/c^3 vanishes only at c*^2 = (n+2)/(n+4): r falls from 1 at
// t = 0 to its minimum at c* and then rises for good. On [0, t1] the largest |r - 1| is at t1
// or at c*.
template <class T>
T log_blinn_over_beckmann(const T& n, const T& c) {
    using std::log;
    return (n + 4) * log(c) + (n + 2) * (1 - c * c) / (2 * c * c);
}

}  // namespace detail

// The lobe where the comparison of values is made: Beckmann's exponential above 1e-3 of its peak.
inline constexpr double mapping_lobe_fraction = 1e-3;

inline record mapping_record(const decimal& n_in) {
    const double n = n_in.to<double>();  // where the comparison is in double; long double below
    using std::abs;
    using std::atan;
    using std::cos;
    using std::exp;
    using std::log;
    using std::sqrt;
    using R = long double;
    // The mapping alpha(n) in double, as engines compute it; n itself in long double.
    const R nn = n_in.to<R>(), alpha = beckmann_alpha_of_exponent(n);
    const R t1 = atan(alpha * sqrt(-log(R(mapping_lobe_fraction))));  // tan^2 t1 / alpha^2 = ln 1000
    const R c_star = sqrt((nn + 2) / (nn + 4));
    const R rel_at_edge = abs(exp(detail::log_blinn_over_beckmann(nn, cos(t1))) - 1);
    const R rel_at_min = cos(t1) < c_star ? abs(exp(detail::log_blinn_over_beckmann(nn, c_star)) - 1) : R(0);
    const R max_rel = rel_at_edge > rel_at_min ? rel_at_edge : rel_at_min;
    // Where the two cross again (r = 1 beyond c*): a kink of |D_b - D_p|, found by bisection in c.
    R crossing_tan = 0;
    {
        auto g = [&](R c) { return detail::log_blinn_over_beckmann(nn, c); };
        R lo = 1e-30L, hi = c_star;  // g(lo) > 0 > g(hi) (ln c is outgrown by 1/c^2 near 0)
        if (g(lo) > 0 && g(hi) < 0) {
            boost::math::tools::eps_tolerance<R> tol(60);
            std::uintmax_t iters = 200;
            const auto root = boost::math::tools::bisect(g, lo, hi, tol, iters);
            const R c = (root.first + root.second) / 2;
            crossing_tan = sqrt((1 - c) * (1 + c)) / c;
        }
    }
    // L1 distance of the projected densities, integral |D_p - D_b| (N.h) d(omega_h), in [0, 2].
    const R two_pi = boost::math::constants::two_pi<R>();
    auto diff = [&](const quadrature::slope_point<R>& p) {
        const vec3<R> h(p.sin_t, 0, p.cos_t);
        const R d_blinn = (nn + 2) / two_pi * pow_lobe(normal<R>(), h, nn);
        return abs(d_blinn - microfacet::d_beckmann::d(h, microfacet::ndf_params<R>{alpha, alpha})) * p.cos_t * p.sin_t;
    };
    std::vector<R> kinks{crossing_tan};
    auto l1 = quadrature::slope_integral<R>(diff, alpha, kinks);
    l1.value *= two_pi;
    l1.abs_error *= two_pi;
    // The Blinn-Phong projected normalization by the same rule (it must be 1).
    auto blinn = [&](const quadrature::slope_point<R>& p) {
        const vec3<R> h(p.sin_t, 0, p.cos_t);
        return (nn + 2) / two_pi * pow_lobe(normal<R>(), h, nn) * p.cos_t * p.sin_t;
    };
    auto bp = quadrature::slope_integral<R>(blinn, alpha);
    bp.value *= two_pi;
    bp.abs_error *= two_pi;
    const wide np_beckmann = microfacet::d_beckmann::non_projected(wide(static_cast<double>(alpha)));
    const double np_blinn = (n + 2) / (n + 1);  // integral of (n+2)/(2 pi) cos^n over the hemisphere
    const bool ok = detail::usable(l1) && detail::usable(bp) && abs(bp.value - 1) <= bp.abs_error + 4 * eps<R>() &&
                    l1.abs_error < 1e-12L;
    record r{"phong-beckmann", {}};
    r.set("n", n)
        .set("n_input", n_in.text())
        .set("alpha", static_cast<double>(alpha))
        .set("peak_ratio", static_cast<double>(((nn + 2) / two_pi) * (boost::math::constants::pi<R>() * alpha * alpha)))
        .set("max_rel_difference_D", static_cast<double>(max_rel))
        .set("lobe_edge_deg", static_cast<double>(t1 * 180 / boost::math::constants::pi<R>()))
        .set("l1_distance", static_cast<double>(l1.value))
        .set("l1_error_estimate", static_cast<double>(l1.abs_error))
        .set("blinn_projected_quadrature", static_cast<double>(bp.value))
        .set("non_projected_blinn", np_blinn)
        .set("non_projected_beckmann", static_cast<double>(np_beckmann))
        .set("non_projected_rel_difference", static_cast<double>(np_beckmann / wide(np_blinn) - 1))
        .set("pass", ok);
    return r;
}

inline std::vector<record> mapping_table(const std::vector<decimal>& exponents, unsigned jobs) {
    std::vector<record> out(exponents.size());
    detail::parallel_for(exponents.size(), jobs, [&](std::size_t i) { out[i] = mapping_record(exponents[i]); });
    return out;
}

inline table_info ndf_info() {
    table_info info{
        "ndf",
        "Beckmann and GGX: projected normalization and non-projected integral against closed forms",
        {"D(h) from the vector h in long double; integral over the polar angle in u = ln(tan t / alpha) "
         "(quadrature/slope.hpp: adaptive Gauss-Kronrod 21 on panels <= 2 wide over u in [-50, 50], tails "
         "bounded from their measured decay), times 2 pi for the azimuth",
         "projected: integral of D(h) (N.h) d(omega_h), 1 by design; non-projected: integral of D(h) d(omega_h) "
         "against the closed forms in 50 digits (microfacet/distribution.hpp)",
         "exponent_equivalent: n = 2/alpha^2 - 2 (Phong-Beckmann mapping, Walter et al. 2007)",
         "pass: both agree within their error bound (+ 2 ulp) and both bounds are below 1e-15"},
        {"ndf", "alpha", "projected_quadrature", "non_projected_quadrature", "non_projected_closed_form", "digits",
         "non_projected_error_estimate", "pass"}};
    info.id_keys = {"ndf", "alpha"};
    return info;
}

inline table_info furnace_info() {
    table_info info{
        "ndf-furnace",
        "Smith G1 of Beckmann and GGX and the weak white furnace test (Heitz 2014) over alpha and view angle",
        {"area: integral over h of D(h) max(V.h, 0), azimuth in closed form, polar angle by quadrature/slope.hpp "
         "with a breakpoint at the kink t = 90 deg - t_v (long double)",
         "g1_quadrature = (N.V) / area (the masking equation); g1_closed_form: erf form (Beckmann), rational "
         "(GGX), in 50 digits",
         "furnace = G1(V) / (N.V) * area = integral over L of G1(V) D(h) / (4 |N.V|); 1 for every V",
         "pass: |furnace - 1| <= error_estimate + 8 ulp and the relative bound of the area below 1e-15"},
        {"ndf", "alpha", "theta_v_deg", "g1_closed_form", "g1_quadrature", "furnace", "error_estimate", "pass"},
        {"g1_closed_form", "g1_quadrature"}};
    info.id_keys = {"ndf", "alpha", "theta_v_deg"};
    return info;
}

inline table_info mapping_info() {
    table_info info{
        "phong-beckmann",
        "The Phong-Beckmann mapping alpha = sqrt(2/(n+2)): normalized Blinn-Phong NDF against Beckmann",
        {"D_blinn = (n+2)/(2 pi) (N.h)^n and D_beckmann at alpha = sqrt(2/(n+2)) (Walter et al. 2007: alpha_p = "
         "2/alpha^2 - 2); equal peaks, peak_ratio = 1 up to rounding",
         "max_rel_difference_D: max |D_blinn / D_beckmann - 1| over the lobe t <= lobe_edge_deg (Beckmann's "
         "exponential >= 1e-3 of its peak), from the ratio's one stationary point and the lobe edge (closed form)",
         "l1_distance: integral |D_blinn - D_beckmann| (N.h) d(omega_h) (0 to 2) by quadrature/slope.hpp",
         "non_projected_*: integral of D d(omega_h): (n+2)/(n+1) for Blinn-Phong, the closed form for Beckmann",
         "pass: the Blinn-Phong projected integral is 1 within its bound, and the L1 bound is below 1e-12",
         "n_input: the exponent as given, a decimal, taken in long double (the findings are shown to 4 digits)"},
        {"n_input", "alpha", "peak_ratio", "max_rel_difference_D", "l1_distance", "non_projected_blinn",
         "non_projected_beckmann", "pass"},
        {"non_projected_blinn", "non_projected_beckmann"}};
    info.id_keys = {"n"};
    return info;
}

}  // namespace verify
