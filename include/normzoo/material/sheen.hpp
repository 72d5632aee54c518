// KHR_materials_sheen (docs/materials.md#khr_materials_sheen): a sheen lobe over the material,
// layered by albedo scaling.
//   sheen_brdf(alpha)     V D, D = Charlie's (2 + 1/alpha) sin^(1/alpha) t_h / (2 pi), V = G / (4 N.L N.V),
//                         G = 1 / (1 + Lambda(N.L) + Lambda(N.V)), Lambda fitted
//                                                     Estevez and Kulla 2017; KHR_materials_sheen
//                         (microfacet/d_charlie.hpp, microfacet/masking.hpp's charlie-sheen)
//   albedo_scaling        sheen_material = sheenColor sheen_brdf + s material,
//                         s = min(1 - max_value(sheenColor) E(N.V), 1 - max_value(sheenColor) E(N.L)),
//                         E the sheen lobe's directional albedo     KHR_materials_sheen, "Albedo scaling"
// alpha = sheenRoughness^2. E is computed here, not looked up: sheen_albedo below.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "../geometry.hpp"
#include "../microfacet/d_charlie.hpp"
#include "../microfacet/masking.hpp"
#include "../quadrature/adaptive.hpp"
#include "../quadrature/estimate.hpp"
#include "material.hpp"

namespace normzoo::material {

struct sheen_brdf {
    static constexpr const char* formula = "V D, D = Charlie(alpha), V = G / (4 N.L N.V), G = charlie-sheen";
    static constexpr const char* literature =
        "Estevez and Kulla 2017, \"Production Friendly Microfacet Sheen BRDF\"; KHR_materials_sheen";
    double alpha;

    // G of the charlie-sheen part (its fitted Lambda, not written twice).
    double g(double nl, double nv) const {
        microfacet::shading<double> s;
        s.nl = nl, s.nv = nv, s.alpha = alpha;
        return microfacet::g_charlie_sheen::g(s);
    }
    double d(const vec3<double>& h) const {
        microfacet::ndf_params<double> np;
        np.alpha_x = np.alpha_y = alpha;
        return microfacet::d_charlie::d(h, np);
    }
    // V D at unit L, V with N.L, N.V > 0 and h their half vector.
    double value(const vec3<double>& l, const vec3<double>& v, const vec3<double>& h) const {
        return d(h) * g(l.z(), v.z()) / (4 * l.z() * v.z());
    }
};

// The albedo scaling of the base below a sheen of colour max_value(sheenColor) = c: the factor
// min(1 - c E(N.V), 1 - c E(N.L)) = 1 - c max(E(N.V), E(N.L)).
struct albedo_scaling {
    double c;
    double factor(double e_v, double e_l) const { return std::min(1 - c * e_v, 1 - c * e_l); }
};

namespace detail {

// Charlie's D integrated over L's azimuth at N.L = y, N.V = x (sines sy, sx):
//     K(x, y) = integral_0^(2 pi) D(h) d(phi) = (2 + r)/pi integral_0^pi (n / (n + (x + y)^2))^(r/2) d(psi),
// r = 1/alpha, psi = pi - phi, since sin^2 t_h = |tangential part of L + V|^2 / |L + V|^2 with
// n = (sx - sy)^2 + 4 sx sy sin^2(psi/2) the tangential part's square and |L + V|^2 = n + (x + y)^2:
// no cancellation, (sx - sy) taken as (y - x)(y + x)/(sx + sy). Near y = x the integrand turns at
// psi ~ 2 sqrt(A/B) (A = (sx - sy)^2, B = 4 sx sy): panels graded from there; toward psi = pi
// (its peak, narrow for small alpha) graded too. Rounding: ln of the ratio by log1p, times r/2,
// its exp: (8 + r |ln q|) eps of a node's value.
inline quadrature::estimate<double> charlie_azimuthal(double x, double sx, double y, double sy, double alpha,
                                                      double tol) {
    const double eps = std::numeric_limits<double>::epsilon();
    const double r = 1 / alpha, s2 = (x + y) * (x + y);
    const double diff = sx + sy > 0 ? (y - x) * (y + x) / (sx + sy) : 0.0;
    const double a = diff * diff, b = 4 * sx * sy, pi_ = pi<double>();
    const double scale = (2 + r) / pi_;
    if (b == 0 || s2 == 0) {  // V or L at the normal: no azimuthal dependence
        if (s2 == 0) return {0, 0, 1};
        const double lnq = -std::log1p(s2 / a);
        const double v = a > 0 ? scale * pi_ * std::exp(r / 2 * lnq) : 0.0;
        return {v, (8 + r * std::abs(lnq)) * eps * v, 1};
    }
    auto f = [&](double psi) -> quadrature::estimate<double> {
        const double sh = std::sin(psi / 2), n = a + b * sh * sh;
        if (!(n > 0)) return {0, 0, 1};
        const double lnq = -std::log1p(s2 / n), v = scale * std::exp(r / 2 * lnq);
        return {v, (8 + r * std::abs(lnq)) * eps * v, 1};
    };
    std::vector<double> breaks{0, pi_};
    for (double w = 2 * std::sqrt(a / b); w < pi_ && w > 0; w *= 4) breaks.push_back(w);
    for (double d = pi_ / 4; d > pi_ / (4 * std::sqrt(r)); d /= 4) breaks.push_back(pi_ - d);
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    const quadrature::adaptive_kronrod<double, 15> rule(400);
    return rule.integrate(f, breaks, tol, 0.0);
}

}  // namespace detail

// E(mu), the sheen lobe's directional albedo at N.V = mu (KHR_materials_sheen's E, here exact):
//     E(x) = 1/(4 x) integral_0^1 G(y, x) K(x, y) dy,
// G of N.L and N.V alone (charlie-sheen), so only D depends on L's azimuth: its integral K over it
// (detail::charlie_azimuthal) is the inner integral. Panels in y: at y = x (K's turn), at 1/2
// (where the fitted Lambda changes branch: C^1, not C^2), graded toward 0 and 1 (Lambda goes like
// y^c and (1 - y)^c there, c ~ 0.2) and toward x. The bound: the outer |K - G|, the inner bounds
// weighted as the values, G's rounding (a few exp and divisions: 64 eps of a node). The same E as
// microfacet::directional_albedo of charlie/charlie-sheen/one, which takes 30x to 100x longer
// (tests/test_material_sheen.cpp checks one against the other). mu in (0, 1] (checked against
// that from 1e-8), alpha in [1e-3, 1]. G: charlie-sheen, the extension's; neubelt, its "simpler"
// visibility, takes the same route (a closed form at mu = 1 checks it).
template <class G = microfacet::g_charlie_sheen>
quadrature::estimate<double> sheen_albedo(double mu, double alpha, double tolerance = 1e-10) {
    if (!(mu > 0 && mu <= 1)) throw std::invalid_argument("sheen_albedo: mu = " + std::to_string(mu) + " is outside (0, 1]");
    if (!(alpha >= 1e-3 && alpha <= 1))
        throw std::invalid_argument("sheen_albedo: alpha = " + std::to_string(alpha) + " is outside [1e-3, 1]");
    const double eps = std::numeric_limits<double>::epsilon();
    const double x = mu, sx = std::sqrt((1 - mu) * (1 + mu));
    auto g_of = [&](double y) {
        microfacet::shading<double> s;
        s.nl = y, s.nv = x, s.alpha = alpha;
        return G::g(s) / (4 * x);
    };
    // the inner integrals to what makes their part of E, weighted by G/(4x) <= G(1, x)/(4x) (G is
    // largest at y = 1: Lambda is smallest there, and neubelt's G grows with N.L), tol/2
    const double inner_tol = tolerance / (2 * g_of(1.0));
    auto f = [&](double y) -> quadrature::estimate<double> {
        const double sy = std::sqrt((1 - y) * (1 + y));
        const double g = y > 0 ? g_of(y) : 0.0;
        if (g == 0) return {0, 0, 1};
        auto k = detail::charlie_azimuthal(x, sx, y, sy, alpha, inner_tol);
        const double v = g * k.value;
        return {v, 64 * eps * std::abs(v) + g * k.abs_error, k.evaluations};
    };
    std::vector<double> breaks{0, 0.5, x, 1};
    for (double d = 0.125; d > 1e-7; d /= 4) breaks.push_back(d);
    for (double d = 0.125; d > 1e-4; d /= 4) breaks.push_back(1 - d);
    for (double d = std::max(1e-3, alpha * x / 8); d < 1; d *= 4) breaks.insert(breaks.end(), {x - d, x + d});
    breaks.erase(std::remove_if(breaks.begin(), breaks.end(), [](double b) { return !(b >= 0 && b <= 1); }), breaks.end());
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    const quadrature::adaptive_kronrod<double, 15> rule(800);
    auto e = rule.integrate(f, breaks, tolerance / 2, 0.0);
    e.abs_error += 4 * eps * std::abs(e.value);
    return e;
}

}  // namespace normzoo::material
