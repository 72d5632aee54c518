// The sheen lobe's directional albedo E(y) over the whole of N.L = y in (0, 1] for one alpha,
// built once from exact E (sheen.hpp's sheen_albedo) and then read at any y for a few hundred
// nanoseconds (docs/materials.md, "E as a curve"). The albedo scaling needs E at every node of
// an outer integral over N.L, a thousand to four thousand of them a point, and each exact E is a
// 2D integral of 1 to 15 ms; E depends on the sheen's alpha alone, so one curve serves every
// point, every lobe and every incidence of a material.
//
// Pieces of Chebyshev series, each in a variable where E is smooth:
//   (0, 1/8]     t = ln y, the series of y E(y): E grows like y^-0.93 toward the horizon and the
//                fitted Lambda has terms in y^c (c ~ 0.2 to 0.5), all of them exp(k t) in t
//   [1/8, 1/2], [1/2, 7/8]
//                t = y, the series of E (Lambda's fit changes branch at 1/2: E is C^1 there)
//   [7/8, 1)     t = ln(1 - y), the series of E (Lambda's terms in (1 - y)^c); E(1) apart.
// Each piece is bisected until its series meets the tolerance (Boyd, "Chebyshev and Fourier
// Spectral Methods", 2.12: the last coefficients measure the truncation). The bound at a y:
//     2 (|c_(n-2)| + |c_(n-1)| + |c_n|)     the truncation and its aliasing in the interpolant
//   + sum_k |d_k| |l_k(x)|                  the exact E's own bounds d_k at the nodes through the
//                                           Lagrange basis l_k at x (barycentric, Berrut and
//                                           Trefethen 2004): a node's bound weighs near it, so a
//                                           piece over y from 1e-10 to 1e-5 keeps each end's own
//                                           bound; each d_k also holds twice the series' slope times
//                                           the shift of t_k that rounding its y makes (1 - y near
//                                           1e-15 moves by up to half of itself, E like (1 - y)^c)
//   + 4 n eps sum |c_k|                     Clenshaw's rounding
// and each piece is checked at four points between its nodes against exact E: a piece whose
// series misses one by more than the bound there and the point's own bound is bisected as well
// (a steep piece, E falling to 1e-150 near y = 1 at alpha 1e-3, has its last coefficients below
// the error of its ends); at the deepest level its bound becomes twice the largest miss. Below
// y = 1e-10 (where the outer integrals' weights are about y, so that it holds 1e-17 of them) E
// is only enclosed: y E(y) in [0, y_lo E(y_lo)], y E(y) rising from 0 there (measured for alpha
// 1e-3 to 1 from 1e-14 up: E grows like y^-0.93).
// Once built, each piece is cut where its series is proven monotone (find_stretches), so that
// crossings() finds every y where the curve crosses a level, the kinks of max(0, E - E_v), or
// says that it may not have (a level within a stretch not proven monotone).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

#include <boost/math/special_functions/chebyshev.hpp>

#include "../microfacet/masking.hpp"
#include "../quadrature/estimate.hpp"
#include "sheen.hpp"

namespace normzoo::material {

template <class G = microfacet::g_charlie_sheen>
class sheen_albedo_curve {
public:
    static constexpr std::size_t degree = 24;
    static constexpr double y_lo = 1e-10, low_end = 0.125, high_start = 0.875;

    // E for the sheen's alpha (sheenRoughness^2, in [1e-3, 1]), to `tolerance` times max(1, E).
    sheen_albedo_curve(double alpha, double tolerance) : alpha_(alpha), tolerance_(tolerance) {
        const double eps = std::numeric_limits<double>::epsilon();
        for (std::size_t k = 0; k <= degree; ++k) {
            const double th = pi<double>() * (k + 0.5) / (degree + 1);
            node_x_[k] = std::cos(th), node_w_[k] = (k % 2 ? -1 : 1) * std::sin(th);
        }
        fit(region::low, std::log(y_lo), std::log(low_end), 0);
        fit(region::middle, low_end, 0.5, 0);
        fit(region::middle, 0.5, high_start, 0);
        fit(region::high, std::log(eps / 2), std::log(1 - high_start), 0);
        e_at_1_ = sheen_albedo<G>(1.0, alpha_, tolerance_ / 4);
        evaluations_ += e_at_1_.evaluations;
        find_stretches();
    }

    double alpha() const { return alpha_; }
    double tolerance() const { return tolerance_; }
    // E's evaluations the curve took to build (exact E at every node and check point)
    std::size_t evaluations() const { return evaluations_; }
    std::size_t pieces() const { return pieces_.size(); }

    // E(y) and its bound, y in (0, 1]; evaluations 0 (the curve is built).
    quadrature::estimate<double> operator()(double y) const {
        if (y >= 1) return {e_at_1_.value, e_at_1_.abs_error, 0};
        if (y < y_lo) {  // the enclosure: 0 <= y E(y) <= y_lo E(y_lo)
            const auto at_lo = series(region::low, std::log(y_lo));
            const double top = at_lo.value + at_lo.abs_error;
            return {top / (2 * y), top / (2 * y), 0};
        }
        if (y < low_end) {
            const auto h = series(region::low, std::log(y));
            return {h.value / y, h.abs_error / y + 2 * std::numeric_limits<double>::epsilon() * std::abs(h.value / y), 0};
        }
        if (y <= high_start) return series(region::middle, y);
        return series(region::high, std::log1p(-y));
    }

    // |dE/dy| at y from the series' derivative: what a rounding of y moves E by, per unit of y
    // (a caller whose y is itself rounded, N.L from a half vector).
    double slope(double y) const {
        if (y < y_lo) {  // E <= y_lo E(y_lo) / y, and its slope about that over y
            const auto at_lo = series(region::low, std::log(y_lo));
            return (at_lo.value + at_lo.abs_error) / (y * y);
        }
        const double top = std::nextafter(1.0, 0.0);
        if (y < low_end) {  // the value alone: its bound (through the nodes) is not read here
            const piece& p = piece_at(region::low, std::log(y));
            const double x = x_in(p, std::log(y));
            const double h = boost::math::chebyshev_clenshaw_recurrence(p.c.data(), p.c.size(), x);
            const double dh = boost::math::chebyshev_clenshaw_recurrence(p.d.data(), p.d.size(), x);
            return std::abs(dh - h) / (y * y);
        }
        if (y <= high_start) return std::abs(derivative(region::middle, y));
        const double z = std::min(y, top);
        return std::abs(derivative(region::high, std::log1p(-z))) / (1 - z);
    }

    // The y in (0, 1) where the curve crosses `level` (docs/materials.md, "E as a curve"): the
    // curve is cut where it was proven monotone when built, so that each stretch crosses at most
    // once, where its ends straddle the level (found on its series to 1e-14 of t); a stretch not
    // proven so (1e-12 of t wide or less: about an extremum of E) is searched on a grid of 32 as
    // well unless that narrow, and where its enclosure holds the level it may cross more often
    // than that finds: `complete` (if given) then says false. Two pieces' series differ at their join by up to their bounds, so a join
    // crosses where its two sides straddle the level; below y_lo the enclosure falls as 1/y.
    std::vector<double> crossings(double level, bool* complete = nullptr) const {
        std::vector<double> out;
        if (complete) *complete = true;
        const auto at_lo = series(region::low, std::log(y_lo));
        const double top = (at_lo.value + at_lo.abs_error) / 2;  // y E(y) below y_lo, as (*this) reads it
        if (level > top / y_lo) out.push_back(top / level);
        double before = top / y_lo;  // E just below the stretch's lower end
        const piece* before_in = nullptr;
        for (const stretch& s : stretches_) {
            const piece& p = pieces_[s.piece];
            const double e_a = e_at(p, s.ta), e_b = e_at(p, s.tb);
            const bool falls_in_t = p.in == region::high;  // t = ln(1 - y)
            if (before_in != &p && (before > level) != ((falls_in_t ? e_b : e_a) > level)) out.push_back(s.ya);
            const bool narrow = s.monotone || std::abs(s.tb - s.ta) < 1e-12 * std::max(1.0, std::abs(s.ta));
            const int steps = narrow ? 1 : 32;
            if (!s.monotone && complete && level >= s.e_lo && level <= s.e_hi) *complete = false;
            for (int k = 0; k < steps; ++k) {
                const double ta = k == 0 ? s.ta : s.ta + (s.tb - s.ta) * k / steps;
                const double tb = k + 1 == steps ? s.tb : s.ta + (s.tb - s.ta) * (k + 1) / steps;
                crossing_in(p, ta, tb, level, out);
            }
            before = falls_in_t ? e_a : e_b, before_in = &p;
        }
        std::sort(out.begin(), out.end());
        return out;
    }

private:
    enum class region { low, middle, high };
    struct piece {
        region in;
        double a, b;
        std::vector<double> c;
        double bound;                  // truncation, rounding and the check points' misses
        std::vector<double> node_bound;  // the exact E's bounds at the nodes
        std::vector<double> d;           // the series of its derivative in its own variable
    };

    // a stretch of one piece, t in [ta, tb], y in [ya, yb], where its series is monotone (or
    // was not proven so: then E within [e_lo, e_hi] over it)
    struct stretch {
        std::size_t piece;
        double ta, tb, ya, yb;
        bool monotone;
        double e_lo, e_hi;
    };

    double y_of(region in, double t) const {
        return in == region::low ? std::exp(t) : in == region::high ? -std::expm1(t) : t;
    }
    // the fitted function at t, y E(y) in the low region and E elsewhere, from exact E to a
    // sixteenth of the tolerance times max(1, E) (E grows like y^-0.93 toward the horizon: 1e4 at
    // y = 1e-12, where an absolute 1e-12 is below its rounding), with its bound; `at` the t of the
    // y it took (y rounded: 1 - y near 1e-15 moves by up to half of itself, and E like (1 - y)^c)
    quadrature::estimate<double> fitted(region in, double t, double& at) {
        const double y = y_of(in, t);
        at = in == region::low ? std::log(y) : in == region::high ? std::log1p(-y) : y;
        double scale = 1;
        if (in == region::low) {
            const auto quick = sheen_albedo<G>(y, alpha_, 1e-3);
            evaluations_ += quick.evaluations;
            scale = std::max(1.0, quick.value - quick.abs_error);
        }
        const auto e = sheen_albedo<G>(y, alpha_, tolerance_ / 16 * scale);
        evaluations_ += e.evaluations;
        const double w = in == region::low ? y : 1.0;
        return {w * e.value, w * e.abs_error + 2 * std::numeric_limits<double>::epsilon() * w * e.value, e.evaluations};
    }
    void fit(region in, double a, double b, int depth);
    void find_stretches();
    // The y where p's series crosses `level` on [ta, tb], if its ends straddle it: the Illinois
    // form of regula falsi (Dowell and Jarratt 1971), which keeps the crossing bracketed, to
    // 1e-14 of t.
    void crossing_in(const piece& p, double ta, double tb, double level, std::vector<double>& out) const {
        double a = ta, b = tb, fa = e_at(p, a) - level, fb = e_at(p, b) - level;
        if ((fa > 0) == (fb > 0)) return;
        for (int k = 0, kept_side = 0; k < 100 && std::abs(b - a) > 1e-14 * std::max(1.0, std::abs(a)); ++k) {
            double c = (a * fb - b * fa) / (fb - fa);
            if (!(c > std::min(a, b) && c < std::max(a, b))) c = a + (b - a) / 2;
            const double fc = e_at(p, c) - level;
            if (fc == 0) {
                a = b = c;
                break;
            }
            if ((fc > 0) == (fa > 0)) {  // a moves: b's value halved if a moved last time too
                a = c, fa = fc;
                if (kept_side == -1) fb /= 2;
                kept_side = -1;
            } else {
                b = c, fb = fc;
                if (kept_side == 1) fa /= 2;
                kept_side = 1;
            }
        }
        out.push_back(y_of(p.in, a + (b - a) / 2));
    }
    // E at t from piece p's series alone (its value, no bound)
    double e_at(const piece& p, double t) const {
        const double v = boost::math::chebyshev_clenshaw_recurrence(p.c.data(), p.c.size(), x_in(p, t));
        return p.in == region::low ? v / std::exp(t) : v;
    }
    const piece& piece_at(region in, double t) const;
    quadrature::estimate<double> series(region in, double t) const;
    // t's place in its piece, in [-1, 1]
    static double x_in(const piece& p, double t) { return std::clamp((2 * t - p.a - p.b) / (p.b - p.a), -1.0, 1.0); }
    double derivative(region in, double t) const {
        const piece& p = piece_at(in, t);
        return boost::math::chebyshev_clenshaw_recurrence(p.d.data(), p.d.size(), x_in(p, t));
    }
    // sum_k |node_bound_k| |l_k(x)| at x in [-1, 1] of the piece
    double through_nodes(const piece& p, double x) const;

    double alpha_, tolerance_;
    std::vector<piece> pieces_;  // in order of t within each region
    std::vector<stretch> stretches_;  // in order of y, covering [y_lo, 1 - eps/2]
    quadrature::estimate<double> e_at_1_;
    std::size_t evaluations_ = 0;
    double node_x_[degree + 1], node_w_[degree + 1];  // the nodes in [-1, 1], their barycentric weights
};

// Interpolates at the n + 1 Chebyshev points of the first kind on [a, b]; bisects where the
// tail or a check point between the nodes misses the tolerance (at most 12 levels deep).
template <class G>
void sheen_albedo_curve<G>::fit(region in, double a, double b, int depth) {
    constexpr std::size_t n = degree;
    const double pi_ = pi<double>(), eps = std::numeric_limits<double>::epsilon();
    const double mid = (a + b) / 2, half = (b - a) / 2;
    // the piece's target: the tolerance in E, times max(1, E) (in y E below 1/8: times max(y, y E))
    double f[n + 1], shift[n + 1], target = in == region::low ? std::exp(a) : 1.0;
    piece p{in, a, b, std::vector<double>(n + 1), 0, std::vector<double>(n + 1), {}};
    for (std::size_t k = 0; k <= n; ++k) {
        double at = 0;
        const double t = mid + half * node_x_[k];
        const auto v = fitted(in, t, at);
        f[k] = v.value, p.node_bound[k] = v.abs_error, shift[k] = std::abs(at - t);
    }
    if (in == region::low) target = std::max(target, *std::min_element(f, f + n + 1));
    target *= tolerance_;
    double sum = 0;
    for (std::size_t j = 0; j <= n; ++j) {
        double s = 0;
        for (std::size_t k = 0; k <= n; ++k) s += f[k] * std::cos(pi_ * j * (k + 0.5) / (n + 1));
        p.c[j] = 2 * s / (n + 1), sum += std::abs(p.c[j]);
    }
    // the derivative's series in t (Numerical Recipes' chder): d_j = d_(j+2) + 2 (j + 1) c_(j+1)
    p.d.assign(n + 1, 0.0);
    for (std::size_t j = n; j-- > 0;) p.d[j] = (j + 2 <= n ? p.d[j + 2] : 0.0) + 2.0 * (j + 1) * p.c[j + 1];
    for (double& dj : p.d) dj /= half;
    // a node's value is E at the t its rounded y has: twice the series' slope times that shift
    for (std::size_t k = 0; k <= n; ++k)
        p.node_bound[k] += 2 * std::abs(boost::math::chebyshev_clenshaw_recurrence(p.d.data(), n + 1, node_x_[k])) * shift[k];
    const double tail = std::abs(p.c[n - 2]) + std::abs(p.c[n - 1]) + std::abs(p.c[n]);
    p.bound = 2 * tail + 4 * n * eps * sum;
    bool split = depth < 12 && 4 * tail > target;
    for (double x : {-0.99, -0.5, 0.3, 0.99}) {  // between nodes: the interpolant misses most near the ends
        if (split) break;
        double at = 0;
        const auto truth = fitted(in, mid + half * x, at);
        const double xa = x_in(p, at);  // where its rounded y is
        const double miss = std::abs(boost::math::chebyshev_clenshaw_recurrence(p.c.data(), n + 1, xa) - truth.value);
        const double within = p.bound + through_nodes(p, xa) + truth.abs_error;
        if (miss > within && depth < 12) split = true;
        if (miss > within) p.bound = std::max(p.bound, 2 * miss + truth.abs_error);  // 12 levels deep
    }
    if (split) {
        fit(in, a, mid, depth + 1);
        fit(in, mid, b, depth + 1);
        return;
    }
    pieces_.push_back(std::move(p));
}

// Each piece cut where its series is monotone in y: E's slope in t has the sign of a series q
// (the derivative's, less the series itself in y E(y) below 1/8: E = h e^-t there), and q has no
// root on [x - r, x + r] where |q(x)| exceeds its largest change there, r max|q'| or
// r |q'(x)| + r^2 max|q''| / 2 (Taylor), with the rounding of q(x) and q'(x); max|q'| and max|q''|
// at most the sums of their series' |coefficients|. A part not proven so is halved until it is
// 1e-14 of the piece wide (about a root of q) or the piece has taken 4096 halvings; it is then a
// stretch of its own, not monotone, with an enclosure of E over it (the series at its middle, give
// or take r max|f'|). Proven parts of one sign are joined.
template <class G>
void sheen_albedo_curve<G>::find_stretches() {
    constexpr std::size_t n = degree;
    const double eps = std::numeric_limits<double>::epsilon();
    struct part {
        double a, b;
        int sign;  // q's, 0 where not proven
    };
    auto derivative_of = [](const std::vector<double>& c) {  // in x (Numerical Recipes' chder)
        std::vector<double> d(n + 1, 0.0);
        for (std::size_t j = n; j-- > 0;) d[j] = (j + 2 <= n ? d[j + 2] : 0.0) + 2.0 * (j + 1) * c[j + 1];
        return d;
    };
    auto sum_abs = [](const std::vector<double>& c) {
        double t = 0;
        for (double x : c) t += std::abs(x);
        return t;
    };
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
        const piece& p = pieces_[i];
        std::vector<double> q = p.d;
        if (p.in == region::low)
            for (std::size_t k = 0; k <= n; ++k) q[k] -= p.c[k];
        const std::vector<double> dq = derivative_of(q), d2q = derivative_of(dq), df = derivative_of(p.c);
        const double m1 = sum_abs(dq), m2 = sum_abs(d2q), m1f = sum_abs(df);
        const double rounding = 4 * (n + 1) * eps * sum_abs(q), rounding1 = 4 * (n + 1) * eps * m1;
        const double rounding_f = 4 * (n + 1) * eps * sum_abs(p.c);
        std::vector<part> parts, todo{{-1, 1, 0}};  // todo: the leftmost last
        for (int halvings = 0; !todo.empty();) {
            const part u = todo.back();
            todo.pop_back();
            const double mid = (u.a + u.b) / 2, r = (u.b - u.a) / 2;
            const double qm = boost::math::chebyshev_clenshaw_recurrence(q.data(), n + 1, mid);
            const double dqm = boost::math::chebyshev_clenshaw_recurrence(dq.data(), n + 1, mid);
            const double change = std::min(r * m1, r * (std::abs(dqm) + rounding1) + r * r * m2 / 2);
            const int sign = std::abs(qm) > change + rounding ? (qm > 0 ? 1 : -1) : 0;
            if (sign == 0 && r >= 1e-14 && halvings < 4096) {
                ++halvings;
                todo.push_back({mid, u.b, 0}), todo.push_back({u.a, mid, 0});
                continue;
            }
            if (!parts.empty() && parts.back().sign == sign) parts.back().b = u.b;
            else parts.push_back({u.a, u.b, sign});
        }
        const double mid_t = (p.a + p.b) / 2, half_t = (p.b - p.a) / 2;
        for (const part& u : parts) {
            const double ta = u.a == -1 ? p.a : mid_t + half_t * u.a, tb = u.b == 1 ? p.b : mid_t + half_t * u.b;
            const double y1 = y_of(p.in, ta), y2 = y_of(p.in, tb);
            stretch st{i, ta, tb, std::min(y1, y2), std::max(y1, y2), u.sign != 0, 0, 0};
            if (!st.monotone) {  // f within fm -+ r max|f'|; E = f there, f / y below 1/8
                const double fm = boost::math::chebyshev_clenshaw_recurrence(p.c.data(), n + 1, (u.a + u.b) / 2);
                // twice the series' rounding (fm's and a node's), and 8 ulps for e^t and the division
                const double spread = (u.b - u.a) / 2 * m1f + 2 * rounding_f;
                const double lo = fm - spread, hi = fm + spread;
                const double e_lo = p.in == region::low ? std::min(lo / st.ya, lo / st.yb) : lo;
                const double e_hi = p.in == region::low ? std::max(hi / st.ya, hi / st.yb) : hi;
                st.e_lo = e_lo - 8 * eps * std::abs(e_lo), st.e_hi = e_hi + 8 * eps * std::abs(e_hi);
            }
            stretches_.push_back(st);
        }
    }
    std::sort(stretches_.begin(), stretches_.end(), [](const stretch& a, const stretch& b) { return a.ya < b.ya; });
}

template <class G>
const typename sheen_albedo_curve<G>::piece& sheen_albedo_curve<G>::piece_at(region in, double t) const {
    const piece* p = nullptr;
    for (const piece& q : pieces_)
        if (q.in == in && t >= q.a && t <= q.b) return q;
    // at the region's ends by rounding: its nearest piece
    for (const piece& q : pieces_)
        if (q.in == in && (!p || std::min(std::abs(t - q.a), std::abs(t - q.b)) < std::min(std::abs(t - p->a), std::abs(t - p->b))))
            p = &q;
    return *p;
}

template <class G>
quadrature::estimate<double> sheen_albedo_curve<G>::series(region in, double t) const {
    const piece& p = piece_at(in, t);
    const double x = x_in(p, t);
    const double v = boost::math::chebyshev_clenshaw_recurrence(p.c.data(), p.c.size(), x);
    return {v, p.bound + through_nodes(p, x), 0};
}

template <class G>
double sheen_albedo_curve<G>::through_nodes(const piece& p, double x) const {
    double num = 0, den = 0;
    for (std::size_t k = 0; k <= degree; ++k) {
        if (x == node_x_[k]) return p.node_bound[k];
        const double w = node_w_[k] / (x - node_x_[k]);
        num += std::abs(w) * p.node_bound[k], den += w;
    }
    // 8 eps for the sum's rounding, relative to what it bounds
    return num / std::abs(den) * (1 + 8 * std::numeric_limits<double>::epsilon());
}

// The curve for alpha and tolerance, built on this thread's first call for them and kept (the
// last eight): a sweep over incidence and the base's parameters builds it once. `built` says
// whether this call built it (its evaluations are then this call's).
template <class G = microfacet::g_charlie_sheen>
std::shared_ptr<const sheen_albedo_curve<G>> sheen_curve_for(double alpha, double tolerance, bool* built = nullptr) {
    thread_local std::vector<std::shared_ptr<const sheen_albedo_curve<G>>> kept;
    if (built) *built = false;
    for (const auto& c : kept)
        if (c->alpha() == alpha && c->tolerance() == tolerance) return c;
    if (kept.size() == 8) kept.erase(kept.begin());
    kept.push_back(std::make_shared<const sheen_albedo_curve<G>>(alpha, tolerance));
    if (built) *built = true;
    return kept.back();
}

}  // namespace normzoo::material
