// Phong as a BRDF: the zoo's RDF divided by the cosine (not reciprocal), and the modified
// (reciprocal) form. R is the mirror of L, so the lobe (R.V)^n peaks at V = R.
// Literature: Phong 1975; Lewis 1994; Lafortune and Willems 1994; "The Blinn-Phong
// Normalization Zoo" (energy conservation of the original and modified forms).
// The lobe and the constants are the zoo rows' (zoo/phong.hpp): one formula for both.
#pragma once
#include "../zoo/phong.hpp"
#include "brdf.hpp"

namespace normzoo::brdf {

struct phong {
    static constexpr const char* id = "phong";
    static constexpr const char* formula = "(n+1)/(2 pi) (R.V)^n / (N.L)";
    static constexpr const char* literature = "Phong 1975; Lewis 1994";
    static constexpr bool has_exponent = true;
    static constexpr bool has_specular = false;
    static constexpr std::array<parameter, 1> parameters{exponent_n};
    static constexpr check_point monte_carlo_case{4, 80};
    static constexpr bool reciprocal = false;
    static constexpr lobe_kind lobe = lobe_kind::mirror;
    static constexpr int inverse_lh_power = 0;
    static constexpr bool fresnel = false;
    static constexpr const char* zoo_row = "phong";
    // The constant in front of the lobe, and the exact normalization a shader should use.
    template <class T>
    static T constant(const T& n) { return zoo::phong::closed_form(n); }
    template <class T>
    static T exact_constant(const T& n) { return constant(n); }

    template <class T>
    static T f(const vec3<T>& l, const vec3<T>& v, const params<T>& p) {
        return constant(p.n) * zoo::phong::lobe(l, v, p.n) / normal<T>().dot(l);
    }
    // At L = N the lobe is (N.V)^n: (n+1)/(2 pi) * 2 pi / (n+2).
    template <class T>
    static T albedo_at_normal(const params<T>& p) {
        const T& n = p.n;
        return (n + 1) / (n + 2);
    }
};

struct phong_modified {
    static constexpr const char* id = "phong-modified";
    static constexpr const char* formula = "(n+2)/(2 pi) (R.V)^n";
    static constexpr const char* literature = "Lewis 1994; Lafortune and Willems 1994";
    static constexpr bool has_exponent = true;
    static constexpr bool has_specular = false;
    static constexpr std::array<parameter, 1> parameters{exponent_n};
    static constexpr check_point monte_carlo_case{16, 45};
    static constexpr bool reciprocal = true;
    static constexpr lobe_kind lobe = lobe_kind::mirror;
    static constexpr int inverse_lh_power = 0;
    static constexpr bool fresnel = false;
    static constexpr const char* zoo_row = "phong-modified";
    // The constant in front of the lobe, and the exact normalization a shader should use.
    template <class T>
    static T constant(const T& n) { return zoo::phong_modified::closed_form(n); }
    template <class T>
    static T exact_constant(const T& n) { return constant(n); }

    template <class T>
    static T f(const vec3<T>& l, const vec3<T>& v, const params<T>& p) {
        return constant(p.n) * zoo::phong::lobe(l, v, p.n);
    }
    template <class T>
    static T albedo_at_normal(const params<T>& /*p*/) { return T(1); }
};

}  // namespace normzoo::brdf
