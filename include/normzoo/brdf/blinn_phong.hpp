// Blinn-Phong as a BRDF: the plain form over N.L (not reciprocal), the modified form with the
// exact normalization of the zoo, and the modified form with the popular (n+8)/(8 pi).
// Literature: Blinn 1977; Gotanda 2010 (plain); Giesen and Akenine-Moller, Haines and Hoffman
// (RTR) for the exact modified factor; (n+8)/(8 pi) as in RTR and "The Blinn-Phong
// Normalization Zoo", which bounds it.
// The lobe (N.H)^n and the exact constants are the zoo rows' (zoo/blinn_phong.hpp).
#pragma once
#include "../zoo/blinn_phong.hpp"
#include "brdf.hpp"

namespace normzoo::brdf {

struct blinn_phong {
    static constexpr const char* id = "blinn-phong";
    static constexpr const char* formula = "norm_bp(n) (N.H)^n / (N.L), norm_bp(n) = (n+2) / (4 pi (2 - 2^(-n/2)))";
    static constexpr const char* literature = "Blinn 1977; Gotanda 2010";
    static constexpr bool has_exponent = true;
    static constexpr bool has_specular = false;
    static constexpr std::array<parameter, 1> parameters{exponent_n};
    static constexpr check_point monte_carlo_case{64, 70};
    static constexpr bool reciprocal = false;
    static constexpr lobe_kind lobe = lobe_kind::half;
    static constexpr int inverse_lh_power = 0;
    static constexpr bool fresnel = false;
    static constexpr const char* zoo_row = "blinn-phong";
    // The constant in front of the lobe, and the exact normalization a shader should use.
    template <class T>
    static T constant(const T& n) { return zoo::blinn_phong::closed_form(n); }
    template <class T>
    static T exact_constant(const T& n) { return constant(n); }

    template <class T>
    static T f(const vec3<T>& l, const vec3<T>& v, const params<T>& p) {
        return constant(p.n) * zoo::blinn_phong::lobe(half_vector(l, v), p.n) / normal<T>().dot(l);
    }
    // f = constant(n) (N.H)^n x lobe_factor (lobe_albedo.hpp)
    template <class T>
    static T lobe_factor(const T& nl, const T& /*lh*/, const params<T>& /*p*/) { return 1 / nl; }
    template <class T>
    static T albedo_at_normal(const params<T>& p) {
        const T& n = p.n;
        return zoo::blinn_phong::closed_form(n) * detail::half_vector_albedo_moment(n);
    }
};

struct blinn_phong_modified {
    static constexpr const char* id = "blinn-phong-modified";
    static constexpr const char* formula = "norm_bpm(n) (N.H)^n, norm_bpm(n) = (n+2)(n+4) / (8 pi (2^(-n/2) + n))";
    static constexpr const char* literature = "Blinn 1977; Giesen; Akenine-Moller, Haines and Hoffman (RTR)";
    static constexpr bool has_exponent = true;
    static constexpr bool has_specular = false;
    static constexpr std::array<parameter, 1> parameters{exponent_n};
    static constexpr check_point monte_carlo_case{256, 30};
    static constexpr bool reciprocal = true;
    static constexpr lobe_kind lobe = lobe_kind::half;
    static constexpr int inverse_lh_power = 0;
    static constexpr bool fresnel = false;
    static constexpr const char* zoo_row = "blinn-phong-modified";
    // The constant in front of the lobe, and the exact normalization a shader should use.
    template <class T>
    static T constant(const T& n) { return zoo::blinn_phong_modified::closed_form(n); }
    template <class T>
    static T exact_constant(const T& n) { return constant(n); }

    template <class T>
    static T f(const vec3<T>& l, const vec3<T>& v, const params<T>& p) {
        return constant(p.n) * zoo::blinn_phong::lobe(half_vector(l, v), p.n);
    }
    // f = constant(n) (N.H)^n x lobe_factor (lobe_albedo.hpp)
    template <class T>
    static T lobe_factor(const T& /*nl*/, const T& /*lh*/, const params<T>& /*p*/) { return T(1); }
    template <class T>
    static T albedo_at_normal(const params<T>& p) {
        const T& n = p.n;
        return zoo::blinn_phong_modified::closed_form(n) * detail::half_vector_albedo_moment(n);
    }
};

struct blinn_phong_modified_approx {
    static constexpr const char* id = "blinn-phong-modified-approx";
    static constexpr const char* formula = "(n+8)/(8 pi) (N.H)^n";
    static constexpr const char* literature = "Akenine-Moller, Haines and Hoffman (RTR); \"The Blinn-Phong Normalization Zoo\"";
    static constexpr bool has_exponent = true;
    static constexpr bool has_specular = false;
    static constexpr std::array<parameter, 1> parameters{exponent_n};
    static constexpr check_point monte_carlo_case{8, 0};
    static constexpr bool reciprocal = true;
    static constexpr lobe_kind lobe = lobe_kind::half;
    static constexpr int inverse_lh_power = 0;
    static constexpr bool fresnel = false;
    static constexpr const char* zoo_row = "blinn-phong-modified";
    // The constant in front of the lobe, and the exact normalization a shader should use.
    template <class T>
    static T constant(const T& n) { return (n + 8) / (8 * pi<T>()); }
    template <class T>
    static T exact_constant(const T& n) { return zoo::blinn_phong_modified::closed_form(n); }

    template <class T>
    static T f(const vec3<T>& l, const vec3<T>& v, const params<T>& p) {
        return constant(p.n) * zoo::blinn_phong::lobe(half_vector(l, v), p.n);
    }
    // f = constant(n) (N.H)^n x lobe_factor (lobe_albedo.hpp)
    template <class T>
    static T lobe_factor(const T& /*nl*/, const T& /*lh*/, const params<T>& /*p*/) { return T(1); }
    template <class T>
    static T albedo_at_normal(const params<T>& p) {
        const T& n = p.n;
        return (n + 8) / (8 * pi<T>()) * detail::half_vector_albedo_moment(n);
    }
};

}  // namespace normzoo::brdf
