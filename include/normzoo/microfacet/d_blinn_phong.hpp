// Blinn-Phong's distribution D(m) = (n+2)/(2 pi) (N.m)^n at n = 2/alpha^2 - 2 (Blinn 1977; the
// mapping of Walter et al. 2007): the zoo's Blinn-Phong lobe (zoo/blinn_phong.hpp) with the
// heightfield row's constant; the rows include nothing of microfacet/, so the dependence runs one way.
#pragma once
#include "../zoo/blinn_phong.hpp"
#include "blinn_phong_polar.hpp"
#include "distribution_part.hpp"

namespace normzoo::microfacet {

struct d_blinn_phong {
    static constexpr std::string_view id = "blinn-phong";
    static constexpr auto parameters = no_parameters;  // what it reads beyond alpha (composition::reads)
    static constexpr const char* formula = "(n+2)/(2 pi) (N.m)^n, n = 2/alpha^2 - 2";
    static constexpr const char* literature = "Blinn 1977; the mapping of Walter et al. 2007";
    static constexpr bool isotropic = true, has_exact_lambda = false, has_polar_map = true, has_azimuthal_integral = false, has_azimuthal_schlick_integral = false, has_non_projected = false;
    template <class T>
    static T exponent(const ndf_params<T>& p) { return 2 / (p.alpha_x * p.alpha_x) - 2; }
    // mass below t: 1 - cos^(n+2) t = sin^2 psi (blinn_phong_polar.hpp)
    template <class T>
    static void polar(const T& psi, const ndf_params<T>& p, T& c, T& s) { blinn_phong_polar(psi, exponent(p), c, s); }
    template <class T>
    static T theta_to_psi(const T& t, const ndf_params<T>& p) { return blinn_phong_theta_to_psi(t, exponent(p)); }
    // (N.m)^n with the heightfield row's (n+2)/(2 pi): D (N.m) integrates to 1 (zoo/blinn_phong.hpp)
    template <class T>
    static T d(const vec3<T>& m, const ndf_params<T>& p) {
        if (!(m.z() > 0)) return T(0);
        const T n = exponent(p);
        return zoo::blinn_phong_heightfield::closed_form(n) * zoo::blinn_phong::lobe(m, n);
    }
};

}  // namespace normzoo::microfacet
