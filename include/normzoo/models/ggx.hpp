// GGX (Trowbridge-Reitz), D(h) = a^2 / (pi cos^4 t (a^2 + tan^2 t)^2).
// Literature: Trowbridge and Reitz 1975; Walter, Marschner, Li and Torrance 2007, "Microfacet
// models for refraction through rough surfaces" (D and the rational Smith G1); Heitz 2014,
// "Understanding the masking-shadowing function in microfacet-based BRDFs" (Lambda).
// The non-projected integral, derived here: with w = sqrt(1 + tan^2 t) and b^2 = 1 - a^2,
//     integral of D dw = a^2 integral_1^inf 2 w^2 / (w^2 - b^2)^2 dw = 1 + a^2 atanh(b) / b,
// for a < 1; a^2 atan(c) / c with c^2 = a^2 - 1 for a > 1, and 2 at a = 1. Small a: 1 + a^2 ln(2/a);
// the heavy tail (D ~ a^2 / tan^4) makes it grow like (pi/2) a for wide lobes.
#pragma once
#include <boost/math/special_functions/atanh.hpp>
#include <cmath>

#include "ndf_row.hpp"

namespace normzoo::models {

struct ggx {
    static constexpr const char* id = "ggx";
    static constexpr const char* expression = "a^2 / (pi cos^4 t (a^2 + tan^2 t)^2)";
    static constexpr const char* non_projected_formula =
        "1 + a^2 atanh(b)/b, b = sqrt(1 - a^2) (a < 1); 1 + a^2 atan(c)/c, c = sqrt(a^2 - 1) (a > 1)";
    static constexpr const char* g1_formula = "2 / (1 + sqrt(1 + a^2 tan^2 t_v))";
    static constexpr const char* literature =
        "Trowbridge and Reitz 1975; Walter et al. 2007 (D, G1); Heitz 2014 (Lambda, weak white furnace)";

    // Also microfacet::d_ggx's D.
    template <class T>
    static T d(const vec3<T>& h, const T& alpha) {
        if (!(h.z() > 0)) return T(0);
        const T a2 = alpha * alpha, c2 = h.z() * h.z();
        const T k = a2 + tan2_of(h);
        return a2 / (pi<T>() * c2 * c2 * k * k);
    }
    // microfacet::detail::ggx_lambda is the same Lambda without the cancellation of sqrt(...) - 1
    // (another rounding): the tables hold each.
    template <class T>
    static T lambda(const T& cos_v, const T& sin_v, const T& alpha) {
        using std::sqrt;
        const T at = alpha * sin_v / cos_v;
        return (sqrt(1 + at * at) - 1) / 2;
    }
    template <class T>
    static T g1(const T& cos_v, const T& sin_v, const T& alpha) {
        using std::sqrt;
        const T at = alpha * sin_v / cos_v;
        return 2 / (1 + sqrt(1 + at * at));
    }
    template <class T>
    static T non_projected(const T& alpha) {
        using boost::math::atanh;
        using std::atan;
        using std::sqrt;
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
};

}  // namespace normzoo::models
