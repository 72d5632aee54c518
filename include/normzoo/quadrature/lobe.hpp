// 1D quadrature of a cosine lobe: integral over t in [0, t_end] of f, where f carries a factor
// cos^n(theta), theta = alpha t, peaked at t = 0 (alpha = 1 for cos t, 1/2 for cos(t/2)).
//
// Why a substitution: cos^n(theta) has width ~1/sqrt(n) and n reaches 1e7, so a rule over the
// whole interval samples nothing but zeros (Boost 1.74's tanh_sinh then reports 0 with error 0),
// and pow(cos, n) loses ~n ulps. With the Laplace variable
//     s = -ln cos(theta),   x = k s   (k ~ n + 1, the integrand's decay rate in s, measured),
// the lobe becomes cos^n(theta) = exp(-n s), computed from s itself (no cosine is raised to a
// power), decays on the scale x ~ 1 whatever n is, and the end-point branch of cos^n at
// theta = pi/2 for small n moves to x = infinity. Every zoo integrand is then analytic in x on
// the panels below, where Gauss-Legendre converges geometrically.
//
// The estimate is cross-checked, never Boost's alone: two independent rules on different panel
// sets (30-point Gauss on A, 20-point Gauss on B: no node in common) must agree, and the error
// bound is their difference plus a rounding bound plus the truncated tail.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "estimate.hpp"

namespace normzoo::quadrature {

// A node of the lobe variable, with what an integrand needs already computed.
template <class Real>
struct lobe_point {
    Real s;          // -ln cos(theta)
    Real cos_theta;  // exp(-s)
    Real sin_theta;  // sqrt(1 - exp(-2 s)), from expm1: exact near theta = 0
    Real power;      // cos^n(theta) = exp(-n s)
    Real alpha;
    Real t() const {
        using std::atan2;
        return atan2(sin_theta, cos_theta) / alpha;
    }
};

namespace detail {

// Panel edges in x and the two Gauss-Legendre orders, by precision. Beyond x_last the lobe is
// below e^-x_last of its peak: 3e-37 for binary128 (84), 1.4e-21 for double and long double (48).
template <class Real, bool High = (std::numeric_limits<Real>::digits > 64)>
struct panel_plan {
    static constexpr std::array<double, 5> a{8, 20, 36, 56, 84};
    static constexpr unsigned order_a = 30;
    static constexpr std::array<double, 6> b{4, 12, 24, 40, 60, 84};
    static constexpr unsigned order_b = 20;
    static constexpr double x_last = 84;
};
template <class Real>
struct panel_plan<Real, false> {
    static constexpr std::array<double, 4> a{6, 16, 30, 48};
    static constexpr unsigned order_a = 20;
    static constexpr std::array<double, 5> b{4, 11, 22, 36, 48};
    static constexpr unsigned order_b = 15;
    static constexpr double x_last = 48;
};

// "Gauss-Legendre 30 on [0,8,...,84] checked by 20 on [0,4,...,84]": the plan, for table heads.
template <class Real>
std::string describe_plan() {
    using plan = panel_plan<Real>;
    auto edges = [](const auto& e) {
        std::string s = "[0";
        for (double x : e) s += "," + std::to_string(static_cast<int>(x));
        return s + "]";
    };
    return "Gauss-Legendre " + std::to_string(plan::order_a) + " on " + edges(plan::a) + " checked by " +
           std::to_string(plan::order_b) + " on " + edges(plan::b);
}

template <unsigned N, class Real, class G, std::size_t K>
Real panel_sum(const G& g, const std::array<double, K>& edges, const Real& x_end, Real& l1) {
    Real sum = 0;
    Real a = 0;
    for (double e : edges) {
        Real b = e;
        if (b > x_end) b = x_end;
        if (b > a) {
            Real panel_l1 = 0;
            sum += boost::math::quadrature::gauss<Real, N>::integrate(g, a, b, &panel_l1);
            l1 += panel_l1;
        }
        a = b;
        if (!(a < x_end)) break;
    }
    return sum;
}

}  // namespace detail

template <class Real>
class lobe_quadrature {
    using plan = detail::panel_plan<Real>;

public:
    // Integral over t in [0, theta_end / alpha] of f(p), p a lobe_point. theta_end <= pi/2;
    // pass half_pi for the whole lobe to the horizon (then the range in x is unbounded).
    // f must be cos^n(theta) w(theta) with w(theta)/sin(theta) bounded at theta_end.
    template <class F>
    estimate<Real> integrate(const F& f, const Real& alpha, const Real& n, const Real& theta_end) const {
        using std::abs;
        using std::cos;
        using std::exp;
        using std::expm1;
        using std::log;
        using std::sqrt;
        const Real half_pi = boost::math::constants::half_pi<Real>();
        const bool to_horizon = !(theta_end < half_pi);
        const Real s_end = to_horizon ? std::numeric_limits<Real>::infinity() : -log(cos(theta_end));
        // cos = 1 + expm1(-s) and sin^2 = 1 - cos^2 = -expm1(-s) (2 + expm1(-s)): one exponential
        // gives both, without the cancellation of 1 - cos^2 near the peak.
        auto node = [&](const Real& s) {
            const Real e = expm1(-s);
            return lobe_point<Real>{s, 1 + e, sqrt(-e * (2 + e)), exp(-n * s), alpha};
        };
        // The integrand in s, dtheta/ds = cos/sin included.
        auto in_s = [&](const Real& s) -> Real {
            const lobe_point<Real> p = node(s);
            return f(p) * p.cos_theta / p.sin_theta;
        };
        const Real scale = decay_rate(in_s, n, s_end);
        const Real x_end = to_horizon ? Real(plan::x_last) : s_end * scale;
        const Real x_stop = x_end < Real(plan::x_last) ? x_end : Real(plan::x_last);

        std::size_t calls = 2;  // the two spent on the decay rate
        auto g = [&](const Real& x) -> Real {
            ++calls;
            return in_s(x / scale);
        };
        Real l1_a = 0, l1_b = 0;
        const Real qa = detail::panel_sum<plan::order_a>(g, plan::a, x_stop, l1_a);
        const Real qb = detail::panel_sum<plan::order_b>(g, plan::b, x_stop, l1_b);
        // Rounding: each node errs by a few ulps, plus ~x ulps in exp(-n s) where x is large
        // and the weight is below e^-x; (4 + x_last/8) ulps of the L1 norm covers both with room.
        const Real rounding = (4 + Real(plan::x_last) / 8) * eps * l1_a;

        // The tail beyond x_last (absent where the interval ends first): bounded by the
        // integrand at the cut times the decay length seen over the last 8 units, doubled.
        Real tail = 0;
        if (x_end > x_stop) {
            const Real g_cut = abs(g(x_stop));
            const Real g_before = abs(g(x_stop - 8));
            const Real decay = g_before > g_cut && g_cut > 0 ? log(g_before / g_cut) / 8 : Real(0);
            const Real width = x_end - x_stop;
            Real length = decay > 0 ? 1 / decay : width;
            if (length > width) length = width;
            tail = 2 * g_cut * length;
        }
        const Real jacobian = 1 / (alpha * scale);  // dt = dtheta / alpha, ds = dx / scale
        estimate<Real> r;
        r.value = qa * jacobian;
        r.abs_error = (abs(qa - qb) + rounding + tail) * jacobian;
        r.evaluations = calls;
        return r;
    }

private:
    // The integrand decays in s like exp(-(n + m) s), m = 1 or 2 for the zoo's weights (the
    // cosines beside the lobe). Measured between two points of the lobe and clamped to
    // [n + 1, n + 8], it sets x = rate * s so that every integrand decays like e^-x on the panels.
    template <class G>
    static Real decay_rate(const G& in_s, const Real& n, const Real& s_end) {
        using std::isfinite;
        using std::log;
        Real s0 = Real(0.5) / (n + 1), s1 = Real(1.5) / (n + 1);
        if (s1 > s_end / 2) s0 = s_end / 8, s1 = s_end / 2;
        const Real g0 = in_s(s0), g1 = in_s(s1);
        Real rate = g0 > 0 && g1 > 0 ? log(g0 / g1) / (s1 - s0) : n + 1;
        if (!(rate >= n + 1)) rate = n + 1;
        if (rate > n + 8) rate = n + 8;
        return rate;
    }

    const Real eps = std::numeric_limits<Real>::epsilon();
};

}  // namespace normzoo::quadrature
