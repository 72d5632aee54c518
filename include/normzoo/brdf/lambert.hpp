// Lambert: f = 1/pi, the zoo row's normalization (zoo/lambert.hpp). Literature: Lambert,
// Photometria (1760).
#pragma once
#include "../zoo/lambert.hpp"
#include "brdf.hpp"

namespace normzoo::brdf {

struct lambert {
    static constexpr const char* id = "lambert";
    static constexpr const char* formula = "1/pi";
    static constexpr const char* literature = "Lambert, Photometria (1760)";
    static constexpr bool has_exponent = false;
    static constexpr bool has_specular = false;
    static constexpr std::array<parameter, 0> parameters{};
    static constexpr check_point monte_carlo_case{0, 60};
    static constexpr bool reciprocal = true;
    static constexpr lobe_kind lobe = lobe_kind::normal;
    static constexpr int inverse_lh_power = 0;
    static constexpr bool fresnel = false;
    static constexpr const char* zoo_row = "lambert";
    // The constant in front of the lobe, and the exact normalization a shader should use.
    template <class T>
    static T constant(const T& n) { return zoo::lambert::closed_form(n); }
    template <class T>
    static T exact_constant(const T& /*n*/) { return constant(T(0)); }

    template <class T>
    static T f(const vec3<T>& /*l*/, const vec3<T>& /*v*/, const params<T>& /*p*/) { return constant(T(0)); }
    template <class T>
    static T albedo_at_normal(const params<T>& /*p*/) { return T(1); }
};

}  // namespace normzoo::brdf
