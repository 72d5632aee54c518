// The albedo at V of lobes weighted by functions of V.H alone, with the half vector in polar
// coordinates about V (docs/materials.md, "Weights of V.H: the half vector about V"). With
// V = (sin t_v, 0, cos t_v), cos t_v = mu, and h = cos b V + sin b (cos g T + sin g B),
// T = (-mu, 0, sin t_v), B = (0, 1, 0), V.h = cos b, and d(omega_L) = 4 V.h d(omega_h), so that
//     integral over L of F(V.h) f N.L d(omega_L) = integral_0^(pi/2) F(cos b) K(b) sin b db,
//     K(b) = 4 cos b integral over g of f N.L dg      (over the arc where N.L > 0),
// the lobe's kernel K free of F: a weight that is costly (a thin film's Fresnel, two spectral
// sums and their rounding in extended precision) is evaluated once a node of b, not once a node
// of a 2D integral, and its kinks in V.H are breakpoints in b. For GGX's specular_brdf,
// f N.L = D G / (4 N.V): K = (cos b / mu) integral D G dg, one adaptive integral in g; for
// Lambert, f = 1/pi: K = (4 cos b / pi) integral N.L dg, in closed form.
//
// The arc: N.h = cos b mu + sin b sin t_v cos g and N.L = 2 cos b N.h - mu, so N.L > 0 for
// cos g > -mu / (sin t_v tan 2b): the whole circle up to b1 = asin(mu)/2, none beyond
// b2 = pi/2 - asin(mu)/2 (microfacet/stretched.hpp has the same events about N). Between them the
// arc's end moves like the square root of the distance to b1 and b2: there
// b = b1 + (b2 - b1)(1 - cos(pi s))/2 makes the kernel smooth in s. D's peak is at b = t_v, g = 0,
// alpha wide in b and alpha / sqrt(sin b sin t_v) in g: breakpoints graded from there.
//
// Rounding: D reads tan^2 of h, whose tangential part h_x = sin(t_v - b) + 2 sin b mu sin^2(g/2)
// is taken without cancellation (sin(t_v - b) as sin t_v cos b - mu sin b by a difference of
// products with one fused multiply-add, Kahan's), so that a narrow lobe (alpha 1e-8) keeps its
// relative accuracy at its peak; each node bounds its own relative error from the magnitudes of
// the terms that cancel (h_x, N.h and N.L), as microfacet/albedo.hpp's nodes do.
//
// A factor of N.L on the lobes (the sheen's max(0, E(N.L) - E_v), sheen_nodes.hpp) multiplies
// both kernels' integrands: Lambert's is then integrated in g too. Its kinks in N.L are
// breakpoints in g (N.L = y at cos g = ((y + mu) / (2 cos b) - cos b mu) / (sin b sin t_v)) and in
// b (where N.L = y meets the arc's ends: cos(2b - t_v) = y at g = 0, cos(2b + t_v) = y at g = pi),
// and its bound carries N.L's rounding through the factor's slope.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "../quadrature/adaptive.hpp"
#include "../quadrature/channels.hpp"
#include "../quadrature/estimate.hpp"
#include "albedo.hpp"
#include "anisotropy.hpp"
#include "lobes.hpp"

namespace normzoo::material {

// One node of the integral in b: V.h = c, and each kernel times sin b and the map's db/dx, with
// the bound of its error (the specular's inner quadrature and rounding; the diffuse's rounding).
struct about_v_node {
    double c;
    double specular, specular_error;
    double diffuse, diffuse_error;
    std::size_t evaluations;
};

// No factor of N.L: the kernels as they are (Lambert's in closed form). A factor is a type with
// `quadrature::estimate<double> operator()(double nl) const` (its value and bound at N.L),
// `double slope(double nl) const` (|d/dN.L|, for N.L's rounding),
// `const std::vector<double>& kinks() const` (the N.L where it kinks) and `bool kinks_complete()
// const` (whether those are all of them: where not, the inner integrals keep the rule's
// bisection check).
struct no_nl_factor {};

namespace detail {

template <class Factor>
constexpr bool has_nl_factor = !std::is_same_v<Factor, no_nl_factor>;

// a b - c d to a few ulps of the result (Kahan: the rounding of c d recovered by a fused
// multiply-add).
inline double difference_of_products(double a, double b, double c, double d) {
    const double cd = c * d;
    return std::fma(a, b, -cd) + std::fma(-c, d, cd);
}

// The map from x in [0, 2] to b: x in [0, 1] the whole circle (b = b1 x), x in [1, 2] the arc
// (the cosine map above), and back.
struct about_v_map {
    double mu, sv, b1, b2;
    about_v_map(double mu_, double sv_)
        : mu(mu_), sv(sv_), b1(std::asin(mu_) / 2), b2(pi<double>() / 2 - std::asin(mu_) / 2) {}
    bool arc() const { return b2 > b1; }
    double b_of(double x, double& db_dx) const {
        if (x <= 1) return db_dx = b1, b1 * x;
        const double p = pi<double>(), s = x - 1;
        db_dx = (b2 - b1) * p / 2 * std::sin(p * s);
        return b1 + (b2 - b1) * (1 - std::cos(p * s)) / 2;
    }
    double x_of(double b) const {
        if (b <= b1) return b / b1;
        return 1 + std::acos(std::clamp(1 - 2 * (b - b1) / (b2 - b1), -1.0, 1.0)) / pi<double>();
    }
    // b(x) - b(xp) without cancellation where x is near xp (y = x - xp exact): sines of half the
    // difference in the arc, and terms of one sign where the two are on either side of x = 1.
    double b_difference(double xp, double y) const {
        const double x = xp + y, p = pi<double>(), w = b2 - b1;
        auto above_b1 = [&](double s) { const double h = std::sin(p * s / 2); return w * h * h; };  // b(1 + s) - b1
        if (x <= 1 && xp <= 1) return b1 * y;
        if (x > 1 && xp > 1) return w * std::sin(p * (2 * (xp - 1) + y) / 2) * std::sin(p * y / 2);
        if (x <= 1) return b1 * (x - 1) - above_b1(xp - 1);
        return above_b1(x - 1) + b1 * (1 - xp);
    }
    // The arc's end g0 in [0, pi] at b: N.L > 0 for |g| < g0.
    // From the node's offset db = b - t_v: 2b - pi = 2 (db - asin(mu)), exact where b nears pi/2
    // (a grazing V), where tan 2b from a rounded b would err by an ulp of pi over 2b - pi.
    double g0(double db, double x) const {
        if (x <= 1) return pi<double>();
        const double cg = -mu / (sv * std::tan(2 * (db - 2 * b1)));  // 2 b1 = asin(mu), exactly
        return std::acos(std::clamp(cg, -1.0, 1.0));
    }
};

// The g in (0, g0) where N.L = y at b, for each y of `at` (N.L falls as |g| grows).
inline void nl_crossings(const about_v_map& m, double cb, double sb, double g0, const std::vector<double>& at,
                         std::vector<double>& out) {
    const double ss = sb * m.sv;
    if (!(ss > 0 && cb > 0)) return;
    for (double y : at) {
        const double cg = ((y + m.mu) / (2 * cb) - cb * m.mu) / ss;
        if (cg > -1 && cg < 1 && std::acos(cg) < g0) out.push_back(std::acos(cg));
    }
}

// The factor at a node's N.L = nl, computed with absolute error nl_error: its value, and its
// bound plus what that error moves it by.
template <class Factor>
quadrature::estimate<double> factor_at(const Factor& factor, double nl, double nl_error) {
    auto e = factor(nl);
    e.abs_error += factor.slope(nl) * nl_error;
    return e;
}

// integral_-g0^g0 N.L factor(N.L) dg at b (Lambert's kernel under a factor), twice the half; N.L =
// mu cos 2b + 2 cos b sin b sin t_v cos g, its rounding from the two terms' magnitudes.
template <class Factor>
quadrature::estimate<double> lambert_arc(const about_v_map& m, double cb, double sb, double cos_2b, double g0,
                                         const Factor& factor, double tol, std::size_t max_panels) {
    const double eps = std::numeric_limits<double>::epsilon(), a = m.mu * cos_2b, c = 2 * cb * sb * m.sv;
    auto f = [&](double g) -> quadrature::estimate<double> {
        const double nl = a + c * std::cos(g);
        if (!(nl > 0)) return {0, 0, 1};
        const double nl_error = 8 * eps * (std::abs(a) + c);
        const auto k = factor_at(factor, nl, nl_error);
        const double v = nl * k.value;
        return {v, nl_error * std::abs(k.value) + nl * k.abs_error + 2 * eps * std::abs(v), 1};
    };
    std::vector<double> half{0, g0};
    nl_crossings(m, cb, sb, g0, factor.kinks(), half);
    return over_the_arc(true, half, f, tol, max_panels, !factor.kinks_complete());
}

// What the integral reads of a lobe beyond d, lambda and g: the widths its breakpoints are graded
// by (the smaller alpha) and its domain is checked against, and whether it is symmetric in g (an
// isotropic lobe: V lies in the plane of N and T; KHR_materials_anisotropy's turned from it is not).
inline double narrowest_alpha(const specular_brdf& l) { return l.alpha; }
inline double narrowest_alpha(const anisotropic_specular_brdf& l) { return std::min(l.alpha_t, l.alpha_b); }
inline double widest_alpha(const specular_brdf& l) { return l.alpha; }
inline double widest_alpha(const anisotropic_specular_brdf& l) { return std::max(l.alpha_t, l.alpha_b); }
inline bool symmetric_in_g(const specular_brdf&) { return true; }
inline bool symmetric_in_g(const anisotropic_specular_brdf& l) { return !l.anisotropic(); }

// f integrated over an azimuth from -end to end, given the breakpoints `half` of [0, end]: twice
// the half where f is even (a symmetric lobe), else both halves; to tol absolute.
template <class F>
auto over_the_arc(bool symmetric, const std::vector<double>& half, const F& f, double tol, std::size_t max_panels,
                  bool check_bisections = false, const std::vector<double>& more = {}) {
    std::vector<double> breaks = half;
    if (!symmetric) {
        for (double x : half) breaks.push_back(-x);
        const double end = *std::max_element(half.begin(), half.end());
        for (double x : more)
            if (x > -end && x < end) breaks.push_back(x);
    }
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    const quadrature::adaptive_kronrod<double, 21> rule(max_panels, check_bisections);
    auto e = rule.integrate(f, breaks, symmetric ? tol / 2 : tol, 0.0);
    if (symmetric) e.value += e.value, e.abs_error += e.abs_error;  // doubling is exact
    return e;
}

// An anisotropic D is a ridge along its direction t, alpha_b wide across it: large where h's
// component along b = (-sin r, cos r, 0) vanishes. On a circle of azimuths, a + p cos g + q sin g
// = 0 there; the azimuths where it crosses and where it passes closest, graded by alpha_b / |(p, q)|
// on both sides, wrapped into [-pi, pi] (the caller keeps those inside its arc).
inline std::vector<double> ridge_breaks(const specular_brdf&, double, double, double) { return {}; }
inline std::vector<double> ridge_breaks(const anisotropic_specular_brdf& l, double a, double p, double q) {
    std::vector<double> out;
    const double r = std::hypot(p, q), pi_ = pi<double>();
    if (!l.anisotropic() || !(r > 0)) return out;
    const double phase = std::atan2(q, p);
    std::vector<double> centres{phase, phase + pi_};
    if (std::abs(a) <= r) {
        const double h = std::acos(std::clamp(-a / r, -1.0, 1.0));
        centres.insert(centres.end(), {phase + h, phase - h});
    }
    for (double c : centres)
        for (double w = l.alpha_b / r; w < 2 * pi_; w *= 4)
            for (double g : {c, c - w, c + w}) out.push_back(std::remainder(g, 2 * pi_));
    return out;
}

// integral_-g0^g0 D G dg at b (cos b = cb, sin b = sb, sin(t_v - b) = d0), twice the half for a
// lobe symmetric in g; each node's relative rounding bounded from the terms of h_x, N.h and N.L
// (an anisotropic D's with its smaller alpha, which bounds it from above, and its frame's turn).
template <class Lobe, class Factor>
quadrature::estimate<double> specular_arc(const Lobe& lobe, double lambda_v, const about_v_map& m, double cb, double sb,
                                          double d0, double g0, double tol, std::size_t max_panels, const Factor& factor) {
    using std::abs;
    const double eps = std::numeric_limits<double>::epsilon(), mu = m.mu, sv = m.sv, alpha = narrowest_alpha(lobe);
    auto f = [&](double g) -> quadrature::estimate<double> {
        const double sh = std::sin(g / 2), ch = std::cos(g / 2);
        const double one_minus_cos = 2 * sh * sh, cg = 1 - one_minus_cos, sg = 2 * sh * ch;
        const double bend = sb * mu * one_minus_cos;
        const double hx = d0 + bend, hy = sb * sg, hz = cb * mu + sb * sv * cg;
        const vec3<double> h(hx, hy, hz), l(2 * cb * hx - sv, 2 * cb * hy, 2 * cb * hz - mu);
        if (!(l.z() > 0)) return {0, 0, 1};
        const double d = lobe.d(h), g_ = lobe.g(lobe.lambda(l), lambda_v), v = d * g_;
        // h_x: d0 to 2 ulps, the bend to 6; tan^2 = (h_x^2 + h_y^2) / N.h^2 relative
        const double s2 = hx * hx + hy * hy;
        const double hx_error = 2 * eps * abs(d0) + 6 * eps * bend + eps * abs(hx);
        const double nh_rel = 4 * eps * (cb * mu + sb * sv * abs(cg)) / hz;
        const double tan2_rel = s2 > 0 ? (2 * abs(hx) * hx_error + 6 * eps * s2) / s2 + 2 * nh_rel : 0.0;
        const double a2 = alpha * alpha, tan2 = s2 / (hz * hz);
        const double d_rel = 2 * (tan2 * tan2_rel / (a2 + tan2) + 2 * eps) + 4 * nh_rel + 12 * eps;
        // G's Lambda reads N.L, which cancels toward the horizon
        const double nl_rel = 4 * eps * (2 * cb * hz + mu) / l.z();
        const double rel = d_rel + 2 * nl_rel + 16 * eps;
        if constexpr (has_nl_factor<Factor>) {
            const auto k = factor_at(factor, l.z(), nl_rel * l.z());
            const double vk = v * k.value;
            return {vk, rel * abs(vk) + abs(v) * k.abs_error, 1};
        }
        return {v, rel * abs(v), 1};
    };
    std::vector<double> half{0, g0};
    const double r = std::max(alpha, abs(d0)), ss = sb * sv;
    if (ss > r * r)
        for (double w = r / std::sqrt(ss); w < g0; w *= 4) half.push_back(w);
    // toward the horizon at g0 G falls to 0 where N.L ~ alpha (Lambda ~ alpha / N.L), and turns
    // where Lambda(N.L) meets Lambda(N.V), N.L ~ mu: graded from the smaller of the two
    const double slope = 2 * cb * ss * std::sin(g0);  // dN.L/dg at g0
    if (slope > 0)
        for (double w = std::min(alpha, mu) / slope; w < g0; w *= 4) half.push_back(g0 - w);
    if constexpr (has_nl_factor<Factor>) nl_crossings(m, cb, sb, g0, factor.kinks(), half);
    // the ridge: h.b = -cos b sin t_v sin r + sin b mu sin r cos g + sin b cos r sin g
    std::vector<double> ridge;
    if constexpr (std::is_same_v<Lobe, anisotropic_specular_brdf>)
        ridge = ridge_breaks(lobe, -cb * sv * lobe.sin_r, sb * mu * lobe.sin_r, sb * lobe.cos_r);
    bool check = false;
    if constexpr (has_nl_factor<Factor>) check = !factor.kinks_complete();
    return over_the_arc(symmetric_in_g(lobe), half, f, tol, max_panels, check, ridge);
}

}  // namespace detail

// integral over L of the weights w(node) times the lobes, V at cos t = mu: w returns the
// channels' values (each a sum of weight x node.specular and weight x node.diffuse) with their
// bounds; `kinks` are the weights' kinks in V.h (ascending, in (0, 1)). The specular kernel is
// `lobe`'s (GGX's specular_brdf, or anisotropic_specular_brdf); tol the absolute target of each
// channel. Throws for mu outside [1e-8, 1] or an alpha outside [1e-8, 1].
template <class Lobe, class W, class Factor = no_nl_factor>
auto about_v_integral(const Lobe& lobe, double mu, const std::vector<double>& kinks, double tol, std::size_t max_panels,
                      const W& w, const Factor& factor = {}) {
    const double alpha = detail::narrowest_alpha(lobe), widest = detail::widest_alpha(lobe);
    if (!(mu >= 1e-8 && mu <= 1)) throw std::invalid_argument("mu = " + std::to_string(mu) + " is not in [1e-8, 1]");
    if (!(alpha >= 1e-8 && widest <= 1))
        throw std::invalid_argument("alpha = " + std::to_string(alpha) + " to " + std::to_string(widest) + " is not in [1e-8, 1]");
    using std::abs;
    const double eps = std::numeric_limits<double>::epsilon(), p = pi<double>();
    const double sv = std::sqrt((1 - mu) * (1 + mu));
    const detail::about_v_map map(mu, sv);
    const double lambda_v = lobe.lambda(vec3<double>(sv, 0, mu));
    // the inner integrals' errors weighted by |F| cos b sin b / mu integrate to |F| error / (2 mu)
    const double inner_tol = tol * mu / 2;
    // The variable is y = x - xp, xp where b = t_v: D's peak at y = 0 exactly, so that the nodes'
    // rounding does not jitter a peak narrower than an ulp of t_v (b(xp) is t_v to an ulp: the
    // whole lobe moved by that, not its nodes one by one).
    const double t_v = std::atan2(sv, mu), top = map.arc() ? map.b2 : map.b1, xp = map.x_of(t_v);
    auto f = [&](double y) {
        double db_dx = 0;
        // cos b, sin b and cos 2b from db = b - t_v and t_v's own cosine and sine: cos b from a
        // rounded b near pi/2 would err by an ulp of b over cos b (2e-8 at mu = 1e-8)
        const double x = xp + y, db = map.b_difference(xp, y);
        map.b_of(x, db_dx);
        const double cd = std::cos(db), sd = std::sin(db);
        const double cb = mu * cd - sv * sd, sb = sv * cd + mu * sd, jac = sb * db_dx;
        const double g0 = map.g0(db, x), cos_2b = -std::cos(2 * (db - 2 * map.b1));
        about_v_node node{cb, 0, 0, 0, 0, 1};
        if (g0 > 0 && jac > 0 && cb > 0) {
            const double d0 = -sd;  // sin(t_v - b)
            const auto i = detail::specular_arc(lobe, lambda_v, map, cb, sb, d0, g0, inner_tol, max_panels, factor);
            const double k = cb / mu * jac;
            node.specular = k * i.value;
            node.specular_error = k * i.abs_error + 4 * eps * abs(node.specular);
            node.evaluations = i.evaluations + 1;
            if constexpr (detail::has_nl_factor<Factor>) {
                const auto l = detail::lambert_arc(map, cb, sb, cos_2b, g0, factor, inner_tol, max_panels);
                const double kd = 4 * cb / p * jac;
                node.diffuse = kd * l.value;
                node.diffuse_error = kd * l.abs_error + 4 * eps * abs(node.diffuse);
                node.evaluations += l.evaluations;
            } else {
                // Lambert: (8 cos b / pi)(mu cos 2b g0 + 2 cos b sin b sin t_v sin g0)
                const double t1 = mu * cos_2b * g0, t2 = 2 * cb * sb * sv * std::sin(g0), kd = 8 * cb / p * jac;
                node.diffuse = kd * (t1 + t2);
                node.diffuse_error = kd * 16 * eps * (abs(t1) + abs(t2)) + 4 * eps * abs(node.diffuse);
            }
        }
        return w(node);
    };
    const double end = map.arc() ? 2 : 1;
    std::vector<double> breaks{-xp, 1 - xp, end - xp, 0};
    for (double d = alpha; d < 2; d *= 4)
        for (double b : {t_v - d, t_v + d})
            if (b > 0 && b < top) breaks.push_back(map.x_of(b) - xp);
    // toward the end, where the arc's largest N.L ~ 2 (top - b) falls to 0, G falls where N.L ~ alpha
    // (and turns where N.L ~ mu): graded as the inner integral is toward its horizon
    for (double d = std::min(alpha, mu) / 2; d < top / 2; d *= 4) breaks.push_back(map.x_of(top - d) - xp);
    for (double k : kinks) {
        const double b = std::acos(std::clamp(k, 0.0, 1.0));
        if (b > 0 && b < top) breaks.push_back(map.x_of(b) - xp);
    }
    if constexpr (detail::has_nl_factor<Factor>)  // the factor's kinks meet the arc's ends
        for (double y : factor.kinks()) {
            const double a = std::acos(std::clamp(y, -1.0, 1.0));
            for (double b : {(t_v + a) / 2, (t_v - a) / 2, (a - t_v) / 2})
                if (b > 0 && b < top) breaks.push_back(map.x_of(b) - xp);
        }
    const bool kinked = !kinks.empty() || detail::has_nl_factor<Factor>;
    breaks.erase(std::remove_if(breaks.begin(), breaks.end(), [&](double y) { return !(y >= -xp && y <= end - xp); }),
                 breaks.end());
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    const quadrature::adaptive_kronrod<double, 21> rule(max_panels, kinked);
    return rule.integrate(f, breaks, tol / 2, 0.0);
}

// The albedo of material m with V at cos t = mu, single scattering, each lobe and the whole per
// channel, to about settings.tolerance, by the integral above: for a material whose weights read
// V.H and N.V alone (M::weights_of_vh_alone: not N.L, not N.h) and whose lobes are its
// specular lobe (the peaked maps; isotropic or anisotropic) and Lambert (the smooth ones), as the
// glTF material's are under a thin film. The same value as albedo_by_nodes (tests/test_material_about_v.cpp holds
// one to the other), with the weights evaluated once a node of V.h; each lobe times `factor` of
// N.L where one is given. Throws std::invalid_argument where albedo_by_nodes does.
template <class M, class Factor = no_nl_factor>
material_albedo<M::lobe_count> albedo_about_v(const M& m, double mu, const albedo_settings& settings = {},
                                              const Factor& factor = {}) {
    static_assert(M::weights_of_vh_alone, "a material whose weights read N.L or N.h: albedo_by_nodes");
    constexpr std::size_t n = 3 * M::lobe_count;
    using value = quadrature::channels<double, n>;
    using estimate = quadrature::estimate<value>;
    const auto maps = m.maps();
    for (const auto& map : maps)
        if (!map.by_nodes) throw std::invalid_argument("a lobe albedo_about_v does not integrate (a sheen, a coat)");
    const auto lobe = m.specular_lobe();
    const auto terms = m.weight_terms();
    const double eps = std::numeric_limits<double>::epsilon(), nan = std::numeric_limits<double>::quiet_NaN();
    auto w = [&](const about_v_node& x) -> estimate {
        // N.L and N.h as NaN: a weight that read them would show in every value
        const cosines c{nan, mu, nan, x.c};
        const auto weights = m.weights(c, terms);
        std::array<rgb, M::lobe_count> rounding{};
        if constexpr (detail::has_weight_rounding<M>::value) rounding = m.weight_rounding(c, terms);
        estimate e{value{}, value{}, x.evaluations};
        for (std::size_t i = 0; i < M::lobe_count; ++i) {
            const double k = maps[i].peaked ? x.specular : x.diffuse, k_error = maps[i].peaked ? x.specular_error : x.diffuse_error;
            for (std::size_t ch = 0; ch < 3; ++ch) {
                const double wt = weights[i][ch];
                e.value[3 * i + ch] = wt * k;
                e.abs_error[3 * i + ch] = std::abs(wt) * k_error + (8 * eps + rounding[i][ch]) * std::abs(k) +
                                          eps * std::abs(e.value[3 * i + ch]);
            }
        }
        return e;
    };
    std::vector<double> kinks;
    if constexpr (detail::has_weight_kinks<M>::value) kinks = m.weight_kinks();
    // the relative target of the adaptive rule is on the sum of the channels: an eighth each
    const auto e = about_v_integral(lobe, mu, kinks, settings.tolerance / 8, settings.max_panels, w, factor);
    material_albedo<M::lobe_count> r;
    r.evaluations = e.evaluations;
    for (std::size_t i = 0; i < M::lobe_count; ++i)
        for (std::size_t ch = 0; ch < 3; ++ch) {
            r.lobes[i].value[ch] = e.value[3 * i + ch];
            r.lobes[i].abs_error[ch] = e.abs_error[3 * i + ch];
        }
    detail::sum_lobes(r);
    return r;
}

}  // namespace normzoo::material
