// The energy single scattering loses, and the two ways engines give it back (docs/microfacet.md,
// "Multiple scattering"):
//   E_avg(alpha) = 2 integral_0^1 E(mu) mu dmu, the albedo averaged over the cosine-weighted
//                  hemisphere (Kulla and Conty 2017, "Revisiting Physically Based Shading at
//                  Imageworks");
//   Kulla-Conty  f_ms(L, V) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)), a lobe whose albedo
//                is 1 - E(mu_o), so that f + f_ms passes the white furnace; with a Fresnel term
//                it is scaled by F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), F_avg = 2 integral F mu dmu;
//   Turquin      f_ss (1 + F0 (1/E(mu_o) - 1)) (Turquin 2019, "Practical multiple scattering
//                compensation for microfacet models"): at F0 = 1 its albedo is 1.
//   Fdez-Aguera  E_F + F_ms (1 - E), F_ms = E_F F_avg / (1 - F_avg (1 - E)) (Fdez-Aguera 2019, "A
//                Multiple-Scattering Microfacet Model for Real-Time Image-based Lighting", JCGT 8(1)):
//                the bounces after the first as a geometric series, each losing 1 - E and taking
//                F_avg; the total is E_F / (1 - F_avg (1 - E)), E_F the albedo with the
//                composition's F. F_avg is fresnel_average's (F0 + (1 - F0)/21 for Schlick's F).
// E here is the composition with F = 1. Each albedo is computed by quadrature: f_ms's over the
// incident hemisphere is 2 pi times a 1D integral in mu_i of exact albedos (it does not depend on
// the azimuth), by its own Gauss-Kronrod nodes, not E_avg's.
#pragma once
#include <limits>
#include <algorithm>
#include <cmath>

#include "albedo.hpp"

namespace normzoo::microfacet {

namespace detail {
// 2 integral_0^1 g(mu) mu dmu of an estimate-valued g, panels graded toward 0 (where albedos
// move like mu ln mu); `Points` picks the Kronrod rule, so that two uses can take different nodes.
template <unsigned Points, class G>
quadrature::estimate<double> cosine_average(const G& g, double tolerance, std::size_t max_panels) {
    const quadrature::adaptive_kronrod<double, Points> rule(max_panels);
    auto weighted = [&](double mu) {
        auto e = g(mu);
        return quadrature::estimate<double>{2 * mu * e.value, 2 * mu * e.abs_error, e.evaluations};
    };
    return rule.integrate(weighted, {0.0, 1e-4, 1e-3, 1e-2, 0.1, 0.5, 1.0}, tolerance, tolerance);
}

inline composition with_f_one(composition c) {
    c.f_part = index_of<fresnel_parts>("one");
    c.compensation = composition::compensation_kind::none;
    return c;
}
}  // namespace detail

// E_avg(alpha) of the composition at F0 f0 (its F part as it is; for the compensation, F = 1).
inline quadrature::estimate<double> average_albedo(const composition& c, double alpha, double f0 = 1,
                                                   const albedo_settings& s = {}) {
    composition single = c;
    single.compensation = composition::compensation_kind::none;
    albedo_settings inner = s;
    inner.tolerance = s.tolerance / 2;
    return detail::cosine_average<15>([&](double mu) { return directional_albedo(single, mu, alpha, f0, inner); },
                                      s.tolerance / 2, s.max_panels);
}

// F_avg = 2 integral_0^1 F(mu) mu dmu of the composition's F part at F0 f0 (and its eta, k, F90).
inline quadrature::estimate<double> fresnel_average(const composition& c, double f0, double tolerance = 1e-12) {
    const fresnel_params<double> fp = c.fresnel_at(f0);
    auto f = [&](double mu) {
        const double v = detail::visit_part<fresnel_parts, double>(c.f_part, [&](auto part) { return decltype(part)::eval(mu, fp); });
        return quadrature::estimate<double>{v, 4e-16 * std::abs(v), 1};
    };
    return detail::cosine_average<31>(f, tolerance, 400);
}

// What the Kulla-Conty lobe's albedo reads of alpha and F0 alone: I = 2 integral (1 - E(mu_i)) mu_i
// dmu_i (Kronrod 31 nodes), E_avg (average_albedo, Kronrod 15 nodes) and F_avg. A sweep over mu
// at one alpha computes them once (kulla_conty_at) instead of once per mu. They hold for the
// parts and parameters, alpha, F0 and settings they were computed at only; compensated_albedo
// checks that.
struct kulla_conty_terms {
    quadrature::estimate<double> lost, e_avg, f_avg;
    composition of;  // the parts and their parameters
    double alpha = std::numeric_limits<double>::quiet_NaN(), f0 = alpha, tolerance = alpha;
    std::size_t max_panels = 0;
    bool hold_at(const composition& c, double a, double f, const albedo_settings& s) const {
        return of.same_brdf(c) && a == alpha && f == f0 && s.tolerance == tolerance && s.max_panels == max_panels;
    }
};

inline kulla_conty_terms kulla_conty_at(const composition& c, double alpha, double f0 = 1, const albedo_settings& s = {}) {
    const composition one = detail::with_f_one(c);
    albedo_settings part = s;
    part.tolerance = s.tolerance / 8;
    kulla_conty_terms t;
    t.of = c;
    t.alpha = alpha, t.f0 = f0, t.tolerance = s.tolerance, t.max_panels = s.max_panels;
    // The lobe's albedo reads lost / (1 - E_avg): two quadratures of the same quantity, whose
    // errors it multiplies by up to 1 / (1 - E_avg) (the factor 1 - E(mu) is at most 1). Where
    // E_avg is near 1 (smooth surfaces) both are computed to that much less (not below 1e-14, where
    // their rounding is).
    t.e_avg = average_albedo(one, alpha, 1, part);
    part.tolerance = std::max(1e-14, part.tolerance * std::min(1.0, std::abs(1 - t.e_avg.value)));
    if (t.e_avg.abs_error > part.tolerance) {
        const std::size_t spent = t.e_avg.evaluations;
        t.e_avg = average_albedo(one, alpha, 1, part);
        t.e_avg.evaluations += spent;
    }
    t.lost = detail::cosine_average<31>(
        [&](double mu_i) {
            auto e = directional_albedo(one, mu_i, alpha, 1, part);
            return quadrature::estimate<double>{1 - e.value, e.abs_error, e.evaluations};
        },
        part.tolerance, s.max_panels);
    t.f_avg = c.f_part == one.f_part ? quadrature::estimate<double>{1, 0, 0} : fresnel_average(c, f0);
    return t;
}

namespace detail {
// Fdez-Aguera's total E_F / q, q = 1 - F_avg (1 - E), from E_F (e_ss), E (e1, F = 1) and F_avg:
// its bound from each one's, to first order with q's bound taken off q (white: E_F is E, the
// ratio 1 up to rounding, and the bound is the same expression).
inline quadrature::estimate<double> fdez_aguera_albedo(const composition& c, double f0,
                                                       const quadrature::estimate<double>& e_ss,
                                                       const quadrature::estimate<double>& e1, bool white) {
    const quadrature::estimate<double> f_avg = white ? quadrature::estimate<double>{1, 0, 0} : fresnel_average(c, f0);
    const double lost = 1 - e1.value, q = 1 - f_avg.value * lost;
    const double q_error = f_avg.abs_error * lost + (f_avg.value + f_avg.abs_error) * e1.abs_error + 4e-16;
    quadrature::estimate<double> r = e_ss;
    r.value = e_ss.value / q;
    r.abs_error = e_ss.abs_error / (q - q_error) + e_ss.value * q_error / (q * (q - q_error)) + 4e-16 * r.value;
    r.evaluations += f_avg.evaluations;
    return r;
}
}  // namespace detail

// The compensated albedo from the single-scattering albedos at this mu: e_ss with the
// composition's F at F0 f0, e1 with F = 1 (the same estimate where F is 1), each to s.tolerance / 8;
// the Kulla-Conty terms as compensated_albedo below takes them. A caller with several F0 at one mu
// computes e1 once (material/compensation.hpp). The evaluations counted are e_ss's and this
// function's own (F_avg, the Kulla-Conty terms computed here): e1's are its caller's to count.
inline quadrature::estimate<double> compensated_albedo_from(const composition& c, double alpha, double f0,
                                                            const quadrature::estimate<double>& e_ss,
                                                            const quadrature::estimate<double>& e1, const albedo_settings& s,
                                                            const kulla_conty_terms* terms, std::size_t count = 1) {
    using kind = composition::compensation_kind;
    if (c.compensation == kind::none) return e_ss;
    const bool white = c.f_part == detail::with_f_one(c).f_part;
    quadrature::estimate<double> r = e_ss;
    if (c.compensation == kind::fdez_aguera) return detail::fdez_aguera_albedo(c, f0, e_ss, e1, white);
    if (c.compensation == kind::turquin) {
        // E_F(mu) (1 + F0 (1/E - 1)), F0 = F(1) of the F part (an exact part's from its eta and k)
        const double k = detail::visit_part<fresnel_parts, double>(
            c.f_part, [&](auto part) { return decltype(part)::eval(1.0, c.fresnel_at(f0)); });
        const double factor = 1 + k * (1 / e1.value - 1);
        const double factor_error = k * e1.abs_error / (e1.value * (e1.value - e1.abs_error));
        r.value = e_ss.value * factor;
        r.abs_error = e_ss.abs_error * factor + e_ss.value * factor_error + 4e-16 * r.value;
        return r;
    }
    // Kulla-Conty: the lobe's albedo (1 - E(mu)) I / (1 - E_avg), times Kulla and Conty's Fresnel
    // factor F_avg^2 E_avg / (1 - F_avg (1 - E_avg)) when F is not 1.
    const kulla_conty_terms* held = nullptr;
    for (std::size_t i = 0; terms && i < count && !held; ++i)
        if (terms[i].hold_at(c, alpha, f0, s)) held = &terms[i];
    const bool shared = held != nullptr;
    const kulla_conty_terms own = shared ? kulla_conty_terms{} : kulla_conty_at(c, alpha, f0, s);
    const kulla_conty_terms& t = shared ? *held : own;
    const auto& lost = t.lost;
    const auto& e_avg = t.e_avg;
    const double denom = 1 - e_avg.value;
    double scale = 1, scale_error = 0;
    if (!white) {
        const double q = 1 - t.f_avg.value * (1 - e_avg.value);
        scale = t.f_avg.value * t.f_avg.value * e_avg.value / q;
        scale_error = 8 * (t.f_avg.abs_error + e_avg.abs_error) * (1 + scale) / q;
    }
    const double ms = (1 - e1.value) * lost.value / denom;
    const double ms_error = (e1.abs_error * lost.value + (1 - e1.value) * lost.abs_error) / denom +
                            ms * e_avg.abs_error / (denom - e_avg.abs_error);
    r.value = e_ss.value + scale * ms;
    r.abs_error = e_ss.abs_error + scale * ms_error + scale_error * ms + 4e-16 * r.value;
    // the terms' work is counted where they are computed (a sweep shares it)
    r.evaluations += shared ? 0 : lost.evaluations + e_avg.evaluations;
    return r;
}

// The albedo of the composition with its compensation: E_ss(mu) + the compensation's albedo,
// each by quadrature, with the first of the `count` Kulla-Conty terms at `terms` that holds for
// this composition, alpha, F0 and tolerance (a sweep's shared terms, and those at the inputs a
// rounding slope moves to: input_rounding_step), else with terms computed here. With F = 1 each
// compensations give 1 (the white furnace).
inline quadrature::estimate<double> compensated_albedo(const composition& c, double mu, double alpha, double f0,
                                                       const albedo_settings& s, const kulla_conty_terms* terms,
                                                       std::size_t count = 1) {
    composition single = c;
    single.compensation = composition::compensation_kind::none;
    if (c.compensation == composition::compensation_kind::none) return directional_albedo(single, mu, alpha, f0, s);
    albedo_settings part = s;
    part.tolerance = s.tolerance / 8;
    const auto e_ss = directional_albedo(single, mu, alpha, f0, part);
    const composition one = detail::with_f_one(c);
    const bool white = c.f_part == one.f_part;
    const auto e1 = white ? e_ss : directional_albedo(one, mu, alpha, 1, part);
    auto r = compensated_albedo_from(c, alpha, f0, e_ss, e1, s, terms, count);
    r.evaluations += white ? 0 : e1.evaluations;
    return r;
}

inline quadrature::estimate<double> compensated_albedo(const composition& c, double mu, double alpha, double f0 = 1,
                                                       const albedo_settings& s = {}) {
    return compensated_albedo(c, mu, alpha, f0, s, nullptr);
}

}  // namespace normzoo::microfacet
