// OpenPBR's metal lobe with V fixed as one integral over N.L (docs/materials.md, "OpenPBR Surface
// 1.1", "The albedo"): GGX with height-correlated Smith under the F82-tint Fresnel, per channel
//     F = F0 + (1 - F0) (1 - V.h)^5 - b V.h (1 - V.h)^6      (openpbr_model.hpp, f82),
// affine in 1, (1 - V.h)^5 and V.h (1 - V.h)^6, and D times each has its integral over L's azimuth
// in closed form (microfacet/ggx_schlick_azimuth.hpp), so that the lobe's albedo per channel is
//     w / (4 mu) integral_0^1 G(N.L, N.V) [F0 D1 + (1 - F0) D5 - b D6] dN.L,
// w = specular_weight: the composition's 1D route (microfacet/azimuthal_albedo.hpp) with three
// weights, where GGX's map took a 2D integral. Not under a film, whose Fresnel has no such form.
// Each node's bound: D1's 64 ulps, D5's and D6's rounding bounds (their alternating sums), the
// weights' few ulps, and 48 ulps of the product (as the composition's node).
#pragma once
#include <cmath>
#include <cstddef>
#include <limits>

#include "../microfacet/azimuthal_albedo.hpp"
#include "../microfacet/ggx_schlick_azimuth.hpp"
#include "../quadrature/adaptive.hpp"
#include "../quadrature/channels.hpp"
#include "about_v.hpp"
#include "albedo.hpp"
#include "lobes.hpp"

namespace normzoo::material::detail {

// The F82 metal's albedo at V = (sqrt(1 - mu^2), 0, mu), GGX at alpha in (0, 1], per channel
// F0 = f0[k] and b = b[k], times the weight w and, where given, a factor of N.L per channel
// (an absorbing coat's h(N.L), openpbr_coat.hpp, giving its value per channel: 32 ulps of the node
// for its rounding, as GGX's map takes a weight's; no_nl_factor, about_v.hpp's, where none); to
// `tol` (the sum of the channels' bounds).
template <class H = no_nl_factor>
rgb_estimate f82_metal_albedo(double alpha, double mu, const rgb& f0, const rgb& b, double w, double tol, std::size_t max_panels,
                              std::size_t& evaluations, const H& factor = H{}) {
    using value = quadrature::channels<double, 3>;
    using estimate = quadrature::estimate<value>;
    const double eps = std::numeric_limits<double>::epsilon(), sv2 = (1 - mu) * (1 + mu);
    const specular_brdf lobe{alpha, smith_form::height_correlated};
    const double lambda_v = lobe.lambda(vec3<double>(std::sqrt(sv2), 0, mu)), scale = w / (4 * mu);
    auto at = [&](double nl, double sl2, double nl_minus_nv) -> estimate {
        estimate e{value{}, value{}, 1};
        if (!(nl > 0)) return e;
        const auto phi = microfacet::detail::ggx_schlick_azimuthal_integrals<true>(nl, mu, nl_minus_nv, sl2, sv2, alpha);
        const double g = lobe.g(lobe.lambda(vec3<double>(std::sqrt(sl2), 0, nl)), lambda_v) * scale;
        rgb h = grey(1);
        if constexpr (has_nl_factor<H>) h = factor(nl);
        for (std::size_t k = 0; k < 3; ++k) {
            const double t1 = f0[k] * phi.d, t5 = (1 - f0[k]) * phi.d5, t6 = b[k] * phi.d6, gh = g * h[k];
            e.value[k] = gh * (t1 + t5 - t6);
            e.abs_error[k] = std::abs(gh) * (std::abs(f0[k]) * 64 * eps * phi.d + std::abs(1 - f0[k]) * phi.d5_error +
                                             std::abs(b[k]) * phi.d6_error + 4 * eps * (std::abs(t1) + std::abs(t5) + std::abs(t6))) +
                             48 * eps * std::abs(e.value[k]);
            if constexpr (has_nl_factor<H>) e.abs_error[k] += 32 * eps * std::abs(e.value[k]);
        }
        return e;
    };
    // N.L itself on [0, mu/2] and the offset x = N.L - N.V beyond, as the composition's route
    const double one_minus_mu = 1 - mu;
    auto in_nl = [&](double nl) { return at(nl, (1 - nl) * (1 + nl), nl - mu); };
    auto in_x = [&](double x) {
        const double nl = mu + x;
        return at(nl, (one_minus_mu - x) * (1 + nl), x);
    };
    const microfacet::detail::azimuthal_breaks breaks(mu, alpha);
    const quadrature::adaptive_kronrod<double, 15> rule(max_panels);
    const auto peak = rule.integrate(in_x, breaks.x, tol / 2, 0.0), horizon = rule.integrate(in_nl, breaks.nl, tol / 2, 0.0);
    evaluations += peak.evaluations + horizon.evaluations;
    rgb_estimate r;
    for (std::size_t k = 0; k < 3; ++k) {
        r.value[k] = peak.value[k] + horizon.value[k];
        r.abs_error[k] = peak.abs_error[k] + horizon.abs_error[k] + 4 * eps * std::abs(r.value[k]);
    }
    return r;
}

}  // namespace normzoo::material::detail
