// A zoo row's normalization by quadrature, each a value with its relative error bound:
//   zoo_norm_1d  the reduced 1D integrand of the row in the lobe quadrature (binary128 by default)
//   zoo_norm_2d  the row's vector expression over the hemisphere (long double by default)
// The closed forms beside them are the rows' own (zoo/*.hpp); docs/method.md says how the
// error bounds are made. n may be a decimal (exactly as typed: the bound then covers n's rounding
// to Real), a number in Real, or a double (the number the double holds).
#pragma once
#include <boost/math/constants/constants.hpp>
#include <cstddef>
#include <string_view>
#include <type_traits>

#include "decimal.hpp"
#include "geometry.hpp"
#include "quadrature/hemisphere.hpp"
#include "quadrature/lobe.hpp"
#include "real.hpp"

namespace normzoo {

// Trapezoid nodes in the azimuth of the 2D integral (with V = N any count is exact).
inline constexpr unsigned default_zoo_azimuths = 4;

template <class Real>
struct normalization_estimate {
    Real norm;       // 1 / integral over the hemisphere
    Real rel_error;  // bound on |norm - truth| / truth
    std::size_t evaluations;
};

namespace detail {
// 1/I from I with a relative bound e: the reciprocal's relative bound is e / (1 - e).
template <class Real>
normalization_estimate<Real> reciprocal(const quadrature::estimate<Real>& e) {
    using std::abs;
    const Real rel = abs(e.abs_error / e.value);
    return {1 / e.value, rel < 1 ? rel / (1 - rel) : Real(1), e.evaluations};
}
template <class Row, class Real>
Real exponent_of(const Real& n) { return Row::has_exponent ? n : Real(0); }
template <class T>
struct identity { using type = T; };
template <class T>
using exactly_t = typename identity<T>::type;  // a parameter of this type is not deduced
}  // namespace detail

// 1 / (2 pi (the azimuth) x the integral of f(p) over the row's lobe), f a function of the lobe
// point p of lobe.hpp: the row's reduced integrand, or another way of writing it.
template <class Row, class Real, class F>
normalization_estimate<Real> zoo_norm_1d_of(const detail::exactly_t<Real>& n_in, const F& f) {
    const Real n = detail::exponent_of<Row>(n_in);
    const Real alpha = Row::lobe_alpha;
    auto e = quadrature::lobe_quadrature<Real>{}.integrate(f, alpha, n, alpha * boost::math::constants::half_pi<Real>());
    e.value *= boost::math::constants::two_pi<Real>();
    e.abs_error *= boost::math::constants::two_pi<Real>();
    return detail::reciprocal(e);
}

// The reduced 1D integrand, in the Laplace variable of lobe.hpp, at the exponent n itself (a
// double is taken as the number it holds: 0.37 as 0.36999999999999999555...).
template <class Row, class Real = quad>
normalization_estimate<Real> zoo_norm_1d(const detail::exactly_t<Real>& n) {
    return zoo_norm_1d_of<Row, Real>(n, [](const auto& p) { return p.power * Row::weight(p.cos_theta, p.sin_theta); });
}

// The vector expression with V = N, integrated over its direction on the hemisphere, at n itself.
template <class Row, class Real = longd>
normalization_estimate<Real> zoo_norm_2d(const detail::exactly_t<Real>& n_in, unsigned azimuths = default_zoo_azimuths) {
    const Real n = detail::exponent_of<Row>(n_in);
    const vec3<Real> v = normal<Real>();
    auto g = [&](const vec3<Real>& omega) { return Row::rdf(omega, v, n); };
    return detail::reciprocal(quadrature::hemisphere_quadrature<Real>(azimuths).integrate(g, Real(Row::lobe_alpha), n));
}

namespace detail {
// |dN/dn| n / N, the normalization's sensitivity to a relative change of n, measured from the 1D
// quadrature over a relative step of 1e-12 (its error, ~1e-33, then moves the slope by ~1e-21;
// doubled for the curvature over the step). For the input's rounding: docs/method.md, "Inputs".
template <class Row>
double normalization_elasticity(const quad& n, const normalization_estimate<quad>& at_n) {
    using std::abs;
    if (!Row::has_exponent || n == 0) return 0;
    const quad h = quad(1e-12);
    const auto moved = zoo_norm_1d<Row, quad>(n * (1 + h));
    const quad slope = (abs(moved.norm - at_n.norm) + (moved.rel_error * abs(moved.norm) + at_n.rel_error * abs(at_n.norm))) /
                       (h * abs(at_n.norm));
    return 2 * static_cast<double>(slope);
}
}  // namespace detail

namespace detail {
// A normalization e computed at the decimal n rounded to Real, its bound widened by the
// normalization's change across that rounding (none when Real holds n exactly).
template <class Row, class Real>
normalization_estimate<Real> with_input_rounding(normalization_estimate<Real> e, const decimal& n) {
    if (const double r = n.rounding<Real>(); Row::has_exponent && r > 0) {
        const quad nq = n.to<quad>();
        double slope = 0;
        if constexpr (std::is_same_v<Real, quad>) slope = normalization_elasticity<Row>(nq, e);  // e is at nq
        else slope = normalization_elasticity<Row>(nq, zoo_norm_1d<Row, quad>(nq));
        e.rel_error += Real(slope * r);
    }
    return e;
}
}  // namespace detail

// At the decimal n as typed: the quadrature at n rounded to Real, its bound covering that rounding.
template <class Row, class Real = quad>
normalization_estimate<Real> zoo_norm_1d(const decimal& n) {
    return detail::with_input_rounding<Row>(zoo_norm_1d<Row, Real>(n.to<Real>()), n);
}
template <class Row, class Real = longd>
normalization_estimate<Real> zoo_norm_2d(const decimal& n, unsigned azimuths = default_zoo_azimuths) {
    return detail::with_input_rounding<Row>(zoo_norm_2d<Row, Real>(n.to<Real>(), azimuths), n);
}
// A number as text ("0.37"): the decimal it denotes.
template <class Row, class Real = quad>
normalization_estimate<Real> zoo_norm_1d(std::string_view n) { return zoo_norm_1d<Row, Real>(decimal(n)); }
template <class Row, class Real = longd>
normalization_estimate<Real> zoo_norm_2d(std::string_view n, unsigned azimuths = default_zoo_azimuths) {
    return zoo_norm_2d<Row, Real>(decimal(n), azimuths);
}

}  // namespace normzoo
