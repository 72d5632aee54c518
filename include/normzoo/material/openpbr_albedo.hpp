// The albedo of OpenPBR's lobes with V fixed (docs/materials.md, "OpenPBR Surface 1.1", "The
// albedo"): albedo scaling reads E at V only, so each lobe's albedo is its own integral times
// numbers of V, with one exception, the coat's absorption T(L, V) = h(N.L) h(N.V) under a partial
// coat: with P_j(g) = int f_j g(N.L) N.L dL,
//   E_j = (1 - F E_fuzz) D_mod [(1 - C) P_j(1) + C (1 - E_coat) h(N.V) P_j(h)]
// for the base's lobes j (diffuse, specular, metal), D_mod = lerp(1, Delta, C coat_darkening),
//   E_coat-lobe = (1 - F E_fuzz) C E_coat,   E_fuzz-lobe = F fuzz_color E_fuzz x int D_LTC dL.
// P_j(h) is one more integral only where the coat absorbs (coat_color < 1, C > 0): EON's in N.L
// with its azimuth in closed form (openpbr_coat.hpp), the specular's in GGX's map, the metal's as
// its P_j(1). Without a film the metal's P_j(1) and P_j(h) are one integral over N.L each, F82's
// azimuthal integrals closed (openpbr_metal.hpp), unless its bound misses the target (a narrow
// lobe under a strong tint): then GGX's map's, and P_j(h) the specular's and metal's six-channel
// integral there. Under a thin film the specular's F, and so E_spec, is per channel, and the
// integrals take the film's kinks in V.H as breakpoints; those whose weights read V.H alone (the
// specular's and the metal's P_j(1)) take the half vector about V (about_v.hpp), where the film's
// Fresnel is evaluated once a node of V.H. Each factor's bound enters its lobe's.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "../microfacet/albedo.hpp"
#include "../microfacet/composition.hpp"
#include "../microfacet/stretched.hpp"
#include "../quadrature/channels.hpp"
#include "about_v.hpp"
#include "albedo.hpp"
#include "openpbr_metal.hpp"
#include "openpbr_model.hpp"

namespace normzoo::material {

namespace detail {

// The albedo at V = (sqrt(1 - mu^2), 0, mu) of GGX at alpha with height-correlated Smith times N
// weights w(V.H, N.L), in GGX's polar map (microfacet/stretched.hpp): the integrand G V.h / (mu N.h)
// w, the node's rounding bounded as material/albedo.hpp's for a peaked lobe, the weights' by
// 32 eps absolute (a Fresnel factor and a power of a number at most 1, each a few ulps) plus what
// `rounding(vh, nl)` says beyond that (a film's ill-conditioning); the weights' kinks in V.H (a
// film's) as breakpoints.
template <std::size_t N>
struct no_weight_rounding {
    std::array<double, N> operator()(double, double = 0) const { return {}; }
};
template <std::size_t N, class W, class R = no_weight_rounding<N>>
std::array<quadrature::estimate<double>, N> ggx_albedo_channels(double alpha, double mu, const W& weights,
                                                                const std::vector<double>& kinks, double tol,
                                                                std::size_t max_panels, std::size_t& evaluations,
                                                                const R& rounding = R{}) {
    using value = quadrature::channels<double, N>;
    using estimate = quadrature::estimate<value>;
    const double sv = std::sqrt((1 - mu) * (1 + mu)), eps = std::numeric_limits<double>::epsilon();
    const vec3<double> v(sv, 0, mu);
    const specular_brdf lobe{alpha, smith_form::height_correlated};
    const double lambda_v = lobe.lambda(v);
    auto w = [&](const microfacet::half_vector_node& x) -> estimate {
        const vec3<double> h(x.st * x.cphi, x.st * x.sphi, x.ct);
        const vec3<double> l = 2 * x.vh * h - v;
        const double base = lobe.g(lobe.lambda(l), lambda_v) * (x.vh * x.inv_muct);
        const double rel =
            32 + (8 * (2 * x.vh * x.ct + mu + x.st) * x.vh + 12 * (x.st + mu * x.ct) * x.nl) / (x.nl * x.vh);
        const std::array<double, N> f = weights(x.vh, x.nl), r = rounding(x.vh, x.nl);
        estimate e{value{}, value{}, 1};
        for (std::size_t k = 0; k < N; ++k) {
            e.value[k] = base * f[k];
            e.abs_error[k] = eps * rel * std::abs(e.value[k]) + (32 * eps + r[k]) * std::abs(base);
        }
        return e;
    };
    const auto e = ggx_map_integral(alpha, mu, kinks, tol, max_panels, w);
    evaluations += e.evaluations;
    std::array<quadrature::estimate<double>, N> r;
    for (std::size_t k = 0; k < N; ++k) r[k] = {e.value[k], e.abs_error[k], 0};
    return r;
}

// The same with an RGB weight of V.H alone, and what rounding moves it beyond a few ulps (of V.H
// alone too). Where the weight is costly (a film's Fresnel: `film`), the half vector about V
// (about_v.hpp), which evaluates it once a node of V.H: 10x to 80x faster there, and up to 3x
// slower than GGX's map for a cheap weight (results/bench-material.md).
template <class F, class R = no_weight_rounding<3>>
rgb_estimate ggx_albedo_rgb(double alpha, double mu, const F& fresnel, const std::vector<double>& kinks, double tol,
                            std::size_t max_panels, std::size_t& evaluations, const R& rounding = R{}, bool film = false) {
    rgb_estimate r;
    if (film) {
        using value = quadrature::channels<double, 3>;
        const double eps = std::numeric_limits<double>::epsilon();
        const specular_brdf lobe{alpha, smith_form::height_correlated};
        const auto e = about_v_integral(lobe, mu, kinks, tol, max_panels, [&](const about_v_node& x) {
            quadrature::estimate<value> n{value{}, value{}, x.evaluations};
            const rgb f = fresnel(x.c), rf = rounding(x.c);
            for (std::size_t k = 0; k < 3; ++k) {
                n.value[k] = f[k] * x.specular;
                n.abs_error[k] = std::abs(f[k]) * x.specular_error + (32 * eps + rf[k]) * std::abs(x.specular);
            }
            return n;
        });
        evaluations += e.evaluations;
        for (std::size_t k = 0; k < 3; ++k) r.value[k] = e.value[k], r.abs_error[k] = e.abs_error[k];
        return r;
    }
    const auto e = ggx_albedo_channels<3>(
        alpha, mu, [&](double vh, double) { return fresnel(vh); }, kinks, tol, max_panels, evaluations,
        [&](double vh, double) { return rounding(vh); });
    for (std::size_t k = 0; k < 3; ++k) r.value[k] = e[k].value, r.abs_error[k] = e[k].abs_error;
    return r;
}

// GGX with height-correlated Smith and the exact dielectric F at eta >= 1, by the composition's 1D
// albedo (microfacet/albedo.hpp: its dielectric F reads the index from F0).
inline quadrature::estimate<double> dielectric_albedo(double alpha, double eta, double mu, const albedo_settings& s) {
    static const auto c = microfacet::composition::parse("ggx/smith-height-correlated/dielectric");
    return microfacet::directional_albedo(c, mu, alpha, microfacet::f0_of_eta(eta), s);
}

// The untinted specular lobe's albedo at mu: the dielectric's 1D albedo, or under a film its F
// per channel in GGX's map with the film's kinks.
inline rgb_estimate specular_albedo(const openpbr& m, double mu, const std::vector<double>& kinks, const albedo_settings& s,
                                    std::size_t& evaluations) {
    if (!m.film().active()) {
        const auto e = dielectric_albedo(m.alpha(), m.specular_eta(), mu, s);
        evaluations += e.evaluations;
        return {grey(e.value), grey(e.abs_error)};
    }
    return ggx_albedo_rgb(m.alpha(), mu, [&](double vh) { return m.specular_fresnel(vh); }, kinks, s.tolerance,
                          s.max_panels, evaluations, [&](double vh) { return m.specular_rounding(vh); }, true);
}

// F82's b per channel (openpbr_model.hpp, f82_b): the metal's F0 and specular_color.
inline rgb f82_b_of(const openpbr& m) {
    const rgb f0 = m.metal_f0();
    rgb b;
    for (std::size_t k = 0; k < 3; ++k) b[k] = f82_b(f0[k], m.in.specular_color[k]);
    return b;
}

// Whether the F82 metal's integral over N.L met its target: its bound holds the rounding of F82's
// seven alternating terms, times b, which a narrow lobe near normal incidence under a strong tint
// (b near 10) lifts to 1e-11 or more (openpbr_metal.hpp); GGX's map takes those.
inline bool within(const rgb_estimate& e, double tolerance) { return max_value(e.abs_error) <= tolerance; }

// The metal lobe's albedo at mu, untinted by metalness: F82 by its 1D integral
// (openpbr_metal.hpp), or where that misses its target in GGX's map; under a film in the map
// about V with the film's kinks.
inline rgb_estimate metal_albedo(const openpbr& m, double mu, const std::vector<double>& kinks, const albedo_settings& s,
                                 std::size_t& evaluations) {
    const bool film = m.film().active();
    if (!film) {
        const auto e =
            f82_metal_albedo(m.alpha(), mu, m.metal_f0(), f82_b_of(m), m.in.specular_weight, s.tolerance, s.max_panels, evaluations);
        if (within(e, s.tolerance)) return e;
    }
    return ggx_albedo_rgb(m.alpha(), mu, [&](double vh) { return m.metal_fresnel(vh); }, kinks, s.tolerance, s.max_panels,
                          evaluations, [&](double vh) { return m.metal_rounding(vh); }, film);
}

}  // namespace detail

// What the layering reads at V, with bounds: the untinted specular lobe's and the coat's albedos,
// the darkening factor lerp(1, Delta, C coat_darkening) per channel, E_fuzz (the fit's value); and
// the film's kinks in V.H (none without a film), which the albedo's integrals take.
struct openpbr_view_terms {
    rgb_estimate spec;
    quadrature::estimate<double> coat;
    rgb_estimate darkening{grey(1), grey(0)};
    double fuzz = 0;
    std::vector<double> kinks;
    openpbr_view_values values() const { return {spec.value, coat.value, darkening.value, fuzz}; }
};

// E_b, the base-substrate's albedo at normal incidence (the darkening's "normal-incidence albedos
// of the individual slabs, blended by their mix weights"): each slab's computed, not approximated.
inline rgb_estimate openpbr_base_at_normal(const openpbr& m, const std::vector<double>& kinks, const albedo_settings& s,
                                           std::size_t& evaluations) {
    const double eps = std::numeric_limits<double>::epsilon(), met = m.in.base_metalness;
    const rgb_estimate spec = detail::specular_albedo(m, 1, kinks, s, evaluations);
    rgb_estimate metal;
    if (met > 0) metal = detail::metal_albedo(m, 1, kinks, s, evaluations);
    brdf::params<double> p;
    p.roughness = m.in.base_diffuse_roughness;
    rgb_estimate e;
    for (std::size_t k = 0; k < 3; ++k) {
        p.specular = m.in.base_weight * m.in.base_color[k];
        const double diffuse = brdf::eon::albedo_at_normal(p), tint = m.in.specular_color[k];
        e.value[k] = (1 - met) * (tint * spec.value[k] + (1 - spec.value[k]) * diffuse) + met * metal.value[k];
        e.abs_error[k] = (1 - met) * (std::abs(tint - diffuse) * spec.abs_error[k] + 16 * eps) + met * metal.abs_error[k] +
                         8 * eps * std::abs(e.value[k]);
    }
    return e;
}

inline openpbr_view_terms openpbr_terms(const openpbr& m, double mu, const albedo_settings& s, std::size_t& evaluations) {
    const auto& in = m.in;
    openpbr_view_terms t;
    t.kinks = m.film_kinks();
    t.spec = detail::specular_albedo(m, mu, t.kinks, s, evaluations);
    t.coat = in.coat_weight > 0 ? detail::dielectric_albedo(m.coat_alpha(), in.coat_ior, mu, s)
                                : quadrature::estimate<double>{0, 0, 0};
    evaluations += t.coat.evaluations;
    const double cd = in.coat_weight * in.coat_darkening;
    if (cd > 0) {
        const double xi = std::min(std::max(in.specular_weight * microfacet::f0_of_eta(openpbr::specular_ior_ratio(in)), 0.0), 1.0);
        const double r = in.specular_roughness, r_d = (1 - xi) + xi * r, r_b = (1 - in.base_metalness) * r_d + in.base_metalness * r;
        const auto e_f = openpbr_coat::fresnel_average_exact(in.coat_ior);
        const auto k = openpbr_coat::internal_reflection(mu, in.coat_ior, r_b, e_f);
        const auto delta = openpbr_coat::darkening(openpbr_base_at_normal(m, t.kinks, s, evaluations), k);
        for (std::size_t c = 0; c < 3; ++c) {
            t.darkening.value[c] = 1 - cd + cd * delta.value[c];
            t.darkening.abs_error[c] = cd * delta.abs_error[c] + 4 * std::numeric_limits<double>::epsilon();
        }
    }
    if (in.fuzz_weight > 0) t.fuzz = openpbr_fuzz::e_fuzz(mu, in.fuzz_roughness);
    return t;
}

// The view terms at V (cos t = mu) at the tolerance an albedo's parts take.
inline openpbr_view_terms openpbr_terms(const openpbr& m, double mu, const albedo_settings& s = {}) {
    std::size_t n = 0;
    return openpbr_terms(m, mu, s, n);
}

namespace detail {

// P_j(1) and P_j(h) of the base's three lobes (diffuse, specular, metal) without their layer
// factors: the diffuse (1 - M)(1 - E_spec) E_EON, the specular (1 - M) specular_color E_spec, the
// metal M E_metal; `absorbing` adds the weighted ones.
struct openpbr_base_parts {
    std::array<rgb_estimate, 3> plain, weighted;
};

inline openpbr_base_parts openpbr_base_albedos(const openpbr& m, double mu, const openpbr_view_terms& t, bool absorbing,
                                               const albedo_settings& s, std::size_t& evaluations) {
    using std::abs;
    const double eps = std::numeric_limits<double>::epsilon(), met = m.in.base_metalness;
    const auto& in = m.in;
    openpbr_base_parts r;
    brdf::params<double> p;
    p.roughness = in.base_diffuse_roughness;
    rgb rho;
    for (std::size_t k = 0; k < 3; ++k) {
        p.specular = rho[k] = in.base_weight * in.base_color[k];
        const double e = brdf::eon::albedo_of(mu, p);
        r.plain[0].value[k] = (1 - met) * (1 - t.spec.value[k]) * e;
        r.plain[0].abs_error[k] = (1 - met) * e * t.spec.abs_error[k] + 16 * eps * e;
        r.plain[1].value[k] = (1 - met) * in.specular_color[k] * t.spec.value[k];
        r.plain[1].abs_error[k] = (1 - met) * in.specular_color[k] * t.spec.abs_error[k] + 8 * eps * abs(r.plain[1].value[k]);
    }
    if (met > 0) {
        const rgb_estimate e = metal_albedo(m, mu, t.kinks, s, evaluations);
        r.plain[2].value = met * e.value;
        r.plain[2].abs_error = met * e.abs_error;
    }
    if (!absorbing) {
        r.weighted = r.plain;
        return r;
    }
    auto h = [&](double nl) { return openpbr_coat::absorption_half(in.coat_color, nl, in.coat_ior); };
    const rgb_estimate d = openpbr_coat::eon_weighted_albedo(rho, in.base_diffuse_roughness, mu, h, s.tolerance);
    // P_j(h) of the specular and the metal: without a film the metal by its integral over N.L
    // (where it meets its target) and the specular alone in GGX's map; else both in the map, as
    // six channels
    rgb_estimate spec_h, metal_h;
    bool in_map = m.film().active();
    if (!in_map && met > 0) {
        metal_h = f82_metal_albedo(m.alpha(), mu, m.metal_f0(), f82_b_of(m), in.specular_weight, s.tolerance, s.max_panels,
                                   evaluations, h);
        in_map = !within(metal_h, s.tolerance);
    }
    if (!in_map) {
        const auto g = ggx_albedo_channels<3>(
            m.alpha(), mu, [&](double vh, double nl) { return h(nl) * m.specular_fresnel(vh); }, t.kinks, s.tolerance,
            s.max_panels, evaluations);
        for (std::size_t k = 0; k < 3; ++k) spec_h.value[k] = g[k].value, spec_h.abs_error[k] = g[k].abs_error;
    } else {
        const auto g = ggx_albedo_channels<6>(
            m.alpha(), mu,
            [&](double vh, double nl) {
                const rgb a = h(nl), f82 = m.metal_fresnel(vh), fd = m.specular_fresnel(vh);
                return std::array<double, 6>{fd[0] * a[0], fd[1] * a[1], fd[2] * a[2], f82[0] * a[0], f82[1] * a[1], f82[2] * a[2]};
            },
            t.kinks, s.tolerance, s.max_panels, evaluations, [&](double vh, double nl) {
                const rgb a = h(nl), rs = m.specular_rounding(vh), rm = m.metal_rounding(vh);
                return std::array<double, 6>{rs[0] * a[0], rs[1] * a[1], rs[2] * a[2], rm[0] * a[0], rm[1] * a[1], rm[2] * a[2]};
            });
        for (std::size_t k = 0; k < 3; ++k) {
            spec_h.value[k] = g[k].value, spec_h.abs_error[k] = g[k].abs_error;
            metal_h.value[k] = g[3 + k].value, metal_h.abs_error[k] = g[3 + k].abs_error;
        }
    }
    for (std::size_t k = 0; k < 3; ++k) {
        r.weighted[0].value[k] = (1 - met) * (1 - t.spec.value[k]) * d.value[k];
        r.weighted[0].abs_error[k] = (1 - met) * (d.abs_error[k] + abs(d.value[k]) * t.spec.abs_error[k]) + 8 * eps * abs(d.value[k]);
        r.weighted[1].value[k] = (1 - met) * in.specular_color[k] * spec_h.value[k];
        r.weighted[1].abs_error[k] = (1 - met) * in.specular_color[k] * spec_h.abs_error[k] + 8 * eps * abs(r.weighted[1].value[k]);
        r.weighted[2].value[k] = met * metal_h.value[k];
        r.weighted[2].abs_error[k] = met * metal_h.abs_error[k];
    }
    return r;
}

}  // namespace detail

// The albedo of OpenPBR with V at cos t = mu, each lobe (with its weight and the factors above it)
// and the whole, per channel, to about settings.tolerance.
inline material_albedo<openpbr::lobe_count> openpbr_albedo(const openpbr& m, double mu, const albedo_settings& settings = {}) {
    using std::abs;
    const double eps = std::numeric_limits<double>::epsilon();
    albedo_settings s = settings;
    s.tolerance = settings.tolerance / 16;
    const auto& in = m.in;
    material_albedo<openpbr::lobe_count> r;
    const openpbr_view_terms t = openpbr_terms(m, mu, s, r.evaluations);
    const double c = in.coat_weight, top = 1 - in.fuzz_weight * t.fuzz;
    const bool absorbing = c > 0 && !(in.coat_color == grey(1));
    const auto parts = detail::openpbr_base_albedos(m, mu, t, absorbing, s, r.evaluations);
    const rgb h_v = c > 0 ? openpbr_coat::absorption_half(in.coat_color, mu, in.coat_ior) : grey(1);
    for (std::size_t j = 0; j < 3; ++j)
        for (std::size_t k = 0; k < 3; ++k) {
            const auto &a = parts.plain[j], &g = parts.weighted[j];
            const double under = c * (1 - t.coat.value) * h_v[k];
            const double pv = (1 - c) * a.value[k] + under * g.value[k];
            const double pe = (1 - c) * a.abs_error[k] + under * g.abs_error[k] + c * h_v[k] * abs(g.value[k]) * t.coat.abs_error;
            const double dk = t.darkening.value[k];
            r.lobes[j].value[k] = top * dk * pv;
            r.lobes[j].abs_error[k] = top * (dk * pe + abs(pv) * t.darkening.abs_error[k]) + 16 * eps * abs(r.lobes[j].value[k]);
        }
    r.lobes[3].value = grey(top * c * t.coat.value);
    r.lobes[3].abs_error = grey(top * c * t.coat.abs_error + 4 * eps * t.coat.value);
    if (in.fuzz_weight > 0) {
        const auto n = openpbr_fuzz::ltc_normalization(mu, in.fuzz_roughness, s.tolerance);
        r.evaluations += n.evaluations;
        const double scale = in.fuzz_weight * t.fuzz;
        r.lobes[4].value = (scale * n.value) * in.fuzz_color;
        r.lobes[4].abs_error = (abs(scale) * n.abs_error + 8 * eps * abs(scale * n.value)) * in.fuzz_color;
    }
    detail::sum_lobes(r);
    return r;
}

}  // namespace normzoo::material
