// Anisotropic GGX (Burley 2012); its Lambda is GGX's at the roughness seen along w's azimuth
// (Heitz 2014, section 5).
#pragma once
#include "d_ggx.hpp"

namespace normzoo::microfacet {

struct d_ggx_aniso {
    static constexpr std::string_view id = "ggx-aniso";
    static constexpr std::array<parameter, 1> parameters{aspect_parameter};
    static constexpr const char* formula = "1 / (pi ax ay cos^4 t (1 + tan^2 t (cos^2 p / ax^2 + sin^2 p / ay^2))^2)";
    static constexpr const char* literature = "Burley 2012; Heitz 2014, section 5 (Lambda)";
    static constexpr bool isotropic = false, has_exact_lambda = true, has_polar_map = false, has_azimuthal_integral = false, has_azimuthal_schlick_integral = false, has_non_projected = false;
    template <class T>
    static T d(const vec3<T>& m, const ndf_params<T>& p) {
        if (!(m.z() > 0)) return T(0);
        const T c2 = m.z() * m.z();
        const T e = (m.x() * m.x() / (p.alpha_x * p.alpha_x) + m.y() * m.y() / (p.alpha_y * p.alpha_y)) / c2;
        return 1 / (detail::pi<T>() * p.alpha_x * p.alpha_y * c2 * c2 * (1 + e) * (1 + e));
    }
    template <class T>
    static T lambda(const vec3<T>& w, const ndf_params<T>& p) { return detail::ggx_lambda(w, detail::projected_alpha(w, p)); }
};

}  // namespace normzoo::microfacet
