// Integrals of a microfacet NDF (a D part of microfacet/distribution.hpp) by quadrature, each a value
// with its error bound, in long double over the polar angle of h in the log-slope variable of
// quadrature/slope.hpp:
//   ndf_integral<Ndf>(alpha, k)            integral of D(h) (N.h)^k over the hemisphere: k = 1 is
//                                          the projected normalization (1), k = 0 the plain one
//   visible_projected_area<Ndf>(alpha, t)  integral of D(h) max(V.h, 0) over h, V at polar angle t;
//                                          by the masking equation (Heitz 2014) it is N.V / G1(V)
// and the Phong-Beckmann mapping n = 2/alpha^2 - 2 (Walter et al. 2007). docs/models.md derives
// the azimuth of the masking integral in closed form.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <vector>

#include "geometry.hpp"
#include "microfacet/distribution.hpp"
#include "quadrature/estimate.hpp"
#include "quadrature/slope.hpp"
#include "real.hpp"

namespace normzoo {

// The Phong-Beckmann mapping (Walter et al. 2007): alpha_p = 2/alpha^2 - 2, alpha = sqrt(2/(n+2)).
inline double beckmann_alpha_of_exponent(double n) { return std::sqrt(2 / (n + 2)); }
inline double exponent_of_beckmann_alpha(double alpha) { return 2 / (alpha * alpha) - 2; }

namespace detail {

using ndf_real = long double;

template <class Ndf>
ndf_real ndf_at(const quadrature::slope_point<ndf_real>& p, ndf_real alpha) {
    return Ndf::d(vec3<ndf_real>(p.sin_t, 0, p.cos_t), microfacet::ndf_params<ndf_real>{alpha, alpha});
}

// An estimate of the integral and whether it may be compared: finite bound.
inline bool usable(const quadrature::estimate<ndf_real>& e) { return std::isfinite(static_cast<double>(e.abs_error)); }

}  // namespace detail

// Integral over the hemisphere of D(h) (N.h)^k, k = 1 (projected) or 0, 2 pi from the azimuth.
template <class Ndf>
quadrature::estimate<long double> ndf_integral(double alpha_in, int cos_power) {
    using R = detail::ndf_real;
    const R alpha = alpha_in, two_pi = boost::math::constants::two_pi<R>();
    auto f = [&](const quadrature::slope_point<R>& p) {
        const R w = cos_power == 1 ? p.cos_t : R(1);
        return detail::ndf_at<Ndf>(p, alpha) * w * p.sin_t;
    };
    auto e = quadrature::slope_integral<R>(f, alpha);
    e.value *= two_pi;
    e.abs_error *= two_pi;
    return e;
}

// Integral over h of D(h) max(V.h, 0), V at polar angle t_v (degrees), azimuth in closed form.
template <class Ndf>
quadrature::estimate<long double> visible_projected_area(double alpha_in, double theta_v_deg) {
    using R = detail::ndf_real;
    const R alpha = alpha_in;
    const degrees_angle<R> v(theta_v_deg);
    const R two_pi = boost::math::constants::two_pi<R>();
    auto f = [&](const quadrature::slope_point<R>& p) {
        using std::atan2;
        using std::sqrt;
        const R a = p.sin_t * v.sin_t, b = p.cos_t * v.cos_t;
        R azimuth = two_pi * b;
        if (a > b) {
            const R s = sqrt((a - b) * (a + b));  // a sin p0
            azimuth = 2 * (b * atan2(s, -b) + s);
        }
        return detail::ndf_at<Ndf>(p, alpha) * azimuth * p.sin_t;
    };
    // the kink at t = 90 deg - t_v: tan t = cot t_v
    std::vector<R> kinks;
    if (v.sin_t > 0) kinks.push_back(v.cos_t / v.sin_t);
    return quadrature::slope_integral<R>(f, alpha, kinks);
}

}  // namespace normzoo
