// An albedo integral in a distribution's own variable (docs/microfacet.md, "The albedo in the
// distribution's own variable"): with V = (sqrt(1 - mu^2), 0, mu) fixed,
//     E(mu) = integral over L of f(L, V) N.L d(omega_L) = integral of D(h) N.h * w(h) d(omega_h)
// over the half vectors h whose mirror direction L = 2 (V.h) h - V is above the horizon, for a
// lobe D(h) N.h that is a probability density of h (d(omega_L) = 4 V.h d(omega_h), so
// w = f N.L 4 V.h / (D N.h)). A D with a polar map (distribution.hpp, blinn_phong_polar.hpp) gives
// the polar angle t of h from psi in [0, pi/2) so that the mass below t is sin^2 psi; in (psi,
// phi) the density is sin(2 psi) / (2 pi): flat in the distribution's mass, whatever its width,
// so the lobe is no feature of the integrand and no lobe width has to be found (the inverse CDF
// the importance samplers of Walter et al. 2007 use, here as a change of variables for
// Gauss-Kronrod instead of random numbers).
//
// The horizon N.L = 0 is, with N.L = sin t_v sin(2t) cos(phi) + mu cos(2t), the azimuth
//     phi_max(t) = acos(-mu cos(2t) / (sin t_v sin(2t))),
// all of [0, pi] up to t1 = asin(mu)/2 and none beyond t2 = pi/2 - asin(mu)/2. So: region 1, psi
// in [0, psi(t1)] with phi in [0, pi] (smooth: a full circle of a smooth function of h), and region
// 2, psi in [psi(t1), psi(t2)] with phi in [0, phi_max], where phi_max moves like the square root
// of the distance to either end: there psi = psi1 + (psi2 - psi1)(1 - cos(pi s))/2 makes it
// smooth in s. The configuration is symmetric in phi -> -phi (twice [0, pi]).
//
// The caller's w(node) returns its value and its rounding bound; the quadrature error is adaptive
// Gauss-Kronrod's |K - G| (quadrature/adaptive.hpp) in both variables, or the periodic
// trapezoid's on a whole circle (quadrature/periodic.hpp).
#pragma once
#include <boost/math/constants/constants.hpp>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <vector>

#include "../detail/kinks_vh.hpp"
#include "../detail/sign_changes.hpp"
#include "../quadrature/adaptive.hpp"
#include "../quadrature/estimate.hpp"
#include "../quadrature/periodic.hpp"

namespace normzoo::microfacet {

// One node of the integral in the half vector h = (sin t cos phi, sin t sin phi, cos t): what a
// w reads. N.L > 0 and V.h > 0 there.
struct half_vector_node {
    double ct, st;        // cos t, sin t of h
    double cphi, sphi;    // cos phi, sin phi of h
    double vh, nl;        // V.h, N.L of the mirror direction L
    double inv_muct;      // 1 / (mu cos t)
};

// What the integral needs to know of the lobe beyond its polar map: the width alpha its panels
// are graded by (the roughness; sqrt(2/(n+2)) for Blinn-Phong's exponent n), whether w is
// essentially singular where N.L = 1 (Beckmann's Lambda: a function of tan t_L, not of its
// square), which bounds the strip of the whole-circle trapezoid, and whether the lobe's mass
// beyond t falls like e^(-t^2 / alpha^2) (Beckmann, Blinn-Phong; GGX's like alpha^2 / t^2).
struct stretched_lobe {
    double alpha = 0.5;
    bool singular_at_normal = false;
    bool gaussian_tail = false;
    // Where w has kinks (a G that is a min(): Cook-Torrance's; a weight of V.h with kinks: a thin
    // film's, material/albedo.hpp), the values of V.h along them at the half vector's cosine:
    // kink_vm(mu, cos t, vm[max_kinks]) -> how many, at most max_kinks, +inf for one that does not
    // exist there (masking.hpp). Each is a
    // breakpoint in phi, and where one enters or leaves the domain a breakpoint in t.
    int (*kink_vm)(double mu, double ct, double vm[3]) = nullptr;
    // A kink of w at one value of V.h (F's at total internal reflection's critical angle:
    // composition::critical_vh), after kink_vm's; 0: none.
    double critical_vh = 0;
};

// The most kinks a lobe has at one t (stretched_lobe): Cook-Torrance's 3 and a critical angle's
// one, a thin film's up to 16 (and no critical angle).
inline constexpr int max_kinks = 16;

// The values of V.h where w has kinks at the half vector's cos t: kink_vm's, then the lobe's
// critical V.h; at most max_kinks together.
inline int kinks_vh(const stretched_lobe& lobe, double mu, double ct, double vm[]) {
    return normzoo::detail::kinks_vh(lobe.kink_vm, lobe.critical_vh, mu, ct, vm, max_kinks);
}
inline bool has_kinks(const stretched_lobe& lobe) { return lobe.kink_vm || lobe.critical_vh > 0; }

namespace detail {

// The polar angles t in (0, t2) of the half vector where a kink of w (stretched_lobe::kink_vm)
// meets the edge of the azimuth's range (V.h there: mu cos t + sin t_v sin t at phi = 0, mu cos t
// - sin t_v sin t at phi = pi while the whole circle is inside, mu / (2 cos t) at phi_max beyond
// t1) or another kink: the sign changes of their differences on a grid fine near 0 (the events
// of a grazing V are within mu of it) and uniform beyond, each bisected to full precision.
// kink_vm(mu, cos t, vm) as kinks_vh takes it. A template, so that an includer whose integrals
// meet no kinks (a form's lobe, lobe_albedo.hpp) does not compile Boost's bisection.
template <class KinkVm>
std::vector<double> kink_events(KinkVm kink_vm, double mu, double sv, double t1, double t2) {
    using std::cos;
    using std::sin;
    // The differences at t, in a fixed order; +inf where a kink does not exist at t.
    constexpr int kinds = max_kinks, count = kinds * 2 + kinds * (kinds - 1) / 2;
    auto differences = [&](double t, double out[count]) {
        const double ct = cos(t), st = sin(t);
        double k[kinds];
        const int n = kink_vm(mu, ct, k);
        for (int i = n; i < kinds; ++i) k[i] = std::numeric_limits<double>::infinity();
        const double at_0 = mu * ct + sv * st, at_far = t < t1 ? mu * ct - sv * st : mu / (2 * ct);
        int j = 0;
        for (int i = 0; i < kinds; ++i) out[j++] = k[i] - at_0, out[j++] = k[i] - at_far;
        for (int i = 0; i < kinds; ++i)
            for (int m = i + 1; m < kinds; ++m) out[j++] = k[i] - k[m];
    };
    std::vector<double> grid;  // ascending, as sign_changes needs
    for (double t = t2 * 1e-12; t < t2 / 1024; t *= 1.5) grid.push_back(t);
    for (int i = 1; i <= 1024; ++i) grid.push_back(t2 * i / 1024);
    return normzoo::detail::sign_changes<count>(differences, grid);
}

// The integral over phi at one psi of D's map, for the integral below: what it reads (D's
// parameters np, V's cosine mu and sine sv, the lobe, the caller's w) and the adaptive rule the
// outer integrals over psi share.
template <class D, unsigned Points, class NdfParams, class Weight>
struct stretched_inner {
    using estimate = decltype(std::declval<const Weight&>()(std::declval<const half_vector_node&>()));
    using Value = decltype(estimate{}.value);
    const NdfParams& np;
    double mu, sv;
    const stretched_lobe& lobe;
    const Weight& weight;
    quadrature::adaptive_kronrod<double, Points> rule;

    stretched_inner(const NdfParams& np_, double mu_, double sv_, const stretched_lobe& lobe_, const Weight& weight_,
                    std::size_t max_panels)
        : np(np_), mu(mu_), sv(sv_), lobe(lobe_), weight(weight_), rule(max_panels) {}

    // w at (t, phi), from cos t, sin t, 1 / (mu cos t), cos phi, sin phi.
    estimate w(double ct, double st, double inv_muct, double cphi, double sphi) const {
        const double vh = sv * st * cphi + mu * ct;
        const double nl = 2 * vh * ct - mu;
        if (!(nl > 0 && vh > 0)) return {Value{}, Value{}, 1};
        return weight(half_vector_node{ct, st, cphi, sphi, vh, nl, inv_muct});
    }

    // The horizon's azimuth phi_max at the half vector's cos(2t), where N.L = amp cos(phi) + mu
    // cos(2t) falls to 0: pi where all of the circle is above it, 0 where none is.
    double horizon_azimuth(double cos2t, double amp) const {
        using std::acos;
        const double pi = boost::math::constants::pi<double>();
        double phi_max = pi;
        if (sv > 0) {
            const double c0 = -mu * cos2t / amp;
            phi_max = c0 <= -1 ? pi : c0 >= 1 ? 0 : acos(c0);
        } else if (!(cos2t > 0)) {
            phi_max = 0;
        }
        return phi_max;
    }

    // The kinks' azimuths inside (0, phi_max): V.h = sin t_v sin t cos(phi) + mu cos t = vm.
    std::vector<double> kinks_in_phi(double ct, double st, double phi_max) const {
        using std::acos;
        std::vector<double> kinks;
        if (has_kinks(lobe) && sv > 0 && st > 0) {
            double vm[max_kinks];
            const int n = kinks_vh(lobe, mu, ct, vm);
            for (int i = 0; i < n; ++i) {
                const double c = (vm[i] - mu * ct) / (sv * st);
                if (c > -1 && c < 1) {
                    const double phi = acos(c);
                    if (phi > 0 && phi < phi_max) kinks.push_back(phi);
                }
            }
        }
        return kinks;
    }

    // The whole circle: the integrand is smooth, even and periodic in phi, and the trapezoidal
    // rule converges geometrically (quadrature/periodic.hpp), with a first spacing of half the
    // strip where it is analytic. Its edge is the nearest complex phi where N.L or V.h vanishes
    // (Smith's Lambda, Schlick's G1 and Kelemen's G are singular there or beyond: Lambda's branch
    // points at N.L = +-i alpha/sqrt(1 - alpha^2) lie farther out), or where N.L = 1 for a w
    // singular there. The trapezoid's first number of intervals; above 256 where the strip is too
    // narrow for it.
    std::size_t whole_circle_intervals(double ct, double st, double cos2t, double amp) const {
        const double pi = boost::math::constants::pi<double>();
        const double b = mu * cos2t, amp_vh = sv * st;
        auto strip = [](std::complex<double> cos_phi) { return std::abs(std::acos(cos_phi).imag()); };
        double width = pi;
        if (amp > 0) width = std::min(width, strip({-b / amp, 0}));
        if (amp > 0 && lobe.singular_at_normal) width = std::min(width, strip({(1 - b) / amp, 0}));
        if (amp_vh > 0) width = std::min(width, strip({-mu * ct / amp_vh, 0}));
        std::size_t n = 4;
        while (n <= 256 && pi / double(n) > width / 2) n *= 2;
        return n;
    }

    // Gauss-Kronrod's panels in phi. Near phi_max, N.L falls to its least value there; G turns
    // over where N.L ~ alpha (Smith's Lambda, Schlick's k): panels end at distances growing 4x
    // from where N.L has risen by alpha/4, so that the turn is never narrower than its panel.
    std::vector<double> phi_breaks(double cos2t, double amp, double phi_max, const std::vector<double>& kinks) const {
        using std::acos;
        using std::cos;
        const double alpha = lobe.alpha;
        std::vector<double> breaks{0.0};
        const double nl_min = amp * cos(phi_max) + mu * cos2t;
        if (amp > 0 && nl_min < 4 * alpha) {
            const double knee = phi_max - acos(std::min(1.0, cos(phi_max) + alpha / (4 * amp)));
            std::vector<double> inner;
            for (double d = knee; d < phi_max / 2; d *= 4) inner.push_back(phi_max - d);
            breaks.insert(breaks.end(), inner.rbegin(), inner.rend());
        }
        breaks.push_back(phi_max);
        if (!kinks.empty()) {
            breaks.insert(breaks.end(), kinks.begin(), kinks.end());
            std::sort(breaks.begin(), breaks.end());
        }
        return breaks;
    }

    // The integral over phi at one psi, times the density sin(2 psi) / pi (both signs of phi),
    // to `budget` absolute after that factor (the inner errors are part of the outer bound:
    // where the density is small, the inner integral needs fewer digits).
    estimate over_phi(double psi, double budget) const {
        using std::sin;
        const double pi = boost::math::constants::pi<double>();
        double ct, st;
        D::polar(psi, np, ct, st);
        const double cos2t = (ct - st) * (ct + st);
        const double amp = sv * 2 * st * ct;  // N.L = amp cos(phi) + mu cos(2t)
        const double phi_max = horizon_azimuth(cos2t, amp);
        if (!(phi_max > 0)) return {Value{}, Value{}, 0};
        const std::vector<double> kinks = kinks_in_phi(ct, st, phi_max);
        const double density = sin(2 * psi) / pi;
        const double inv_muct = 1 / (mu * ct);  // once per psi, not per node
        const double inner_tol = budget / density;
        auto g = [&](double, double cphi, double sphi) { return w(ct, st, inv_muct, cphi, sphi); };  // an angle integrand
        auto scaled = [&](const estimate& e) { return estimate{e.value * density, e.abs_error * density, e.evaluations}; };
        std::size_t spent = 0;
        if (phi_max == pi && kinks.empty()) {
            const std::size_t n = whole_circle_intervals(ct, st, cos2t, amp);
            if (n <= 256) {
                const auto r = quadrature::periodic_trapezoid<double>(g, n, 256, inner_tol);
                if (r.converged) return scaled(r.integral);
                spent = r.integral.evaluations;
            }
        }
        // Otherwise Gauss-Kronrod on graded panels.
        estimate e = rule.integrate(g, phi_breaks(cos2t, amp, phi_max, kinks), inner_tol, 0.0);
        e.evaluations += spent;
        return scaled(e);
    }
};

// Appends panel ends graded toward `to` from `from`: at distances 4x apart from |to - from|/4
// down to alpha/16.
inline void graded_toward(double from, double to, double alpha, std::vector<double>& ts) {
    for (double d = std::abs(to - from) / 4; d > alpha / 16; d /= 4) ts.push_back(to + (from < to ? -d : d));
}

// Region 1's panel ends in psi, from its ends in t (see stretched_integral) and the kinks' events
// before t1, up to psi1 = psi(t1).
template <class D, class NdfParams>
std::vector<double> region1_breaks(const NdfParams& np, const stretched_lobe& lobe, double t1, double psi1,
                                   const std::vector<double>& kink_ts) {
    using std::acos;
    const double alpha = lobe.alpha;
    std::vector<double> ts;
    for (double t = t1 / 64; t < t1; t *= 2)
        if (t > alpha / 4) ts.push_back(t);
    graded_toward(0, t1, alpha, ts);
    for (double t : kink_ts)
        if (t < t1) ts.push_back(t);
    std::vector<double> breaks{0.0};
    for (double t : ts)
        if (t > 0 && t < t1) breaks.push_back(D::theta_to_psi(t, np));
    // A Gaussian tail puts the whole lobe within t1/64 when it is narrow, so that one panel in psi
    // holds all of its mass, and t ~ alpha sqrt(-ln cos^2 psi) makes w singular at that panel's
    // end (at F0 = 0 near normal incidence, w ~ (1 - L.H)^5 ~ (ln cos psi)^5): the bound came out
    // at 0.9x to 1.1x the true error there. Panels then also end where the mass beyond is e^-k,
    // k = 1, 2, 4, ..., 64: graded through the lobe in its own widths.
    if (lobe.gaussian_tail)
        for (double k = 1; k <= 64; k *= 2) {
            const double psi = acos(std::exp(-k / 2));
            if (psi < psi1) breaks.push_back(psi);
        }
    breaks.push_back(psi1);
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    return breaks;
}

// Region 2's panel ends in s (psi = psi1 + span (1 - cos(pi s))/2): at t1 + (t2 - t1) j/4, graded
// toward t1 and t2, and at the kinks' events between them.
template <class D, class NdfParams>
std::vector<double> region2_breaks(const NdfParams& np, double alpha, double t1, double t2, double psi1, double span,
                                   const std::vector<double>& kink_ts) {
    using std::acos;
    const double pi = boost::math::constants::pi<double>();
    std::vector<double> t2s;
    for (int j = 1; j < 4; ++j) t2s.push_back(t1 + (t2 - t1) * j / 4);
    graded_toward(t2, t1, alpha, t2s);
    graded_toward(t1, t2, alpha, t2s);
    t2s.insert(t2s.end(), kink_ts.begin(), kink_ts.end());
    std::vector<double> s_breaks{0.0, 1.0};
    for (double t : t2s) {
        if (!(t > t1 && t < t2)) continue;
        const double psi = D::theta_to_psi(t, np);
        s_breaks.push_back(acos(std::min(1.0, std::max(-1.0, 1 - 2 * (psi - psi1) / span))) / pi);
    }
    std::sort(s_breaks.begin(), s_breaks.end());
    s_breaks.erase(std::unique(s_breaks.begin(), s_breaks.end()), s_breaks.end());
    return s_breaks;
}

// The integral at the top of this file for D (a type with polar and theta_to_psi), its
// parameters np (an ndf_params, or what D's map reads), V's cosine mu and sine sv,
// w(half_vector_node) -> estimate<Value> (Value: a number or channels), at tolerance tol
// (absolute up to 1, relative beyond) and at most max_panels panels per adaptive integral.
// `size`: how large the integral is known to be, at least (1 where it is at most ~1): the inner
// integrals' budgets scale with it. MayKink false: the lobe has no kinks (a form's lobe,
// lobe_albedo.hpp), and the search for kinks is not compiled.
template <class D, unsigned Points, bool MayKink = true, class NdfParams, class Weight>
auto stretched_integral(const NdfParams& np, double mu, double sv, const stretched_lobe& lobe, double tol,
                        std::size_t max_panels, const Weight& weight, double size = 1) {
    using std::abs;
    using std::asin;
    using std::cos;
    using std::sin;
    const stretched_inner<D, Points, NdfParams, Weight> inner(np, mu, sv, lobe, weight, max_panels);
    using estimate = typename stretched_inner<D, Points, NdfParams, Weight>::estimate;
    const double pi = boost::math::constants::pi<double>();
    const double eps = std::numeric_limits<double>::epsilon();

    // Breakpoints in t, mapped to psi: the map squeezes the tail t >> alpha into psi near pi/2,
    // where the horizon's features, O(1) wide in t, would be narrower than a panel. So the panels
    // end at t = t1/2, t1/4, ... down to alpha (region 1) and at t1 + (t2 - t1) j/4 (region 2);
    // and toward t1 and t2, where the cut meets the lobe's turn of G (N.L ~ alpha at t1 - t ~
    // alpha/4), at distances 4x apart down to alpha/16.
    const double a = asin(mu) / 2;  // the distance of t1 from 0 and of t2 from pi/2
    const double t1 = a, t2 = pi / 2 - a;
    const double psi1 = D::theta_to_psi(t1, np), psi2 = D::theta_to_psi(t2, np);
    // Where a kink enters or leaves the domain (meets phi = 0, phi = pi or phi_max) or the kinks
    // cross, the integral over phi has a kink or a (t - t*)^(3/2) term: a breakpoint in t.
    std::vector<double> kink_ts;
    if constexpr (MayKink)
        if (has_kinks(lobe))
            kink_ts = kink_events([&](double m, double ct, double* vm) { return kinks_vh(lobe, m, ct, vm); }, mu, sv, t1, t2);
    const std::vector<double> breaks = region1_breaks<D>(np, lobe, t1, psi1, kink_ts);
    // The tolerance: a quarter to each region's outer |K - G| and a quarter to its inner errors.
    const double budget = tol * size;
    estimate total = inner.rule.integrate([&](double psi) { return inner.over_phi(psi, budget / (4 * psi1)); }, breaks,
                                          budget / 4, tol / 4);
    if (psi2 > psi1) {
        const double span = psi2 - psi1;
        auto region2 = [&](double s) -> estimate {
            const double jacobian = span * pi / 2 * sin(pi * s);
            const estimate e = inner.over_phi(psi1 + span * (1 - cos(pi * s)) / 2, budget / (4 * jacobian));
            return estimate{e.value * jacobian, e.abs_error * jacobian, e.evaluations};
        };
        const std::vector<double> s_breaks = region2_breaks<D>(np, lobe.alpha, t1, t2, psi1, span, kink_ts);
        const estimate r2 = inner.rule.integrate(region2, s_breaks, budget / 4, tol / 4);
        total.value += r2.value;
        total.abs_error += r2.abs_error;
        total.evaluations += r2.evaluations;
    }
    total.abs_error += eps * abs(total.value);
    return total;
}

}  // namespace detail

}  // namespace normzoo::microfacet
