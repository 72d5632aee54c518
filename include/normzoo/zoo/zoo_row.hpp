// What every row of the normalization zoo (docs/conventions.md, "The zoo rows") has, and the generic pieces they share.
//
// A row is a small value type with:
//   id, expression, integrand, normalization, literature  (strings for tables and docs)
//   parameters      what it reads, declared as every model declares them (parameter.hpp): the
//                   exponent n, or none (Lambert); has_exponent says the same for the integrators
//   lobe_alpha      theta = alpha t is the lobe angle: cos^n(theta) is the row's peak at t = 0
//   rdf(omega, V, n)    the zoo's expression from vectors, omega the integration direction
//                       (L, or h for the NDF rows), evaluated with V = N
//   weight(c, s)    the reduced 1D integrand is cos^n(theta) * weight(cos theta, sin theta)
//   closed_form(n)  the normalization, 1 / (integral of rdf over the hemisphere)
#pragma once
#include <boost/math/constants/constants.hpp>
#include <cmath>

#include "../geometry.hpp"
#include "../parameter.hpp"

namespace normzoo {

namespace zoo {
// The zoo's one parameter: the exponent n of the lobe (docs/conventions.md, "The zoo rows").
inline constexpr std::array<parameter, 1> exponent_only{parameter{"n", "the lobe exponent", 0, 1e9, {}, 0}};
}  // namespace zoo

// The reduced 1D integrand of a row in t, as the zoo writes it (e.g. cos^n(t/2) sin t).
// The power is taken from 1 - cos(theta) = 2 sin^2(theta/2), never as pow(cos, n).
template <class Row, class T>
T reduced_integrand(const T& t, const T& n) {
    using std::cos;
    using std::sin;
    const T theta = T(Row::lobe_alpha) * t;
    const T half = sin(theta / 2);
    return pow_cosine(T(2) * half * half, Row::has_exponent ? n : T(0)) * Row::weight(cos(theta), sin(theta));
}

}  // namespace normzoo
