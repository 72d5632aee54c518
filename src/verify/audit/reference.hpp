// The error audit's reference values ("truths"): closed forms in more precision than the value
// checked (docs/error-audit.md, "What is drawn"). The zoo's formulas in 50 digits; for the
// lights, pi sin^2 b cos t_c above the horizon and Snyder's formula in its original form (as
// written by Lagarde and de Rousiers, with the cancellation the library's rewritten form avoids)
// in 100 digits across it; for the albedos, closed forms derived here in u = (N.H)^2,
// independently of brdf/*.hpp's.
//
// Apart from the tables (tables/tables.hpp) because the 100-digit type costs compile time.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <limits>
#include <string>

#include <normzoo/irradiance.hpp>
#include <normzoo/real.hpp>
#include <normzoo/wide.hpp>

#include "../library_names.hpp"

namespace verify {

// 100 decimal digits: the reference for the lights, whose original closed form cancels.
using audit_reference = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<100>,
                                                      boost::multiprecision::et_off>;

namespace detail {

// E / L for a cap of half-angle b (sin b and cot b given) tilted by t_c: the closed forms in
// their original, unrewritten shape. Above the horizon pi sin^2 b cos t_c; across it
//     x = cot b, y = -x cot t_c, w = sin t_c sqrt(1 - y^2),
//     E / L = (cos t_c acos y - x w) sin^2 b + atan(w / x).
inline audit_reference audit_cap_truth(const audit_reference& sin_b, const audit_reference& cot_b, double tilt_deg) {
    using std::acos;
    using std::atan;
    using std::cos;
    using std::sin;
    using std::sqrt;
    const audit_reference pi = boost::math::constants::pi<audit_reference>();
    const audit_reference t = audit_reference(tilt_deg) * pi / 180;
    const audit_reference ct = cos(t), st = sin(t), s2 = sin_b * sin_b;
    if (ct >= sin_b) return pi * s2 * ct;
    if (ct <= -sin_b) return audit_reference(0);
    const audit_reference y = -cot_b * ct / st;
    const audit_reference w = st * sqrt(1 - y * y);
    return (ct * acos(y) - cot_b * w) * s2 + atan(w / cot_b);
}

// The albedo at L = N in closed form, derived in u = (N.H)^2: there N.H = L.H = cos(t_v / 2),
// N.V = 2u - 1 and sin t_v dt_v = 2 du, so a form K (N.H)^(2a) has
//     rho = 4 pi K G(a),   G(a) = integral over u in [1/2, 1] of u^a (2u - 1) du
//         = 2 (1 - 2^-(a+2)) / (a+2) - (1 - 2^-(a+1)) / (a+1).
// A mirror lobe at L = N is (N.V)^n: rho = 2 pi K / (n + 2).
inline wide audit_one_minus_two_power_over(const wide& b) {  // (1 - 2^-b) / b, ln 2 at b = 0
    using std::expm1;
    using std::log;
    const wide ln2 = log(wide(2));
    return b == 0 ? ln2 : wide(-expm1(-b * ln2) / b);
}
inline wide audit_albedo_truth(const std::string& form, const wide& n) {
    using std::pow;
    const wide pi = boost::math::constants::pi<wide>();
    auto g = [](const wide& a) { return 2 * audit_one_minus_two_power_over(a + 2) - audit_one_minus_two_power_over(a + 1); };
    if (form == "lambert" || form == "phong-modified") return wide(1);
    if (form == "phong") return (n + 1) / (n + 2);
    if (form == "blinn-phong") return (n + 2) / (2 - pow(wide(2), -n / 2)) * g(n / 2);  // K = (n+2) / (4 pi (2 - 2^(-n/2)))
    if (form == "blinn-phong-modified")
        return 4 * pi * ((n + 2) * (n + 4) / (8 * pi * (pow(wide(2), -n / 2) + n))) * g(n / 2);
    if (form == "blinn-phong-modified-approx") return (n + 8) / 2 * g(n / 2);
    if (form == "microfacet-blinn") return (n + 2) / 2 * g(n / 2);          // F(1, x) = 1
    if (form == "minimalist-cook-torrance") return (n + 1) / 2 * g((n - 3) / 2);  // c^n / c^3
    if (form == "cook-torrance-ksk") return (n + 2) * 4 / 8 * g((n - 2) / 2);     // (n+2)/(2 pi) c^n / (4 c^2)
    return wide(std::numeric_limits<double>::quiet_NaN());
}

}  // namespace detail

// A zoo row's normalization at exponent n: the row's own closed form in 50 digits.
template <class Row>
wide audit_zoo_truth(double n) {
    return Row::closed_form(wide(n));
}

// E / L of a light at r0/r = ratio whose centre is tilt_deg from N, in 100 digits.
inline audit_reference audit_light_truth(light_kind kind, double ratio, double tilt_deg) {
    using std::sqrt;
    const audit_reference r(ratio);
    // sphere: sin b = r0/r; disk facing the receiver: tan b = r0/r
    const audit_reference sin_b = kind == light_kind::sphere ? r : r / sqrt(1 + r * r);
    const audit_reference cot_b = kind == light_kind::sphere ? sqrt((1 - r) * (1 + r)) / r : 1 / r;
    return detail::audit_cap_truth(sin_b, cot_b, tilt_deg);
}

}  // namespace verify
