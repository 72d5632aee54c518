// The glTF material's albedo with V fixed where KHR_materials_sheen is on (docs/materials.md,
// "KHR_materials_sheen", its albedo): the core's lobes are scaled by
// s(L) = min(1 - c E(N.V), 1 - c E(N.L)) = 1 - c max(E_v, E(N.L)), c = max_value(sheenColor), a
// factor of N.L, so that each core lobe's albedo is
//     integral w f s N.L d(omega) = (1 - c E_v) A - c integral_0^1 g(y) max(0, E(y) - E_v) dy,
// A its albedo unscaled (albedo_of) and g(y) its integrand over N.L = y after the azimuthal
// integral in closed form (microfacet/azimuthal_albedo.hpp: the lobe is a composition, its
// weight a + b (1 - V.h)^5, so g = a g1 + b g5). The second integral is one adaptive
// Gauss-Kronrod over y with the four g's (diffuse and specular, F = 1 and F = (1 - V.h)^5) as
// channels, E(y) from the sheen's curve (sheen_curve.hpp: built once for the sheen's alpha,
// then read at each node) and E_v from it too: its support is where E(y) > E_v, which contains
// y = mu's side where E is larger; E is not monotone (it rises from the horizon to a maximum
// near grazing, then falls, and grows like y^-0.93 below y ~ 1e-4), so the other ends are the
// curve's crossings of E_v (sheen_curve.hpp), as breakpoints: where they are all of them, no kink
// lies inside a panel. The sheen lobe itself is sheenColor E_v.
// The coat's weights are in albedo_of's. Cost: the curve, 1.5 to 4 s for an alpha, then 0.1 to
// 1 ms a point, up to 2 ms under a smooth sheen (docs/materials.md, "E as a curve").
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

#include "../microfacet/azimuthal_albedo.hpp"
#include "../microfacet/d_ggx.hpp"
#include "../quadrature/adaptive.hpp"
#include "../quadrature/channels.hpp"
#include "albedo.hpp"
#include "gltf.hpp"
#include "sheen.hpp"
#include "sheen_curve.hpp"

namespace normzoo::material {

namespace detail {

// max(0, E(y) - E_v) at a node of the outer integral, E(y) from the sheen's curve, with its
// bound (E(y)'s and E_v's: max moves by at most its argument's error); `zero` where a node
// contributes 0 exactly.
struct node_excess {
    double value = 0, error = 0;
    bool zero = true;
};
inline node_excess sheen_excess_at(double y, const sheen_albedo_curve<>& e_of, const quadrature::estimate<double>& e_v) {
    node_excess r;
    const auto e = e_of(y);
    r.value = std::max(0.0, e.value - e_v.value), r.error = e.abs_error + e_v.abs_error;
    r.zero = r.value == 0 && e.value + r.error < e_v.value;
    return r;
}

// The tolerance of the sheen's curve of E for an albedo to `tolerance`: one curve (1e-11, the
// one the material's f reads) for the default 1e-10 and anything looser.
inline double sheen_curve_tolerance(double tolerance) { return std::min(gltf::sheen_curve_tolerance, tolerance / 10); }

// integral_0^1 g_k(y) max(0, E(y) - E_v) dy for k = diffuse F = 1, diffuse F = s, specular F = 1,
// specular F = s (each g_k of albedo_of's composition for the lobe, without its scale).
inline quadrature::estimate<quadrature::channels<double, 4>> sheen_excess(const gltf& m, double mu,
                                                                        const quadrature::estimate<double>& e_v,
                                                                        const sheen_albedo_curve<>& e_of, double tol,
                                                                        std::size_t max_panels) {
    using value = quadrature::channels<double, 4>;
    using estimate = quadrature::estimate<value>;
    using integrand = microfacet::detail::azimuthal_integrand<microfacet::d_ggx>;
    const auto diffuse = m.lobe_composition(0), specular = m.lobe_composition(1);
    // each composition at F = 1 and F = s (its Schlick part at F0 = 1 and 0, one G for both)
    const integrand g[2] = {{diffuse.c, mu, diffuse.alpha, 1}, {specular.c, mu, specular.alpha, 1}};
    auto f = [&](double y) -> estimate {
        estimate r{value{}, value{}, 1};
        if (!(y > 0)) return r;
        const node_excess x = sheen_excess_at(y, e_of, e_v);
        if (x.zero) return r;
        const double excess = x.value, excess_error = x.error;
        const double sl2 = (1 - y) * (1 + y);
        std::array<quadrature::estimate<double>, 2> pair;
        for (std::size_t k = 0; k < 4; ++k) {
            if (k % 2 == 0) pair = g[k / 2].one_and_schlick(y, sl2, y - mu);
            const auto& gk = pair[k % 2];
            r.value[k] = gk.value * excess;
            // max(0, .) moves by at most its argument's error; 4 eps of the product
            r.abs_error[k] = std::abs(gk.value) * excess_error + gk.abs_error * excess +
                             4 * std::numeric_limits<double>::epsilon() * std::abs(r.value[k]);
        }
        return r;
    };
    // the lobes' panels (their peak at y = mu, the horizon), E's (its branch at 1/2, graded
    // toward the horizon, where it turns)
    std::vector<double> breaks{0, 0.5, mu, 1};
    for (double alpha : {diffuse.alpha, specular.alpha}) {
        const microfacet::detail::azimuthal_breaks b(mu, alpha);
        for (double x : b.x) breaks.push_back(mu + x);
        breaks.insert(breaks.end(), b.nl.begin(), b.nl.end());
    }
    for (double d = 0.125; d > 1e-4; d /= 4) breaks.push_back(d);
    // where E crosses E_v: max(0, .) kinks there
    bool complete = true;
    for (double y : e_of.crossings(e_v.value, &complete)) breaks.push_back(y);
    breaks = microfacet::detail::azimuthal_breaks::kept(breaks, 0.0, 1.0);
    // Where the crossings are all of the curve's, no kink lies inside a panel: no bisection check.
    // Where they may not be (E_v within a stretch of the curve not proven monotone: E below its
    // bound near y = 1 at a small alpha), or where the nodes' own errors stop the rule above twice
    // its target (a narrow lobe at grazing, the azimuthal integral's bound large there), the rule
    // with the check: its finer panels look for kinks and bring its part down.
    const auto e = quadrature::adaptive_kronrod<double, 15>(max_panels, !complete).integrate(f, breaks, tol, 0.0);
    if (!complete || e.abs_error[0] + e.abs_error[1] + e.abs_error[2] + e.abs_error[3] <= 2 * tol) return e;
    auto checked = quadrature::adaptive_kronrod<double, 15>(max_panels, true).integrate(f, breaks, tol, 0.0);
    checked.evaluations += e.evaluations;
    return checked;
}

}  // namespace detail

// The glTF material's albedo with V at cos t = mu, single scattering, each lobe and the whole,
// per channel: albedo_of where the sheen is off (the core, and the coat: no other route), the
// scaling above where it is on. Throws std::invalid_argument where albedo_of does.
inline material_albedo<gltf::lobe_count> gltf_albedo(const gltf& m, double mu, const albedo_settings& settings = {}) {
    if (!m.sheen_on()) return albedo_of(m, mu, settings);
    const double eps = std::numeric_limits<double>::epsilon();
    const double c = m.sheen_scaling().c, alpha_s = m.sheen_lobe().alpha;
    bool built = false;
    const auto e_of = sheen_curve_for(alpha_s, detail::sheen_curve_tolerance(settings.tolerance), &built);
    const auto e_v = (*e_of)(mu);
    const double keep = 1 - c * e_v.value;  // 1 - c E_v, negative where E_v > 1/c (a smooth sheen at grazing)
    // the tolerance's shares: where |1 - c E_v| <= 1, 4/5 to the unscaled albedos (at 1e-10
    // their compositions' stay at 1e-11, where Schlick's azimuthal integral is closed:
    // microfacet/azimuthal_albedo.hpp) and 1/10 to the excess, E's curve at most 1/10 of it;
    // beyond (c E_v > 2, a smooth sheen at grazing, where E_v's own bound is larger and those
    // albedos are integrated in 2D anyway) 1/2 and 1/8. The excess's channels enter the whole
    // up to 4 times (the diffuse's scale 4, the specular composition's in two lobes).
    const bool near = std::abs(keep) <= 1;
    albedo_settings s = settings;
    s.tolerance = near ? settings.tolerance * 4 / 5 : settings.tolerance / (2 * std::abs(keep));
    material_albedo<gltf::lobe_count> r = albedo_of(m, mu, s);
    const auto excess = detail::sheen_excess(m, mu, e_v, *e_of, settings.tolerance / ((near ? 40 : 32) * c), settings.max_panels);
    r.evaluations += excess.evaluations + (built ? e_of->evaluations() : 0);
    const auto terms = m.weight_terms();
    const auto a = m.weights(cosines{1, mu, 1, 1}, terms), at_0 = m.weights(cosines{1, mu, 1, 0}, terms);
    for (std::size_t i = 0; i < 3; ++i) {
        const double scale = m.lobe_composition(i).scale;
        const std::size_t k = i == 0 ? 0 : 2;  // the diffuse's channels, or the specular composition's
        for (std::size_t ch = 0; ch < 3; ++ch) {
            const double b = at_0[i][ch] - a[i][ch];
            const double lost = scale * (a[i][ch] * excess.value[k] + b * excess.value[k + 1]);
            const double lost_error = scale * (std::abs(a[i][ch]) * excess.abs_error[k] + std::abs(b) * excess.abs_error[k + 1] +
                                               8 * eps * (std::abs(excess.value[k]) + std::abs(excess.value[k + 1])));
            auto& lobe = r.lobes[i];
            const double unscaled = lobe.value[ch];
            lobe.value[ch] = keep * unscaled - c * lost;
            lobe.abs_error[ch] = std::abs(keep) * lobe.abs_error[ch] + c * e_v.abs_error * std::abs(unscaled) + c * lost_error +
                                 4 * eps * (std::abs(keep * unscaled) + std::abs(c * lost));
        }
    }
    const rgb weight = a[3];  // under the coat, sheenColor
    for (std::size_t ch = 0; ch < 3; ++ch) {
        r.lobes[3].value[ch] = weight[ch] * e_v.value;
        r.lobes[3].abs_error[ch] = weight[ch] * e_v.abs_error + 2 * eps * r.lobes[3].value[ch];
    }
    detail::sum_lobes(r);
    return r;
}

}  // namespace normzoo::material
