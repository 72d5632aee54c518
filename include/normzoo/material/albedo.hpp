// The directional albedo of a material and of each of its lobes, per channel, with V fixed
// (docs/materials.md, "The albedo and its bound"): with V = (sqrt(1 - mu^2), 0, mu),
//     E(mu) = integral over L of f(L, V) N.L d(omega_L),
// what a white furnace shows. Two routes, each the other's check (tests/test_material.cpp):
// albedo_of, for a material whose weights are affine in Schlick's factor (glTF), by two 1D
// albedos of each lobe's composition (below); and albedo_by_nodes, for any weights, node by node:
// the lobes whose maps are peaked (material.hpp, lobe_map: a GGX lobe at its alpha) together, each
// channel of each a channel of one integral in GGX's polar map at that alpha
// (microfacet/stretched.hpp): their D is the map's density, so w = weight x G V.h / (mu N.h); the
// smooth lobes (Lambert) one more integral in the flat map (GGX at alpha = 1, D N.h = cos t / pi),
// w = weight x lobe x 4 pi N.L V.h / cos t. Each channel's bound is its estimate's; the whole's
// is the sum of its lobes'.
//
// A node's rounding: w's relative error is bounded as for a composition (microfacet/albedo.hpp:
// 32 eps + 8 eps (2 V.h N.h + mu + sin t) / N.L + 12 eps (sin t + mu cos t) / V.h: G is at most
// linear in N.L, the factors are sums of O(1) terms), twice that for a smooth lobe (its w is
// linear in both N.L and V.h, and 1 - F(V.h) too near V.h = 0), and the weights, a few operations
// on inputs at most 1 that can cancel (1 - specular max_value(fr) near fr = 1), err by at most
// 8 eps absolute times the lobe's w without its weight.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "../albedo.hpp"
#include "../microfacet/albedo.hpp"
#include "../microfacet/stretched.hpp"
#include "../microfacet/stretched_aniso.hpp"
#include "../quadrature/channels.hpp"
#include "../quadrature/estimate.hpp"
#include "material.hpp"

namespace normzoo::material {

// A per-channel value with its bound on |value - truth| per channel.
struct rgb_estimate {
    rgb value{}, abs_error{};
    double largest() const { return max_value(value); }
    // the bound of the largest channel: the largest bound, so that it holds whichever is largest
    double largest_error() const { return max_value(abs_error); }
};

template <std::size_t Lobes>
struct material_albedo {
    std::array<rgb_estimate, Lobes> lobes;  // in the material's lobe_ids order
    rgb_estimate whole;                     // their sum
    std::size_t evaluations = 0;
};

namespace detail {

// Whether a specular lobe may be anisotropic (material/anisotropy.hpp): it has alpha_t.
template <class Lobe, class = void>
struct may_be_anisotropic_lobe : std::false_type {};
template <class Lobe>
struct may_be_anisotropic_lobe<Lobe, std::void_t<decltype(Lobe::alpha_t)>> : std::true_type {};

// Whether a material reports the values of V.H where its weights have kinks (weight_kinks()).
template <class M, class = void>
struct has_weight_kinks : std::false_type {};
template <class M>
struct has_weight_kinks<M, std::void_t<decltype(std::declval<const M&>().weight_kinks())>> : std::true_type {};
// Whether a material bounds its weights' rounding beyond a few ulps (weight_rounding(c, terms)).
template <class M, class = void>
struct has_weight_rounding : std::false_type {};
template <class M>
struct has_weight_rounding<M, std::void_t<decltype(std::declval<const M&>().weight_rounding(
                                  cosines{}, std::declval<const M&>().weight_terms()))>> : std::true_type {};

// The kinks of the weights being integrated, for stretched_lobe::kink_vm, a plain function pointer:
// set by lobes_in_map around its integral, on the thread that runs it.
inline thread_local std::array<double, microfacet::max_kinks> weight_kinks_vh{};
inline thread_local int weight_kink_count = 0;
inline int weight_kink_vm(double, double, double vm[]) {
    for (int i = 0; i < weight_kink_count; ++i) vm[i] = weight_kinks_vh[std::size_t(i)];
    return weight_kink_count;
}

// The whole from its lobes, with the sum's own rounding (a few ulps of each channel).
template <std::size_t Lobes>
void sum_lobes(material_albedo<Lobes>& r) {
    r.whole = {};
    for (const auto& l : r.lobes) {
        r.whole.value = r.whole.value + l.value;
        r.whole.abs_error = r.whole.abs_error + l.abs_error;
    }
    for (std::size_t k = 0; k < 3; ++k) r.whole.abs_error[k] += 4 * std::numeric_limits<double>::epsilon() * std::abs(r.whole.value[k]);
}

// w integrated over L in GGX's polar map at alpha (microfacet/stretched.hpp) with V at cos t = mu,
// the values of V.h in `kinks` (a thin film's, ascending) as breakpoints.
template <class W>
auto ggx_map_integral(double alpha, double mu, const std::vector<double>& kinks, double tol, std::size_t max_panels,
                      const W& w) {
    if (kinks.size() > std::size_t(microfacet::max_kinks))
        throw std::invalid_argument("the weights have " + std::to_string(kinks.size()) + " kinks in V.H, more than the " +
                                    std::to_string(microfacet::max_kinks) + " the integral takes as breakpoints");
    const double sv = std::sqrt((1 - mu) * (1 + mu));
    microfacet::ndf_params<double> np;
    np.alpha_x = np.alpha_y = alpha;
    microfacet::stretched_lobe map_lobe{alpha, false, false};
    if (kinks.empty())
        return microfacet::detail::stretched_integral<microfacet::d_ggx, 15, false>(np, mu, sv, map_lobe, tol, max_panels, w);
    weight_kink_count = int(kinks.size());
    std::copy(kinks.begin(), kinks.end(), weight_kinks_vh.begin());
    map_lobe.kink_vm = &weight_kink_vm;
    const auto e = microfacet::detail::stretched_integral<microfacet::d_ggx, 15, true>(np, mu, sv, map_lobe, tol, max_panels, w);
    weight_kink_count = 0;
    return e;
}

// The integral of the lobes of map kind `peaked` (material.hpp), each channel a channel.
template <class M>
quadrature::estimate<quadrature::channels<double, 3 * M::lobe_count>> lobes_in_map(const M& m, bool peaked, double alpha,
                                                                                   double mu, double tol,
                                                                                   std::size_t max_panels) {
    using std::abs;
    using std::sqrt;
    constexpr std::size_t n = 3 * M::lobe_count;
    using value = quadrature::channels<double, n>;
    using estimate = quadrature::estimate<value>;
    const double sv = sqrt((1 - mu) * (1 + mu));
    const vec3<double> v(sv, 0, mu);
    const auto maps = m.maps();
    const auto lobe = m.specular_lobe();
    const double lambda_v = lobe.lambda(v);
    const auto terms = m.weight_terms();  // what the weights read of the inputs alone, once
    const double eps = std::numeric_limits<double>::epsilon();
    auto w = [&](const microfacet::half_vector_node& x) -> estimate {
        const vec3<double> h(x.st * x.cphi, x.st * x.sphi, x.ct);
        const vec3<double> l = 2 * x.vh * h - v;
        // the lobe's w without its weight: G V.h / (mu N.h) in a GGX lobe's own map, lobe x 4 pi
        // N.L V.h / cos t in the flat map
        const double base = peaked ? lobe.g(lobe.lambda(l), lambda_v) * (x.vh * x.inv_muct)
                                   : 4 * pi<double>() * x.nl * x.vh / x.ct;
        const double rel =
            32 + (8 * (2 * x.vh * x.ct + mu + x.st) * x.vh + 12 * (x.st + mu * x.ct) * x.nl) / (x.nl * x.vh);
        const double relative = eps * (peaked ? rel : 2 * rel + 8 / x.vh);
        const cosines c{x.nl, mu, x.ct, x.vh};
        const auto weights = m.weights(c, terms);
        std::array<rgb, M::lobe_count> rounding{};
        if constexpr (has_weight_rounding<M>::value) rounding = m.weight_rounding(c, terms);
        const auto values = m.lobes(l, v, h);
        estimate e{value{}, value{}, 1};
        for (std::size_t i = 0; i < M::lobe_count; ++i) {
            if (maps[i].peaked != peaked) continue;
            const double b = peaked ? base : base * values[i];
            for (std::size_t k = 0; k < 3; ++k) {
                e.value[3 * i + k] = b * weights[i][k];
                e.abs_error[3 * i + k] = relative * abs(e.value[3 * i + k]) + (8 * eps + rounding[i][k]) * abs(b);
            }
        }
        return e;
    };
    // the values of V.h where the weights have kinks (a thin film's): breakpoints of the integral
    std::vector<double> kinks;
    if constexpr (has_weight_kinks<M>::value) kinks = m.weight_kinks();
    // an anisotropic specular lobe's peaked lobes in its own map (microfacet/stretched_aniso.hpp)
    if constexpr (may_be_anisotropic_lobe<std::decay_t<decltype(lobe)>>::value)
        if (peaked && lobe.anisotropic()) {
            if (!kinks.empty()) throw std::invalid_argument("weights with kinks (a thin film) on an anisotropic lobe: not integrated");
            return microfacet::detail::aniso_stretched_integral<15>({lobe.alpha_t, lobe.alpha_b, lobe.cos_r, lobe.sin_r}, mu,
                                                                    sv, tol, max_panels, w);
        }
    return ggx_map_integral(alpha, mu, kinks, tol, max_panels, w);
}

}  // namespace detail

// The albedo of material m with V at cos t = mu, single scattering, node by node: each lobe and the
// whole, per channel, to about settings.tolerance absolute. M (material.hpp) gives its maps, weights(c,
// weight_terms()), lobes(L, V, H) and specular_lobe(), the specular_brdf its peaked lobes share
// (one GGX alpha: the glTF core's; a clearcoat or sheen lobe with its own D will be one more
// integral here, in its own map).
// Throws std::invalid_argument for mu outside [1e-8, 1] or an alpha outside [1e-8, 1].
template <class M>
material_albedo<M::lobe_count> albedo_by_nodes(const M& m, double mu, const albedo_settings& settings = {}) {
    const auto maps = m.maps();
    double alpha = 1;
    bool any_peaked = false;
    for (const auto& map : maps)
        if (!map.by_nodes) throw std::invalid_argument("a lobe albedo_by_nodes does not integrate (a sheen, a coat)");
    for (const auto& map : maps)
        if (map.peaked) {
            if (any_peaked && map.alpha != alpha) throw std::invalid_argument("the peaked lobes' alphas differ");
            alpha = map.alpha, any_peaked = true;
        }
    microfacet::detail::check_incidence(mu, alpha);
    if (alpha > 1) throw std::invalid_argument("alpha = " + std::to_string(alpha) + " is above 1");
    // each of the two integrals to an eighth: a channel's bound is at most its integral's, and
    // the relative target of the adaptive rule is on the sum of up to 3 x lobes channels
    const double tol = settings.tolerance / 8;
    material_albedo<M::lobe_count> r;
    for (const bool peaked : {true, false}) {
        const auto e = detail::lobes_in_map(m, peaked, peaked ? alpha : 1.0, mu, tol, settings.max_panels);
        r.evaluations += e.evaluations;
        for (std::size_t i = 0; i < M::lobe_count; ++i) {
            if (maps[i].peaked != peaked) continue;
            for (std::size_t k = 0; k < 3; ++k) {
                r.lobes[i].value[k] = e.value[3 * i + k];
                r.lobes[i].abs_error[k] = e.abs_error[3 * i + k];
            }
        }
    }
    detail::sum_lobes(r);
    return r;
}

// The albedo of material m with V at cos t = mu, single scattering, each lobe and the whole, per
// channel, where every lobe's weight is affine in Schlick's factor s = (1 - V.H)^5 (the glTF
// core and KHR_materials_ior and _specular: M::weights_affine_in_schlick): weight = a + b s, a the
// weight at V.H = 1 and b that at V.H = 0 less a (M's operators, evaluated, not written twice),
// so the lobe's albedo is a E(F = 1) + b E(F = s), two albedos of its composition by the 1D
// integral with D's azimuthal integral in closed form (microfacet/azimuthal_albedo.hpp;
// ggx_schlick_azimuth.hpp for s): M::lobe_composition(i) gives lobe i as a composition and the
// factor that makes it the lobe (Lambert is 4 x ggx/implicit at alpha = 1, where GGX's D is
// 1/pi). 10 to 100 us, where albedo_by_nodes takes 0.1 to 4 ms; each checks the other (tests).
// M::in_albedo_of(i) says which lobes it integrates; the others are left 0.
template <class M>
material_albedo<M::lobe_count> albedo_of(const M& m, double mu, const albedo_settings& settings = {}) {
    static_assert(M::weights_affine_in_schlick, "a material whose weights are not affine in (1 - V.H)^5: albedo_by_nodes");
    using std::abs;
    const double eps = std::numeric_limits<double>::epsilon();
    const auto terms = m.weight_terms();
    const auto a = m.weights(cosines{1, mu, 1, 1}, terms);  // s = 0
    const auto at_0 = m.weights(cosines{1, mu, 1, 0}, terms);  // s = 1
    albedo_settings s = settings;
    s.tolerance = settings.tolerance / 8;  // the two albedos of each of up to 3 lobes, and their sums
    material_albedo<M::lobe_count> r;
    quadrature::estimate<double> e1, e5;
    for (std::size_t i = 0, last = M::lobe_count; i < M::lobe_count; ++i) {
        if (!m.in_albedo_of(i)) continue;  // 0, or another route's (glTF's sheen)
        const auto [c, alpha, scale] = m.lobe_composition(i);
        // lobes of one composition (glTF's specular and metal) share its two albedos
        const bool same = last < i && m.lobe_composition(last).c.id == c.id && m.lobe_composition(last).alpha == alpha;
        last = i;
        if (!same) {
            e1 = microfacet::directional_albedo(c, mu, alpha, 1, s), e5 = microfacet::directional_albedo(c, mu, alpha, 0, s);
            r.evaluations += e1.evaluations + e5.evaluations;
        }
        for (std::size_t k = 0; k < 3; ++k) {
            const double b = at_0[i][k] - a[i][k];
            r.lobes[i].value[k] = scale * (a[i][k] * e1.value + b * e5.value);
            // a and b are a few operations on inputs at most 1, and b a difference: 8 eps each
            r.lobes[i].abs_error[k] = scale * (abs(a[i][k]) * e1.abs_error + abs(b) * e5.abs_error + 8 * eps * (e1.value + e5.value)) +
                                      4 * eps * abs(r.lobes[i].value[k]);
        }
    }
    detail::sum_lobes(r);
    return r;
}

}  // namespace normzoo::material
