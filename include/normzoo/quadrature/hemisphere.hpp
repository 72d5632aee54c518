// 2D quadrature over the upper hemisphere of an integrand peaked about the normal N:
// the integral of g(omega) d(omega) with omega = direction(t, p), d(omega) = sin t dt dp.
// The polar angle goes through the lobe substitution of lobe.hpp (g is evaluated at the vector
// omega, never at the lobe variable), the azimuth through the periodic trapezoid rule, which is
// exact for trigonometric polynomials of degree below the number of azimuths.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <cmath>

#include "../geometry.hpp"
#include "estimate.hpp"
#include "lobe.hpp"

namespace normzoo::quadrature {

template <class Real>
class hemisphere_quadrature {
public:
    explicit hemisphere_quadrature(unsigned azimuths = 8) : azimuths_(azimuths < 2 ? 2 : azimuths & ~1u) {}

    // alpha, n: the lobe the integrand has about N (as in lobe.hpp), used only to place nodes.
    template <class G>
    estimate<Real> integrate(const G& g, const Real& alpha, const Real& n) const {
        using std::abs;
        using std::cos;
        using std::sin;
        const Real two_pi = boost::math::constants::two_pi<Real>();
        const Real half_pi = boost::math::constants::half_pi<Real>();
        Real fine = 0, coarse = 0, inner_error = 0;
        std::size_t calls = 0;
        for (unsigned j = 0; j < azimuths_; ++j) {
            const Real phi = two_pi * (Real(j) + Real(0.5)) / Real(azimuths_);
            const Real cp = cos(phi), sp = sin(phi);
            auto polar = [&](const lobe_point<Real>& p) -> Real {
                const Real t = p.t();
                const Real st = sin(t);
                const vec3<Real> omega(st * cp, st * sp, cos(t));
                return g(omega) * st;
            };
            const auto e = lobe_quadrature<Real>{}.integrate(polar, alpha, n, half_pi * alpha);
            fine += e.value;
            inner_error += e.abs_error;
            calls += e.evaluations;
            if (j % 2 == 0) coarse += e.value;
        }
        const Real w = two_pi / Real(azimuths_);
        estimate<Real> r;
        r.value = fine * w;
        r.abs_error = abs(fine * w - coarse * 2 * w) + inner_error * w;
        r.evaluations = calls;
        return r;
    }

private:
    unsigned azimuths_;
};

}  // namespace normzoo::quadrature
