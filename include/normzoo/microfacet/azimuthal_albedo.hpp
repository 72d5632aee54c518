// The directional albedo with F = 1 as a 1D integral (docs/microfacet.md, "F = 1: D over L's
// azimuth in closed form"):
//     E(mu) = 1/(4 mu) integral over L of D(h) G(L, V) d(omega_L)
//           = 1/(4 mu) integral_0^1 G(N.L) [integral over phi_L of D(h)] d(N.L),
// where G reads N.L and N.V alone (Smith's forms with an isotropic Lambda, the implicit G, the
// Schlick and Hammon approximations: reads_half_vector false), so that only D depends on L's
// azimuth, and D's integral over it has a closed form (has_azimuthal_integral: GGX). Every L
// above the horizon counts, whatever its azimuth: no horizon cut crosses the domain, and the
// integrand is one function of N.L with a peak of width ~alpha sin t_V + alpha^2 at N.L = N.V
// (the mirror direction's polar angle) and, near N.L = 0, G's turn where N.L ~ alpha and the
// factor N.L + N.V where N.L ~ N.V.
//
// The variable is N.L itself on [0, 1/2] and 1 - N.L on [0, 1/2] (1 - N.L near the pole, where
// the peak of a normal V is alpha^2 wide and doubles of N.L near 1 are too coarse to place
// nodes in it); N.L - N.V is then exact where the two are close. Adaptive Gauss-Kronrod 15 on
// panels graded toward the peak (4x apart from alpha (alpha + sin t_V) / 8) and toward the
// horizon (from min(alpha, mu) / 16); the bound is |K - G| and a rounding bound. A node's value
// is a few sums of terms >= 0, two square roots and G: 64 ulps of it bound its rounding (the
// largest seen in the validation, docs/microfacet.md, was within a tenth of the bound's total).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "../albedo.hpp"
#include "../geometry.hpp"
#include "../quadrature/adaptive.hpp"
#include "../quadrature/estimate.hpp"
#include "composition.hpp"

namespace normzoo::microfacet {

namespace detail {

// Whether E(mu) of c at alpha is this 1D integral: F = 1, a D with the azimuthal integral, a G of
// N.L and N.V, alpha <= 1 (where the closed form's terms are all >= 0).
inline bool in_closed_azimuth(const composition& c, double alpha) {
    const bool d_has = visit_part<distribution_parts, bool>(c.d_part, [](auto part) { return decltype(part)::has_azimuthal_integral; });
    const bool g_cosines = visit_part<masking_parts, bool>(c.g_part, [](auto part) { return !decltype(part)::reads_half_vector; });
    return d_has && g_cosines && c.f_part == index_of<fresnel_parts>("one") && alpha <= 1;
}

template <class D>
quadrature::estimate<double> azimuthal_albedo(const composition& c, double mu, double alpha, const albedo_settings& set) {
    using estimate = quadrature::estimate<double>;
    const double eps = std::numeric_limits<double>::epsilon();
    const double sv2 = (1 - mu) * (1 + mu), sv = std::sqrt(sv2);
    const vec3<double> v(sv, 0, mu);
    const brdf::params<double> p{0, 1, alpha};
    const composition::view_terms<double> view = c.at_view(v, p);
    const double scale = 1 / (4 * mu);
    // The integrand at N.L = nl, from sin^2 t_L and N.L - N.V as the variable gives them.
    auto at = [&](double nl, double sl2, double nl_minus_nv) -> estimate {
        const double phi = D::azimuthal_integral(azimuth_point<double>{nl, mu, nl_minus_nv, sl2, sv2}, view.np);
        shading<double> s;
        s.nl = nl, s.nv = mu;
        s.nm = s.vm = std::numeric_limits<double>::quiet_NaN();  // read by no G that comes here
        const double g = c.masking(s, vec3<double>(std::sqrt(sl2), 0, nl), view);
        const double value = g * phi * scale;
        return {value, 64 * eps * std::abs(value), 1};
    };
    const double one_minus_mu = 1 - mu;  // exact for mu >= 1/2, where the peak is in u
    auto in_nl = [&](double nl) { return at(nl, (1 - nl) * (1 + nl), nl - mu); };
    auto in_u = [&](double u) { return at(1 - u, u * (2 - u), one_minus_mu - u); };  // u = 1 - N.L

    // Breakpoints in [0, 1/2] of each variable: toward the peak from both sides, and in N.L
    // toward the horizon.
    const double width = alpha * (alpha + sv) / 8;
    std::vector<double> in_nl_breaks{0.0, 0.5, mu}, in_u_breaks{0.0, 0.5, one_minus_mu};
    for (double d = width; d < 1; d *= 4) {
        in_nl_breaks.insert(in_nl_breaks.end(), {mu - d, mu + d});
        in_u_breaks.insert(in_u_breaks.end(), {one_minus_mu - d, one_minus_mu + d});
    }
    for (double d = std::min(alpha, mu) / 16; d < 0.5; d *= 4) in_nl_breaks.push_back(d);
    auto kept = [](std::vector<double> b) {
        b.erase(std::remove_if(b.begin(), b.end(), [](double x) { return !(x >= 0 && x <= 0.5); }), b.end());
        std::sort(b.begin(), b.end());
        b.erase(std::unique(b.begin(), b.end()), b.end());
        return b;
    };
    const quadrature::adaptive_kronrod<double, 15> rule(set.max_panels);
    estimate total = rule.integrate(in_nl, kept(in_nl_breaks), set.tolerance / 2, 0.0);
    const estimate pole = rule.integrate(in_u, kept(in_u_breaks), set.tolerance / 2, 0.0);
    total.value += pole.value;
    total.abs_error += pole.abs_error + 4 * eps * std::abs(total.value);
    total.evaluations += pole.evaluations;
    return total;
}

}  // namespace detail

}  // namespace normzoo::microfacet
