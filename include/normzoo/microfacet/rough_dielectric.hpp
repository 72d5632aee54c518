// The albedo of a rough dielectric interface, reflection and transmission together (Walter et al.
// 2007, "Microfacet models for refraction through rough surfaces"; docs/microfacet.md, "A rough
// dielectric: reflection and transmission"): GGX's D, Smith's separable G and the exact F at the
// relative index eta = n_t / n_i (eta < 1: V on the denser side, with total internal reflection).
// In the half vector h, with V = (sqrt(1 - mu^2), 0, mu), both parts are one integral of the
// lobe's density D(h) N.h:
//     E_R = integral of D N.h  V.h / (mu N.h)  F(V.h)       G1(V) G1(L_r)   over N.L_r > 0,
//     E_T = integral of D N.h  V.h / (mu N.h)  (1 - F(V.h)) G1(V) G1(L_t)   over N.L_t < 0,
// over the half vectors with V.h > 0: L_r = 2 (V.h) h - V, and L_t = (e c - k) h - e V with
// e = 1/eta, c = V.h, k = sqrt(1 - e^2 (1 - c^2)) (Walter's eq. 40; its Jacobian, eq. 17, cancels
// the BTDF's denominator). The weights read h through V.h and the two directions; they are 0 or
// jump at three values of V.h at each polar angle t of h:
//     N.L_r = 0 at c = mu / (2 cos t);  the critical angle c = sqrt(1 - eta^2) (eta < 1);
//     N.L_t = 0 at c = (q^2 + e^2 - 1) / (2 e q), q = e mu / cos t (eta < 1: N.L_t falls with c),
// which are breakpoints in h's azimuth phi, and where they meet the azimuth's ends or each other,
// breakpoints in t. For eta >= 1, N.L_t <= -mu / eta: no light is refracted back above.
// The variables are GGX's polar map (stretched.hpp): psi with tan t = alpha tan psi and phi, flat
// in the lobe's mass; V.h > 0 for every phi up to t = asin(mu), beyond it for phi below
// acos(-mu cos t / (sin t_v sin t)), which closes like a square root there (the same substitution
// in s as stretched.hpp's region 2). Adaptive Gauss-Kronrod in both; the bound is |K - G|, the
// inner integrals' bounds, and each node's rounding (64 ulps of its value, and F's at the
// critical angle, where g = sqrt(eta^2 - 1 + c^2) cancels: 4 eps / g absolute).
#pragma once
#include <boost/math/constants/constants.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "../detail/sign_changes.hpp"
#include "../geometry.hpp"
#include "../quadrature/adaptive.hpp"
#include "../quadrature/channels.hpp"
#include "../quadrature/estimate.hpp"
#include "d_ggx.hpp"
#include "fresnel.hpp"
#include "stretched.hpp"

namespace normzoo::microfacet {

// E_R and E_T of one V, each with its bound.
struct rough_dielectric_albedo {
    quadrature::estimate<double> reflection, transmission;
    std::size_t evaluations = 0;
};

namespace detail {

// The interface at one V: what a node of h reads, and the values of V.h where its weights jump.
struct rough_dielectric_view {
    double alpha, eta, mu, sv, e;  // e = 1 / eta
    double critical;               // the critical V.h (0: none, eta >= 1)

    rough_dielectric_view(double alpha_, double eta_, double mu_)
        : alpha(alpha_), eta(eta_), mu(mu_), sv(std::sqrt((1 - mu_) * (1 + mu_))), e(1 / eta_),
          critical(eta_ < 1 ? std::sqrt((1 - eta_) * (1 + eta_)) : 0.0) {}

    // The values of V.h at cos t where a weight jumps or kinks: N.L_r = 0, the critical angle,
    // N.L_t = 0 (+inf where one does not exist). Three, in that order.
    std::array<double, 3> jumps(double ct) const {
        const double inf = std::numeric_limits<double>::infinity();
        std::array<double, 3> c{mu / (2 * ct), inf, inf};
        if (eta < 1) {
            c[1] = critical;
            const double q = e * mu / ct;
            c[2] = (q * q + (e - 1) * (e + 1)) / (2 * e * q);
        }
        return c;
    }

    // The weights (R, T) at h = (st cos phi, st sin phi, ct), times the density's V.h / (mu N.h).
    quadrature::estimate<quadrature::channels<double, 2>> at(double ct, double st, double cphi, double sphi) const {
        using std::abs;
        using std::sqrt;
        using value = quadrature::channels<double, 2>;
        const double eps = std::numeric_limits<double>::epsilon();
        const double c = sv * st * cphi + mu * ct;
        quadrature::estimate<value> r{value{}, value{}, 1};
        if (!(c > 0)) return r;
        const vec3<double> h(st * cphi, st * sphi, ct), v(sv, 0, mu);
        const double g1v = 1 / (1 + ggx_lambda(v, alpha));
        const double g2 = eta * eta - 1 + c * c;
        const double f = g2 > 0 ? fresnel_dielectric::eval(c, fresnel_params<double>{0, 0, eta}) : 1.0;
        const double f_error = g2 > 0 ? eps * (16 + 4 / sqrt(g2)) : 0.0;
        const double scale = c / (mu * ct) * g1v;
        const vec3<double> lr = 2 * c * h - v;
        if (lr.z() > 0) {
            const double w = scale / (1 + ggx_lambda(lr, alpha));
            r.value[0] = w * f;
            r.abs_error[0] = 64 * eps * abs(r.value[0]) + w * f_error;
        }
        if (g2 > 0) {
            const double k = sqrt(1 - e * e * (1 - c * c));
            const vec3<double> lt = (e * c - k) * h - e * v;
            const double length = sqrt(lt.dot(lt));  // 1 up to rounding
            if (lt.z() < 0) {
                const double w = scale / (1 + ggx_lambda(lt / length, alpha));
                r.value[1] = w * (1 - f);
                r.abs_error[1] = 64 * eps * abs(r.value[1]) + w * f_error;
            }
        }
        return r;
    }

    static double ggx_lambda(const vec3<double>& w, double a) { return microfacet::detail::ggx_lambda(w, a); }
};

// The polar angles t of h in (0, pi/2) where a jump of V.h meets the azimuth's ends (V.h at phi = 0,
// and at phi = pi up to t = asin(mu)) or another jump: sign changes on a grid, bisected.
inline std::vector<double> rough_dielectric_events(const rough_dielectric_view& x, double t_closing) {
    using std::cos;
    using std::sin;
    const double pi = boost::math::constants::pi<double>(), t_end = pi / 2;
    constexpr std::size_t count = 3 * 2 + 3;
    auto differences = [&](double t, double out[count]) {
        const double ct = cos(t), st = sin(t), inf = std::numeric_limits<double>::infinity();
        const std::array<double, 3> j = x.jumps(ct);
        const double at_0 = x.mu * ct + x.sv * st, at_pi = t < t_closing ? x.mu * ct - x.sv * st : inf;
        std::size_t n = 0;
        for (double c : j) out[n++] = c - at_0, out[n++] = std::isfinite(at_pi) ? c - at_pi : inf;
        out[n++] = j[0] - j[1], out[n++] = j[0] - j[2], out[n++] = j[1] - j[2];
        for (std::size_t i = 0; i < count; ++i)
            if (!std::isfinite(out[i])) out[i] = inf;
    };
    std::vector<double> grid;
    for (double t = t_end * 1e-12; t < t_end / 1024; t *= 1.5) grid.push_back(t);
    for (int i = 1; i < 1024; ++i) grid.push_back(t_end * i / 1024);
    return normzoo::detail::sign_changes<count>(differences, grid);
}

}  // namespace detail

// E_R and E_T of GGX at alpha in (0, 1] with Smith's separable G and the exact F at eta > 0, at
// V's cosine mu in (0, 1], each to tol absolute (a quarter to each region's outer |K - G|, a
// quarter to its inner errors), at most max_panels panels per adaptive integral; Gauss-Kronrod
// with Points nodes (a template so that the command compiles it once: detail/compiled_kernels.hpp).
template <unsigned Points = 15>
rough_dielectric_albedo rough_dielectric_albedo_of(double alpha, double eta, double mu, double tol, std::size_t max_panels) {
    using std::acos;
    using std::asin;
    using std::cos;
    using std::sin;
    using value = quadrature::channels<double, 2>;
    using estimate = quadrature::estimate<value>;
    const double pi = boost::math::constants::pi<double>(), eps = std::numeric_limits<double>::epsilon();
    const detail::rough_dielectric_view x(alpha, eta, mu);
    const ndf_params<double> np{alpha, alpha};
    const quadrature::adaptive_kronrod<double, Points> rule(max_panels);
    const double t1 = asin(mu);  // V.h > 0 on the whole circle of h below t1
    const std::vector<double> events = detail::rough_dielectric_events(x, t1);

    // Over phi at one psi, times the map's density sin(2 psi) / pi (both signs of phi).
    auto over_phi = [&](double psi, double budget) -> estimate {
        double ct, st;
        d_ggx::polar(psi, np, ct, st);
        const double amp = x.sv * st;
        double phi_end = pi;
        if (amp > 0 && x.mu * ct < amp) phi_end = acos(-x.mu * ct / amp);
        std::vector<double> breaks{0.0, phi_end};
        double critical_phi = -1;  // where V.h is the critical angle's, if inside
        if (amp > 0) {
            const std::array<double, 3> jumps = x.jumps(ct);
            for (std::size_t j = 0; j < jumps.size(); ++j) {
                const double k = (jumps[j] - x.mu * ct) / amp;
                if (!(k > -1 && k < 1)) continue;
                const double phi = acos(k);
                if (!(phi > 0 && phi < phi_end)) continue;
                breaks.push_back(phi);
                if (j == 1) {
                    critical_phi = phi;
                    continue;
                }
                // G1 of L_r or L_t turns over where its N.L ~ alpha: panels end from where N.L
                // has moved by alpha/4, 4x apart (as the reflection's map grades its horizon)
                const double c = jumps[j], slope_c = j == 0 ? 2 * ct : (x.e - x.e * x.e * c / std::sqrt(1 - x.e * x.e * (1 - c * c))) * ct;
                const double slope = std::abs(slope_c) * amp * sin(phi);  // |d N.L / d phi|
                // at most ~20 panel ends a side: from 1e-12 of the range where the slope is
                // unbounded (N.L_t = 0 at the critical angle itself, k = 0)
                if (slope > 0)
                    for (double d = std::max(alpha / (4 * slope), phi_end * 1e-12); d < phi_end; d *= 4)
                        for (const double b : {phi - d, phi + d})
                            if (b > 0 && b < phi_end) breaks.push_back(b);
            }
        }
        std::sort(breaks.begin(), breaks.end());
        const double density = sin(2 * psi) / pi;
        if (critical_phi < 0) {
            auto g = [&](double, double cphi, double sphi) { return x.at(ct, st, cphi, sphi); };
            const estimate e = rule.integrate(g, breaks, budget / density, 0.0);
            return estimate{e.value * density, e.abs_error * density, e.evaluations};
        }
        // F goes like sqrt(V.h - critical) beyond the critical angle: on each side of it phi =
        // critical_phi -+ span s^2, smooth in s, half of the budget to each side.
        estimate e{value{}, value{}, 0};
        for (const double side : {-1.0, 1.0}) {
            const double span = side < 0 ? critical_phi : phi_end - critical_phi;
            std::vector<double> in_s{0.0, 1.0};
            for (double b : breaks) {
                const double u = side * (b - critical_phi) / span;
                if (u > 0 && u < 1) in_s.push_back(std::sqrt(u));
            }
            std::sort(in_s.begin(), in_s.end());
            auto g = [&](double q) {
                const double phi = critical_phi + side * span * q * q;
                estimate n = x.at(ct, st, cos(phi), sin(phi));
                const double jacobian = 2 * span * q;
                return estimate{n.value * jacobian, n.abs_error * jacobian, n.evaluations};
            };
            const estimate half = rule.integrate(g, in_s, budget / (2 * density), 0.0);
            e.value += half.value, e.abs_error += half.abs_error, e.evaluations += half.evaluations;
        }
        return estimate{e.value * density, e.abs_error * density, e.evaluations};
    };

    const stretched_lobe lobe{alpha};
    const double t_end = pi / 2, psi1 = d_ggx::theta_to_psi(t1, np), span = t_end - psi1;  // psi(pi/2) = pi/2
    estimate total = rule.integrate([&](double psi) { return over_phi(psi, tol / (4 * psi1)); },
                                    detail::region1_breaks<d_ggx>(np, lobe, t1, psi1, events), tol / 4, 0.0);
    if (span > 0) {
        auto region2 = [&](double s) -> estimate {
            const double jacobian = span * pi / 2 * sin(pi * s);
            const estimate e = over_phi(psi1 + span * (1 - cos(pi * s)) / 2, tol / (4 * jacobian));
            return estimate{e.value * jacobian, e.abs_error * jacobian, e.evaluations};
        };
        const estimate r2 = rule.integrate(region2, detail::region2_breaks<d_ggx>(np, alpha, t1, t_end, psi1, span, events),
                                           tol / 4, 0.0);
        total.value += r2.value, total.abs_error += r2.abs_error, total.evaluations += r2.evaluations;
    }
    rough_dielectric_albedo r;
    r.reflection = {total.value[0], total.abs_error[0] + eps * total.value[0], 0};
    r.transmission = {total.value[1], total.abs_error[1] + eps * total.value[1], 0};
    r.evaluations = total.evaluations;
    return r;
}

}  // namespace normzoo::microfacet
