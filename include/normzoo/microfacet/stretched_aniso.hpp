// The albedo integral of stretched.hpp for anisotropic GGX (Burley 2012): with V = (sqrt(1 -
// mu^2), 0, mu) fixed and GGX's roughness alpha_t along the direction t = (cos r, sin r, 0) and
// alpha_b along b = (-sin r, cos r, 0),
//     E(mu) = integral of D(h) N.h * w(h) d(omega_h)
// over the half vectors whose mirror L = 2 (V.h) h - V is above the horizon (docs/materials.md,
// "KHR_materials_anisotropy"). stretched.hpp's polar maps are of an isotropic D; here the map is
// the slopes stretched to the unit roughness (the substitution of Heitz 2014, section 5):
// h ~ (alpha_t u, alpha_b v, 1) in (t, b, N), and (u, v) = tan(psi) (cos phi, sin phi) has the
// density sin(2 psi) / (2 pi) in (psi, phi), flat in the lobe's mass whatever its two widths. A
// mirror L is above the horizon where 2 (V.m) > mu |m|^2 for m = (alpha_t u, alpha_b v, 1):
// mu B r^2 - 2 A r - mu < 0 with r = tan psi, A = alpha_t V.t cos phi + alpha_b V.b sin phi,
// B = alpha_t^2 cos^2 phi + alpha_b^2 sin^2 phi, so that at each phi psi runs over [0, psi_max),
//     tan psi_max = (A + sqrt(A^2 + mu^2 B)) / (mu B) = mu / (sqrt(A^2 + mu^2 B) - A)
// (the second form where A < 0, without cancellation). The inner integral over psi has panels
// graded toward psi_max, where G turns over (N.L ~ alpha); the outer one over phi in [0, 2 pi]
// panels graded toward the zeros of A, where psi_max moves from ~mu to ~pi/2 within ~mu of phi.
// The caller's w reads the same half_vector_node as stretched.hpp's (h's polar angle and azimuth).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "stretched.hpp"

namespace normzoo::microfacet::detail {

// The anisotropic GGX lobe: its two roughnesses and the direction of alpha_t, at angle r from x.
struct aniso_lobe {
    double alpha_t, alpha_b, cos_r, sin_r;
};

template <unsigned Points, class Weight>
auto aniso_stretched_integral(const aniso_lobe& lobe, double mu, double sv, double tol, std::size_t max_panels,
                              const Weight& weight) {
    using std::abs;
    using std::atan2;
    using std::cos;
    using std::sin;
    using std::sqrt;
    using estimate = decltype(weight(std::declval<const half_vector_node&>()));
    using Value = decltype(estimate{}.value);
    const double pi = boost::math::constants::pi<double>();
    const double at = lobe.alpha_t, ab = lobe.alpha_b;
    const double vt = sv * lobe.cos_r, vb = -sv * lobe.sin_r;  // V in (t, b, N)
    const quadrature::adaptive_kronrod<double, Points> rule(max_panels);
    // w at (psi, phi): h from m = (alpha_t u, alpha_b v, 1) cos psi, turned from (t, b) to (x, y)
    auto node = [&](double cpsi, double spsi, double cphi, double sphi) -> estimate {
        const double mt = at * spsi * cphi, mb = ab * spsi * sphi;
        const double mx = mt * lobe.cos_r - mb * lobe.sin_r, my = mt * lobe.sin_r + mb * lobe.cos_r;
        const double rho = sqrt(mx * mx + my * my), len = sqrt(rho * rho + cpsi * cpsi);
        const double ct = cpsi / len, st = rho / len;
        const double hx = rho > 0 ? mx / rho : 1, hy = rho > 0 ? my / rho : 0;
        const double vh = sv * st * hx + mu * ct;
        const double nl = 2 * vh * ct - mu;
        if (!(nl > 0 && vh > 0)) return {Value{}, Value{}, 1};
        return weight(half_vector_node{ct, st, hx, hy, vh, nl, 1 / (mu * ct)});
    };
    const double alpha_min = std::min(at, ab);
    auto over_psi = [&](double phi, double cphi, double sphi) -> estimate {
        const double a = at * vt * cphi + ab * vb * sphi, b = at * at * cphi * cphi + ab * ab * sphi * sphi;
        const double s = sqrt(a * a + mu * mu * b);
        const double psi_max = a >= 0 ? atan2(a + s, mu * b) : atan2(mu, s - a);
        std::vector<double> breaks{0.0};
        graded_toward(0, psi_max, alpha_min, breaks);
        breaks.push_back(psi_max);
        std::sort(breaks.begin(), breaks.end());
        auto g = [&](double psi) -> estimate {
            const double cpsi = cos(psi), spsi = sin(psi);
            estimate e = node(cpsi, spsi, cphi, sphi);
            const double density = spsi * cpsi / pi;  // sin(2 psi) / (2 pi)
            return {e.value * density, e.abs_error * density, e.evaluations};
        };
        (void)phi;
        return rule.integrate(g, breaks, tol / (8 * pi), 0.0);
    };
    // The outer panels: quarters, and graded toward the zeros of A = C cos(phi - phi_c).
    std::vector<double> breaks{0, pi / 2, pi, 3 * pi / 2, 2 * pi};
    const double ta = at * vt, tb = ab * vb;
    if (ta != 0 || tb != 0) {
        const double phi_c = atan2(tb, ta);
        for (double z : {phi_c + pi / 2, phi_c + 3 * pi / 2}) {
            z = std::fmod(z + 4 * pi, 2 * pi);
            breaks.push_back(z);
            std::vector<double> near;
            graded_toward(z - pi / 4, z, std::max(mu, 1e-12), near);
            graded_toward(z + pi / 4, z, std::max(mu, 1e-12), near);
            for (double x : near) breaks.push_back(std::fmod(x + 4 * pi, 2 * pi));
        }
    }
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    estimate total = rule.integrate(over_psi, breaks, tol / 4, tol / 4);
    total.abs_error += std::numeric_limits<double>::epsilon() * abs(total.value);
    return total;
}

}  // namespace normzoo::microfacet::detail
