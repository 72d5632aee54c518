// The trapezoidal rule for a smooth 2 pi-periodic even function, over [0, pi] (half its circle).
//
// On a full period the trapezoidal rule converges geometrically: for f analytic in the strip
// |Im x| < a its error falls like exp(-a n) with n nodes per period (Trefethen and Weideman,
// "The exponentially convergent trapezoidal rule", SIAM Review 2014), where Gauss-Kronrod on
// panels pays for ends that are not there. Nodes double from a first spacing the caller
// derives from the strip (no wider than half its narrowest feature: the guard against
// agreeing on a feature neither grid sees, as breakpoints are for adaptive.hpp); the error
// bound of T(n) is |T(n) - T(n/2)| (the error of the coarser sum, an overestimate once the
// sums converge, as |K - G| is), plus the nodes' own error bounds, plus rounding. The integrand
// may return channels (channels.hpp); the sums then stop on their magnitude.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <limits>
#include <utility>
#include <vector>

#include "channels.hpp"
#include "estimate.hpp"

namespace normzoo::quadrature {

// The result, and whether its bound met the tolerance within max_intervals.
template <class Value>
struct periodic_estimate {
    estimate<Value> integral;
    bool converged = false;
};

namespace detail {
// cos and sin of pi j / 1024, j = 0..1024, once: the nodes of every level are among them, and
// an integrand of an angle wants both (a table instead of a sincos per node).
constexpr std::size_t circle_intervals = 1024;
template <class Real>
const std::vector<std::pair<Real, Real>>& circle_table() {
    static const std::vector<std::pair<Real, Real>> table = [] {
        std::vector<std::pair<Real, Real>> t(circle_intervals + 1);
        const Real pi = Real(3.141592653589793238462643383279502884L);
        for (std::size_t j = 0; j <= circle_intervals; ++j) {
            using std::cos;
            using std::sin;
            const Real x = pi * Real(j) / Real(circle_intervals);
            t[j] = {cos(x), sin(x)};
        }
        return t;
    }();
    return table;
}
}  // namespace detail

// Integral over [0, pi] of f, even and 2 pi-periodic, starting with `intervals` and doubling to
// max_intervals (powers of 2, at most 1024; other starts throw std::invalid_argument), until
// |T(n) - T(n/2)| meets abs_tol or the sums' own rounding. f(x, cos x, sin x) returns
// estimate<Value> (value and its own bound), Value Real or channels of Real.
template <class Real, class F,
          class Value = decltype(std::declval<const F&>()(Real(), Real(), Real()).value)>
periodic_estimate<Value> periodic_trapezoid(const F& f, std::size_t intervals, std::size_t max_intervals,
                                            const Real& abs_tol) {
    using std::abs;
    const Real pi = Real(3.141592653589793238462643383279502884L);
    auto power_of_two = [](std::size_t k) { return k >= 2 && (k & (k - 1)) == 0; };
    if (!power_of_two(intervals) || intervals > detail::circle_intervals)
        throw std::invalid_argument("periodic_trapezoid: intervals must be a power of 2 from 2 to 1024");
    std::size_t n = intervals;
    if (max_intervals > detail::circle_intervals) max_intervals = detail::circle_intervals;
    const auto& table = detail::circle_table<Real>();
    Value sum{}, coarse{}, inner{}, l1{};
    std::size_t calls = 0;
    auto add = [&](std::size_t j, std::size_t of, Real weight, Value* also) {
        const auto& cs = table[j * (detail::circle_intervals / of)];
        const estimate<Value> s = f(pi * Real(j) / Real(of), cs.first, cs.second);
        calls += s.evaluations;
        sum += weight * s.value;
        inner += weight * s.abs_error;
        l1 += weight * abs(s.value);
        if (also) *also += weight * s.value;
    };
    for (std::size_t j = 0; j <= n; ++j) add(j, n, (j == 0 || j == n) ? Real(0.5) : Real(1), j % 2 == 0 ? &coarse : nullptr);
    Value fine_value = sum * pi / Real(n), coarse_value = coarse * pi / Real(n / 2);
    // where the sums agree to their own rounding, more nodes cannot do better
    auto floor_of = [&](std::size_t m) {
        return magnitude(Value(inner + 8 * std::numeric_limits<Real>::epsilon() * l1)) * pi / Real(m);
    };
    auto done = [&] { return magnitude(Value(fine_value - coarse_value)) <= std::max(abs_tol, floor_of(n)); };
    while (!done() && 2 * n <= max_intervals) {
        coarse_value = fine_value;
        for (std::size_t j = 1; j < 2 * n; j += 2) add(j, 2 * n, Real(1), nullptr);
        n *= 2;
        fine_value = sum * pi / Real(n);
    }
    periodic_estimate<Value> r;
    const Real h = pi / Real(n);
    r.integral = {fine_value, abs(fine_value - coarse_value) + inner * h + 8 * std::numeric_limits<Real>::epsilon() * l1 * h, calls};
    r.converged = done();
    return r;
}

}  // namespace normzoo::quadrature
