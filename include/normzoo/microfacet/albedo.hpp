// The directional albedo of a microfacet composition (docs/microfacet.md, "The albedo in the
// distribution's own variable"):
//     E(mu) = integral over L of f(L, V) N.L d(omega_L),   V = (sqrt(1 - mu^2), 0, mu),
// in the half vector h, where D(h) N.h is a probability density (stretched.hpp):
//     E(mu) = integral of D(h) N.h * w(h) d(omega_h),   w = G F(V.h) V.h / (mu N.h).
//
// Each node's rounding is bounded from the conditioning of N.L and V.h (both sums of O(1) terms,
// absolutely accurate; the azimuth's cosine and sine err by up to 4 ulps, from the addition
// formulas of quadrature/adaptive.hpp): the relative error of w is at most 32 eps + 8 eps (2 V.h
// N.h + mu + sin t)/N.L + 12 eps (sin t + mu cos t)/V.h, as G and the Fresnel term are at most
// linear in N.L and V.h near 0 (Kelemen's G is 1/(V.h)^2: 2x).
#pragma once
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "../albedo.hpp"
#include "../geometry.hpp"
#include "../quadrature/estimate.hpp"
#include "../real.hpp"
#include "azimuthal_albedo.hpp"
#include "composition.hpp"
#include "rough_dielectric.hpp"
#include "stretched.hpp"

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
    using std::sqrt;
    using Value = std::decay_t<decltype(fresnel(1.0, std::declval<const composition::view_terms<double>&>()))>;
    using estimate = quadrature::estimate<Value>;
    const double sv = sqrt((1 - mu) * (1 + mu));
    const vec3<double> v(sv, 0, mu);
    const ndf_params<double> np = c.ndf(alpha);
    const brdf::params<double> p{0, f0, alpha};
    const composition::view_terms<double> view = c.at_view(v, p);
    const double eps = std::numeric_limits<double>::epsilon();
    auto w = [&](const half_vector_node& x) -> estimate {
        const vec3<double> h(x.st * x.cphi, x.st * x.sphi, x.ct);
        const vec3<double> l = 2 * x.vh * h - v;
        shading<double> s;
        s.nl = x.nl, s.nv = mu, s.nm = x.ct, s.vm = x.vh;
        double g;
        if constexpr (std::is_void_v<G>) {
            g = c.masking(s, l, view);
        } else {
            s.alpha = view.alpha;
            if constexpr (G::needs_lambda) s.lambda_v = view.lambda_v, s.lambda_l = D::lambda(l, view.np);
            g = G::g(s);
        }
        const Value value = g * fresnel(x.vh, view) * (x.vh * x.inv_muct);
        const double relative =
            32 + (8 * (2 * x.vh * x.ct + mu + x.st) * x.vh + 12 * (x.st + mu * x.ct) * x.nl) / (x.nl * x.vh);
        return {value, eps * relative * abs(value), 1};
    };
    stretched_lobe lobe{alpha, std::is_same_v<D, d_beckmann> && view.needs_lambda,
                        std::is_same_v<D, d_beckmann> || std::is_same_v<D, d_blinn_phong>};
    lobe.kink_vm = c.kink_vm();
    lobe.critical_vh = c.critical_vh();
    return stretched_integral<D, Points>(np, mu, sv, lobe, set.tolerance, set.max_panels, w);
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
// than through the pointer on ggx/smith-height-correlated/one, the same values. So is Schlick's
// (B of the split-sum pair is the Schlick albedo at F0 = 0): the 64^2 (A, B) table 1.13x faster
// than through the pointer (0.708 s against 0.800 s, the least of six runs), the same values.
template <class D, unsigned Points = 15>
quadrature::estimate<double> stretched_albedo(const composition& c, double mu, double alpha, double f0,
                                              const albedo_settings& set) {
    if (c.f_part == index_of<fresnel_parts>("one"))
        return stretched_albedo<D, Points>(c, mu, alpha, f0, set, [](double vh, const composition::view_terms<double>& view) {
            return fresnel_one::eval(vh, view.fp);
        });
    if (c.f_part == index_of<fresnel_parts>("schlick"))
        return stretched_albedo<D, Points>(c, mu, alpha, f0, set, [](double vh, const composition::view_terms<double>& view) {
            return fresnel_schlick::eval(vh, view.fp);
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

// The smallest roughness taken, likewise: at 1e-8 every part's integral holds its bound (every D,
// mu from 1e-8 to 1), below it some fail (GGX's a^4 underflows in its azimuthal integral: E = NaN
// at alpha = 1e-100, mu = 1; the generic integral ran for minutes at 1e-200).
inline constexpr double smallest_alpha = 1e-8;

namespace detail {

inline void check_incidence(double mu, double alpha) {
    if (!(mu >= smallest_mu && mu <= 1))
        throw std::invalid_argument("mu = " + std::to_string(mu) + " is not in [1e-8, 1]");
    if (!(alpha >= smallest_alpha && alpha < std::numeric_limits<double>::infinity()))
        throw std::invalid_argument("alpha = " + std::to_string(alpha) + " is not in [1e-8, inf)");
}

// charlie-sheen's Lambda is a fit over alpha in [0, 1] (KHR_materials_sheen's sheenRoughness): beyond
// it the interpolated coefficients extrapolate (b changes sign at alpha = 3.75, a pole of 1/(1 + b
// x^c)), and at alpha = 4 the integral's bound fell below its true error; up to 1.5 it held
// (docs/microfacet.md#the-charlie-sheen-distribution). The command refuses a typed alpha above 1,
// the fit's domain; the library takes up to 1.5, where an input's rounding step may go.
inline constexpr double charlie_sheen_largest_alpha = 1.5;
inline void check_part_domain(const composition& c, double alpha) {
    if (c.g_part == index_of<masking_parts>("charlie-sheen") && alpha > charlie_sheen_largest_alpha)
        throw std::invalid_argument("alpha = " + std::to_string(alpha) +
                                    ": charlie-sheen's fitted Lambda is defined for alpha in [0, 1] (the albedo takes it up to 1.5)");
}

// Whether E(mu) of c at alpha is integrated in the distribution's own variable (stretched_albedo)
// rather than by the generic integral of albedo.hpp.
inline bool in_distribution_variable(const composition& c, double alpha) {
    // Cook-Torrance's G is a min(): its kinks, curves across the domain, can fool the
    // Gauss-Kronrod estimate of a panel unless they are breakpoints, which they are here (in phi
    // at each t, and in t where they enter or leave the domain: stretched.hpp). It has no poles,
    // and beyond alpha = 1 the panels held for it too (GGX and Beckmann, alpha 1.2 to 5), where
    // the generic integral missed (docs/microfacet.md); Blinn-Phong's exponent is < 0 there.
    const bool kinked = c.kinked();
    // Above alpha = 1 (GGX's Lambda branches and Schlick's poles move to real N.L > 1, and D's
    // mass to the horizon) the graded panels were not made for it: at alpha = 3, mu = 1e-4
    // (ggx/schlick-ggx-remapped/schlick) their bound was 0.4 of the true error. The generic
    // integral's bounds held there (180 cases, alpha 1.2 to 5).
    return c.has_polar_map() && (alpha <= 1 || (kinked && c.d_part != index_of<distribution_parts>("blinn-phong")));
}

}  // namespace detail

// E(mu) of composition c at roughness alpha and F0 f0 (the Schlick parts' F0; a dielectric's
// index follows from it), to settings.tolerance absolute (relative above 1). With F = one (GGX or
// Beckmann) or Schlick's (GGX; tolerance >= 1e-11) and a G of N.L and N.V, up to alpha = 1, a 1D
// integral over N.L with D F's azimuthal integral in closed form (azimuthal_albedo.hpp); otherwise compositions whose D has a polar map
// (blinn-phong, beckmann, ggx) are integrated in it up to alpha = 1 (Beckmann and GGX at every
// alpha with Cook-Torrance's G); the others (gtr, the anisotropic parts, alpha > 1) by the generic
// lobe-centred integral of albedo.hpp. Throws std::invalid_argument for mu outside [smallest_mu, 1] or alpha not in [smallest_alpha, inf).
inline quadrature::estimate<double> directional_albedo(const composition& c, double mu, double alpha, double f0 = 1,
                                                       const albedo_settings& settings = {}) {
    detail::check_incidence(mu, alpha);
    detail::check_part_domain(c, alpha);
    if (c.transmission) {  // reflection plus transmission (rough_dielectric.hpp)
        if (!(alpha <= 1)) throw std::invalid_argument("the transmitting interface's albedo takes alpha <= 1");
        const rough_dielectric_albedo r =
            rough_dielectric_albedo_of<15>(alpha, c.fresnel_at(f0).eta, mu, settings.tolerance, settings.max_panels);
        return {r.reflection.value + r.transmission.value, r.reflection.abs_error + r.transmission.abs_error, r.evaluations};
    }
    if (detail::in_closed_azimuth(c, alpha, settings.tolerance))
        return detail::visit_part<distribution_parts, quadrature::estimate<double>>(c.d_part, [&](auto part) {
            using D = decltype(part);
            if constexpr (D::has_azimuthal_integral) return detail::azimuthal_albedo<D>(c, mu, alpha, f0, settings);
            return quadrature::estimate<double>{};
        });
    if (detail::in_distribution_variable(c, alpha))
        return detail::visit_part<distribution_parts, quadrature::estimate<double>>(c.d_part, [&](auto part) {
            using D = decltype(part);
            if constexpr (D::has_polar_map) return detail::stretched_albedo<D>(c, mu, alpha, f0, settings);
            return quadrature::estimate<double>{};
        });
    albedo_settings s = settings;
    // Cook-Torrance's kinks are breakpoints of its inner integrals, not of its outer one over
    // the azimuth, where they come and go: 1/100 of the tolerance there (docs/microfacet.md).
    if (c.kinked()) s.tolerance /= 100;
    return normzoo::albedo<composition>(angle_of_cosine(mu), composition::node_exponent(alpha), f0, s, alpha, c);
}

}  // namespace normzoo::microfacet

#ifdef NORMZOO_COMPILED_KERNELS
#include "../detail/compiled_kernels.hpp"
#endif
