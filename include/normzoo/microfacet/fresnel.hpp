// The Fresnel parts F(c) of a microfacet BRDF, c = V.H = L.H the cosine at the microfacet
// (docs/microfacet.md). Each is a small value type: its id (the F of a composition id
// D/G/F), its formula, its literature, and eval(c, p) in any real type.
//   one           1: the white furnace
//   schlick       F0 + (1 - F0) (1 - c)^5                Schlick 1994
//   schlick-f90   F0 + (F90 - F0) (1 - c)^5              Burley 2012; Lagarde and de Rousiers 2014
//   dielectric    the unpolarized Fresnel reflectance of a dielectric of relative index eta
//                 (total internal reflection gives 1)    Cook and Torrance 1982; Walter et al. 2007, eq. 22
//   conductor     the same for a conductor of complex index eta + i k, in real arithmetic
//                                                        Lagarde 2013, "Memo on Fresnel equations"
#pragma once
#include <array>
#include <cmath>
#include <limits>
#include <string_view>
#include <tuple>

#include "../detail/by_id.hpp"
#include "part_parameters.hpp"

namespace normzoo::microfacet {

// What the Fresnel parts read: Schlick's F0 and F90, or the indices of the interface.
template <class T>
struct fresnel_params {
    T f0 = T(0.04), f90 = T(1);
    T eta = T(1.5), k = T(0);
};

// F0 of a dielectric at normal incidence, ((eta - 1) / (eta + 1))^2.
template <class T>
T f0_of_eta(const T& eta) {
    const T r = (eta - 1) / (eta + 1);
    return r * r;
}

namespace detail {
template <class T>
T pow5(const T& x) {
    const T x2 = x * x;
    return x2 * x2 * x;
}
}  // namespace detail

struct fresnel_one {
    static constexpr std::string_view id = "one";
    static constexpr auto parameters = no_parameters;  // what it reads (composition::reads)
    static constexpr const char* formula = "1";
    static constexpr const char* literature = "the white furnace (docs/conventions.md)";
    template <class T>
    static T eval(const T& /*c*/, const fresnel_params<T>& /*p*/) { return T(1); }
};

struct fresnel_schlick {
    static constexpr std::string_view id = "schlick";
    static constexpr auto parameters = std::array<parameter, 1>{f0_parameter};
    static constexpr const char* formula = "F0 + (1 - F0) (1 - c)^5";
    static constexpr const char* literature = "Schlick 1994";
    template <class T>
    static T eval(const T& c, const fresnel_params<T>& p) { return p.f0 + (1 - p.f0) * detail::pow5(1 - c); }
};

struct fresnel_schlick_f90 {
    static constexpr std::string_view id = "schlick-f90";
    static constexpr auto parameters = std::array<parameter, 2>{f0_parameter, f90_parameter};
    static constexpr const char* formula = "F0 + (F90 - F0) (1 - c)^5";
    static constexpr const char* literature = "Burley 2012; Lagarde and de Rousiers 2014";
    template <class T>
    static T eval(const T& c, const fresnel_params<T>& p) { return p.f0 + (p.f90 - p.f0) * detail::pow5(1 - c); }
};

struct fresnel_dielectric {
    static constexpr std::string_view id = "dielectric";
    static constexpr auto parameters = std::array<parameter, 2>{f0_parameter, eta_parameter};  // f0 or eta: the index from F0
    static constexpr const char* formula =
        "1/2 ((g - c)/(g + c))^2 (1 + ((c (g + c) - 1)/(c (g - c) + 1))^2), g^2 = eta^2 - 1 + c^2";
    static constexpr const char* literature = "Cook and Torrance 1982; Walter et al. 2007, eq. 22";
    template <class T>
    static T eval(const T& c_in, const fresnel_params<T>& p) {
        using std::abs;
        using std::sqrt;
        const T c = abs(c_in);
        if (!(p.eta < std::numeric_limits<T>::infinity())) return T(1);  // F0 = 1: the limit eta -> inf
        const T g2 = p.eta * p.eta - 1 + c * c;
        if (g2 < 0) return T(1);  // total internal reflection
        const T g = sqrt(g2);
        const T a = (g - c) / (g + c);
        const T b = (c * (g + c) - 1) / (c * (g - c) + 1);
        return a * a * (1 + b * b) / 2;
    }
};

struct fresnel_conductor {
    static constexpr std::string_view id = "conductor";
    static constexpr auto parameters = std::array<parameter, 3>{f0_parameter, eta_parameter, k_parameter};
    static constexpr const char* formula = "(R_s + R_p) / 2 for the complex index eta + i k";
    static constexpr const char* literature = "Lagarde 2013, \"Memo on Fresnel equations\"";
    template <class T>
    static T eval(const T& c_in, const fresnel_params<T>& p) {
        using std::abs;
        using std::sqrt;
        const T c = abs(c_in), c2 = c * c, s2 = 1 - c2;
        if (!(p.eta < std::numeric_limits<T>::infinity())) return T(1);  // F0 = 1: the limit eta -> inf
        const T eta2 = p.eta * p.eta, k2 = p.k * p.k;
        const T t0 = eta2 - k2 - s2;
        const T a2b2 = sqrt(t0 * t0 + 4 * eta2 * k2);  // a^2 + b^2
        // a^2 = (a^2 + b^2 + t0) / 2, which cancels where t0 < 0 (eta < 1 beyond the critical
        // angle, k small): there 2 eta^2 k^2 / (a^2 + b^2 - t0), the same since their product is
        // 4 eta^2 k^2. (With k = 0, sqrt(t0^2) can round below -t0: the sum was negative and a NaN.)
        const T a = sqrt(t0 >= 0 ? (a2b2 + t0) / 2 : 2 * eta2 * k2 / (a2b2 - t0));
        const T t1 = a2b2 + c2, t2 = 2 * c * a;
        const T rs = (t1 - t2) / (t1 + t2);
        const T t3 = c2 * a2b2 + s2 * s2, t4 = t2 * s2;
        const T rp = rs * (t3 - t4) / (t3 + t4);
        return (rs + rp) / 2;
    }
};

// The Fresnel parts, one list: a composition id's F is one of these ids.
using fresnel_parts = std::tuple<fresnel_one, fresnel_schlick, fresnel_schlick_f90, fresnel_dielectric, fresnel_conductor>;

// Calls fn(part) with the part named `id`; false when there is none.
template <class Fn>
bool with_fresnel(std::string_view id, Fn&& fn) {
    return normzoo::detail::with_id<fresnel_parts>(id, fn);
}

}  // namespace normzoo::microfacet
