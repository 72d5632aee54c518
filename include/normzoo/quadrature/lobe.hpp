// 1D quadrature of a cosine lobe: integral over t in [0, t_end] of f, where f carries a factor
// cos^n(theta), theta = alpha t, peaked at t = 0 (alpha = 1 for cos t, 1/2 for cos(t/2)).
//
// Why a substitution: cos^n(theta) has width ~1/sqrt(n) and n reaches 1e9. A fixed rule over the
// whole interval sees none of it; adaptive ones spend their levels finding it and may claim less
// error than they make (Boost's tanh_sinh and gauss_kronrod do, in the stability-naive table);
// pow(cos, n) carries n times the cosine's rounding. With the Laplace variable
//     s = -ln cos(theta),   x = k s   (k = n + m, m the integrand's extra decay rate, measured),
// the lobe becomes cos^n(theta) = exp(-n s) = e^-x / cos^m (no cosine is raised to the power n),
// decays on the scale x ~ 1 whatever n is, and the end-point branch of cos^n at
// theta = pi/2 for small n moves to x = infinity. Every zoo integrand is then analytic in x on
// the panels below, where Gauss-Legendre converges geometrically.
//
// The estimate is cross-checked, never Boost's alone: two independent rules on different panel
// sets (30-point Gauss on A, 20-point Gauss on B: no node in common) must agree, and the error
// bound is their difference plus a rounding bound plus the truncated tail.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "../detail/binary128_exp.hpp"
#include "../real.hpp"
#include "estimate.hpp"
#include "gauss_rules.hpp"

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
// below e^-x_last of its peak: 3e-37 for binary128 (84), 1.4e-21 for long double (48), 4e-18
// for double (40). Sized so that both rules integrate e^-(beta x) to the type's precision for
// beta up to 2-4 (bench/ and the tests measure it); double needs the fewest nodes.
template <class Real, int Digits = std::numeric_limits<Real>::digits>
struct panel_plan {
    static constexpr std::array<double, 5> a{8, 20, 36, 56, 84};
    static constexpr unsigned order_a = 30;
    static constexpr std::array<double, 6> b{4, 12, 24, 40, 60, 84};
    static constexpr unsigned order_b = 20;
    static constexpr double x_last = 84;
    static constexpr bool horizon_tail = false;  // e^-x_last is below the type's rounding
};
template <class Real>
struct panel_plan<Real, 64> {
    static constexpr std::array<double, 4> a{6, 16, 30, 48};
    static constexpr unsigned order_a = 20;
    static constexpr std::array<double, 5> b{4, 11, 22, 36, 48};
    static constexpr unsigned order_b = 15;
    static constexpr double x_last = 48;
    static constexpr bool horizon_tail = false;  // e^-x_last is below the type's rounding
};
template <class Real>
struct panel_plan<Real, 53> {
    static constexpr std::array<double, 3> a{6, 17, 40};
    static constexpr unsigned order_a = 20;
    static constexpr std::array<double, 4> b{4, 11, 24, 40};
    static constexpr unsigned order_b = 15;
    static constexpr double x_last = 40;
    static constexpr bool horizon_tail = false;  // e^-x_last is below the type's rounding
};

// A plan for about 1e-8 relative in double, at less than half the nodes. For e^-(beta x), beta
// from 1/2 to 4, rule A errs by at most 6e-13 and rule B by 4e-10: the value is A's and |A - B|,
// B's error, bounds it with room (two rules of equal order err alike, with one sign, and their
// difference can fall below both errors). The lobe beyond x = 24 is below 4e-11 of its
// peak, a tail its bound counts (the full plans' e^-x_last is below their type's rounding). Where
// the bound comes out above the caller's tolerance, lobe_quadrature takes the full plan instead
// (docs/method.md, "Speed").
struct quick_plan {
    static constexpr std::array<double, 2> a{7, 24};
    static constexpr unsigned order_a = 16;
    static constexpr std::array<double, 2> b{5, 24};
    static constexpr unsigned order_b = 12;
    static constexpr double x_last = 24;
    static constexpr bool horizon_tail = true;
};

// Where a double result is summed: in long double, so that the sum adds no rounding of its own
// to the double path's few-ulp answer.
template <class Real>
using accumulator = std::conditional_t<std::is_same_v<Real, double>, long double, Real>;

// Where rounding bounds are kept: double for double (no conversions on its fast path), else long
// double (binary128's exponent range, no more precision needed).
template <class Real>
using bound_type = std::conditional_t<std::is_same_v<Real, double>, double, long double>;

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

// A node of a rule in x, with e^-x precomputed: with x = k s and k = n + m, the lobe is
// cos^n = exp(-n s) = e^-x / cos^m, so a node needs one exponential (cos), not two.
template <class Real>
struct lobe_node {
    Real x, weight, exp_minus_x;
    bound_type<Real> x_low, weight_low;  // for the rounding bounds, which need no more precision,
    bound_type<Real> exp_minus_x_low;    // and for the nodes a binary128 rule evaluates in long double
};

// e^-y for y >= 0: std::exp, and in binary128 the table method of binary128_exp.hpp where it applies.
template <class T>
T exp_of_minus(const T& y) {
    using std::exp;
    return exp(-y);
}
inline quad exp_of_minus(const quad& y) {
    if (y < 5000) return quad(normzoo::detail::exp_and_expm1_of_minus(y.backend().value()).first);
    using std::exp;
    return exp(-y);
}

// A panel of a rule: Gauss-Legendre N on [a, b] as nodes in x.
template <unsigned N, class Real>
using panel_nodes = std::array<lobe_node<Real>, N>;

template <unsigned N, class Real>
void fill_panel(panel_nodes<N, Real>& out, const Real& a, const Real& b) {
    using rule = gauss_rule<Real, N>;
    using low = bound_type<Real>;
    const Real c = (a + b) / 2, h = (b - a) / 2;
    const auto& xi = rule::abscissa();
    const auto& w = rule::weights();
    std::size_t i = 0;
    for (std::size_t j = 0; j < xi.size(); ++j) {
        if (xi[j] == 0) {
            out[i++] = {c, h * w[j], 0, 0, 0, 0};
        } else {
            out[i++] = {c - h * xi[j], h * w[j], 0, 0, 0, 0};
            out[i++] = {c + h * xi[j], h * w[j], 0, 0, 0, 0};
        }
    }
    // the exponentials in a loop of their own (a panel rebuilt where a range ends costs no more)
    for (auto& node : out) {
        node.exp_minus_x = exp_of_minus(node.x);
        node.x_low = static_cast<low>(node.x);
        node.weight_low = static_cast<low>(node.weight);
        node.exp_minus_x_low = static_cast<low>(node.exp_minus_x);
    }
}

// cos(theta) = e^-s and sin(theta) = sqrt(1 - e^-2s) from one exponential, both to a few ulps:
// near the peak from expm1 (sin^2 = -e (2 + e), no cancellation of 1 - cos^2), far out from exp
// (where 1 + expm1(-s) would cancel to nothing).
template <class T>
inline std::pair<T, T> cos_sin_of_s(const T& s) {
    using std::exp;
    using std::expm1;
    using std::sqrt;
    if (s < T(0.5)) {
        const T e = expm1(-s);
        return {1 + e, sqrt(-e * (2 + e))};
    }
    const T c = exp(-s);  // <= 0.61: 1 - c does not cancel
    return {c, sqrt((1 - c) * (1 + c))};
}

// The same in binary128, where it is most of a node's cost: exp by binary128_exp.hpp, and the
// square root as one Newton step from long double's (its error squared, 1e-38, then rounding).
inline std::pair<quad, quad> cos_sin_of_s(const quad& s) {
    const auto [c, e] = normzoo::detail::exp_and_expm1_of_minus(s.backend().value());
    const __float128 a = -e * (2 + e);
    if (!(a > 0)) return {quad(c), quad(0)};
    const __float128 y = sqrtl(static_cast<long double>(a));
    return {quad(c), quad((y + a / y) / 2)};
}

// A rule's nodes on its whole panel set, built once per type: most integrals use them as they
// are (the horizon beyond x_last); a range that ends inside a panel rebuilds that one.
template <unsigned N, class Real, std::size_t K>
std::vector<panel_nodes<N, Real>> build_panels(const std::array<double, K>& edges) {
    std::vector<panel_nodes<N, Real>> panels(K);
    Real a = 0;
    for (std::size_t i = 0; i < K; ++i) {
        fill_panel<N>(panels[i], a, Real(edges[i]));
        a = edges[i];
    }
    return panels;
}

template <class Real, class Plan = panel_plan<Real>>
struct plan_nodes {
    using plan = Plan;
    std::vector<panel_nodes<plan::order_a, Real>> a = build_panels<plan::order_a, Real>(plan::a);
    std::vector<panel_nodes<plan::order_b, Real>> b = build_panels<plan::order_b, Real>(plan::b);
    static const plan_nodes& get() {
        static const plan_nodes nodes;
        return nodes;
    }
};

// Sum of w g over the panels of one rule up to x_end; l1 gets sum |w g|, rounding its rounding
// bound, evaluations the count of g's calls. g evaluates a whole panel into arrays (values, |g|,
// rounding bounds), and the sums come after: the nodes' evaluations are then independent of each
// other (they overlap in the processor) and the running sums stay in registers.
template <unsigned N, class Real, class G, std::size_t K>
Real panel_sum(const G& g, const std::array<double, K>& edges, const std::vector<panel_nodes<N, Real>>& full,
               const Real& x_end, bound_type<Real>& l1_out, bound_type<Real>& rounding_out, std::size_t& evaluations) {
    using B = bound_type<Real>;
    accumulator<Real> sum = 0;
    B l1 = 0, rounding = 0;
    Real a = 0;
    panel_nodes<N, Real> cut;
    std::array<Real, N> values;
    std::array<B, N> magnitudes, bounds;  // |g| and its rounding bound
    for (std::size_t i = 0; i < edges.size(); ++i) {
        Real b = edges[i];
        const panel_nodes<N, Real>* nodes = &full[i];
        if (b > x_end) {
            b = x_end;
            fill_panel<N>(cut, a, b);
            nodes = &cut;
        }
        if (b > a) {
            const lobe_node<Real>* node = nodes->data();
            g(node, values, magnitudes, bounds);
            accumulator<Real> panel = 0;  // one chain per loop: none waits for another's sum
            for (std::size_t j = 0; j < N; ++j) panel += accumulator<Real>(node[j].weight) * values[j];
            sum += panel;
            for (std::size_t j = 0; j < N; ++j) {
                l1 += node[j].weight_low * magnitudes[j];
                rounding += node[j].weight_low * bounds[j];
            }
            evaluations += N;
        }
        a = b;
        if (!(a < x_end)) break;
    }
    l1_out += l1;
    rounding_out += rounding;
    return Real(sum);
}

// c^m for the lobe's extra decay rate m in 1..8, by squaring: at most m - 1 roundings, as the
// rounding bound assumes, on a shorter chain of multiplications than a loop.
template <class T>
T small_power(const T& c, long m) {
    const T c2 = c * c, c4 = c2 * c2;
    switch (m) {
        case 1: return c;
        case 2: return c2;
        case 3: return c2 * c;
        case 4: return c4;
        case 5: return c4 * c;
        case 6: return c4 * c2;
        case 7: return c4 * (c2 * c);
        default: return c4 * c4;
    }
}

}  // namespace detail

template <class Real>
class lobe_quadrature {
public:
    // The full plan: the integral to a few ulps of Real.
    lobe_quadrature() = default;
    // A relative tolerance of 1e-9 or more first tries the quick plan (about 1e-8 at 58 nodes in
    // double, against 122); where its bound exceeds the tolerance, the full plan's result comes
    // back instead (the evaluations count both).
    explicit lobe_quadrature(const Real& relative_tolerance) : tolerance_(relative_tolerance) {}

    // Integral over t in [0, theta_end / alpha] of f(p), p a lobe_point. theta_end <= pi/2;
    // pass half_pi for the whole lobe to the horizon (then the range in x is unbounded).
    // f must be cos^n(theta) w(theta) with w(theta)/sin(theta) bounded at theta_end.
    // A generic f (one that also takes a lobe_point<long double>) lets binary128 evaluate the
    // nodes that carry less than 1e-17 of the peak in long double: their rounding, bounded
    // below, stays under 1e-36 of the integral, and each costs a twentieth of a binary128 node.
    template <class F>
    estimate<Real> integrate(const F& f, const Real& alpha, const Real& n, const Real& theta_end) const {
        using std::abs;
        if (!(tolerance_ >= Real(1e-9))) return integrate_with<detail::panel_plan<Real>>(f, alpha, n, theta_end);
        const estimate<Real> quick = integrate_with<detail::quick_plan>(f, alpha, n, theta_end);
        if (quick.abs_error <= tolerance_ * abs(quick.value)) return quick;
        estimate<Real> full = integrate_with<detail::panel_plan<Real>>(f, alpha, n, theta_end);
        full.evaluations += quick.evaluations;
        return full;
    }

private:
    template <class Plan, class F>
    estimate<Real> integrate_with(const F& f, const Real& alpha, const Real& n, const Real& theta_end) const {
        using plan = Plan;
        using std::abs;
        using std::cos;
        using std::log;
        const Real half_pi = boost::math::constants::half_pi<Real>();
        const bool to_horizon = !(theta_end < half_pi);
        const Real s_end = to_horizon ? std::numeric_limits<Real>::infinity() : -log(cos(theta_end));
        // The integrand in s, dtheta/ds = cos/sin included, for the decay rate and the tail.
        auto in_s = [&](const Real& s) -> Real {
            const auto [c, sn] = detail::cos_sin_of_s(s);
            const lobe_point<Real> p{s, c, sn, detail::exp_of_minus(n * s), alpha};
            return f(p) * p.cos_theta / p.sin_theta;
        };
        // x = k s with k = n + m, m the integrand's extra decay rate rounded (1..8).
        const Real rate = decay_rate(in_s, n, s_end);
        long m = std::lround(static_cast<double>(rate - n));
        m = m < 1 ? 1 : m > 8 ? 8 : m;
        const Real k = n + Real(m);
        const Real inv_k = 1 / k;
        const auto inv_k_low = static_cast<detail::bound_type<Real>>(inv_k);
        const auto alpha_low = static_cast<detail::bound_type<Real>>(alpha);
        // To the horizon, x runs to infinity: the quick plan counts the lobe beyond x_last as a
        // tail, the full plans' e^-x_last is below their rounding (x_end = x_last: no tail).
        const Real x_end = to_horizon ? (plan::horizon_tail ? std::numeric_limits<Real>::infinity() : Real(plan::x_last)) : s_end * k;
        const Real x_stop = x_end < Real(plan::x_last) ? x_end : Real(plan::x_last);

        std::size_t calls = 2;  // the two spent on the decay rate
        using B = detail::bound_type<Real>;
        // The integrand at a node in number type T from the node's cos and sin, and a bound on its
        // rounding: a few ulps for the node's functions and cos^m, and 2x ulps from s = x/k
        // carried into exp(-n s) = e^-x/cos^m.
        auto at_in = [&](auto type, const detail::lobe_node<Real>& node, const auto& cos_sin, B& magnitude, B& bound) -> Real {
            using T = decltype(type);
            // a long double node of a binary128 rule reads the node's long double copies
            constexpr bool low = std::is_same_v<T, B> && !std::is_same_v<T, Real>;
            T x, e_x, inv_k_t, alpha_t;
            if constexpr (low) {
                x = node.x_low, e_x = node.exp_minus_x_low, inv_k_t = inv_k_low, alpha_t = alpha_low;
            } else {
                x = node.x, e_x = node.exp_minus_x, inv_k_t = inv_k, alpha_t = alpha;
            }
            const auto& [c, sn] = cos_sin;
            const lobe_point<T> p{x * inv_k_t, c, sn, e_x / detail::small_power(c, m), alpha_t};
            const T v = f(p) * p.cos_theta / p.sin_theta;
            magnitude = std::abs(static_cast<B>(v));
            bound = magnitude * (6 + B(m) + 2 * node.x_low) * static_cast<B>(std::numeric_limits<T>::epsilon());
            return Real(v);
        };
        // A panel of nodes. In a built-in type, every node's cos and sin first, in a loop of their
        // own (the library calls then overlap: a fifth of the double path's time); in binary128 node
        // by node, those far out in long double where f allows it.
        auto panel = [&](const detail::lobe_node<Real>* node, auto& values, auto& magnitudes, auto& bounds) {
            constexpr std::size_t count = std::tuple_size_v<std::remove_reference_t<decltype(values)>>;
            if constexpr (std::is_floating_point_v<Real>) {
                std::array<std::pair<Real, Real>, count> cos_sin;
                for (std::size_t j = 0; j < count; ++j) cos_sin[j] = detail::cos_sin_of_s(node[j].x * inv_k);
                for (std::size_t j = 0; j < count; ++j) values[j] = at_in(Real(0), node[j], cos_sin[j], magnitudes[j], bounds[j]);
            } else {
                for (std::size_t j = 0; j < count; ++j) {
                    if constexpr (tiered<F>) {
                        if (node[j].exp_minus_x_low < 1e-17L) {
                            const long double s = node[j].x_low * inv_k_low;
                            values[j] = at_in(s, node[j], detail::cos_sin_of_s(s), magnitudes[j], bounds[j]);
                            continue;
                        }
                    }
                    values[j] = at_in(Real(0), node[j], detail::cos_sin_of_s(Real(node[j].x * inv_k)), magnitudes[j], bounds[j]);
                }
            }
        };
        const auto& nodes = detail::plan_nodes<Real, Plan>::get();
        detail::bound_type<Real> l1_a = 0, l1_b = 0, rounding_a = 0, rounding_b = 0;
        const Real qa = detail::panel_sum<plan::order_a>(panel, plan::a, nodes.a, x_stop, l1_a, rounding_a, calls);
        const Real qb = detail::panel_sum<plan::order_b>(panel, plan::b, nodes.b, x_stop, l1_b, rounding_b, calls);
        // Rounding: the nodes' own bounds, plus the sum's (a few ulps of the L1 norm).
        const Real rounding = Real((rounding_a + 4 * static_cast<detail::bound_type<Real>>(eps) * l1_a) * (1 + 1e-12L));

        // The tail beyond x_last (absent where the interval ends first): bounded by the
        // integrand at the cut times the decay length seen over the last 8 units, doubled.
        Real tail = 0;
        if (x_end > x_stop) {
            auto g = [&](const Real& x) { ++calls; return in_s(x / k); };
            const Real g_cut = abs(g(x_stop));
            const Real g_before = abs(g(x_stop - 8));
            const Real decay = g_before > g_cut && g_cut > 0 ? Real(std::log(static_cast<double>(g_before / g_cut)) / 8) : Real(0);
            const Real width = x_end - x_stop;
            Real length = decay > 0 ? 1 / decay : width;
            if (length > width) length = width;
            tail = 2 * g_cut * length;
        }
        const Real jacobian = 1 / (alpha * k);  // dt = dtheta / alpha, ds = dx / k
        estimate<Real> r;
        r.value = qa * jacobian;
        r.abs_error = (abs(qa - qb) + rounding + tail) * jacobian;
        r.evaluations = calls;
        return r;
    }

    // The integrand decays in s like exp(-(n + m) s), m a few units for the zoo's weights (the
    // cosines beside the lobe). Measured between two points of the lobe and clamped to
    // [n + 1, n + 8]; its m sets x = (n + m) s so that every integrand decays like e^-x on the panels.
    template <class G>
    static Real decay_rate(const G& in_s, const Real& n, const Real& s_end) {
        Real s0 = Real(0.5) / (n + 1), s1 = Real(1.5) / (n + 1);
        if (s1 > s_end / 2) s0 = s_end / 8, s1 = s_end / 2;
        const Real g0 = in_s(s0), g1 = in_s(s1);
        // only m = round(rate - n) is used: double's logarithm is accurate enough (1e-7 at n = 1e9)
        Real rate = g0 > 0 && g1 > 0 ? Real(std::log(static_cast<double>(g0 / g1)) / static_cast<double>(s1 - s0)) : n + 1;
        if (!(rate >= n + 1)) rate = n + 1;
        if (rate > n + 8) rate = n + 8;
        return rate;
    }

    template <class F>
    static constexpr bool tiered = (std::numeric_limits<Real>::digits > 64) &&
                                   std::is_invocable_v<const F&, const lobe_point<long double>&>;

    const Real eps = std::numeric_limits<Real>::epsilon();
    Real tolerance_ = 0;  // 0: the full plan alone
};

}  // namespace normzoo::quadrature
