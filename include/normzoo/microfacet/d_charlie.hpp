// The "Charlie" sheen distribution (Estevez and Kulla 2017, "Production Friendly Microfacet Sheen
// BRDF"): D(m) = (2 + r) sin^r t / (2 pi), r = 1/alpha, an inverted lobe whose mass lies toward
// the horizon, t = pi/2, not at the normal (docs/microfacet.md#the-charlie-sheen-distribution).
// Its mass below t, the integral of D N.m, is (2 + r) integral_0^t sin^(r+1) cos = sin^(r+2) t: the
// polar map is sin psi = sin^((r+2)/2) t, and the albedo is integrated in psi as for the others
// (microfacet/stretched.hpp). It has no Smith Lambda in closed form; the sheen's G parts
// (masking.hpp: neubelt, charlie-sheen) read none.
#pragma once
#include <cmath>

#include "distribution_part.hpp"

namespace normzoo::microfacet {

struct d_charlie {
    static constexpr std::string_view id = "charlie";
    static constexpr auto parameters = no_parameters;
    static constexpr const char* formula = "(2 + 1/a) sin^(1/a) t / (2 pi)";
    static constexpr const char* literature =
        "Estevez and Kulla 2017, \"Production Friendly Microfacet Sheen BRDF\"; KHR_materials_sheen";
    static constexpr bool isotropic = true, has_exact_lambda = false, has_polar_map = true, has_azimuthal_integral = false,
                          has_azimuthal_schlick_integral = false, has_non_projected = false;
    // The exponent r = 1/alpha.
    template <class T>
    static T exponent(const ndf_params<T>& p) { return 1 / p.alpha_x; }
    // ln sin x, from cos^2 x where x is near pi/2 (sin x would lose the distance from 1 there).
    template <class T>
    static T log_sin(const T& x) {
        using std::cos; using std::log; using std::log1p; using std::sin;
        if (x > T(0.785)) {
            const T c = cos(x);
            return log1p(-c * c) / 2;
        }
        return log(sin(x));
    }
    // mass below t: sin^(r+2) t = sin^2 psi, so sin t = sin^e psi, e = 2/(r+2), and cos^2 t = 1 -
    // e^(2 e ln sin psi), by expm1 (near t = pi/2, where the mass of a narrow lobe is, 1 - sin^2 t
    // would cancel).
    template <class T>
    static void polar(const T& psi, const ndf_params<T>& p, T& c, T& s) {
        using std::exp; using std::expm1; using std::sqrt;
        const T e = 2 / (exponent(p) + 2), ls = log_sin(psi);
        s = exp(e * ls), c = sqrt(-expm1(2 * e * ls));
    }
    // psi at t: sin psi = e^x, cos psi = sqrt(1 - e^(2x)), x = (r+2)/2 ln sin t.
    template <class T>
    static T theta_to_psi(const T& t, const ndf_params<T>& p) {
        using std::atan2; using std::exp; using std::expm1; using std::sqrt;
        const T x = (exponent(p) + 2) / 2 * log_sin(t);
        return atan2(exp(x), sqrt(-expm1(2 * x)));
    }
    template <class T>
    static T d(const vec3<T>& m, const ndf_params<T>& p) {
        using std::pow;
        if (!(m.z() > 0)) return T(0);
        const T r = exponent(p), s2 = m.x() * m.x() + m.y() * m.y();
        return (2 + r) * pow(s2, r / 2) / (2 * detail::pi<T>());
    }
};

}  // namespace normzoo::microfacet
