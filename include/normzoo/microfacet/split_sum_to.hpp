// The split-sum pair (split_sum.hpp) to a tolerance asked per value: A to tol.a and B to tol.b,
// each returned with its bound (never below the true error), so that a check of an engine's
// table computes each texel to what its verdict needs and no more (docs/lut.md, "How a check
// chooses its accuracy"). split_sum() stays as it is: the committed tables are made with it.
//
// Where B is the integral over N.L with Schlick's factor in closed form (GGX, a G of N.L and N.V,
// alpha <= 1, both tolerances >= 1e-11: azimuthal_albedo.hpp), A and B come from one pass, two
// channels of the same nodes (A's integrand G (Phi - Phi5), B's G Phi5: the elliptic integrals of
// a node serve both, where split_sum() integrates A + B and B apart). Each channel is weighted by
// a power of two near 1/tolerance (exact), so that the panels stop when every channel meets its
// own tolerance. The variable is x = N.L - N.V = w sinh t around the peak (w = alpha (alpha +
// sin t_V) / 2, its width, or mu / 2 where less) and N.L = b sinh s next to the horizon (b =
// min(alpha, mu) / 2), or x = mu u below a peak at least mu / 2 wide: the peak, a ratio of powers
// of (x^2 + w^2), and its tails, powers of x, are smooth in t, so that a panel 3 wide on the peak
// and panels doubling away from it replace the panels graded 4x apart in x. All regions are one
// adaptive integral, so that the tolerance goes where the mass is. Gauss-Kronrod 15 from a
// tolerance of 1e-7, 21 from 1e-9, 31 below (the fewest evaluations at each); the bound is
// |K - G| and the rounding bound of azimuthal_albedo.hpp (docs/microfacet.md, "The split-sum pair
// to a tolerance", gives the measurements).
//
// At the edges of a corner-aligned table the pair takes its limits (docs/lut.md, "Edges"): at
// alpha = 0 the mirror's, A = 1 - (1 - mu)^5 and B = (1 - mu)^5 (D N.h d(omega_h) tends to a
// point mass at h = N, where V.h = N.L = mu and Smith's G is 1); at mu = 0 the integral over N.L
// with G / mu replaced by its limit (GGX: 2 / alpha for the height-correlated G, 2 G1(L) / alpha
// for the separable one); at both, A = 0 and B somewhere in [0, 1] (it has no limit there): 1/2
// +- 1/2. Limits are derived for Smith's two G only; other compositions are refused there.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "../quadrature/adaptive.hpp"
#include "../quadrature/channels.hpp"
#include "split_sum.hpp"

namespace normzoo::microfacet {

// What each value of the pair is asked to: an absolute tolerance on A and one on B.
struct split_sum_tolerance {
    double a = 1e-10, b = 1e-10;
};

namespace detail {

using split_sum_channels = quadrature::channels<double, 2>;  // (A, B)

// A power of two w with w * tolerance in [1, 2): a channel times w meets 1 where it meets its
// tolerance, and scaling by w rounds nothing.
inline double tolerance_weight(double tolerance) {
    int e = 0;
    (void)std::frexp(tolerance, &e);
    return std::ldexp(1.0, 1 - e);
}

// Whether c's G is one of Smith's exact two, and which: the edges' limits are derived for them.
inline bool smith_masking(const composition& c) {
    return c.g_part == index_of<masking_parts>("smith-height-correlated") || c.g_part == index_of<masking_parts>("smith-separable");
}

// The integrand of the pair over N.L at cos t_V = mu (mu = 0: its limit there), weighted. GGX's
// D and D (1 - V.h)^5 over L's azimuth come from one set of elliptic integrals
// (ggx_schlick_azimuth.hpp), and sin t_L from one square root shared with the masking.
struct split_sum_integrand {
    enum class smith { none, height_correlated, separable };
    const composition& c;
    composition::view_terms<double> view;
    double mu, sv, alpha, scale;  // scale: 1 / (4 mu), or at mu = 0 the limit of G / (4 mu) for Smith's G
    double wa, wb;                // the channels' weights
    bool grazing;
    smith g_kind;  // Smith's two G compiled in (GGX's Lambda called directly); the others through view

    double masking(double nl, double sl) const {
        const vec3<double> l(sl, 0, nl);
        if (g_kind == smith::none) {
            shading<double> s;
            s.nl = nl, s.nv = mu;
            s.nm = s.vm = std::numeric_limits<double>::quiet_NaN();  // read by no G that comes here
            return c.masking(s, l, view);
        }
        const double lambda_l = d_ggx::lambda(l, view.np);
        // at mu = 0, lim G / mu = 1 / lim (mu Lambda(mu)) = 2 / alpha (in scale), times G1(L) for
        // the separable G
        if (grazing) return g_kind == smith::separable ? 1 / (1 + lambda_l) : 1.0;
        return g_kind == smith::separable ? 1 / ((1 + lambda_l) * (1 + view.lambda_v)) : 1 / (1 + lambda_l + view.lambda_v);
    }

    // A node: N.L = nl, sin^2 t_L = sl2, N.L - N.V = x (exact from the variable), the Jacobian jac.
    struct node {
        double nl, sl2, x, jac;
    };
    using value = quadrature::estimate<split_sum_channels>;

    value operator()(const node& n) const { return (*this)(std::array<node, 1>{n})[0]; }

    // A panel's nodes at once: their elliptic integrals side by side (ggx_schlick_azimuth.hpp).
    template <std::size_t N>
    std::array<value, N> operator()(const std::array<node, N>& at) const {
        const double eps = std::numeric_limits<double>::epsilon();
        std::array<double, N> nl, x, sl;
        for (std::size_t i = 0; i < N; ++i) nl[i] = at[i].nl, x[i] = at[i].x, sl[i] = std::sqrt(at[i].sl2);
        const auto phi = ggx_schlick_azimuthal_integrals_at<N>(nl, mu, x, sl, sv, alpha);  // D's and D (1 - V.h)^5's
        std::array<value, N> out;
        for (std::size_t i = 0; i < N; ++i) {
            const double g = masking(nl[i], sl[i]) * scale * at[i].jac;
            const double ga = std::abs(g) * wa, gb = std::abs(g) * wb, d = phi[i].d, d5 = phi[i].d5;
            split_sum_channels v, error;
            v[0] = g * wa * (d - d5);
            v[1] = g * wb * d5;
            // 56 ulps: azimuthal_albedo.hpp's 48 for G and the products, and the Jacobian's
            // rounding; D's integral's own 64 (ggx_schlick_azimuth.hpp)
            error[0] = ga * (56 * eps * (d + std::abs(d5)) + 64 * eps * d + phi[i].d5_error);
            error[1] = gb * (56 * eps * std::abs(d5) + phi[i].d5_error);
            out[i] = {v, error, 1};
        }
        return out;
    }
};

// Breakpoints over [lo, hi] (lo <= 0 <= hi): a panel `step` wide centred on 0 (the peak, smooth
// in t), then panels twice as wide as the one before away from it (the tails), an end panel
// shorter than step / 2 joined to its neighbour.
inline std::vector<double> graded_breaks(double lo, double hi, double step) {
    std::vector<double> b;
    for (double d = step, at = -step / 2; at > lo; d *= 2) b.insert(b.begin(), at), at -= d;
    for (double d = step, at = step / 2; at < hi; d *= 2) b.push_back(at), at += d;
    while (!b.empty() && b.front() - lo < step / 2) b.erase(b.begin());
    while (!b.empty() && hi - b.back() < step / 2) b.pop_back();
    b.insert(b.begin(), lo);
    b.push_back(hi);
    return b;
}

// The pair over N.L in one pass (see above), for GGX.
template <unsigned Points>
split_sum_value split_sum_over_nl(const composition& c, double mu, double alpha, split_sum_tolerance tol, std::size_t max_panels) {
    constexpr double step = 3;  // in t, next to the peak (2, 3, 4 and 6 measured: docs/microfacet.md)
    using integrand = split_sum_integrand;
    const double eps = std::numeric_limits<double>::epsilon();
    const double sv2 = (1 - mu) * (1 + mu), sv = std::sqrt(sv2);
    const bool grazing = mu == 0;
    const brdf::params<double> p{0, 1.0, alpha};
    const auto g_kind = c.g_part == index_of<masking_parts>("smith-height-correlated") ? integrand::smith::height_correlated
                        : c.g_part == index_of<masking_parts>("smith-separable")       ? integrand::smith::separable
                                                                                         : integrand::smith::none;
    const integrand f{c, c.at_view(vec3<double>(sv, 0, mu), p), mu, sv, alpha, grazing ? 1 / (2 * alpha) : 1 / (4 * mu),
                      tolerance_weight(tol.a), tolerance_weight(tol.b), grazing, g_kind};
    // w: the peak's width, or mu / 2 where that is less: there (mu < alpha) Smith's G turns where
    // N.L ~ N.V, Lambda(L) ~ Lambda(V), a feature of width mu at the peak (mu = 0: G / mu has none)
    const double peak = alpha * (alpha + sv) / 2, w = grazing ? peak : std::min(peak, mu / 2);
    const double one_minus_mu = 1 - mu, b = std::min(alpha, mu) / 2;
    using node = integrand::node;
    auto in_t = [&](double t) {  // x = w sinh t
        const double e = std::exp(t), inv = 1 / e, x = w * (e - inv) / 2, nl = mu + x;
        return node{nl, (one_minus_mu - x) * (1 + nl), x, w * (e + inv) / 2};
    };
    // Below the peak, one of two variables on [lo, 0) ahead of t's range [0, hi] (or t's own
    // negative side), so that one adaptive integral chooses its panels across all of them: a
    // region with little in it takes little of the tolerance.
    const bool narrow = grazing || w < mu / 2;
    std::vector<double> breaks;
    double t_lo = 0, s_top = 0;
    if (narrow) {  // around the peak in t, the horizon in s = u - (t_lo - s_top), N.L = b sinh s
        t_lo = std::asinh(-mu / 2 / w), s_top = grazing ? 0 : std::asinh(mu / 2 / b);
        breaks = graded_breaks(t_lo, std::asinh(one_minus_mu / w), step);
        if (!grazing) breaks.insert(breaks.begin(), t_lo - s_top);
    } else {  // the peak at least mu / 2 wide: below it x = mu u, u in [-1, 0) (a node's place
              // relative to the peak errs by an ulp of mu, 2 ulps of the width), above it t
        breaks = graded_breaks(0.0, std::asinh(one_minus_mu / w), step);
        breaks.insert(breaks.begin(), -1.0);
    }
    auto node_at = [&](double u) {
        if (u >= t_lo) return in_t(u);
        if (narrow) {
            const double e = std::exp(u - (t_lo - s_top)), inv = 1 / e, nl = b * (e - inv) / 2;
            return node{nl, (1 - nl) * (1 + nl), nl - mu, b * (e + inv) / 2};
        }
        const double nl = mu * (1 + u);  // 1 + u exact for u <= -1/2, an ulp of >= 1/2 above
        return node{nl, (1 - nl) * (1 + nl), mu * u, mu};
    };
    // one node, or a panel's nodes at once (quadrature/adaptive.hpp)
    auto in_u = [&](const auto& u) {
        if constexpr (std::is_same_v<std::decay_t<decltype(u)>, double>) {
            return f(node_at(u));
        } else {
            std::array<node, std::tuple_size_v<std::decay_t<decltype(u)>>> nodes;
            for (std::size_t i = 0; i < nodes.size(); ++i) nodes[i] = node_at(u[i]);
            return f(nodes);
        }
    };
    const quadrature::adaptive_kronrod<double, Points> rule(max_panels);
    // the weighted channels meet 1 together
    const auto total = rule.integrate(quadrature::nodes_at_once<decltype(in_u)>{in_u}, breaks, 1.0, 0.0);
    split_sum_value r;
    const double weight[2] = {f.wa, f.wb};
    quadrature::estimate<double>* out[2] = {&r.a, &r.b};
    for (int ch = 0; ch < 2; ++ch) {
        const double v = total.value[ch] / weight[ch];
        *out[ch] = {v, total.abs_error[ch] / weight[ch] + 4 * eps * std::abs(v), total.evaluations};
    }
    return r;
}

// The same with the rule the least tolerance takes (docs/microfacet.md, "The split-sum pair to a
// tolerance": the fewest evaluations measured at each).
inline split_sum_value split_sum_over_nl(const composition& c, double mu, double alpha, split_sum_tolerance tol, std::size_t max_panels) {
    const double least = std::min(tol.a, tol.b);
    if (least >= 1e-7) return split_sum_over_nl<15>(c, mu, alpha, tol, max_panels);
    if (least >= 1e-9) return split_sum_over_nl<21>(c, mu, alpha, tol, max_panels);
    return split_sum_over_nl<31>(c, mu, alpha, tol, max_panels);
}

// The pair at alpha = 0 or mu = 0 (see above), for Smith's G; std::invalid_argument otherwise.
inline split_sum_value split_sum_edge(const composition& c, double mu, double alpha, split_sum_tolerance tol, std::size_t max_panels) {
    const double eps = std::numeric_limits<double>::epsilon();
    const bool exact_lambda =
        visit_part<distribution_parts, bool>(c.d_part, [](auto part) { return decltype(part)::has_exact_lambda; });
    if (!smith_masking(c) || !exact_lambda)
        throw std::invalid_argument("the split-sum pair's limits at alpha = 0 and mu = 0 are derived for Smith's G of a D "
                                    "with Smith's Lambda only, not for " + c.id);
    split_sum_value r;
    if (alpha == 0 && mu == 0) {  // A -> 0 on every path to the corner; B has no limit
        r.a = {0, 0, 0};
        r.b = {0.5, 0.5, 0};
        return r;
    }
    if (alpha == 0) {  // the mirror: B = (1 - mu)^5, A = 1 - B; 1 - mu and four products round
        const double b = pow5(1 - mu);
        r.b = {b, 8 * eps * b, 0};
        r.a = {1 - b, 8 * eps * b + eps, 0};
        return r;
    }
    if (!(alpha <= 1) || !(std::min(tol.a, tol.b) >= 1e-11) || c.d_part != index_of<distribution_parts>("ggx"))
        throw std::invalid_argument("the split-sum pair at mu = 0 is derived for GGX up to alpha = 1, at tolerances of "
                                    "1e-11 or more, not for " + c.id);
    return split_sum_over_nl(c, 0.0, alpha, tol, max_panels);
}

}  // namespace detail

// A and B of the composition's D and G (its F part is replaced, as in split_sum()) at mu and
// alpha, A to tol.a and B to tol.b absolute. mu = 0 and alpha = 0 (a table's edges) take the
// limits above; otherwise std::invalid_argument where split_sum() refuses (mu below 1e-8, alpha
// below 1e-8), and for a tolerance that is not > 0.
inline split_sum_value split_sum_to(const composition& c, double mu, double alpha, split_sum_tolerance tol,
                                    std::size_t max_panels = 400) {
    if (!(tol.a > 0 && tol.b > 0)) throw std::invalid_argument("a split-sum tolerance must be > 0");
    composition schlick = c;
    schlick.f_part = detail::index_of<fresnel_parts>("schlick");
    schlick.compensation = composition::compensation_kind::none;
    if ((mu == 0 && alpha >= 0) || (alpha == 0 && mu > 0 && mu <= 1)) return detail::split_sum_edge(schlick, mu, alpha, tol, max_panels);
    detail::check_incidence(mu, alpha);
    const double least = std::min(tol.a, tol.b);
    if (!detail::in_closed_azimuth(schlick, alpha, least) || schlick.d_part != detail::index_of<distribution_parts>("ggx"))
        return split_sum(c, mu, alpha, albedo_settings{least, max_panels});
    return detail::split_sum_over_nl(schlick, mu, alpha, tol, max_panels);
}

}  // namespace normzoo::microfacet
