// OpenPBR Surface 1.1's lobes and layering operators (docs/materials.md, "OpenPBR Surface 1.1"),
// as the specification's reduction to a mixture of lobes writes them, reflection only:
//   f = F f_fuzz + (1 - F E_fuzz(V)) [C f_coat + B(L, V) f_base-substrate]      (F = fuzz_weight)
//   B = lerp(1, T(L, V) (1 - E_coat(V)), C) lerp(1, Delta(V), C coat_darkening)  (C = coat_weight)
//   f_base-substrate = (1 - M) f_dielectric-base + M f_metal                   (M = base_metalness)
//   f_dielectric-base = specular_color f_spec + (1 - E_spec(V)) f_diffuse   (E_spec per channel under a film)
//   f_diffuse = EON(rho = base_weight base_color, r = base_diffuse_roughness)  (brdf/eon.hpp, the
//               authors' compensation, not the specification's printed extra 1/pi)
//   f_spec    = GGX D G / (4 N.L N.V) x lerp(F_dielectric(V.H, eta'), F_film(V.H; F0(eta')), W),
//               eta' = (1 + e) / (1 - e), e = sgn(eta_s - 1) sqrt(specular_weight F0(eta_s)),
//               eta_s = lerp(n_b, n_b/n_c or n_c/n_b (the larger), C), n_b = specular_ior, n_c = coat_ior
//               (the base's index relative to the coat where it covers it, with the TIR fix)
//   GGX       at alpha = r'^2 for the base (specular and metal), r' = lerp(r, min(1, r^4 + 2 r_c^4)^(1/4), C),
//               r = specular_roughness, r_c = coat_roughness (the coat's roughening of the base)
//   f_metal   = GGX D G / (4 N.L N.V) x specular_weight lerp(F82(V.H), F_film(V.H; F0), W), F82 unclamped as
//               1.1 writes it:
//               F82(m) = F0 + (1 - F0)(1 - m)^5 - b m (1 - m)^6, F0 = base_weight base_color,
//               b = (F0 + (1 - F0)(6/7)^5)(1 - specular_color) / ((1/7)(6/7)^6)
//   f_coat    = GGX(coat_roughness^2) D G / (4 N.L N.V) x F_dielectric(V.H, coat_ior)
//   f_fuzz    = fuzz_color E_fuzz(N.V) D_LTC(L) / N.L (Zeltner et al. 2022; openpbr_fuzz.hpp)
//   F_film    = Belcour and Barla 2017 in the form KHR_materials_iridescence gives it
//               (microfacet/fresnel_thin_film.hpp), in air, over the base's index from F0 as
//               MaterialX takes it, sqrt(clamp(F0, 0.01, 0.99)) (W = thin_film_weight; thickness 0 is
//               no film); the specification leaves the film's form to implementations.
// T (the coat's view-dependent absorption) and Delta (its darkening) are openpbr_coat.hpp's.
// Albedo scaling reads E at the view only (the specification's non-reciprocal albedo scaling), so
// with V fixed each lobe's albedo is its own (weighted by T's factor of N.L under an absorbing
// coat) times numbers of V (openpbr_albedo.hpp). E_spec is the untinted lobe's (as MaterialX's
// dielectric_bsdf); E_fuzz the fit's, untinted (the specification's fuzz layering). G is Smith's
// height-correlated form (Heitz 2014) throughout. Not here: transmission, subsurface and
// anisotropy.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "../brdf/eon.hpp"
#include "../geometry.hpp"
#include "../microfacet/albedo.hpp"
#include "../microfacet/composition.hpp"
#include "../microfacet/fresnel.hpp"
#include "../microfacet/stretched.hpp"
#include "../parameter.hpp"
#include "../quadrature/channels.hpp"
#include "albedo.hpp"
#include "iridescence.hpp"
#include "lobes.hpp"
#include "material.hpp"
#include "openpbr_coat.hpp"
#include "openpbr_fuzz.hpp"

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
    double coat_darkening = 1;
    double fuzz_weight = 0;
    rgb fuzz_color = grey(1);
    double fuzz_roughness = 0.5;
    double thin_film_weight = 0, thin_film_thickness = 0.5, thin_film_ior = 1.4;  // thickness in um
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

// What the layering reads at V (openpbr_albedo.hpp computes them): the untinted specular lobe's
// (per channel: a film colours it) and the coat's albedos, the darkening factor lerp(1, Delta, C
// coat_darkening) per channel, and E_fuzz (the fit's value).
struct openpbr_view_values {
    rgb spec{};
    double coat = 0;
    rgb darkening = grey(1);
    double fuzz = 0;
};

struct openpbr {
    static constexpr std::string_view id = "openpbr";
    static constexpr const char* literature =
        "OpenPBR Surface 1.1 (Academy Software Foundation), Model and Reduction to a mixture of lobes; Portsmouth, "
        "Kutz and Hill 2025 (EON); Kutz, Hasan and Edmondson 2021 (F82-tint); Zeltner, Burley and Chiang 2022 "
        "(fuzz); d'Eon 2021 (coat darkening); Belcour and Barla 2017 (thin film); Heitz 2014";
    static constexpr std::size_t lobe_count = 5;
    static constexpr std::array<std::string_view, lobe_count> lobe_ids = {"diffuse", "specular", "metal", "coat", "fuzz"};
    // roughnesses from 1e-4 (alpha 1e-8, as gltf); the iors from 1 (the albedo's dielectric F reads
    // its index from F0: below 1 is refused by input_error); specular_weight unbounded above as 1.1.
    // fuzz_roughness from 0.01, the fits' range (openpbr_fuzz.hpp). thin_film_thickness up to 10 um,
    // as gltf's iridescenceThickness; thin_film_ior from 1 (MaterialX's Airy Fresnel clamps it there).
    static constexpr std::array<parameter, 19> parameters = {{
        {"base_weight", "the base's weight (the metal's F0 and the diffuse albedo), in [0, 1]", 0, 1, {}, 1},
        {"base_color", "the base colour, linear RGB (R,G,B, or one number for grey), each in [0, 1]", 0, 1, {}, 0.8,
         false, 3},
        {"base_metalness", "the mix of the metal over the dielectric base, in [0, 1]", 0, 1, {}, 0},
        {"base_diffuse_roughness", "EON's roughness r, in [0, 1]", 0, 1, {}, 0},
        {"specular_weight", "the dielectric's F0 and the metal's F multiplier, in [0, 1000]", 0, 1000, {}, 1},
        {"specular_color", "the tint of the dielectric's reflection and of the metal's edge, each in [0, 1]", 0, 1,
         {}, 1, false, 3},
        {"specular_roughness", "alpha = specular_roughness^2 (roughened under a coat), in [1e-4, 1]", 1e-4, 1, {}, 0.3},
        {"specular_ior", "the dielectric base's index of refraction, in [1, 1000]", 1, 1000, {}, 1.5},
        {"coat_weight", "the coat's coverage, in [0, 1]", 0, 1, {}, 0},
        {"coat_color", "the coat's transmittance tint on the base (at normal incidence), each in [0, 1]", 0, 1, {}, 1, false, 3},
        {"coat_roughness", "the coat's alpha = coat_roughness^2, in [1e-4, 1]", 1e-4, 1, {}, 1e-4},
        {"coat_ior", "the coat's index of refraction, in [1, 1000]", 1, 1000, {}, 1.6},
        {"coat_darkening", "the coat's darkening of the base (0: boosted back to the undarkened albedo), in [0, 1]", 0, 1,
         {}, 1},
        {"fuzz_weight", "the fuzz layer's coverage, in [0, 1]", 0, 1, {}, 0},
        {"fuzz_color", "the fuzz lobe's albedo tint, each in [0, 1]", 0, 1, {}, 1, false, 3},
        {"fuzz_roughness", "the fuzz's alpha (used as is, not squared), in [0.01, 1]", 0.01, 1, {}, 0.5},
        {"thin_film_weight", "the thin film's coverage over the base, in [0, 1]", 0, 1, {}, 0},
        {"thin_film_thickness", "the thin film's thickness in micrometres, in [0, 10]", 0, 10, {}, 0.5},
        {"thin_film_ior", "the thin film's index of refraction, in [1, 1000]", 1, 1000, {}, 1.4},
    }};

    // The material table's notes on this material (its albedo's route, its claims).
    static constexpr const char* albedo_method =
        "each lobe its own integral times the layering's numbers of V (albedo scaling at the view): EON's closed "
        "form, the dielectric's and coat's 1D albedos (under a thin film the dielectric's per channel in GGX's map, split "
        "at the film's kinks), the F82 metal in GGX's map; under an absorbing coat each "
        "base lobe weighted by coat_color^(1/(2 mu_L^t)), the fuzz lobe's LTC integrated (1 to its bound); "
        "material/openpbr_albedo.hpp, 1e-10";
    static constexpr const char* preservation_claim =
        "conserving: albedo - error_estimate <= 1; preserving: every channel 1 within its bound, where OpenPBR's "
        "White furnace testing claims it (white base_color, specular_color, coat_color and fuzz_color, base_weight "
        "and specular_weight 1), else null; reciprocal: f(L, V) against f(V, L) on 28 pairs of directions, holds "
        "when the largest relative difference is at most 1e-12";

    openpbr_inputs in;

    // Number parameter i's component j, in declaration order; openpbr has no choice parameter.
    void set(std::size_t i, std::size_t j, double x) {
        double* slots[] = {&in.base_weight, &in.base_color[j], &in.base_metalness, &in.base_diffuse_roughness,
                           &in.specular_weight, &in.specular_color[j], &in.specular_roughness, &in.specular_ior,
                           &in.coat_weight, &in.coat_color[j], &in.coat_roughness, &in.coat_ior, &in.coat_darkening,
                           &in.fuzz_weight, &in.fuzz_color[j], &in.fuzz_roughness,
                           &in.thin_film_weight, &in.thin_film_thickness, &in.thin_film_ior};
        if (i < sizeof slots / sizeof slots[0]) *slots[i] = x;
    }
    void choose(std::size_t, std::size_t) {}

    static const char* input_error(const openpbr_inputs& x) {
        if (x.specular_ior < 1 || x.coat_ior < 1) return "specular_ior and coat_ior are at least 1 here";
        // within 4 ulps of 1: decimals whose product is exactly 1 (specular_weight 961 under a full
        // coat of 1.6 over 1.5: F0 = 1/961) can round just below it, and eta' ~ 1e16 there
        if (x.specular_weight * microfacet::f0_of_eta(specular_ior_ratio(x)) >= 1 - 4 * std::numeric_limits<double>::epsilon())
            return "specular_weight F0(eta_s) reaches 1 (eta_s: specular_ior relative to the coat and the ambient "
                   "medium): eta' = (1 + e)/(1 - e) divides by 0 (OpenPBR 1.1)";
        return nullptr;
    }

    // eta_s, the base dielectric's index relative to what lies over it (OpenPBR 1.1, Coat, its
    // equations specular_ior_ratio and specular_ior_ratio_with_tir_fix, after Kutz et al. 2021):
    // n_b/n_c under the coat, inverted to n_c/n_b where the coat is the denser so that the base
    // shows no spurious total internal reflection, lerped with n_b/n_a (n_a = 1) by coat_weight.
    // At least 1; n_b itself without a coat.
    static double specular_ior_ratio(const openpbr_inputs& x) {
        const double nb = x.specular_ior, nc = x.coat_ior, c = x.coat_weight;
        return (1 - c) * nb + c * (nc > nb ? nc / nb : nb / nc);
    }
    // The base's roughness r' under a rough coat (OpenPBR 1.1, Coat, Roughening): slope variances
    // r^4 add, the coat's twice (the light crosses it twice), lerped by coat_weight; r without a coat.
    double base_roughness() const {
        const double r = in.specular_roughness, rc = in.coat_roughness, c = in.coat_weight;
        const double r2 = r * r, rc2 = rc * rc;
        return (1 - c) * r + c * std::sqrt(std::sqrt(std::min(1.0, r2 * r2 + 2 * rc2 * rc2)));
    }
    double alpha() const {
        const double r = base_roughness();
        return r * r;
    }
    double coat_alpha() const { return in.coat_roughness * in.coat_roughness; }
    // eta' of specular_weight (OpenPBR 1.1, Specular): F0(eta') = specular_weight F0(eta_s).
    double specular_eta() const {
        const double e = std::sqrt(in.specular_weight * microfacet::f0_of_eta(specular_ior_ratio(in)));
        return (1 + e) / (1 - e);  // eta_s >= 1: sgn(eta_s - 1) e = e
    }
    rgb metal_f0() const { return in.base_weight * in.base_color; }
    // The film over the base, in air, its thickness in nm, the base's index from F0 as MaterialX
    // takes it (iridescence.hpp: active() when it changes F).
    iridescence_layer film() const {
        return {in.thin_film_weight, {1, in.thin_film_ior, 1000 * in.thin_film_thickness, microfacet::film_base::f0_clamped}};
    }
    rgb metal_fresnel(double vh) const {
        const rgb f0 = metal_f0();
        rgb out;
        for (std::size_t k = 0; k < 3; ++k) out[k] = f82(vh, f0[k], in.specular_color[k]);
        const iridescence_layer layer = film();
        if (layer.active()) out = iridescence_layer::lerp(out, microfacet::thin_film_fresnel(layer.film, f0, vh), layer.weight);
        return in.specular_weight * out;
    }
    // The dielectric's F at eta' under the film, per channel (untinted).
    rgb specular_fresnel(double vh) const {
        const double eta = specular_eta(), fd = dielectric_f(vh, eta);
        const iridescence_layer layer = film();
        if (!layer.active()) return grey(fd);
        return iridescence_layer::lerp(grey(fd), microfacet::thin_film_fresnel(layer.film, grey(microfacet::f0_of_eta(eta)), vh),
                                       layer.weight);
    }
    // What rounding can move specular_fresnel and metal_fresnel beyond a few ulps, per channel: the
    // film's where it is ill-conditioned (iridescence_layer::rounding); 0 without a film.
    rgb specular_rounding(double vh) const {
        const iridescence_layer layer = film();
        return layer.active() ? layer.rounding(vh, grey(microfacet::f0_of_eta(specular_eta()))) : grey(0);
    }
    rgb metal_rounding(double vh) const {
        const iridescence_layer layer = film();
        return layer.active() ? in.specular_weight * layer.rounding(vh, metal_f0()) : grey(0);
    }
    // The values of V.H where the film's Fresnel has kinks (its clamps), for the albedo's
    // integrals; none without a film.
    std::vector<double> film_kinks() const {
        const iridescence_layer layer = film();
        if (!layer.active()) return {};
        // the F0s of the lobes present (a lobe of weight 0 adds no kinks)
        const rgb dielectric = grey(microfacet::f0_of_eta(specular_eta())), metal = metal_f0();
        const double m = in.base_metalness;
        return layer.kinks({m < 1 ? dielectric : metal, m > 0 ? metal : dielectric}, [](double) { return grey(0); });
    }
    static double dielectric_f(double vh, double eta) {
        microfacet::fresnel_params<double> p;
        p.eta = eta;
        return microfacet::fresnel_dielectric::eval(vh, p);
    }

    // The base's factor of (L, V) from the coat: lerp(1, T(L, V) (1 - E_coat(V)), C) per channel.
    rgb under_coat(const vec3<double>& l, const vec3<double>& v, double e_coat) const {
        const double c = in.coat_weight;
        if (c == 0) return grey(1);
        const rgb t = openpbr_coat::absorption_half(in.coat_color, l.z(), in.coat_ior) *
                      openpbr_coat::absorption_half(in.coat_color, v.z(), in.coat_ior);
        return grey(1 - c) + (c * (1 - e_coat)) * t;
    }

    // Each lobe's contribution to f(L, V), per channel, given what the layering reads at V
    // (openpbr_albedo.hpp's openpbr_view_terms: E_spec, E_coat, the darkening, E_fuzz).
    std::array<rgb, lobe_count> f_lobes(const vec3<double>& l, const vec3<double>& v, const openpbr_view_values& t) const {
        std::array<rgb, lobe_count> out{};
        if (!(l.z() > 0 && v.z() > 0)) return out;
        const vec3<double> h = half_vector(l, v);
        const double vh = v.dot(h);
        const specular_brdf spec{alpha(), smith_form::height_correlated}, coat{coat_alpha(), smith_form::height_correlated};
        const double s = spec.value(l, v, h), c = coat.value(l, v, h);
        const double top = 1 - in.fuzz_weight * t.fuzz;
        const rgb base_scale = top * (under_coat(l, v, t.coat) * t.darkening);
        const double m = in.base_metalness;
        brdf::params<double> p;
        p.roughness = in.base_diffuse_roughness;
        for (std::size_t k = 0; k < 3; ++k) {
            p.specular = in.base_weight * in.base_color[k];
            out[0][k] = base_scale[k] * (1 - m) * (1 - t.spec[k]) * brdf::eon::f(l, v, p);
        }
        const rgb fs = specular_fresnel(vh);
        for (std::size_t k = 0; k < 3; ++k) out[1][k] = ((1 - m) * s * fs[k]) * (base_scale[k] * in.specular_color[k]);
        out[2] = (m * s) * (base_scale * metal_fresnel(vh));
        out[3] = grey(top * in.coat_weight * c * dielectric_f(vh, in.coat_ior));
        if (in.fuzz_weight > 0) {
            const double y = in.fuzz_roughness, x = v.z();
            const vec3<double> w = openpbr_fuzz::to_view_frame(l, v);
            const double d = openpbr_fuzz::ltc_density(w.x(), w.y(), w.z(), openpbr_fuzz::ltc_a(x, y), openpbr_fuzz::ltc_b(x, y));
            out[4] = (in.fuzz_weight * t.fuzz * d / l.z()) * in.fuzz_color;
        }
        return out;
    }

    // The whole f(L, V), per channel, with the layering's terms computed at V (openpbr_albedo.hpp
    // defines it: the terms are integrals).
    rgb f(const vec3<double>& l, const vec3<double>& v) const;
};

}  // namespace normzoo::material
