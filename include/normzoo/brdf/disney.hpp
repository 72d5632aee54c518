// Disney's diffuse term and Frostbite's renormalized form, indexed by the roughness r in [0, 1]:
//   disney-diffuse  (1/pi) F(N.L) F(N.V), F(x) = 1 + (F_D90 - 1)(1 - x)^5, F_D90 = 0.5 + 2 r (L.H)^2
//                   Burley 2012, "Physically-based shading at Disney"
//   disney-diffuse-renormalized  the same with F_D90 = r/2 + 2 r (L.H)^2, times 1 + r (1/1.51 - 1)
//                   Lagarde and de Rousiers 2014, "Moving Frostbite to physically based rendering"
// Albedo at L = N, derived here (F(N.L) = 1, (L.H)^2 = (1 + mu)/2 with mu = N.V, and
// integral_0^1 (1 - mu)^5 mu^k dmu = 1/42, 1/168 for k = 1, 2):
//   disney-diffuse               (82 + 5 r) / 84
//   disney-diffuse-renormalized  (1 + r (1/1.51 - 1)) (80 + 7 r) / 84
#pragma once
#include <cmath>

#include "brdf.hpp"

namespace normzoo::brdf {

template <bool Renormalized>
struct disney_diffuse_form {
    static constexpr std::array<parameter, 1> parameters{
        parameter{"r", "the Disney roughness", 0, 1, disney_roughnesses}};
    static constexpr bool has_exponent = false;
    static constexpr bool has_specular = false;
    static constexpr bool reciprocal = true;
    static constexpr lobe_kind lobe = lobe_kind::normal;
    static constexpr int inverse_lh_power = 0;
    static constexpr bool fresnel = false;

    template <class T>
    static T f(const vec3<T>& l, const vec3<T>& v, const params<T>& p) {
        const T nl = l.z(), nv = v.z();
        if (!(nl > 0 && nv > 0)) return T(0);
        const T r = p.roughness;
        const T lh = l.dot(half_vector(l, v));
        const T bias = Renormalized ? r / 2 : T(0.5);
        const T factor = Renormalized ? 1 + r * (1 / T(1.51) - 1) : T(1);
        const T fd90 = bias + 2 * r * lh * lh;
        auto scatter = [&](const T& x) {
            const T m = 1 - x, m2 = m * m;
            return 1 + (fd90 - 1) * m2 * m2 * m;
        };
        return scatter(nl) * scatter(nv) * factor / pi<T>();
    }
    template <class T>
    static T albedo_at_normal(const params<T>& p) {
        const T r = p.roughness;
        if (Renormalized) return (1 + r * (1 / T(1.51) - 1)) * (80 + 7 * r) / 84;
        return (82 + 5 * r) / 84;
    }
};

struct disney_diffuse : disney_diffuse_form<false> {
    static constexpr const char* id = "disney-diffuse";
    static constexpr const char* formula = "(1/pi) F(N.L) F(N.V), F(x) = 1 + (F_D90 - 1)(1 - x)^5, F_D90 = 0.5 + 2 r (L.H)^2";
    static constexpr const char* literature = "Burley 2012, \"Physically-based shading at Disney\"";
    static constexpr check_point monte_carlo_case{1, 80};
};

struct disney_diffuse_renormalized : disney_diffuse_form<true> {
    static constexpr const char* id = "disney-diffuse-renormalized";
    static constexpr const char* formula =
        "(1 + r (1/1.51 - 1))/pi F(N.L) F(N.V), F_D90 = r/2 + 2 r (L.H)^2";
    static constexpr const char* literature =
        "Lagarde and de Rousiers 2014, \"Moving Frostbite to physically based rendering\"";
    static constexpr check_point monte_carlo_case{0.5, 0};
};

}  // namespace normzoo::brdf
