// 1D quadrature over the polar angle t in [0, pi/2) of an integrand with a lobe of width ~a
// about t = 0 that may decay only like a power of tan t (GGX: D ~ a^2 / tan^4 t).
//
// Why not lobe.hpp: its Laplace variable assumes the integrand falls like e^-x in x = k (-ln cos t),
// true for cos^n lobes, false for rational tails, which it would cut with a wrong tail bound. Here
// the variable is the log-slope
//     u = ln(tan t / a),   dt/du = sin t cos t,
// in which the lobe is O(1) wide whatever a is (1e-4 or 10), a power-law tail tan^-p t becomes
// e^(-p u) (geometric, like any lobe in its own variable), and a Gaussian in tan t falls off
// super-exponentially. cos t = 1/hypot(1, tan t) and sin t = tan t cos t from tan t = a e^u: no
// cancellation at either end.
//
// The range u in [-u_far, u_far] is cut into panels <= 2 wide (and at caller-given kinks) for the
// adaptive Gauss-Kronrod of adaptive.hpp. Beyond each end the integrand is bounded by its value at
// the cut times the decay length measured over the last unit, doubled (it must be decaying there;
// else the bound is infinite and the caller sees it).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "adaptive.hpp"
#include "estimate.hpp"

namespace normzoo::quadrature {

template <class Real>
struct slope_point {
    Real tan_t, cos_t, sin_t;
};

template <class Real>
slope_point<Real> slope_point_at(const Real& alpha, const Real& u) {
    using std::exp;
    using std::hypot;
    const Real t = alpha * exp(u);
    const Real c = 1 / hypot(Real(1), t);
    return {t, c, t * c};
}

template <class Real>
struct slope_settings {
    Real u_far = 50;  // the lobe's tails are cut at tan t = a e^(+-50)
    Real tolerance = 64 * std::numeric_limits<Real>::epsilon();  // relative, for the adaptive rule
    std::size_t max_panels = 2000;
};

// Integral over t in [0, pi/2) of f(p) dt, p a slope_point; kinks: angles t (radians) where f
// has a kink, as tan t (any order; those outside the range are ignored).
template <class Real, class F>
estimate<Real> slope_integral(const F& f, const Real& alpha, const std::vector<Real>& kink_tans = {},
                              const slope_settings<Real>& s = {}) {
    using std::abs;
    using std::ceil;
    using std::log;
    auto g = [&](const Real& u) {
        const auto p = slope_point_at(alpha, u);
        return f(p) * p.sin_t * p.cos_t;
    };
    std::vector<Real> breaks;
    const int panels = static_cast<int>(ceil(static_cast<double>(2 * s.u_far) / 2));
    for (int i = 0; i <= panels; ++i) breaks.push_back(-s.u_far + 2 * s.u_far * Real(i) / Real(panels));
    for (const Real& k : kink_tans) {
        if (!(k > 0)) continue;
        const Real u = log(k / alpha);
        if (u > -s.u_far && u < s.u_far) breaks.push_back(u);
    }
    std::sort(breaks.begin(), breaks.end());
    const adaptive_kronrod<Real, 21> rule(s.max_panels);
    estimate<Real> r = rule.integrate(g, breaks, Real(0), s.tolerance);
    // The two tails, from the decay over the last unit before each cut.
    auto tail = [&](const Real& at, const Real& inward) {
        const Real g_cut = abs(g(at)), g_in = abs(g(at + inward));
        r.evaluations += 2;
        if (g_cut == 0) return Real(0);
        if (!(g_in > g_cut)) return std::numeric_limits<Real>::infinity();
        return 2 * g_cut / log(g_in / g_cut);
    };
    r.abs_error += tail(-s.u_far, Real(1)) + tail(s.u_far, Real(-1));
    return r;
}

}  // namespace normzoo::quadrature
