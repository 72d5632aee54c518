// A zoo row's normalization by quadrature, each a value with its relative error bound:
//   zoo_norm_1d  the reduced 1D integrand of the row in the lobe quadrature (binary128 by default)
//   zoo_norm_2d  the row's vector expression over the hemisphere (long double by default)
// The closed forms beside them are the rows' own (models/*.hpp); docs/method.md says how the
// error bounds are made.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <cstddef>

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
template <class Row>
double exponent_of(double n) { return Row::has_exponent ? n : 0.0; }
}  // namespace detail

// 1 / (2 pi (the azimuth) x the integral of f(p) over the row's lobe), f a function of the lobe
// point p of lobe.hpp: the row's reduced integrand, or another way of writing it.
template <class Row, class Real, class F>
normalization_estimate<Real> zoo_norm_1d_of(double n_in, const F& f) {
    const Real n = detail::exponent_of<Row>(n_in);
    const Real alpha = Row::lobe_alpha;
    auto e = quadrature::lobe_quadrature<Real>{}.integrate(f, alpha, n, alpha * boost::math::constants::half_pi<Real>());
    e.value *= boost::math::constants::two_pi<Real>();
    e.abs_error *= boost::math::constants::two_pi<Real>();
    return detail::reciprocal(e);
}

// The reduced 1D integrand, in the Laplace variable of lobe.hpp.
template <class Row, class Real = quad>
normalization_estimate<Real> zoo_norm_1d(double n_in) {
    return zoo_norm_1d_of<Row, Real>(n_in, [](const auto& p) { return p.power * Row::weight(p.cos_theta, p.sin_theta); });
}

// The vector expression with V = N, integrated over its direction on the hemisphere.
template <class Row, class Real = longd>
normalization_estimate<Real> zoo_norm_2d(double n_in, unsigned azimuths = default_zoo_azimuths) {
    const Real n = detail::exponent_of<Row>(n_in);
    const vec3<Real> v = normal<Real>();
    auto g = [&](const vec3<Real>& omega) { return Row::rdf(omega, v, n); };
    return detail::reciprocal(quadrature::hemisphere_quadrature<Real>(azimuths).integrate(g, Real(Row::lobe_alpha), n));
}

}  // namespace normzoo
