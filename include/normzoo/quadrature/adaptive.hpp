// Globally adaptive Gauss-Kronrod quadrature on [a, b] from caller-given breakpoints.
//
// The caller knows where its integrand has features (a lobe's width, a pole's distance, a
// horizon cut) and passes them as breakpoints, usually after a substitution that makes every
// feature O(1) wide (u = ln theta). That is the guard against the failure Boost 1.74's
// adaptive integrators show on a peaked integrand: when no node lands on a narrow peak, the
// Gauss and Kronrod sums agree on the wrong value and the error estimate is tiny. Here no
// panel is ever wider than the features it holds, so the embedded rules see them.
//
// Each panel is Kronrod 2m+1 with its embedded Gauss m (Boost.Math's nodes and weights). The
// panel with the largest |Kronrod - Gauss| is bisected until the sum of those differences
// meets the tolerance. The value is the Kronrod sum; its error bound is, with no heuristic
// scaling, the sum of |K - G| (an overestimate for smooth panels: it is the Gauss error),
// plus the integrand's own errors where it is itself an estimate (a nested integral),
// weighted like its values, plus a rounding bound. The integrand may return channels (several
// integrals from the same nodes, channels.hpp): panels are then chosen by the sum of the
// channels' differences, and each channel gets its own value and bound. An integrand of an angle,
// f(x, cos x, sin x) as periodic.hpp takes it, gets each node's cosine and sine from the panel
// centre's and the node offset's by the addition formulas: one cosine and sine per panel and
// short series for the offsets, instead of a library call per node; the node's cosine and sine
// then err by at most 4 ulps absolutely for angles up to 2 pi (the integrand's rounding model
// allows for that).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "channels.hpp"
#include "estimate.hpp"
#include "gauss_rules.hpp"

namespace normzoo::quadrature {

// An integrand that also takes a panel's nodes at once, f(std::array<Real, n>) returning their n
// values: kronrod_panel then calls it once a panel, so that the processor overlaps the nodes'
// work where one node's is a chain of dependent divisions and roots (microfacet/split_sum_to.hpp).
template <class F>
struct nodes_at_once {
    F f;
    template <class X>
    decltype(auto) operator()(const X& x) const { return f(x); }
};

namespace detail {

template <class F>
constexpr bool takes_nodes_at_once = false;
template <class F>
constexpr bool takes_nodes_at_once<nodes_at_once<F>> = true;

template <class Value>
struct sample {
    Value value;
    Value error;               // the integrand's own error bound (0 for a plain function)
    std::size_t evaluations;   // what computing it took (1 for a plain function)
};
template <class Value>
sample<Value> as_sample(const Value& x) { return {x, Value{}, 1}; }
template <class Value>
sample<Value> as_sample(const estimate<Value>& e) { return {e.value, e.abs_error, e.evaluations}; }

// What an integrand returns: a value (a number or channels), or an estimate of one.
template <class R>
struct value_of { using type = R; };
template <class V>
struct value_of<estimate<V>> { using type = V; };

template <class Real, class Value = Real>
struct panel {
    Real a, b;
    Value kronrod;
    Value differences;  // |Kronrod - Gauss|, or more where the bisection check raised it
    Real difference;    // their magnitude (channels.hpp): what bisection and stopping compare
    Value inner;        // integral of the integrand's own error
    Value l1;           // integral of |f|
    std::size_t evaluations;  // of the integrand, or of what it integrates when it is nested
    bool operator<(const panel& o) const { return difference < o.difference; }  // max-heap on the difference
};

// f(x, cos x, sin x) rather than f(x)
template <class F, class Real>
constexpr bool is_angle_integrand = std::is_invocable_v<const F&, Real, Real, Real>;

template <class F, class Real, bool = is_angle_integrand<F, Real>>
struct integrand_result {
    using type = std::decay_t<decltype(std::declval<const F&>()(std::declval<Real>()))>;
};
template <class F, class Real>
struct integrand_result<F, Real, true> {
    using type =
        std::decay_t<decltype(std::declval<const F&>()(std::declval<Real>(), std::declval<Real>(), std::declval<Real>()))>;
};

// cos o and sin o of the nodes' offsets o = half x[i] from their panel's centre. In double and
// for |half| <= 3/4, Taylor series to o^(2K - 2) and o^(2K - 1), K terms from |half| (9 at 3/4,
// 3 below 0.003) so that the first term left out, which bounds the error of these alternating
// series, is below 1e-18; summed for all offsets at once. Otherwise the library's.
template <class Real, std::size_t M, class X>
void cos_sin_of_offsets(const Real& half, const X& x, std::array<Real, M>& c, std::array<Real, M>& s) {
    using std::abs;
    using std::cos;
    using std::sin;
    if constexpr (std::is_same_v<Real, double>) {
        // (-1)^k / (2k)! and (-1)^k / (2k + 1)!, k = 0..8
        static constexpr double cos_terms[] = {1.0, -1.0 / 2, 1.0 / 24, -1.0 / 720, 1.0 / 40320, -1.0 / 3628800,
                                               1.0 / 479001600, -1.0 / 87178291200.0, 1.0 / 20922789888000.0};
        static constexpr double sin_terms[] = {1.0, -1.0 / 6, 1.0 / 120, -1.0 / 5040, 1.0 / 362880, -1.0 / 39916800,
                                               1.0 / 6227020800.0, -1.0 / 1307674368000.0, 1.0 / 355687428096000.0};
        // the largest |o| for K = 3, 4, ... terms: (1e-18 (2K)!)^(1/(2K)), rounded down
        static constexpr double reach[] = {0.0029, 0.0211, 0.0717, 0.1672, 0.3131, 0.5099, 0.75};
        const double h = abs(half);
        if (h <= 0.75) {
            std::size_t terms = 3;
            while (h > reach[terms - 3]) ++terms;
            std::array<double, M> o, o2, cs, ss;
            for (std::size_t i = 0; i < M; ++i) {
                o[i] = half * x[i], o2[i] = o[i] * o[i];
                cs[i] = cos_terms[terms - 1], ss[i] = sin_terms[terms - 1];
            }
            for (std::size_t k = terms - 1; k-- > 0;)
                for (std::size_t i = 0; i < M; ++i) cs[i] = cs[i] * o2[i] + cos_terms[k], ss[i] = ss[i] * o2[i] + sin_terms[k];
            for (std::size_t i = 0; i < M; ++i) c[i] = cs[i], s[i] = o[i] * ss[i];
            return;
        }
    }
    for (std::size_t i = 0; i < M; ++i) {
        const Real o = half * x[i];
        c[i] = cos(o), s[i] = sin(o);
    }
}

template <class Real, unsigned Points, class F,
          class Value = typename value_of<typename integrand_result<F, Real>::type>::type>
panel<Real, Value> kronrod_panel(const F& f, const Real& a, const Real& b) {
    using std::abs;
    using rule = kronrod_rule<Real, Points>;
    constexpr unsigned gauss_points = (Points - 1) / 2;
    const auto& x = rule::abscissa();
    const auto& wk = rule::weights();
    const auto& wg = gauss_rule<Real, gauss_points>::weights();
    const Real mid = (a + b) / 2, half = (b - a) / 2;
    Value k{}, g{}, inner{}, l1{};
    std::size_t calls = 0;
    constexpr bool angle = is_angle_integrand<F, Real>;
    Real cos_mid{}, sin_mid{};
    if constexpr (angle) {
        using std::cos;
        using std::sin;
        cos_mid = cos(mid), sin_mid = sin(mid);
    }
    // Kronrod nodes x[i] >= 0 ascending, x[0] = 0. The Gauss nodes are every other one: odd i
    // for an even Gauss order, even i (the centre included) for an odd one; weight index i/2.
    // All nodes are evaluated before any is summed, and for an angle all offsets' cosines and
    // sines before any node: independent work the processor overlaps, where summing after each
    // node chained them (docs/microfacet.md, "The albedo in the distribution's own variable").
    constexpr std::size_t m = (Points + 1) / 2;  // x.size(): Kronrod 2m - 1 = Points
    constexpr std::size_t n = 2 * m - 1;          // node j: x[j] for j < m, -x[j - m + 1] after
    std::array<Real, n> nodes, cos_n{}, sin_n{};
    for (std::size_t j = 0; j < n; ++j) nodes[j] = j < m ? mid + half * x[j] : mid - half * x[j - m + 1];
    if constexpr (angle) {  // cos(mid +- o), sin(mid +- o)
        std::array<Real, m> cos_o, sin_o;
        cos_sin_of_offsets(half, x, cos_o, sin_o);
        for (std::size_t i = 0; i < m; ++i) {
            const Real co = cos_o[i], so = sin_o[i];
            cos_n[i] = cos_mid * co - sin_mid * so, sin_n[i] = sin_mid * co + cos_mid * so;
            if (i > 0) cos_n[i + m - 1] = cos_mid * co + sin_mid * so, sin_n[i + m - 1] = sin_mid * co - cos_mid * so;
        }
    }
    std::array<sample<Value>, n> samples;
    if constexpr (takes_nodes_at_once<F>) {
        const auto values = f.f(nodes);
        for (std::size_t j = 0; j < n; ++j) samples[j] = as_sample<Value>(values[j]);
    } else {
        for (std::size_t j = 0; j < n; ++j) {
            if constexpr (angle)
                samples[j] = as_sample<Value>(f(nodes[j], cos_n[j], sin_n[j]));
            else
                samples[j] = as_sample<Value>(f(nodes[j]));
        }
    }
    for (std::size_t i = 0; i < m; ++i)
        for (int side = 0; side < (i == 0 ? 1 : 2); ++side) {
            const sample<Value>& s = samples[side == 0 ? i : i + m - 1];
            calls += s.evaluations;
            k += wk[i] * s.value;
            if (i % 2 != gauss_points % 2) g += wg[i / 2] * s.value;
            inner += wk[i] * s.error;
            l1 += wk[i] * abs(s.value);
        }
    const Value differences = abs(k - g) * half;
    return {a, b, k * half, differences, magnitude(differences), inner * half, l1 * half, calls};
}

}  // namespace detail

template <class Real, unsigned Points = 21>
class adaptive_kronrod {
public:
    // max_panels bounds the work; an estimate whose error exceeds the tolerance comes back as is
    // (the caller decides what an untrusted value means).
    // check_bisections: the check above, for integrands that may have kinks.
    explicit adaptive_kronrod(std::size_t max_panels = 400, bool check_bisections = false)
        : max_panels_(max_panels), check_bisections_(check_bisections) {}

    // Integral of f over [breaks.front(), breaks.back()], panels starting at the breakpoints.
    // f(x), or f(x, cos x, sin x) for an integrand of an angle, returns Real (or channels), or
    // estimate<Real> when it is itself approximate. The target is
    // max(abs_tol, rel_tol * |integral|) for the quadrature part of the error.
    template <class F, class Value = typename detail::value_of<typename detail::integrand_result<F, Real>::type>::type>
    estimate<Value> integrate(const F& f, const std::vector<Real>& breaks, const Real& abs_tol,
                              const Real& rel_tol) const {
        using std::abs;
        using panel = detail::panel<Real, Value>;
        std::vector<panel> heap;
        heap.reserve(breaks.size() + 16);
        Value value{};
        Real difference = 0;
        std::size_t calls = 0;
        auto add = [&](const panel& p) {
            heap.push_back(p);
            std::push_heap(heap.begin(), heap.end());
            value += p.kronrod;
            difference += p.difference;
            calls += p.evaluations;
        };
        for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
            if (!(breaks[i + 1] > breaks[i])) continue;
            auto whole = detail::kronrod_panel<Real, Points>(f, breaks[i], breaks[i + 1]);
            if (!check_bisections_) {
                add(whole);
                continue;
            }
            // Checked from the start: a kink in a first panel can leave its |K - G| tiny.
            const Real mid = (breaks[i] + breaks[i + 1]) / 2;
            auto left = detail::kronrod_panel<Real, Points>(f, breaks[i], mid);
            auto right = detail::kronrod_panel<Real, Points>(f, mid, breaks[i + 1]);
            calls += whole.evaluations;
            checked(whole, left, right);
            add(left);
            add(right);
        }

        Real noise = 0;  // the integrand's own errors: bisecting cannot go below them
        for (const auto& p : heap) noise += magnitude(p.inner);
        while (!heap.empty() && heap.size() < max_panels_) {
            const Real target = std::max(abs_tol, rel_tol * magnitude(value));
            if (difference <= target || difference <= noise) break;
            std::pop_heap(heap.begin(), heap.end());
            const panel worst = heap.back();
            const Real mid = (worst.a + worst.b) / 2;
            if (!(mid > worst.a && mid < worst.b)) break;  // no room left to bisect in Real
            heap.pop_back();
            value -= worst.kronrod;
            difference -= worst.difference;
            noise -= magnitude(worst.inner);
            auto left = detail::kronrod_panel<Real, Points>(f, worst.a, mid);
            auto right = detail::kronrod_panel<Real, Points>(f, mid, worst.b);
            if (check_bisections_) checked(worst, left, right);
            noise += magnitude(left.inner) + magnitude(right.inner);
            add(left);
            add(right);
        }
        // Recomputed from the panels: the running sums carry the rounding of every removal.
        estimate<Value> r{Value{}, Value{}, calls};
        Value differences{}, inner{}, l1{};
        for (const auto& p : heap) {
            r.value += p.kronrod;
            differences += p.differences;
            inner += p.inner;
            l1 += p.l1;
        }
        // Rounding: the weighted sum of the node values errs by a few ulps of the L1 norm.
        r.abs_error = differences + inner + 8 * std::numeric_limits<Real>::epsilon() * l1;
        return r;
    }

private:
    // The bisection check: each half carries at least |parent - (left + right)|.
    template <class Value>
    static void checked(const detail::panel<Real, Value>& parent, detail::panel<Real, Value>& left,
                        detail::panel<Real, Value>& right) {
        using std::abs;
        using std::max;
        const Value d = abs(parent.kronrod - (left.kronrod + right.kronrod));
        left.differences = max(left.differences, d);
        right.differences = max(right.differences, d);
        left.difference = magnitude(left.differences);
        right.difference = magnitude(right.differences);
    }
    std::size_t max_panels_;
    bool check_bisections_;
};

}  // namespace normzoo::quadrature
