// Burley's generalized Trowbridge-Reitz (Burley 2012, appendix B).
#pragma once
#include "distribution_part.hpp"

namespace normzoo::microfacet {

// gamma = 2 is GGX, gamma = 1 Berry's distribution.
struct d_gtr {
    static constexpr std::string_view id = "gtr";
    static constexpr std::array<parameter, 1> parameters{gamma_parameter};
    static constexpr const char* formula =
        "c / (a^2 cos^2 t + sin^2 t)^gamma, c = (gamma - 1)(a^2 - 1) / (pi (1 - a^(2 (1 - gamma)))) "
        "((a^2 - 1) / (pi ln a^2) at gamma = 1; 1/pi at a = 1)";
    static constexpr const char* literature = "Burley 2012, \"Physically-Based Shading at Disney\", appendix B";
    static constexpr bool isotropic = true, has_exact_lambda = false, has_polar_map = false, has_azimuthal_integral = false, has_azimuthal_schlick_integral = false, has_non_projected = false;
    template <class T>
    static T constant(const ndf_params<T>& p) {
        using std::abs;
        using std::exp;
        using std::log;
        const T a2 = p.alpha_x * p.alpha_x, g = p.gamma;
        if (a2 == 1) return 1 / detail::pi<T>();
        if (g == 1) return (a2 - 1) / (detail::pi<T>() * log(a2));
        // 1 - a2^(1 - g) = -(e^x - 1), x = (1 - g) ln a2: by the series of e^x - 1 where x is
        // small (gamma near 1), where 1 - pow(...) would cancel
        const T x = (1 - g) * log(a2);
        T em1 = x;
        if (abs(x) < T(0.5)) {
            T term = x;
            for (int k = 2; abs(term) > std::numeric_limits<T>::epsilon() * abs(em1); ++k) term *= x / k, em1 += term;
        } else {
            em1 = exp(x) - 1;
        }
        return (g - 1) * (a2 - 1) / (detail::pi<T>() * -em1);
    }
    template <class T>
    static T d(const vec3<T>& m, const ndf_params<T>& p) {
        using std::pow;
        if (!(m.z() > 0)) return T(0);
        const T a2 = p.alpha_x * p.alpha_x, c2 = m.z() * m.z(), s2 = m.x() * m.x() + m.y() * m.y();
        return constant(p) / pow(a2 * c2 + s2, p.gamma);
    }
};

}  // namespace normzoo::microfacet
