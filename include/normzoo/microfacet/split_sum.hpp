// The split-sum pair of Karis 2013 ("Real Shading in Unreal Engine 4"): with Schlick's Fresnel
// F = F0 + (F90 - F0)(1 - V.h)^5, the albedo of a composition is linear in F0 and F90,
//     E(mu) = F0 A(mu, alpha) + F90 B(mu, alpha),
//     A = integral of f_1 (1 - (1 - V.h)^5) N.L,   B = integral of f_1 (1 - V.h)^5 N.L,
// f_1 the composition with F = 1 (docs/microfacet.md, "The tables engines bake"). B is the albedo
// with F = Schlick at F0 = 0, A + B the albedo with F = 1: A is their difference, its bound the
// sum of theirs. Engines store (A, B) (Unreal's scale and bias) or (B, A + B) (Filament's DFG,
// F = mix(B, A + B, F0)); both come from this pair. Where A + B is the 1D integral over N.L
// (azimuthal_albedo.hpp: GGX or Beckmann with a G of N.L and N.V), it takes a tenth of the
// tolerance and B alone (the albedo at F0 = 0: with GGX the same integral over N.L with
// Schlick's factor, with Beckmann in the distribution's variable, one channel instead of two,
// 1.3x to 1.6x faster than the pair from shared nodes) the rest (docs/microfacet.md, "The tables
// engines bake"). Below a tolerance of 1e-12 that tenth would meet the 1D integral's rounding floor (A's
// bound came out at up to 2.3x the tolerance at 1e-13): there, as elsewhere in the
// distribution's variable, A + B and B come from the same nodes, as two channels of one integral
// (quadrature/channels.hpp): half the work of two albedos.
#pragma once
#include "../quadrature/channels.hpp"
#include "albedo.hpp"

namespace normzoo::microfacet {

struct split_sum_value {
    quadrature::estimate<double> a, b;
};

// A and B of the composition's D and G (its F part is replaced) at mu and alpha.
inline split_sum_value split_sum(const composition& c, double mu, double alpha, const albedo_settings& s = {}) {
    composition one = c, schlick = c;
    one.f_part = detail::index_of<fresnel_parts>("one");
    schlick.f_part = detail::index_of<fresnel_parts>("schlick");
    one.compensation = schlick.compensation = composition::compensation_kind::none;
    quadrature::estimate<double> e, b;
    std::size_t spent = 0;  // evaluations of the BRDF for both
    detail::check_incidence(mu, alpha);
    // A + B over N.L: a tenth of the tolerance, the rest to B alone (see above).
    const bool over_nl = s.tolerance >= 1e-12 && detail::in_closed_azimuth(one, alpha);
    if (!over_nl && detail::in_distribution_variable(one, alpha)) {
        albedo_settings half = s;
        half.tolerance = s.tolerance / 2;
        // channel 0: F = 1 (A + B); channel 1: Schlick's F at F0 = 0, (1 - V.h)^5 (B)
        using pair = quadrature::channels<double, 2>;
        const auto both = detail::visit_part<distribution_parts, quadrature::estimate<pair>>(one.d_part, [&](auto part) {
            using D = decltype(part);
            if constexpr (D::has_polar_map)
                return detail::stretched_albedo<D>(one, mu, alpha, 1, half, [](double vh, const composition::view_terms<double>&) {
                    pair f;
                    f[0] = 1;
                    f[1] = detail::pow5(1 - vh);
                    return f;
                });
            return quadrature::estimate<pair>{};
        });
        e = {both.value[0], both.abs_error[0], both.evaluations};
        b = {both.value[1], both.abs_error[1], both.evaluations};
        spent = both.evaluations;
    } else {
        albedo_settings for_e = s, for_b = s;
        for_e.tolerance = over_nl ? s.tolerance / 10 : s.tolerance / 2;
        for_b.tolerance = s.tolerance - for_e.tolerance;
        e = directional_albedo(one, mu, alpha, 1, for_e);
        b = directional_albedo(schlick, mu, alpha, 0, for_b);
        spent = e.evaluations + b.evaluations;
    }
    split_sum_value r;
    r.b = b;
    r.a = {e.value - b.value, e.abs_error + b.abs_error + 2.3e-16 * e.value, spent};
    return r;
}

}  // namespace normzoo::microfacet
