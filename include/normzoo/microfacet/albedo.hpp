// The directional albedo of a microfacet composition (docs/microfacet.md, "The albedo in the
// distribution's own variable"):
//     E(mu) = integral over L of f(L, V) N.L d(omega_L),   V = (sqrt(1 - mu^2), 0, mu),
// in the half vector h, where D(h) N.h is a probability density. With d(omega_L) = 4 V.h d(omega_h),
//     E(mu) = integral of D(h) N.h * w(h) d(omega_h),   w = G F(V.h) V.h / (mu N.h),
// over the h whose mirror direction L = 2 (V.h) h - V is above the horizon. The D parts with a
// polar map (distribution.hpp) give the polar angle t of h from psi in [0, pi/2) so that the mass
// below t is sin^2 psi; in (psi, phi) the density is sin(2 psi) / (2 pi): flat in the distribution's
// mass, whatever alpha is, so the lobe is no feature of the integrand and no lobe width has to be
// found (the inverse CDF the importance samplers of Walter et al. 2007 use, here as a change of
// variables for Gauss-Kronrod instead of random numbers).
//
// The horizon N.L = 0 is, with N.L = sin t_v sin(2t) cos(phi) + mu cos(2t), the azimuth
//     phi_max(t) = acos(-mu cos(2t) / (sin t_v sin(2t))),
// all of [0, pi] up to t1 = asin(mu)/2 and none beyond t2 = pi/2 - asin(mu)/2. So: region 1, psi
// in [0, psi(t1)] with phi in [0, pi] (smooth: a full circle of a smooth function of h), and region
// 2, psi in [psi(t1), psi(t2)] with phi in [0, phi_max], where phi_max moves like the square root
// of the distance to either end: there psi = psi1 + (psi2 - psi1)(1 - cos(pi s))/2 makes it
// smooth in s. The configuration is symmetric in phi -> -phi (twice [0, pi]).
//
// Each node's rounding is bounded from the conditioning of N.L and V.h (both sums of O(1) terms,
// absolutely accurate; the azimuth's cosine and sine err by up to 4 ulps, from the addition
// formulas of quadrature/adaptive.hpp): the relative error of w is at most 32 eps + 8 eps (2 V.h
// N.h + mu + sin t)/N.L + 12 eps (sin t + mu cos t)/V.h, as G and the Fresnel term are at most
// linear in N.L and V.h near 0 (Kelemen's G is 1/(V.h)^2: 2x). The quadrature error is adaptive
// Gauss-Kronrod's |K - G| (quadrature/adaptive.hpp) in both variables.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "../albedo.hpp"
#include "../geometry.hpp"
#include "../quadrature/adaptive.hpp"
#include "../quadrature/estimate.hpp"
#include "../quadrature/periodic.hpp"
#include "../real.hpp"
#include "azimuthal_albedo.hpp"
#include "composition.hpp"

namespace normzoo::microfacet {

namespace detail {

// E(mu) for a composition whose D is the part D (which has a polar map) and whose G is the part
// G (void: the composition's G, through view_terms), its Fresnel factor fresnel(V.h, terms of V):
// the composition's F, or channels of several (split_sum.hpp), which are then integrated from the
// same nodes.
template <class D, class G, unsigned Points, class Fresnel>
auto stretched_albedo_with(const composition& c, double mu, double alpha, double f0, const albedo_settings& set,
                           const Fresnel& fresnel) {
    using std::abs;
    using std::acos;
    using std::asin;
    using std::cos;
    using std::sin;
    using std::sqrt;
    using Value = std::decay_t<decltype(fresnel(1.0, std::declval<const composition::view_terms<double>&>()))>;
    using estimate = quadrature::estimate<Value>;
    const double pi = boost::math::constants::pi<double>();
    const double sv = sqrt((1 - mu) * (1 + mu));
    const vec3<double> v(sv, 0, mu);
    const ndf_params<double> np = c.ndf(alpha);
    const brdf::params<double> p{0, f0, alpha};
    const composition::view_terms<double> view = c.at_view(v, p);
    const double tol = set.tolerance, eps = std::numeric_limits<double>::epsilon();
    const quadrature::adaptive_kronrod<double, Points> rule(set.max_panels);

    // w at (t, phi), from cos t, sin t, 1 / (mu cos t), cos phi, sin phi, with its rounding bound.
    auto w = [&](double ct, double st, double inv_muct, double cphi, double sphi) -> estimate {
        const double vh = sv * st * cphi + mu * ct;
        const double nl = 2 * vh * ct - mu;
        if (!(nl > 0 && vh > 0)) return {Value{}, Value{}, 1};
        const vec3<double> h(st * cphi, st * sphi, ct);
        const vec3<double> l = 2 * vh * h - v;
        shading<double> s;
        s.nl = nl, s.nv = mu, s.nm = ct, s.vm = vh;
        double g;
        if constexpr (std::is_void_v<G>) {
            g = c.masking(s, l, view);
        } else {
            s.alpha = view.alpha;
            if constexpr (G::needs_lambda) s.lambda_v = view.lambda_v, s.lambda_l = D::lambda(l, view.np);
            g = G::g(s);
        }
        const Value value = g * fresnel(vh, view) * (vh * inv_muct);
        const double relative = 32 + (8 * (2 * vh * ct + mu + st) * vh + 12 * (st + mu * ct) * nl) / (nl * vh);
        return {value, eps * relative * abs(value), 1};
    };

    // The integral over phi at one psi, times the density sin(2 psi) / pi (both signs of phi),
    // to `budget` absolute after that factor (the inner errors are part of the outer bound:
    // where the density is small, the inner integral needs fewer digits).
    auto over_phi = [&](double psi, double budget) -> estimate {
        double ct, st;
        D::polar(psi, np, ct, st);
        const double cos2t = (ct - st) * (ct + st);
        double phi_max = pi;
        const double amp = sv * 2 * st * ct;  // N.L = amp cos(phi) + mu cos(2t)
        if (sv > 0) {
            const double c0 = -mu * cos2t / amp;
            phi_max = c0 <= -1 ? pi : c0 >= 1 ? 0 : acos(c0);
        } else if (!(cos2t > 0)) {
            phi_max = 0;
        }
        if (!(phi_max > 0)) return {Value{}, Value{}, 0};
        const double weight = sin(2 * psi) / pi;
        const double inv_muct = 1 / (mu * ct);  // once per psi, not per node
        const double inner_tol = budget / weight;
        auto g = [&](double, double cphi, double sphi) { return w(ct, st, inv_muct, cphi, sphi); };  // an angle integrand
        auto scaled = [&](const estimate& e) { return estimate{e.value * weight, e.abs_error * weight, e.evaluations}; };
        std::size_t spent = 0;
        if (phi_max == pi) {
            // The whole circle: the integrand is smooth, even and periodic in phi, and the
            // trapezoidal rule converges geometrically (quadrature/periodic.hpp), with a first
            // spacing of half the strip where it is analytic. Its edge is the nearest complex
            // phi where N.L or V.h vanishes (Smith's Lambda, Schlick's G1 and Kelemen's G are
            // singular there or beyond: Lambda's branch points at N.L = +-i alpha/sqrt(1 -
            // alpha^2) lie farther out), or where N.L = 1 for Beckmann's Lambda (a function of
            // tan t_L itself, not of its square, essentially singular at tan t_L = 0).
            const double b = mu * cos2t, amp_vh = sv * st;
            auto strip = [](std::complex<double> cos_phi) { return std::abs(std::acos(cos_phi).imag()); };
            double width = pi;
            if (amp > 0) width = std::min(width, strip({-b / amp, 0}));
            if (amp > 0 && std::is_same_v<D, d_beckmann> && view.needs_lambda)
                width = std::min(width, strip({(1 - b) / amp, 0}));
            if (amp_vh > 0) width = std::min(width, strip({-mu * ct / amp_vh, 0}));
            std::size_t n = 4;
            while (n <= 256 && pi / double(n) > width / 2) n *= 2;
            if (n <= 256) {
                const auto r = quadrature::periodic_trapezoid<double>(
                    [&](double, double cphi, double sphi) { return w(ct, st, inv_muct, cphi, sphi); }, n, 256, inner_tol);
                if (r.converged) return scaled(r.integral);
                spent = r.integral.evaluations;
            }
        }
        // Otherwise Gauss-Kronrod on graded panels. Near phi_max, N.L falls to its least value
        // there; G turns over where N.L ~ alpha (Smith's Lambda, Schlick's k): panels end at
        // distances growing 4x from where N.L has risen by alpha/4, so that the turn is never
        // narrower than its panel.
        std::vector<double> phi_breaks{0.0};
        const double nl_min = amp * cos(phi_max) + mu * cos2t;
        if (amp > 0 && nl_min < 4 * alpha) {
            const double knee = phi_max - acos(std::min(1.0, cos(phi_max) + alpha / (4 * amp)));
            std::vector<double> inner;
            for (double d = knee; d < phi_max / 2; d *= 4) inner.push_back(phi_max - d);
            phi_breaks.insert(phi_breaks.end(), inner.rbegin(), inner.rend());
        }
        phi_breaks.push_back(phi_max);
        estimate e = rule.integrate(g, phi_breaks, inner_tol, 0.0);
        e.evaluations += spent;
        return scaled(e);
    };

    // Breakpoints in t, mapped to psi: the map squeezes the tail t >> alpha into psi near pi/2,
    // where the horizon's features, O(1) wide in t, would be narrower than a panel. So the panels
    // end at t = t1/2, t1/4, ... down to alpha (region 1) and at t1 + (t2 - t1) j/4 (region 2);
    // and toward t1 and t2, where the cut meets the lobe's turn of G (N.L ~ alpha at t1 - t ~
    // alpha/4), at distances 4x apart down to alpha/16.
    const double a = asin(mu) / 2;  // the distance of t1 from 0 and of t2 from pi/2
    const double t1 = a, t2 = pi / 2 - a;
    const double psi1 = D::theta_to_psi(t1, np), psi2 = D::theta_to_psi(t2, np);
    auto toward = [&](double from, double to, std::vector<double>& ts) {  // graded toward `to`
        for (double d = std::abs(to - from) / 4; d > alpha / 16; d /= 4) ts.push_back(to + (from < to ? -d : d));
    };
    std::vector<double> ts;
    for (double t = t1 / 64; t < t1; t *= 2)
        if (t > alpha / 4) ts.push_back(t);
    toward(0, t1, ts);
    std::vector<double> breaks{0.0};
    for (double t : ts)
        if (t > 0 && t < t1) breaks.push_back(D::theta_to_psi(t, np));
    breaks.push_back(psi1);
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    // The tolerance: a quarter to each region's outer |K - G| and a quarter to its inner errors.
    estimate total = rule.integrate([&](double psi) { return over_phi(psi, tol / (4 * psi1)); }, breaks, tol / 4, tol / 4);
    if (psi2 > psi1) {
        const double span = psi2 - psi1;
        auto region2 = [&](double s) -> estimate {
            const double jacobian = span * pi / 2 * sin(pi * s);
            const estimate e = over_phi(psi1 + span * (1 - cos(pi * s)) / 2, tol / (4 * jacobian));
            return estimate{e.value * jacobian, e.abs_error * jacobian, e.evaluations};
        };
        std::vector<double> t2s;
        for (int j = 1; j < 4; ++j) t2s.push_back(t1 + (t2 - t1) * j / 4);
        toward(t2, t1, t2s);
        toward(t1, t2, t2s);
        std::vector<double> s_breaks{0.0, 1.0};
        for (double t : t2s) {
            if (!(t > t1 && t < t2)) continue;
            const double psi = D::theta_to_psi(t, np);
            s_breaks.push_back(acos(std::min(1.0, std::max(-1.0, 1 - 2 * (psi - psi1) / span))) / pi);
        }
        std::sort(s_breaks.begin(), s_breaks.end());
        s_breaks.erase(std::unique(s_breaks.begin(), s_breaks.end()), s_breaks.end());
        const estimate r2 = rule.integrate(region2, s_breaks, tol / 4, tol / 4);
        total.value += r2.value;
        total.abs_error += r2.abs_error;
        total.evaluations += r2.evaluations;
    }
    total.abs_error += eps * abs(total.value);
    return total;
}

// Smith's two exact G are compiled in (their code inlined: 1.27x faster than through
// view_terms' pointers, the same values); the other G run through the pointers.
template <class D, unsigned Points = 15, class Fresnel>
auto stretched_albedo(const composition& c, double mu, double alpha, double f0, const albedo_settings& set,
                      const Fresnel& fresnel) {
    if constexpr (D::has_exact_lambda) {
        if (c.g_part == index_of<masking_parts>("smith-height-correlated"))
            return stretched_albedo_with<D, g_smith_height_correlated, Points>(c, mu, alpha, f0, set, fresnel);
        if (c.g_part == index_of<masking_parts>("smith-separable"))
            return stretched_albedo_with<D, g_smith_separable, Points>(c, mu, alpha, f0, set, fresnel);
    }
    return stretched_albedo_with<D, void, Points>(c, mu, alpha, f0, set, fresnel);
}

// F = 1 (the white furnace, and the E tables engines bake) is compiled in as well: 1.15x faster
// than through the pointer on ggx/smith-height-correlated/one, the same values.
template <class D, unsigned Points = 15>
quadrature::estimate<double> stretched_albedo(const composition& c, double mu, double alpha, double f0,
                                              const albedo_settings& set) {
    if (c.f_part == index_of<fresnel_parts>("one"))
        return stretched_albedo<D, Points>(c, mu, alpha, f0, set, [](double vh, const composition::view_terms<double>& view) {
            return fresnel_one::eval(vh, view.fp);
        });
    return stretched_albedo<D, Points>(c, mu, alpha, f0, set, [](double vh, const composition::view_terms<double>& view) {
        return view.fresnel(vh, view.fp);
    });
}

}  // namespace detail

// The incident direction at cos t = mu as the generic albedo integral (albedo.hpp) takes it:
// the angle in binary128, with its distance to 90 degrees from asin(mu).
inline degrees_angle<quad> angle_of_cosine(double mu) {
    const quad to_deg = 180 / boost::math::constants::pi<quad>();
    const quad to_90 = asin(quad(mu)) * to_deg;
    return degrees_angle<quad>(90 - to_90, to_90, 90 + to_90);
}

// The smallest incidence cosine taken, 90 - 5.7e-7 degrees: below it the integrals were not
// validated, and some failed (Beckmann's Lambda underflowed to E = 0 +- 0 at mu = 1e-160; the
// generic integral's bound grew past 1e-10 at 1e-20); the tests and tables reach 1e-4
// (docs/microfacet.md, "The albedo in the distribution's own variable").
inline constexpr double smallest_mu = 1e-8;

namespace detail {

inline void check_incidence(double mu, double alpha) {
    if (!(mu >= smallest_mu && mu <= 1))
        throw std::invalid_argument("mu = " + std::to_string(mu) + " is not in [1e-8, 1]");
    if (!(alpha > 0 && alpha < std::numeric_limits<double>::infinity()))
        throw std::invalid_argument("alpha = " + std::to_string(alpha) + " is not > 0");
}

// Whether E(mu) of c at alpha is integrated in the distribution's own variable (stretched_albedo)
// rather than by the generic integral of albedo.hpp.
inline bool in_distribution_variable(const composition& c, double alpha) {
    // Cook-Torrance's G is a min(): its kinks, curves across the domain, can fool the
    // Gauss-Kronrod estimate of a panel (the estimate of the generic integral was 0.81 of the true
    // error at alpha = 0.4, mu = 0.05, tolerance 1e-10). It is integrated by the generic integral at
    // 1/100 of the tolerance asked, where the estimates held (docs/microfacet.md).
    const bool kinked = c.g_part == index_of<masking_parts>("cook-torrance");
    // Above alpha = 1 (GGX's Lambda branches and Schlick's poles move to real N.L > 1, and D's
    // mass to the horizon) the graded panels were not made for it: at alpha = 3, mu = 1e-4
    // (ggx/schlick-ggx-remapped/schlick) their bound was 0.4 of the true error. The generic
    // integral's bounds held there (180 cases, alpha 1.2 to 5).
    return c.has_polar_map() && !kinked && alpha <= 1;
}

}  // namespace detail

// E(mu) of composition c at roughness alpha and F0 f0 (the Schlick parts' F0; a dielectric's
// index follows from it), to settings.tolerance absolute (relative above 1). With F = one, GGX or Beckmann
// and a G of N.L and N.V, up to alpha = 1, a 1D integral over N.L with D's azimuthal integral in
// closed form (azimuthal_albedo.hpp); otherwise compositions whose D has a polar map
// (blinn-phong, beckmann, ggx) are integrated in it up to alpha = 1, but for Cook-Torrance's G;
// the others (gtr, the anisotropic parts, alpha > 1) by the generic lobe-centred integral of
// albedo.hpp. Throws std::invalid_argument for mu outside [smallest_mu, 1] or alpha not in (0, inf).
inline quadrature::estimate<double> directional_albedo(const composition& c, double mu, double alpha, double f0 = 1,
                                                       const albedo_settings& settings = {}) {
    detail::check_incidence(mu, alpha);
    if (detail::in_closed_azimuth(c, alpha))
        return detail::visit_part<distribution_parts, quadrature::estimate<double>>(c.d_part, [&](auto part) {
            using D = decltype(part);
            if constexpr (D::has_azimuthal_integral) return detail::azimuthal_albedo<D>(c, mu, alpha, settings);
            return quadrature::estimate<double>{};
        });
    if (detail::in_distribution_variable(c, alpha))
        return detail::visit_part<distribution_parts, quadrature::estimate<double>>(c.d_part, [&](auto part) {
            using D = decltype(part);
            if constexpr (D::has_polar_map) return detail::stretched_albedo<D>(c, mu, alpha, f0, settings);
            return quadrature::estimate<double>{};
        });
    albedo_settings s = settings;
    if (c.g_part == detail::index_of<masking_parts>("cook-torrance")) s.tolerance /= 100;
    return normzoo::albedo<composition>(angle_of_cosine(mu), composition::node_exponent(alpha), f0, s, alpha, c);
}

}  // namespace normzoo::microfacet
