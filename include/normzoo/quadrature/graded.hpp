// Adaptive Gauss-Kronrod on [0, end] graded towards 0: the integrand has a feature of width x0
// at 0 (a lobe's centre) and its other scales between x0 and end spread evenly in ln x.
// Kronrod on [0, x0], then on u = ln x in panels at most 2 wide, so that every scale between x0
// and end is O(1) wide in u and the embedded rules see it (adaptive.hpp says why that matters).
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "adaptive.hpp"
#include "estimate.hpp"

namespace normzoo::quadrature {

// Integral of g(x) over x in [0, end]; plain Kronrod on [0, end] when x0 is not much below end
// (no scale to resolve). g returns a value or an estimate (a nested integral); check_bisections
// as in adaptive.hpp; kinks: breakpoints where g has a kink (those outside (0, end) are dropped).
template <class Real, unsigned Points, class G>
estimate<Real> graded_integral(const G& g, const Real& x0, const Real& end, const Real& abs_tol,
                              const Real& rel_tol, std::size_t max_panels, bool check_bisections = false,
                              std::vector<Real> kinks = {}) {
    using std::ceil;
    using std::exp;
    using std::log;
    const adaptive_kronrod<Real, Points> rule(max_panels, check_bisections);
    kinks.erase(std::remove_if(kinks.begin(), kinks.end(), [&](const Real& k) { return !(k > 0 && k < end); }),
                kinks.end());
    std::sort(kinks.begin(), kinks.end());
    // [a, b] with the kinks inside it as breakpoints
    auto span = [&](const Real& a, const Real& b) {
        std::vector<Real> v{a};
        for (const Real& k : kinks)
            if (k > a && k < b) v.push_back(k);
        v.push_back(b);
        return v;
    };
    if (!(x0 < end / 16)) return rule.integrate(g, span(Real(0), end), abs_tol, rel_tol);
    auto r = rule.integrate(g, span(Real(0), x0), abs_tol / 2, rel_tol);
    const Real u0 = log(x0), u1 = log(end);
    const int panels = static_cast<int>(ceil(static_cast<double>(u1 - u0) / 2));
    std::vector<Real> breaks;
    for (int i = 0; i < panels; ++i) breaks.push_back(u0 + (u1 - u0) * i / panels);
    breaks.push_back(u1);
    for (const Real& k : kinks)
        if (k > x0) breaks.insert(std::upper_bound(breaks.begin(), breaks.end(), log(k)), log(k));
    auto in_u = [&](const Real& u) {
        const Real x = exp(u);
        estimate<Real> v = g(x);
        return estimate<Real>{v.value * x, v.abs_error * x, v.evaluations};
    };
    const auto s = rule.integrate(in_u, breaks, abs_tol / 2, rel_tol);
    r.value += s.value;
    r.abs_error += s.abs_error;
    r.evaluations += s.evaluations;
    return r;
}

}  // namespace normzoo::quadrature
