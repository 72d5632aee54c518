// GGX (Trowbridge-Reitz), a^2 / (pi cos^4 t (a^2 + tan^2 t)^2) (Trowbridge and Reitz 1975; Walter
// et al. 2007), its Smith Lambda (Heitz 2014) and D's (and D (1 - V.h)^5's) integral over L's azimuth.
#pragma once
#include <boost/math/special_functions/atanh.hpp>

#include "distribution_part.hpp"
#include "ggx_schlick_azimuth.hpp"

namespace normzoo::microfacet {

namespace detail {
template <class T>
T ggx_lambda(const vec3<T>& w, const T& a) {
    using std::sqrt;
    using std::abs;
    // (sqrt(1 + a^2 tan^2) - 1) / 2 without cancellation and with one division (it runs at every
    // node of the albedo integral): with q = a^2 (x^2 + y^2), q / (2 z (z + sqrt(z^2 + q)))
    const T q = a * a * (w.x() * w.x() + w.y() * w.y()), z = abs(w.z());
    return q / (2 * z * (z + sqrt(z * z + q)));
}
}  // namespace detail

struct d_ggx {
    static constexpr std::string_view id = "ggx";
    static constexpr auto parameters = no_parameters;
    static constexpr const char* formula = "a^2 / (pi cos^4 t (a^2 + tan^2 t)^2)";
    static constexpr const char* literature =
        "Trowbridge and Reitz 1975; Walter et al. 2007 (D, G1); Heitz 2014 (Lambda, weak white furnace)";
    static constexpr const char* non_projected_formula =
        "1 + a^2 atanh(b)/b, b = sqrt(1 - a^2) (a < 1); 1 + a^2 atan(c)/c, c = sqrt(a^2 - 1) (a > 1)";
    static constexpr const char* g1_formula = "2 / (1 + sqrt(1 + a^2 tan^2 t_v))";
    static constexpr bool isotropic = true, has_exact_lambda = true, has_polar_map = true, has_azimuthal_integral = true, has_azimuthal_schlick_integral = true, has_non_projected = true;
    // The non-projected integral, derived here: with w = sqrt(1 + tan^2 t) and b^2 = 1 - a^2,
    //     integral of D dw = a^2 integral_1^inf 2 w^2 / (w^2 - b^2)^2 dw = 1 + a^2 atanh(b) / b,
    // for a < 1; a^2 atan(c) / c with c^2 = a^2 - 1 for a > 1, and 2 at a = 1. Small a: 1 + a^2
    // ln(2/a); the heavy tail (D ~ a^2 / tan^4) makes it grow like (pi/2) a for wide lobes.
    template <class T>
    static T non_projected(const T& alpha) {
        using boost::math::atanh; using std::atan; using std::sqrt;
        const T a2 = alpha * alpha;
        if (a2 < 1) {
            const T b = sqrt(1 - a2);
            return 1 + a2 * atanh(b) / b;
        }
        if (a2 > 1) {
            const T c = sqrt(a2 - 1);
            return 1 + a2 * atan(c) / c;
        }
        return T(2);
    }
    // mass below t: tan^2 t / (a^2 + tan^2 t) = sin^2 psi, so tan t = a tan psi
    template <class T>
    static void polar(const T& psi, const ndf_params<T>& p, T& c, T& s) {
        using std::cos; using std::sin; using std::sqrt;
        const T cp = cos(psi), sp = p.alpha_x * sin(psi), r = sqrt(cp * cp + sp * sp);
        c = cp / r, s = sp / r;
    }
    template <class T>
    static T theta_to_psi(const T& t, const ndf_params<T>& p) {
        using std::atan2; using std::cos; using std::sin;
        return atan2(sin(t), p.alpha_x * cos(t));
    }
    template <class T>
    static T d(const vec3<T>& m, const ndf_params<T>& p) {
        if (!(m.z() > 0)) return T(0);
        const T a2 = p.alpha_x * p.alpha_x, c2 = m.z() * m.z();
        const T k = a2 + detail::tan2(m);
        return a2 / (detail::pi<T>() * c2 * c2 * k * k);
    }
    template <class T>
    static T lambda(const vec3<T>& w, const ndf_params<T>& p) { return detail::ggx_lambda(w, p.alpha_x); }
    // Over L's azimuth phi: with h = (L + V) / |L + V|, cos^2 t_h = c^2 / (2 (1 + L.V)), c = N.L +
    // N.V, D = a^2 (2s)^2 / (pi (2s - c^2 (1 - a^2))^2) with s = 1 + L.V = A + B cos phi, a ratio
    // of quadratics in cos phi; the integrals of 1/(R + S cos phi) and of its square over the circle
    // (2 pi / sqrt(R^2 - S^2), 2 pi R / (R^2 - S^2)^(3/2)) give
    //   2 a^2 (1 + 2 c (1 - a^2) / sqrt(Q) + c (1 - a^2)^2 (sin^2 t_L + sin^2 t_V + a^2 c^2) / Q^(3/2)),
    //   Q = (N.L - N.V)^2 + 2 a^2 (sin^2 t_L + sin^2 t_V) + a^4 c^2   ((R^2 - S^2) = c^2 Q),
    // a sum of terms >= 0 for a <= 1 (no cancellation), sharp where Q is least: at N.L = N.V.
    // Its rounding: 16 ulps (a few sums of terms >= 0 and a square root).
    template <class T>
    static azimuthal_value<T> azimuthal_integral(const azimuth_point<T>& a, const ndf_params<T>& p) {
        using std::sqrt;
        const T a2 = p.alpha_x * p.alpha_x, m = 1 - a2, c = a.nl + a.nv, s2 = a.sl2 + a.sv2;
        const T q = a.nl_minus_nv * a.nl_minus_nv + 2 * a2 * s2 + a2 * a2 * c * c;
        const T r = 1 / sqrt(q);
        const T value = 2 * a2 * (1 + 2 * c * m * r + c * m * m * (s2 + a2 * c * c) * (r * r * r));
        return {value, 16 * std::numeric_limits<T>::epsilon() * value};
    }
    // The same of D (1 - V.h)^5: complete elliptic integrals (ggx_schlick_azimuth.hpp), in double.
    static azimuthal_value<double> azimuthal_schlick_integral(const azimuth_point<double>& a, const ndf_params<double>& p) {
        const auto r = detail::ggx_schlick_azimuthal_integrals(a.nl, a.nv, a.nl_minus_nv, a.sl2, a.sv2, p.alpha_x);
        return {r.d5, r.d5_error};
    }
};

}  // namespace normzoo::microfacet
