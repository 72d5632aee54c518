// What every normal distribution part D(m) of a microfacet BRDF has (docs/microfacet.md): each a
// small value type in a header of its own (d_ID.hpp, listed in distribution.hpp) with its id (the
// D of a composition id D/G/F), its formula, its literature, its declared parameters, and
//   d(m, p)          D of the unit microfacet normal m, in the frame N = z, tangent x, bitangent y
//   lambda(w, p)     Smith's Lambda for the direction w, where it has a closed form
//                    (has_exact_lambda); G1(w) = 1 / (1 + Lambda(w))
// p = ndf_params{alpha_x, alpha_y, gamma}: the roughness of Walter et al. 2007 (alpha_x =
// alpha_y for the isotropic parts, which read alpha_x), and GTR's exponent gamma.
//   polar(psi, p)    (has_polar_map) the polar angle t of m, as (cos t, sin t), below which
//                    D(m) N.m holds the mass sin^2 psi; theta_to_psi(t, p) its inverse. In psi
//                    the projected distribution is flat (the inverse CDF of the importance
//                    samplers of Walter et al. 2007): microfacet/albedo.hpp integrates in it.
//   azimuthal_integral(a, p)  (has_azimuthal_integral) the integral of D(h) over L's azimuth,
//                    h the half vector of L and V, at one polar angle of L (an azimuth_point),
//                    with a bound on its rounding (an azimuthal_value): the albedo with F = 1 is
//                    then a 1D integral (microfacet/azimuthal_albedo.hpp). GGX and Beckmann.
//   azimuthal_schlick_integral(a, p)  (has_azimuthal_schlick_integral) the same of D(h) (1 - V.h)^5,
//                    Schlick's factor, and its rounding bound: the albedo with Schlick's F is then
//                    the same 1D integral (microfacet/ggx_schlick_azimuth.hpp). GGX.
//   parameters       what it reads beyond alpha, declared (part_parameters.hpp)
//   isotropic, has_exact_lambda, has_polar_map, has_azimuthal_integral, has_azimuthal_schlick_integral,
//   has_non_projected   which of these it has
//   non_projected(alpha)  (has_non_projected) the integral of D over the hemisphere not weighted
//                    by N.m, in closed form (the projected one is 1 by design): with its formula and
//                    Smith's G1 as text, these parts are the rows of the ndf tables (docs/models.md).
#pragma once
#include <cmath>
#include <limits>
#include <string_view>
#include <type_traits>

#include "../geometry.hpp"
#include "../parameter.hpp"
#include "part_parameters.hpp"

namespace normzoo::microfacet {

template <class T>
struct ndf_params {
    T alpha_x = T(0.5), alpha_y = T(0.5);
    T gamma = T(2);  // GTR only
};

// A polar angle of L for V fixed, as D's integral over L's azimuth reads it: cos t_L and
// cos t_V, their difference (exact where they are close: the peak of D sits there) and the
// squares of their sines, each from the variable it is integrated in (microfacet/azimuthal_albedo.hpp).
template <class T>
struct azimuth_point {
    T nl, nv;          // cos t_L, cos t_V
    T nl_minus_nv;     // cos t_L - cos t_V
    T sl2, sv2;        // sin^2 t_L, sin^2 t_V
};

// D's integral over L's azimuth and a bound on its rounding error.
template <class T>
struct azimuthal_value {
    T value, error;
};

namespace detail {
using normzoo::pi;
// e^x where x <= 0: in double, 0 without calling the library below x = -746, where its result
// rounds to 0 anyway and it takes its underflow path (errno; 2x to 3x the time of a normal call,
// where Beckmann's tails spend a fifth of their time).
template <class T>
T exp_nonpositive(const T& x) {
    using std::exp;
    if constexpr (std::is_same_v<T, double>)
        if (x < -746) return T(0);
    return exp(x);
}
template <class T>
T tan2(const vec3<T>& m) { return tan2_of(m); }
// The roughness seen along w's azimuth: sqrt(cos^2 p ax^2 + sin^2 p ay^2), from w's components.
template <class T>
T projected_alpha(const vec3<T>& w, const ndf_params<T>& p) {
    using std::sqrt;
    const T r2 = w.x() * w.x() + w.y() * w.y();
    if (!(r2 > 0)) return p.alpha_x;
    return sqrt((w.x() * w.x() * p.alpha_x * p.alpha_x + w.y() * w.y() * p.alpha_y * p.alpha_y) / r2);
}
}  // namespace detail

// Smith's masking G1(w) = 1 / (1 + Lambda(w)) of a part with has_exact_lambda (Heitz 2014).
template <class D, class T>
T smith_g1(const vec3<T>& w, const ndf_params<T>& p) {
    return 1 / (1 + D::lambda(w, p));
}

}  // namespace normzoo::microfacet
