// Microfacet forms built on the normalized Blinn-Phong distribution.
//   microfacet-blinn          F(c_spec, L.H) (n+2)/(8 pi) (N.H)^n: Hoffman's form, quoted in
//                             "Adopting a physically based shading model" (no visibility term)
//   minimalist-cook-torrance  k_s (n+1) (N.H)^n / (8 pi (L.H)^3): D = (n+1)/(2 pi) (N.H)^n
//                             with F V = 1 / (4 (L.H)^3), from "The Blinn-Phong Normalization
//                             Zoo" (ShaderX7, shipped in Velvet Assassin)
//   cook-torrance-ksk         D F V, D = (n+2)/(2 pi) (N.H)^n, F = Schlick, and the visibility
//                             V = 1 / (4 (L.H)^2) of Kelemen and Szirmay-Kalos 2001
// microfacet-blinn and cook-torrance-ksk are the compositions blinn-phong/implicit/schlick and
// blinn-phong/kelemen/schlick at alpha = sqrt(2/(n+2)) (microfacet/composition.hpp): their f is
// the parts' code (microfacet/fixed_composition.hpp). minimalist-cook-torrance is not a composition: its D has Phong's (n+1) where
// the normalized Blinn-Phong has (n+2), and its F V = k_s / (4 (L.H)^3) is neither a masking term
// nor a Fresnel term (docs/microfacet.md, "Compositions"). The lobe (N.H)^n and the zoo's
// constants are zoo/blinn_phong.hpp's.
#pragma once
#include "../microfacet/d_blinn_phong.hpp"
#include "../microfacet/fixed_composition.hpp"
#include "../zoo/blinn_phong.hpp"
#include "brdf.hpp"

namespace normzoo::brdf {

struct microfacet_blinn {
    static constexpr const char* id = "microfacet-blinn";
    static constexpr const char* formula = "F_schlick(c_spec, L.H) (n+2)/(8 pi) (N.H)^n";
    static constexpr const char* literature = "Hoffman 2010; \"Adopting a physically based shading model\"";
    static constexpr bool has_exponent = true;
    static constexpr bool has_specular = true;
    static constexpr std::array<parameter, 2> parameters{exponent_n, specular_ks};
    static constexpr check_point monte_carlo_case{1024, 60};
    static constexpr bool reciprocal = true;
    static constexpr lobe_kind lobe = lobe_kind::half;
    static constexpr int inverse_lh_power = 0;
    static constexpr bool fresnel = true;
    static constexpr const char* zoo_row = "blinn-phong-heightfield";
    // The constant in front of the lobe, and the exact normalization a shader should use.
    template <class T>
    static T constant(const T& n) { return (n + 2) / (8 * pi<T>()); }
    template <class T>
    static T exact_constant(const T& n) { return constant(n); }

    using parts = microfacet::fixed_composition<microfacet::d_blinn_phong, microfacet::g_implicit, microfacet::fresnel_schlick>;
    template <class T>
    static T f(const vec3<T>& l, const vec3<T>& v, const params<T>& p) {
        using std::sqrt;
        return parts::f(l, v, sqrt(2 / (p.n + 2)), p.specular);
    }
    // f = constant(n) (N.H)^n x lobe_factor (lobe_albedo.hpp): Schlick's F
    template <class T>
    static T lobe_factor(const T& /*nl*/, const T& lh, const params<T>& p) { return fresnel_schlick(p.specular, lh); }
    template <class T>
    static T albedo_at_normal(const params<T>& p) {
        const T& n = p.n;
        return (n + 2) / (8 * pi<T>()) * detail::half_vector_albedo_moment(n);
    }
};

struct minimalist_cook_torrance {
    static constexpr const char* id = "minimalist-cook-torrance";
    static constexpr const char* formula = "k_s (n+1) (N.H)^n / (8 pi (L.H)^3)";
    static constexpr const char* literature = "Schueler, ShaderX7; \"The Blinn-Phong Normalization Zoo\"";
    static constexpr bool has_exponent = true;
    static constexpr bool has_specular = true;
    static constexpr std::array<parameter, 2> parameters{exponent_n, specular_ks};
    static constexpr check_point monte_carlo_case{16, 75};
    static constexpr bool reciprocal = true;
    static constexpr lobe_kind lobe = lobe_kind::half;
    static constexpr int inverse_lh_power = 3;
    static constexpr bool fresnel = false;
    static constexpr const char* zoo_row = "blinn-phong-ndf";
    // The constant in front of the lobe, and the exact normalization a shader should use.
    template <class T>
    static T constant(const T& n) { return (n + 1) / (8 * pi<T>()); }
    template <class T>
    static T exact_constant(const T& n) { return constant(n); }

    // D = (n+1)/(2 pi) (N.H)^n, and F V = k_s / (4 (L.H)^3) in place of Fresnel and visibility.
    template <class T>
    static T fresnel_visibility(const T& ks, const T& lh) { return ks / (4 * lh * lh * lh); }
    template <class T>
    static T f(const vec3<T>& l, const vec3<T>& v, const params<T>& p) {
        const vec3<T> h = half_vector(l, v);
        // constant(n) = (n+1)/(8 pi) is D's (n+1)/(2 pi) with the 1/4 of F V = k_s / (4 (L.H)^3)
        return constant(p.n) * zoo::blinn_phong::lobe(h, p.n) * 4 * fresnel_visibility(p.specular, l.dot(h));
    }
    // f = constant(n) (N.H)^n x lobe_factor (lobe_albedo.hpp)
    template <class T>
    static T lobe_factor(const T& /*nl*/, const T& lh, const params<T>& p) { return 4 * fresnel_visibility(p.specular, lh); }
    // (N.H)^n / (L.H)^3 = c^(n-3) at L = N.
    template <class T>
    static T albedo_at_normal(const params<T>& p) {
        const T& n = p.n;
        return (n + 1) / (8 * pi<T>()) * detail::half_vector_albedo_moment(n - 3);
    }
};

struct cook_torrance_ksk {
    static constexpr const char* id = "cook-torrance-ksk";
    static constexpr const char* formula = "(n+2)/(2 pi) (N.H)^n F_schlick(k_s, L.H) / (4 (L.H)^2)";
    static constexpr const char* literature = "Cook and Torrance 1982; Kelemen and Szirmay-Kalos 2001; Schlick 1994";
    static constexpr bool has_exponent = true;
    static constexpr bool has_specular = true;
    static constexpr std::array<parameter, 2> parameters{exponent_n, specular_ks};
    static constexpr check_point monte_carlo_case{100, 85};
    static constexpr bool reciprocal = true;
    static constexpr lobe_kind lobe = lobe_kind::half;
    static constexpr int inverse_lh_power = 2;
    static constexpr bool fresnel = true;
    static constexpr const char* zoo_row = "blinn-phong-heightfield";
    // The constant in front of the lobe, and the exact normalization a shader should use.
    template <class T>
    static T constant(const T& n) { return zoo::blinn_phong_heightfield::closed_form(n); }
    template <class T>
    static T exact_constant(const T& n) { return constant(n); }

    // F V with Schlick's F and V = 1 / (4 (L.H)^2).
    template <class T>
    static T fresnel_visibility(const T& ks, const T& lh) { return fresnel_schlick(ks, lh) / (4 * lh * lh); }
    using parts = microfacet::fixed_composition<microfacet::d_blinn_phong, microfacet::g_kelemen, microfacet::fresnel_schlick>;
    template <class T>
    static T f(const vec3<T>& l, const vec3<T>& v, const params<T>& p) {
        using std::sqrt;
        return parts::f(l, v, sqrt(2 / (p.n + 2)), p.specular);
    }
    // f = constant(n) (N.H)^n x lobe_factor (lobe_albedo.hpp): F V
    template <class T>
    static T lobe_factor(const T& /*nl*/, const T& lh, const params<T>& p) { return fresnel_visibility(p.specular, lh); }
    template <class T>
    static T albedo_at_normal(const params<T>& p) {
        const T& n = p.n;
        return (n + 2) / (8 * pi<T>()) * detail::half_vector_albedo_moment(n - 2);
    }
};

}  // namespace normzoo::brdf
