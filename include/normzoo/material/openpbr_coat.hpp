// OpenPBR Surface 1.1's coat beyond its lobe (docs/materials.md, "OpenPBR Surface 1.1"): the
// view-dependent absorption and the darkening, the specification's sections Coat/Darkening and
// Coat/View-dependent absorption.
//   absorption  T(L, V) = coat_color^((1/mu_L^t + 1/mu_V^t) / 2), mu^t = sqrt(1 - (1 - mu^2)/eta_c^2):
//               coat_color is the square of the normal-incidence transmittance tau, so the
//               specification's tau^(1/mu_L^t + 1/mu_V^t) is coat_color at normal incidence;
//               T is a product of a factor of N.L and one of N.V (absorption_half).
//   darkening   Delta = (1 - K) / (1 - E_b K), K = lerp(K_s, K_r, r_b), K_s = F(N.V, eta_c),
//               K_r = 1 - (1 - E_F(eta_c)) / eta_c^2, r_b = lerp(r_d, r, M),
//               r_d = lerp(1, r, clamp(specular_weight F0(eta_s), 0, 1)), r = specular_roughness (as the
//               specification names it: not the coat's roughening of it), eta_s openpbr_model.hpp's;
//               the base is multiplied by lerp(1, Delta, coat_weight coat_darkening).
// E_F is the hemispherical average 2 int F(mu, eta) mu dmu of the exact dielectric Fresnel,
// integrated here (fresnel_average_exact); d'Eon's fit the specification quotes is kept as
// deon_fresnel_average_fit for comparison only (within 0.2 % on [1, 3], the specification says).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "../brdf/eon.hpp"
#include "../microfacet/fresnel.hpp"
#include "../quadrature/adaptive.hpp"
#include "../quadrature/channels.hpp"
#include "../quadrature/estimate.hpp"
#include "../geometry.hpp"
#include "albedo.hpp"
#include "material.hpp"

namespace normzoo::material::openpbr_coat {

// The exact unpolarized dielectric Fresnel reflectance at cos = mu and relative index eta.
inline double fresnel(double mu, double eta) {
    microfacet::fresnel_params<double> p;
    p.eta = eta;
    return microfacet::fresnel_dielectric::eval(mu, p);
}

// mu^t, the cosine of a direction refracted into the coat of index eta >= 1.
inline double refracted_cos(double mu, double eta) { return std::sqrt(1 - (1 - mu) * (1 + mu) / (eta * eta)); }

// coat_color^(1 / (2 mu^t)) per channel: T(L, V) = absorption_half(N.L) x absorption_half(N.V).
inline rgb absorption_half(const rgb& coat_color, double mu, double eta) {
    const double y = 0.5 / refracted_cos(mu, eta);
    return {std::pow(coat_color[0], y), std::pow(coat_color[1], y), std::pow(coat_color[2], y)};
}

// E_F(eta) = 2 int_0^1 F(mu, eta) mu dmu, by adaptive Gauss-Kronrod (F is smooth for eta >= 1).
inline quadrature::estimate<double> fresnel_average_exact(double eta, double tolerance = 1e-13) {
    const double eps = std::numeric_limits<double>::epsilon();
    auto f = [&](double mu) {
        const double v = 2 * mu * fresnel(mu, eta);
        return quadrature::estimate<double>{v, 16 * eps * v, 1};
    };
    return quadrature::adaptive_kronrod<double, 15>(400).integrate(f, {0.0, 0.25, 0.5, 0.75, 1.0}, tolerance, 0.0);
}

// d'Eon's fit of E_F (d'Eon 2021, as OpenPBR 1.1 quotes it in its footnote on the average Fresnel).
inline double deon_fresnel_average_fit(double eta) {
    return std::log((10893 * eta - 1438.2) / (-774.4 * eta * eta + 10212 * eta + 1));
}

// K and its bound: lerp(F(mu, eta_c), 1 - (1 - E_F)/eta_c^2, r_b).
struct coefficient {
    double value, abs_error;
};
inline coefficient internal_reflection(double mu, double eta_c, double r_b, const quadrature::estimate<double>& e_f) {
    const double eps = std::numeric_limits<double>::epsilon();
    const double k_s = fresnel(mu, eta_c), k_r = 1 - (1 - e_f.value) / (eta_c * eta_c);
    const double k = (1 - r_b) * k_s + r_b * k_r;
    return {k, r_b * e_f.abs_error / (eta_c * eta_c) + 16 * eps};
}

// Delta = (1 - K) / (1 - E_b K) per channel, with its bound from E_b's and K's:
// dDelta/dE_b = K (1 - K) / (1 - E_b K)^2, dDelta/dK = (E_b - 1) / (1 - E_b K)^2.
inline rgb_estimate darkening(const rgb_estimate& e_b, const coefficient& k) {
    const double eps = std::numeric_limits<double>::epsilon();
    rgb_estimate d;
    for (std::size_t c = 0; c < 3; ++c) {
        const double den = 1 - e_b.value[c] * k.value;
        d.value[c] = (1 - k.value) / den;
        d.abs_error[c] = (k.value * (1 - k.value) * e_b.abs_error[c] + std::abs(e_b.value[c] - 1) * k.abs_error) / (den * den) +
                         16 * eps * std::abs(d.value[c]);
    }
    return d;
}

// The EON lobe's albedo at V = (sqrt(1 - mu^2), 0, mu) with the integrand weighted by g(N.L) (one
// weight per channel), per channel rho: the azimuth in closed form (s = sin t_L sin t_V cos phi;
// over phi, s / t integrates to 2 sin t_L sin t_V (1 / max(N.L, N.V) - 1)), then N.L adaptively,
// split at N.L = mu where max changes. With g = 1 it is EON's closed-form albedo (a test).
//   int f_EON g N.L dL = rho I1 + rho_ms I2,
//   I1 = int_0^1 x g(x) A (2 + (2 r / pi) S_x S_mu (1 / max(x, mu) - 1)) dx,
//   I2 = int_0^1 x g(x) 2 r A (c1 - G(x)/pi)(c1 - G(mu)/pi) / (c1 - c2) dx   (brdf/eon.hpp).
template <class G>
rgb_estimate eon_weighted_albedo(const rgb& rho, double r, double mu, const G& g, double tolerance) {
    using eon = brdf::eon;
    using value = quadrature::channels<double, 6>;
    const double eps = std::numeric_limits<double>::epsilon(), pi_ = pi<double>();
    const double a = 1 / (1 + eon::c1<double>() * r), so = std::sqrt((1 - mu) * (1 + mu));
    const double lost_o = eon::c1<double>() - eon::g_of(mu) / pi_, denom = eon::c1<double>() - eon::c2<double>();
    auto f = [&](double x) {
        const double sx = std::sqrt((1 - x) * (1 + x));
        const double single = x * a * (2 + 2 * r / pi_ * sx * so * (1 / std::max(x, mu) - 1));
        const double multiple = x * 2 * r * a * (eon::c1<double>() - eon::g_of(x) / pi_) * lost_o / denom;
        const rgb w = g(x);
        quadrature::estimate<value> e{value{}, value{}, 1};
        for (std::size_t c = 0; c < 3; ++c) {
            e.value[c] = single * w[c], e.value[3 + c] = multiple * w[c];
            e.abs_error[c] = 64 * eps * (std::abs(single) + a), e.abs_error[3 + c] = 64 * eps * (std::abs(multiple) + r * a);
        }
        return e;
    };
    std::vector<double> breaks = {0.0, 0.5 * mu, mu, 0.5 * (1 + mu), 1.0};
    const auto e = quadrature::adaptive_kronrod<double, 15>(800).integrate(f, breaks, tolerance / 4, 0.0);
    rgb_estimate out;
    for (std::size_t c = 0; c < 3; ++c) {
        const double ms = eon::rho_ms(rho[c], r);
        out.value[c] = rho[c] * e.value[c] + ms * e.value[3 + c];
        out.abs_error[c] = rho[c] * e.abs_error[c] + ms * e.abs_error[3 + c] + 16 * eps * std::abs(out.value[c]);
    }
    return out;
}

}  // namespace normzoo::material::openpbr_coat
