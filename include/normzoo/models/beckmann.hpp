// Beckmann's distribution of microfacet normals, D(h) = exp(-tan^2 t / a^2) / (pi a^2 cos^4 t).
// Literature: Beckmann and Spizzichino 1963; its Smith masking (erf form) as in Walter, Marschner,
// Li and Torrance 2007, "Microfacet models for refraction through rough surfaces", and Heitz
// 2014, "Understanding the masking-shadowing function in microfacet-based BRDFs".
// The non-projected integral is derived here (no published closed form found; Reed 2013, "How
// Is the NDF Really Defined?", gives "about 1.113" at a = 0.5, which it reproduces): with u = tan^2 t,
//     integral of D dw = (1/a^2) integral_0^inf e^(-u/a^2) sqrt(1 + u) du
//                      = a e^(1/a^2) Gamma(3/2, 1/a^2) = 1 + (sqrt(pi)/2) a e^(1/a^2) erfc(1/a),
// 1 + a^2/2 + O(a^4) for small a.
#pragma once
#include <boost/math/special_functions/erf.hpp>
#include <cmath>

#include "ndf_row.hpp"

namespace normzoo::models {

struct beckmann {
    static constexpr const char* id = "beckmann";
    static constexpr const char* expression = "exp(-tan^2 t / a^2) / (pi a^2 cos^4 t)";
    static constexpr const char* non_projected_formula = "1 + (sqrt(pi)/2) a e^(1/a^2) erfc(1/a)";
    static constexpr const char* g1_formula = "2 / (1 + erf(m) + e^(-m^2) / (m sqrt(pi))), m = 1 / (a tan t_v)";
    static constexpr const char* literature =
        "Beckmann and Spizzichino 1963; Walter et al. 2007 (Smith G1); Heitz 2014 (Lambda, weak white furnace)";

    // microfacet::d_beckmann's D rounds pi a^2 cos^4 t in another order: the tables hold each.
    template <class T>
    static T d(const vec3<T>& h, const T& alpha) {
        using std::exp;
        if (!(h.z() > 0)) return T(0);
        const T c2 = h.z() * h.z();
        return exp(-tan2_of(h) / (alpha * alpha)) / (pi<T>() * alpha * alpha * c2 * c2);
    }
    // Lambda(m) = (e^(-m^2) / (m sqrt(pi)) - erfc(m)) / 2, m = cot(t_v) / a (Heitz 2014).
    // microfacet::detail::beckmann_lambda takes m from w's components and, in double, an erfc not
    // promoted to long double: another rounding, and the tables hold each.
    template <class T>
    static T lambda(const T& cos_v, const T& sin_v, const T& alpha) {
        using boost::math::erfc;
        using std::exp;
        using std::sqrt;
        if (!(sin_v > 0)) return T(0);
        const T m = cos_v / (sin_v * alpha);
        return (exp(-m * m) / (m * sqrt(pi<T>())) - erfc(m)) / 2;
    }
    template <class T>
    static T g1(const T& cos_v, const T& sin_v, const T& alpha) {
        using boost::math::erf;
        using std::exp;
        using std::sqrt;
        if (!(sin_v > 0)) return T(1);
        const T m = cos_v / (sin_v * alpha);
        return 2 / (1 + erf(m) + exp(-m * m) / (m * sqrt(pi<T>())));
    }
    // Wants a type with a wide exponent range (wide): e^(1/a^2) overflows double below a = 0.04.
    template <class T>
    static T non_projected(const T& alpha) {
        using boost::math::erfc;
        using std::exp;
        using std::sqrt;
        return 1 + sqrt(pi<T>()) / 2 * alpha * exp(1 / (alpha * alpha)) * erfc(1 / alpha);
    }
};

}  // namespace normzoo::models
