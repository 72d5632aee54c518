// The directional albedo with F = 1 or Schlick's F as a 1D integral (docs/microfacet.md, "F = 1:
// D over L's azimuth in closed form" and "Schlick's F over L's azimuth"):
//     E(mu) = 1/(4 mu) integral over L of D(h) G(L, V) F(V.h) d(omega_L)
//           = 1/(4 mu) integral_0^1 G(N.L) [integral over phi_L of D(h) F(V.h)] d(N.L),
// where G reads N.L and N.V alone (Smith's forms with an isotropic Lambda, the implicit G, the
// Schlick and Hammon approximations: reads_half_vector false), so that only D F depends on L's
// azimuth, and its integral over it has a closed form: D's (has_azimuthal_integral: GGX,
// Beckmann) for F = 1, and D's and D (1 - V.h)^5's (has_azimuthal_schlick_integral: GGX) for
// Schlick's F0 + (F90 - F0) (1 - V.h)^5. Every L
// above the horizon counts, whatever its azimuth: no horizon cut crosses the domain, and the
// integrand is one function of N.L with a peak of width ~alpha sin t_V + alpha^2 at N.L = N.V
// (the mirror direction's polar angle) and, near N.L = 0, G's turn where N.L ~ alpha and the
// factor N.L + N.V where N.L ~ N.V.
//
// The variable is the offset N.L - N.V around the peak, so that a node's place relative to the
// peak is exact however narrow the peak is (alpha^2 at normal incidence), and N.L itself next to
// the horizon. Adaptive Gauss-Kronrod 15 on panels graded toward the peak (4x apart from
// alpha (alpha + sin t_V) / 8) and toward the horizon (from min(alpha, mu) / 16); the bound is
// |K - G| and a rounding bound: D's azimuthal integral bounds its own (azimuthal_value), and 48
// ulps of the node's value bound G's and the products' (docs/microfacet.md gives the validation).
#pragma once
#include <algorithm>
#include <array>
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

// Whether c's F is Schlick's (with F90 or not).
inline bool schlick_fresnel(const composition& c) {
    return c.f_part == index_of<fresnel_parts>("schlick") || c.f_part == index_of<fresnel_parts>("schlick-f90");
}

// Whether E(mu) of c at alpha is this 1D integral: F = 1 and a D with the azimuthal integral, or
// Schlick's F and a D with that of D (1 - V.h)^5 at a tolerance of 1e-11 or more; a G of N.L and
// N.V; alpha <= 1 (where GGX's closed forms' terms are all >= 0, and which the graded panels were
// made and checked for). Below 1e-11 Schlick's six alternating terms meet their rounding bound
// (at 1e-12 it reached 1.05x the tolerance, 8x at 1e-13): the integral in the distribution's
// variable takes those.
inline bool in_closed_azimuth(const composition& c, double alpha, double tolerance = 1e-10) {
    const bool schlick = schlick_fresnel(c);
    if (schlick && tolerance < 1e-11) return false;
    const bool d_has = visit_part<distribution_parts, bool>(c.d_part, [&](auto part) {
        using D = decltype(part);
        return schlick ? D::has_azimuthal_schlick_integral : D::has_azimuthal_integral;
    });
    const bool g_cosines = visit_part<masking_parts, bool>(c.g_part, [](auto part) { return !decltype(part)::reads_half_vector; });
    return d_has && g_cosines && (schlick || c.f_part == index_of<fresnel_parts>("one")) && alpha <= 1;
}

// The integrand of the 1D integral over N.L, at F0 = f0 (Schlick's parts; F = 1 reads none):
// at(N.L, sin^2 t_L, N.L - N.V) is 1/(4 mu) G [D F's integral over L's azimuth], with its bound.
// Also the inner integral of an albedo weighted by a factor of N.L (material/sheen_albedo.hpp).
template <class D>
struct azimuthal_integrand {
    using estimate = quadrature::estimate<double>;
    const composition& c;
    double mu, sv2;
    composition::view_terms<double> view;
    double scale, w1, w5;

    azimuthal_integrand(const composition& comp, double mu_, double alpha, double f0)
        : c(comp), mu(mu_), sv2((1 - mu_) * (1 + mu_)),
          view(comp.at_view(vec3<double>(std::sqrt(sv2), 0, mu_), brdf::params<double>{0, f0, alpha})),
          scale(1 / (4 * mu_)) {
        // F = w1 + w5 (1 - V.h)^5: (1, 0) for F = 1; Schlick's (F0, 1 - F0) or (F0, F90 - F0).
        const bool schlick = schlick_fresnel(c);
        w1 = schlick ? view.fp.f0 : 1.0;
        w5 = !schlick ? 0.0 : c.f_part == index_of<fresnel_parts>("schlick") ? 1 - view.fp.f0 : view.fp.f90 - view.fp.f0;
    }
    estimate operator()(double nl, double sl2, double nl_minus_nv) const {
        const double eps = std::numeric_limits<double>::epsilon();
        const azimuth_point<double> point{nl, mu, nl_minus_nv, sl2, sv2};
        azimuthal_value<double> phi = D::azimuthal_integral(point, view.np);
        phi.value *= w1, phi.error *= std::abs(w1);
        if constexpr (D::has_azimuthal_schlick_integral)
            if (w5 != 0) {
                const azimuthal_value<double> phi5 = D::azimuthal_schlick_integral(point, view.np);
                phi.value += w5 * phi5.value;
                phi.error += std::abs(w5) * phi5.error + 2 * eps * std::abs(phi.value);
            }
        shading<double> s;
        s.nl = nl, s.nv = mu;
        s.nm = s.vm = std::numeric_limits<double>::quiet_NaN();  // read by no G that comes here
        const double g = c.masking(s, vec3<double>(std::sqrt(sl2), 0, nl), view);
        const double value = g * phi.value * scale;
        return {value, 48 * eps * std::abs(value) + std::abs(g * scale) * phi.error, 1};
    }
    // The integrand at F = 1 and at F = (1 - V.h)^5 at once, as this at F0 = 1 and F0 = 0 of
    // Schlick's part would give them, bit for bit: one azimuth point and one G for both (an outer
    // integral over N.L that needs both, material/sheen_albedo.hpp).
    std::array<estimate, 2> one_and_schlick(double nl, double sl2, double nl_minus_nv) const {
        static_assert(D::has_azimuthal_schlick_integral, "D F's azimuthal integral for Schlick's F");
        const double eps = std::numeric_limits<double>::epsilon();
        const azimuth_point<double> point{nl, mu, nl_minus_nv, sl2, sv2};
        const azimuthal_value<double> phi1 = D::azimuthal_integral(point, view.np);
        const azimuthal_value<double> phi5 = D::azimuthal_schlick_integral(point, view.np);
        shading<double> s;
        s.nl = nl, s.nv = mu;
        s.nm = s.vm = std::numeric_limits<double>::quiet_NaN();
        const double g = c.masking(s, vec3<double>(std::sqrt(sl2), 0, nl), view);
        const double v1 = g * phi1.value * scale, v5 = g * phi5.value * scale;
        return {{{v1, 48 * eps * std::abs(v1) + std::abs(g * scale) * phi1.error, 1},
                 {v5, 48 * eps * std::abs(v5) + std::abs(g * scale) * (phi5.error + 2 * eps * std::abs(phi5.value)), 1}}};
    }
};

// The breakpoints of the 1D integral: toward the peak at N.L = N.V from both sides (4x apart
// from alpha (alpha + sin t_V) / 8), in the offset x = N.L - N.V on [-mu/2, 1 - mu], and toward
// the horizon (from min(alpha, mu) / 16) in N.L on [0, mu/2].
struct azimuthal_breaks {
    std::vector<double> x, nl;
    azimuthal_breaks(double mu, double alpha) {
        const double sv = std::sqrt((1 - mu) * (1 + mu));
        const double width = alpha * (alpha + sv) / 8, half_mu = mu / 2;
        x = {-half_mu, 0.0, 1 - mu}, nl = {0.0, half_mu};
        for (double d = width; d < 1; d *= 4) x.insert(x.end(), {-d, d});
        for (double n = std::min(alpha, mu) / 16; n < 0.5; n *= 4) {
            if (n < half_mu) nl.push_back(n);
            else x.push_back(n - mu);  // the horizon's grading goes on past mu/2
        }
        x = kept(x, -half_mu, 1 - mu), nl = kept(nl, 0.0, half_mu);
    }
    static std::vector<double> kept(std::vector<double> b, double lo, double hi) {
        b.erase(std::remove_if(b.begin(), b.end(), [&](double v) { return !(v >= lo && v <= hi); }), b.end());
        std::sort(b.begin(), b.end());
        b.erase(std::unique(b.begin(), b.end()), b.end());
        return b;
    }
};

// At F0 = f0 (Schlick's parts; F = 1 reads none).
template <class D>
quadrature::estimate<double> azimuthal_albedo(const composition& c, double mu, double alpha, double f0, const albedo_settings& set) {
    using estimate = quadrature::estimate<double>;
    const double eps = std::numeric_limits<double>::epsilon();
    const azimuthal_integrand<D> at(c, mu, alpha, f0);
    // Two variables: N.L itself on [0, mu/2] (the horizon's features, exact there), and the
    // offset x = N.L - N.V on [-mu/2, 1 - mu] (the peak at x = 0: a node's place is exact relative
    // to it, however narrow; N.L = mu + x and 1 - N.L = (1 - mu) - x round by an ulp of
    // themselves, smooth there). In N.L or 1 - N.L alone, a node's rounding moved it by up to an
    // ulp of mu against a peak alpha sin t_V wide: at alpha = 1e-8 the error was 17x the bound.
    const double one_minus_mu = 1 - mu;
    auto in_nl = [&](double nl) { return at(nl, (1 - nl) * (1 + nl), nl - mu); };
    auto in_x = [&](double x) {
        const double nl = mu + x;
        return at(nl, (one_minus_mu - x) * (1 + nl), x);
    };
    const azimuthal_breaks breaks(mu, alpha);
    const quadrature::adaptive_kronrod<double, 15> rule(set.max_panels);
    estimate total = rule.integrate(in_x, breaks.x, set.tolerance / 2, 0.0);
    const estimate horizon = rule.integrate(in_nl, breaks.nl, set.tolerance / 2, 0.0);
    total.value += horizon.value;
    total.abs_error += horizon.abs_error + 4 * eps * std::abs(total.value);
    total.evaluations += horizon.evaluations;
    return total;
}

}  // namespace detail

}  // namespace normzoo::microfacet
