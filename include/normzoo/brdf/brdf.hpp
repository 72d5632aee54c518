// What every BRDF form of SPEC section 3 has, and the pieces they share.
//
// A form is a small value type with:
//   id, formula, literature   strings for tables and docs
//   has_exponent, has_specular, reciprocal (Helmholtz: f(L, V) = f(V, L))
//   lobe      where its peak lies, so the albedo integral can centre its coordinates there:
//             normal (none: around N), mirror ((R.V)^n around R), half ((N.H)^n, over H)
//   inverse_lh_power, fresnel   how f depends on L.H (a factor 1/(L.H)^k, a Schlick term): the
//             albedo integral sizes its rounding error from them near grazing incidence
//   zoo_row   the zoo row (SPEC section 2) whose normalization the form's constant comes from
//   constant(n), exact_constant(n)   the factor in front of the lobe, and the exact one (they
//             differ for blinn-phong-modified-approx only); a shader's own expression replaces
//             constant(n), and the albedo scales with it
//   f(L, V, p)              the BRDF from unit vectors, p = {n, specular}
//   albedo_at_normal(n)     the directional albedo at L = N for specular = 1, in closed form
//                           (derived by hand, for the tables' cross-check and the tests)
#pragma once
#include <cmath>

#include "../geometry.hpp"
#include "../models/zoo_row.hpp"

namespace normzoo::brdf {

using normzoo::pi;

enum class lobe_kind { normal, mirror, half };

template <class T>
struct params {
    T n = 0;         // the exponent
    T specular = 1;  // c_spec or k_s where the form has one
    T roughness = 0; // alpha (Ward) or the Disney roughness r, for the forms indexed by one (brdf/modern.hpp)
};

// Schlick's approximation, F(c, x) = c + (1 - c)(1 - x)^5, x = L.H.
template <class T>
T fresnel_schlick(const T& c, const T& x) {
    const T m = 1 - x;
    const T m2 = m * m;
    return c + (1 - c) * m2 * m2 * m;
}

namespace detail {

// P(k) = integral of c^k over c in [1/sqrt 2, 1] = (1 - 2^(-(k+1)/2)) / (k+1); ln(2)/2 at k = -1.
template <class T>
T half_power_moment(const T& k) {
    using std::expm1;
    using std::log;
    const T ln2 = log(T(2));
    if (k + 1 == 0) return ln2 / 2;
    return -expm1(-(k + 1) * ln2 / 2) / (k + 1);
}

// At L = N: V is the mirror of N about H, N.V = 2c^2 - 1 with c = N.H = L.H, H runs over
// theta_h < 45 degrees, and d(omega_V) = 4 c d(omega_H). A form g(c) c^m then has albedo
//     2 pi * 4 * integral of g c^m (2c^2 - 1) c dc = 8 pi J(m + 1),   J(j) = 2 P(j+2) - P(j).
template <class T>
T half_vector_albedo_moment(const T& m) {
    return 8 * pi<T>() * (2 * half_power_moment(m + 3) - half_power_moment(m + 1));
}

}  // namespace detail

}  // namespace normzoo::brdf
