// OpenPBR Surface 1.1's base, specular, metal and coat (docs/materials.md, "OpenPBR Surface 1.1"),
// as the specification's reduction to a mixture of lobes writes them, reflection only:
//   f = C f_coat + (1 - C E_coat(V)) [coat_color] f_base-substrate            (C = coat_weight)
//   f_base-substrate = (1 - M) f_dielectric-base + M f_metal                   (M = base_metalness)
//   f_dielectric-base = specular_color f_spec + (1 - E_spec(V)) f_diffuse
//   f_diffuse = EON(rho = base_weight base_color, r = base_diffuse_roughness)  (brdf/eon.hpp, the
//               authors' compensation, not the specification's printed extra 1/pi)
//   f_spec    = GGX D G / (4 N.L N.V) x F_dielectric(V.H, eta'), eta' = (1 + e) / (1 - e),
//               e = sgn(eta - 1) sqrt(specular_weight F0(eta)), eta = specular_ior
//   f_metal   = GGX D G / (4 N.L N.V) x specular_weight F82(V.H), unclamped as 1.1 writes it:
//               F82(m) = F0 + (1 - F0)(1 - m)^5 - b m (1 - m)^6, F0 = base_weight base_color,
//               b = (F0 + (1 - F0)(6/7)^5)(1 - specular_color) / ((1/7)(6/7)^6)
//   f_coat    = GGX(coat_roughness^2) D G / (4 N.L N.V) x F_dielectric(V.H, coat_ior)
// Albedo scaling reads E at the view only (the specification's non-reciprocal albedo scaling), so
// with V fixed each lower lobe's albedo is its own times a number, and the whole is the sum of the
// lobes' albedos times those numbers (openpbr_albedo). E_spec is the untinted lobe's (as MaterialX's
// dielectric_bsdf); coat_color multiplies the base flatly (the reference .mtlx graph's
// lerp(1, coat_color, C)), without the view-dependent absorption and without darkening. G is
// Smith's height-correlated form (Heitz 2014) throughout. Not here: fuzz, thin film, transmission,
// subsurface, anisotropy, the coat's IOR ratio under a partial coat and the coat's roughening.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string_view>

#include "../brdf/eon.hpp"
#include "../geometry.hpp"
#include "../microfacet/albedo.hpp"
#include "../microfacet/composition.hpp"
#include "../microfacet/fresnel.hpp"
#include "../microfacet/stretched.hpp"
#include "../parameter.hpp"
#include "../quadrature/channels.hpp"
#include "albedo.hpp"
#include "lobes.hpp"
#include "material.hpp"

namespace normzoo::material {

// The inputs by the specification's names, at its defaults (OpenPBR 1.1, parameter reference).
struct openpbr_inputs {
    double base_weight = 1;
    rgb base_color = grey(0.8);
    double base_metalness = 0, base_diffuse_roughness = 0;
    double specular_weight = 1;
    rgb specular_color = grey(1);
    double specular_roughness = 0.3, specular_ior = 1.5;
    double coat_weight = 0;
    rgb coat_color = grey(1);
    double coat_roughness = 0, coat_ior = 1.6;
};

// F82-tint's b: the metal's edge target specular_color x Schlick(1/7), written as the coefficient of
// m (1 - m)^6 (OpenPBR 1.1, Metal; Kutz et al. 2021; Hoffman 2019).
inline double f82_b(double f0, double tint) {
    const double m = 1.0 / 7, q = 6.0 / 7, q5 = q * q * q * q * q;
    return (f0 + (1 - f0) * q5) * (1 - tint) / (m * q5 * q);
}
inline double f82(double m, double f0, double tint) {
    const double x = 1 - m, x5 = x * x * x * x * x;
    return f0 + (1 - f0) * x5 - f82_b(f0, tint) * m * x5 * x;
}
// Its hemispherical average 2 int F82(m) m dm in closed form: 2 B(2, 6) = 1/21, 2 B(3, 7) = 1/126.
inline double f82_average(double f0, double tint) { return f0 + (1 - f0) / 21 - f82_b(f0, tint) / 126; }

struct openpbr {
    static constexpr std::string_view id = "openpbr";
    static constexpr const char* literature =
        "OpenPBR Surface 1.1 (Academy Software Foundation), Model and Reduction to a mixture of lobes; Portsmouth, "
        "Kutz and Hill 2025 (EON); Kutz, Hasan and Edmondson 2021 (F82-tint); Heitz 2014";
    static constexpr std::size_t lobe_count = 4;
    static constexpr std::array<std::string_view, lobe_count> lobe_ids = {"diffuse", "specular", "metal", "coat"};
    // roughnesses from 1e-4 (alpha 1e-8, as gltf); the iors from 1 (the albedo's dielectric F reads
    // its index from F0: below 1 is refused by input_error); specular_weight unbounded above as 1.1.
    static constexpr std::array<parameter, 12> parameters = {{
        {"base_weight", "the base's weight (the metal's F0 and the diffuse albedo), in [0, 1]", 0, 1, {}, 1},
        {"base_color", "the base colour, linear RGB (R,G,B, or one number for grey), each in [0, 1]", 0, 1, {}, 0.8,
         false, 3},
        {"base_metalness", "the mix of the metal over the dielectric base, in [0, 1]", 0, 1, {}, 0},
        {"base_diffuse_roughness", "EON's roughness r, in [0, 1]", 0, 1, {}, 0},
        {"specular_weight", "the dielectric's F0 and the metal's F multiplier, in [0, 1000]", 0, 1000, {}, 1},
        {"specular_color", "the tint of the dielectric's reflection and of the metal's edge, each in [0, 1]", 0, 1,
         {}, 1, false, 3},
        {"specular_roughness", "alpha = specular_roughness^2, in [1e-4, 1]", 1e-4, 1, {}, 0.3},
        {"specular_ior", "the dielectric base's index of refraction, in [1, 1000]", 1, 1000, {}, 1.5},
        {"coat_weight", "the coat's coverage, in [0, 1]", 0, 1, {}, 0},
        {"coat_color", "the coat's transmittance tint on the base, each in [0, 1]", 0, 1, {}, 1, false, 3},
        {"coat_roughness", "the coat's alpha = coat_roughness^2, in [1e-4, 1]", 1e-4, 1, {}, 1e-4},
        {"coat_ior", "the coat's index of refraction, in [1, 1000]", 1, 1000, {}, 1.6},
    }};

    openpbr_inputs in;

    static const char* input_error(const openpbr_inputs& x) {
        if (x.specular_ior < 1 || x.coat_ior < 1) return "specular_ior and coat_ior are at least 1 here";
        if (x.specular_weight * microfacet::f0_of_eta(x.specular_ior) >= 1)
            return "specular_weight F0(specular_ior) reaches 1: eta' = (1 + e)/(1 - e) divides by 0 (OpenPBR 1.1)";
        return nullptr;
    }

    double alpha() const { return in.specular_roughness * in.specular_roughness; }
    double coat_alpha() const { return in.coat_roughness * in.coat_roughness; }
    // eta' of specular_weight (OpenPBR 1.1, Specular): F0(eta') = specular_weight F0(eta).
    double specular_eta() const {
        const double e = std::sqrt(in.specular_weight * microfacet::f0_of_eta(in.specular_ior));
        return (in.specular_ior >= 1 ? 1 + e : 1 - e) / (in.specular_ior >= 1 ? 1 - e : 1 + e);
    }
    rgb metal_f0() const { return in.base_weight * in.base_color; }
    rgb metal_fresnel(double vh) const {
        const rgb f0 = metal_f0();
        rgb out;
        for (std::size_t k = 0; k < 3; ++k) out[k] = in.specular_weight * f82(vh, f0[k], in.specular_color[k]);
        return out;
    }
    static double dielectric_f(double vh, double eta) {
        microfacet::fresnel_params<double> p;
        p.eta = eta;
        return microfacet::fresnel_dielectric::eval(vh, p);
    }

    // Each lobe's contribution to f(L, V), per channel, given the view-only scale factors of the
    // base (the lower lobes' albedo scaling needs E_spec(V) and E_coat(V): openpbr_albedo's).
    std::array<rgb, lobe_count> f_lobes(const vec3<double>& l, const vec3<double>& v, double e_spec, double e_coat) const {
        std::array<rgb, lobe_count> out{};
        if (!(l.z() > 0 && v.z() > 0)) return out;
        const vec3<double> h = half_vector(l, v);
        const double vh = v.dot(h);
        const specular_brdf spec{alpha(), smith_form::height_correlated}, coat{coat_alpha(), smith_form::height_correlated};
        const double s = spec.value(l, v, h), c = coat.value(l, v, h);
        const rgb base_scale = (1 - in.coat_weight * e_coat) * (grey(1 - in.coat_weight) + in.coat_weight * in.coat_color);
        const double m = in.base_metalness;
        brdf::params<double> p;
        p.roughness = in.base_diffuse_roughness;
        for (std::size_t k = 0; k < 3; ++k) {
            p.specular = in.base_weight * in.base_color[k];
            out[0][k] = base_scale[k] * (1 - m) * (1 - e_spec) * brdf::eon::f(l, v, p);
        }
        out[1] = ((1 - m) * s * dielectric_f(vh, specular_eta())) * (base_scale * in.specular_color);
        out[2] = (m * s) * (base_scale * metal_fresnel(vh));
        out[3] = grey(in.coat_weight * c * dielectric_f(vh, in.coat_ior));
        return out;
    }
};

namespace detail {

// The albedo at V = (sqrt(1 - mu^2), 0, mu) of GGX at alpha with height-correlated Smith times a
// per-channel F(V.H), in GGX's polar map (microfacet/stretched.hpp): w = G V.h / (mu N.h) F, the
// node's rounding bounded as material/albedo.hpp's for a peaked lobe.
template <class F>
rgb_estimate ggx_albedo_rgb(double alpha, double mu, const F& fresnel, double tol, std::size_t max_panels,
                            std::size_t& evaluations) {
    using value = quadrature::channels<double, 3>;
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
        const rgb f = fresnel(x.vh);
        estimate e{value{}, value{}, 1};
        for (std::size_t k = 0; k < 3; ++k) {
            e.value[k] = base * f[k];
            e.abs_error[k] = eps * rel * std::abs(e.value[k]) + 16 * eps * std::abs(base);
        }
        return e;
    };
    microfacet::ndf_params<double> np;
    np.alpha_x = np.alpha_y = alpha;
    const microfacet::stretched_lobe map_lobe{alpha, false, false};
    const auto e = microfacet::detail::stretched_integral<microfacet::d_ggx, 15, false>(np, mu, sv, map_lobe, tol,
                                                                                         max_panels, w);
    evaluations += e.evaluations;
    rgb_estimate r;
    for (std::size_t k = 0; k < 3; ++k) r.value[k] = e.value[k], r.abs_error[k] = e.abs_error[k];
    return r;
}

// GGX with height-correlated Smith and the exact dielectric F at eta >= 1, by the composition's 1D
// albedo (microfacet/albedo.hpp: its dielectric F reads the index from F0).
inline quadrature::estimate<double> dielectric_albedo(double alpha, double eta, double mu, const albedo_settings& s) {
    static const auto c = microfacet::composition::parse("ggx/smith-height-correlated/dielectric");
    return microfacet::directional_albedo(c, mu, alpha, microfacet::f0_of_eta(eta), s);
}

}  // namespace detail

// What albedo scaling reads: the untinted specular lobe's and the coat's albedos at V.
struct openpbr_view_albedos {
    quadrature::estimate<double> spec, coat;
};

inline openpbr_view_albedos openpbr_scales(const openpbr& m, double mu, const albedo_settings& s) {
    return {detail::dielectric_albedo(m.alpha(), m.specular_eta(), mu, s),
            m.in.coat_weight > 0 ? detail::dielectric_albedo(m.coat_alpha(), m.in.coat_ior, mu, s)
                                 : quadrature::estimate<double>{0, 0, 0}};
}

// The albedo of OpenPBR's base and coat with V at cos t = mu, each lobe (with its weight and the
// scale factors above it) and the whole, per channel. The diffuse lobe's is EON's closed form
// (brdf/eon.hpp); the specular's and the coat's the compositions'; the metal's, F82 not being
// affine in Schlick's factor, one integral in GGX's map with the three channels. Each scale factor's
// bound enters its lobe's: |d(scale)| x the lobe's unscaled albedo.
inline material_albedo<openpbr::lobe_count> openpbr_albedo(const openpbr& m, double mu, const albedo_settings& settings = {}) {
    using std::abs;
    const double eps = std::numeric_limits<double>::epsilon();
    albedo_settings s = settings;
    s.tolerance = settings.tolerance / 8;
    const auto& in = m.in;
    material_albedo<openpbr::lobe_count> r;
    const auto sc = openpbr_scales(m, mu, s);
    r.evaluations += sc.spec.evaluations + sc.coat.evaluations;
    const double c = in.coat_weight, met = in.base_metalness;
    const rgb tint = grey(1 - c) + c * in.coat_color;
    // the base's scale and its bound, per channel
    const double under_coat = 1 - c * sc.coat.value, under_coat_err = c * sc.coat.abs_error + 2 * eps;
    // diffuse: EON's albedo, exact (a few ulps: 16 eps)
    brdf::params<double> p;
    p.roughness = in.base_diffuse_roughness;
    for (std::size_t k = 0; k < 3; ++k) {
        p.specular = in.base_weight * in.base_color[k];
        const double e = brdf::eon::albedo_of(mu, p), scale = under_coat * tint[k] * (1 - met) * (1 - sc.spec.value);
        r.lobes[0].value[k] = scale * e;
        r.lobes[0].abs_error[k] = 16 * eps * e + e * tint[k] * (1 - met) *
                                                     (under_coat_err * (1 - sc.spec.value) + under_coat * sc.spec.abs_error);
    }
    // specular: the untinted lobe's albedo, tinted
    for (std::size_t k = 0; k < 3; ++k) {
        const double scale = under_coat * tint[k] * (1 - met) * in.specular_color[k];
        r.lobes[1].value[k] = scale * sc.spec.value;
        const double unscaled = tint[k] * (1 - met) * in.specular_color[k] * sc.spec.value;
        r.lobes[1].abs_error[k] = scale * sc.spec.abs_error + under_coat_err * unscaled + 8 * eps * abs(r.lobes[1].value[k]);
    }
    // metal
    if (met > 0) {
        const rgb_estimate e = detail::ggx_albedo_rgb(m.alpha(), mu, [&](double vh) { return m.metal_fresnel(vh); },
                                                      s.tolerance, s.max_panels, r.evaluations);
        for (std::size_t k = 0; k < 3; ++k) {
            const double scale = under_coat * tint[k] * met;
            r.lobes[2].value[k] = scale * e.value[k];
            r.lobes[2].abs_error[k] = scale * e.abs_error[k] + under_coat_err * tint[k] * met * abs(e.value[k]);
        }
    }
    // coat
    r.lobes[3].value = grey(c * sc.coat.value);
    r.lobes[3].abs_error = grey(c * sc.coat.abs_error);
    detail::sum_lobes(r);
    return r;
}

}  // namespace normzoo::material
