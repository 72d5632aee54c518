// The parts materials are made of (docs/microfacet.md, docs/models.md#eon): the Charlie sheen
// distribution and its visibilities, Fdez-Aguera's compensation, the EON diffuse form, and the
// exact anchors of a material's albedo. Every expected value is computed independently of the
// code it checks: by a plain quadrature over L, or by a closed form derived in the comment.
#include <catch2/catch.hpp>

#include "sanitized.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <normzoo/albedo.hpp>
#include <normzoo/brdf/eon.hpp>
#include <normzoo/microfacet/albedo.hpp>
#include <normzoo/microfacet/multiple_scattering.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace normzoo;
using microfacet::composition;
using R = long double;

namespace {

// E(mu) of c by a plain 2D adaptive Gauss-Kronrod over L's polar angle and azimuth in long
// double, f from vectors (composition::f): it shares neither the half-vector coordinates nor the
// polar map with directional_albedo. A breakpoint at N.L = 1/2, where charlie-sheen's Lambda
// switches branch.
R albedo_over_l(const composition& c, double mu, double alpha, double f0) {
    using gk = boost::math::quadrature::gauss_kronrod<R, 61>;
    const R pi = boost::math::constants::pi<R>();
    const R m = mu, sv = std::sqrt((1 - m) * (1 + m));
    const vec3<R> v(sv, 0, m);
    const brdf::params<R> p{0, R(f0), R(alpha)};
    auto in_theta = [&](R theta) {
        const R ct = std::cos(theta), st = std::sin(theta);
        auto in_phi = [&](R phi) { return c.f(vec3<R>(st * std::cos(phi), st * std::sin(phi), ct), v, p) * ct * st; };
        return 2 * gk::integrate(in_phi, R(0), pi, 15, R(1e-14));
    };
    return gk::integrate(in_theta, R(0), pi / 3, 15, R(1e-14)) + gk::integrate(in_theta, pi / 3, pi / 2, 15, R(1e-14));
}

}  // namespace

TEST_CASE("charlie: D N.m holds the mass sin^(r+2) t below t, and its polar map inverts theta_to_psi") {
    using D = microfacet::d_charlie;
    const double alpha = GENERATE(0.01, 0.2, 1.0, 3.0);
    microfacet::ndf_params<double> p;
    p.alpha_x = p.alpha_y = alpha;
    const double r = 1 / alpha;
    for (double t : {0.1, 0.7, 1.2, 1.5, 1.57}) {
        // the mass below t by quadrature of D(m) cos t sin t 2 pi over the polar angle
        auto density = [&](double u) {
            const vec3<double> m(std::sin(u), 0, std::cos(u));
            return D::d(m, p) * std::cos(u) * std::sin(u) * 2 * boost::math::constants::pi<double>();
        };
        const double mass = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(density, 0.0, t, 15, 1e-14);
        CAPTURE(alpha, t, mass);
        CHECK(mass == Approx(std::pow(std::sin(t), r + 2)).epsilon(1e-12).margin(1e-300));
        double c, s;
        D::polar(D::theta_to_psi(t, p), p, c, s);
        CHECK(std::atan2(s, c) == Approx(t).epsilon(1e-12));
    }
}

// With V = N, f = D(h) / 4 (Neubelt's V = 1 / (4 (N.L + 1 - N.L)) = 1/4) and h lies at half L's
// polar angle, t = t_L / 2, so N.L = cos 2t and d(omega_L) = 4 cos t d(omega_h):
//   E(1) = integral_0^(pi/4) (2 + r)/(2 pi) sin^r t cos 2t cos t 2 pi sin t dt
//        = (2 + r) integral_0^(1/sqrt 2) (u^(r+1) - 2 u^(r+3)) du           (u = sin t)
//        = 2^(-(r+2)/2) (1 - (r + 2)/(r + 4)) = 2^(-r/2) / (r + 4),  r = 1/alpha.
TEST_CASE("charlie/neubelt/one at mu = 1 in closed form: E = 2^(-r/2) / (r + 4), r = 1/alpha") {
    const double alpha = GENERATE(0.01, 0.05, 0.1, 0.25, 0.5, 1.0);
    const double r = 1 / alpha, closed = std::exp2(-r / 2) / (r + 4);
    const auto e = microfacet::directional_albedo(composition::parse("charlie/neubelt/one"), 1.0, alpha);
    CAPTURE(alpha, e.value, e.abs_error, closed);
    CHECK(std::abs(e.value - closed) <= e.abs_error + 4e-16 * closed);
    CHECK(e.abs_error <= 1e-10);
}

// The albedo routes (microfacet/albedo.hpp: the polar map up to alpha = 1, the generic integral
// beyond) on a D whose mass lies toward the horizon, against the plain quadrature over L, at
// small and large alpha and at normal and grazing incidence (docs/microfacet.md#the-charlie-sheen-distribution).
TEST_CASE("the Charlie sheen's albedo against a plain quadrature over L: within its bound") {
    const auto [id, alpha, mu] = GENERATE(normzoo_test::thinned_under_sanitizers(3, table<const char*, double, double>({
        {"charlie/neubelt/one", 0.001, 0.01},
        {"charlie/neubelt/one", 0.05, 0.2},
        {"charlie/neubelt/one", 1.0, 1e-4},
        {"charlie/neubelt/one", 4.0, 0.7},
        {"charlie/charlie-sheen/one", 0.5, 1.0},
        {"charlie/charlie-sheen/one", 0.05, 0.2},
        {"charlie/charlie-sheen/one", 1.0, 0.01},
        {"charlie/charlie-sheen/one", 0.001, 1e-4},
    })));
    const composition c = composition::parse(id);
    const auto e = microfacet::directional_albedo(c, mu, alpha);
    const double reference = static_cast<double>(albedo_over_l(c, mu, alpha, 1));
    CAPTURE(id, alpha, mu, e.value, e.abs_error, reference, e.value - reference);
    CHECK(std::abs(e.value - reference) <= e.abs_error);
    CHECK(e.abs_error <= 1e-10 * std::max(1.0, e.value));
}

TEST_CASE("charlie-sheen's fitted Lambda: KHR_materials_sheen's formula, and refused beyond alpha = 1") {
    // L(x) = a / (1 + b x^c) + d x + e at alpha = 1 (the first of each pair of coefficients) and at
    // alpha = 0.5 (weights 3/4 and 1/4), written out here from the specification's listing
    auto l_at = [](R x, R w) {  // w = (1 - alpha)^2
        auto mix = [&](R at_1, R at_0) { return at_1 + (at_0 - at_1) * w; };
        return mix(21.5473L, 25.3245L) / (1 + mix(3.82987L, 3.32435L) * std::pow(x, mix(0.19823L, 0.16801L))) +
               mix(-1.97760L, -1.27393L) * x + mix(-4.32054L, -4.85967L);
    };
    for (R alpha : {R(1), R(0.5)})
        for (R nl : {R(0.05), R(0.3), R(0.7), R(0.99)}) {
            const R w = (1 - alpha) * (1 - alpha), nv = R(0.4);
            auto lambda = [&](R x) { return x < R(0.5) ? std::exp(l_at(x, w)) : std::exp(2 * l_at(R(0.5), w) - l_at(1 - x, w)); };
            microfacet::shading<R> s;
            s.nl = nl, s.nv = nv, s.alpha = alpha;
            const R expected = 1 / (1 + lambda(nl) + lambda(nv));
            CAPTURE(static_cast<double>(alpha), static_cast<double>(nl));
            CHECK(static_cast<double>(microfacet::g_charlie_sheen::g(s)) == Approx(static_cast<double>(expected)).epsilon(1e-6));
        }
    CHECK_THROWS_AS(microfacet::directional_albedo(composition::parse("charlie/charlie-sheen/one"), 0.5, 1.6),
                    std::invalid_argument);
}

TEST_CASE("neubelt: V = G / (4 N.L N.V) = 1 / (4 (N.L + N.V - N.L N.V)), and ashikhmin is the same formula") {
    for (R nl : {R(1e-6), R(0.2), R(0.9), R(1)})
        for (R nv : {R(1e-3), R(0.5), R(1)}) {
            microfacet::shading<R> s;
            s.nl = nl, s.nv = nv;
            const R v = microfacet::g_neubelt::g(s) / (4 * nl * nv);
            CHECK(static_cast<double>(v) == Approx(static_cast<double>(1 / (4 * (nl + nv - nl * nv)))).epsilon(1e-15));
            CHECK(microfacet::g_ashikhmin::g(s) == microfacet::g_neubelt::g(s));
        }
}

// At alpha = 1 GGX is uniform (D = 1/pi) and the height-correlated G is 2 N.L N.V / (N.L + N.V), so
// f = 1 / (2 pi (N.L + N.V)); at N.V = 1, E = integral of N.L / (2 pi (1 + N.L)) d(omega_L) =
// integral_0^1 x / (1 + x) dx = 1 - ln 2 (docs/microfacet.md: E(mu) = 1 - mu ln(1 + 1/mu)).
TEST_CASE("ggx/smith-height-correlated at alpha = 1 and mu = 1: E = 1 - ln 2") {
    const char* id = GENERATE("ggx/smith-height-correlated/one", "ggx/smith-height-correlated/schlick");
    const auto e = microfacet::directional_albedo(composition::parse(id), 1.0, 1.0, 1.0);
    CAPTURE(id, e.value, e.abs_error);
    CHECK(std::abs(e.value - (1 - std::log(2.0))) <= e.abs_error + 1e-16);
}

// A white metal (Schlick's F at F0 = 1: F = 1 at every angle) with each compensation: its albedo
// is 1, the white furnace, within the bound.
TEST_CASE("a white metal with each of the three compensations gives 1") {
    const char* compensation = GENERATE("kulla-conty", "turquin", "fdez-aguera");
    const double alpha = GENERATE(0.1, 0.5, 1.0);
    const double mu = GENERATE(1.0, 0.3, 0.02);
    const composition c = composition::parse(std::string("ggx/smith-height-correlated/schlick/") + compensation);
    const auto e = microfacet::compensated_albedo(c, mu, alpha, 1.0);
    CAPTURE(compensation, alpha, mu, e.value, e.abs_error, e.value - 1);
    CHECK(std::abs(e.value - 1) <= e.abs_error);
    CHECK(e.abs_error <= 1e-9);
}

// F_avg = 2 integral_0^1 (F0 + (1 - F0)(1 - mu)^5) mu dmu = F0 + (1 - F0) 2 B(2, 6) = F0 + (1 - F0)/21.
TEST_CASE("Fdez-Aguera's F_avg of Schlick's F is F0 + (1 - F0)/21, and the compensation is E_F / (1 - F_avg (1 - E))") {
    const double f0 = GENERATE(0.0, 0.04, 0.5, 0.9, 1.0);
    const composition c = composition::parse("ggx/smith-height-correlated/schlick/fdez-aguera");
    const auto f_avg = microfacet::fresnel_average(c, f0);
    CAPTURE(f0, f_avg.value, f_avg.abs_error);
    CHECK(std::abs(f_avg.value - (f0 + (1 - f0) / 21)) <= f_avg.abs_error + 1e-16);
    // the paper's total from its pieces: E_F with Schlick's F and E with F = 1, each by its own route
    const double alpha = 0.6, mu = 0.4;
    const auto e_f = microfacet::directional_albedo(composition::parse("ggx/smith-height-correlated/schlick"), mu, alpha, f0);
    const auto e_1 = microfacet::directional_albedo(composition::parse("ggx/smith-height-correlated/one"), mu, alpha);
    const double expected = e_f.value / (1 - (f0 + (1 - f0) / 21) * (1 - e_1.value));
    const auto total = microfacet::compensated_albedo(c, mu, alpha, f0);
    CHECK(std::abs(total.value - expected) <= total.abs_error + 4 * (e_f.abs_error + e_1.abs_error));
}

// EON (brdf/eon.hpp): FON's E_avg = A (1 + c2 r) is E's cosine-weighted average (so f_ms's albedo is
// rho_ms (1 - E(mu))), and the form's albedo by the generic quadrature is rho E + rho_ms (1 - E): 1 at rho = 1.
TEST_CASE("eon: E_avg is FON's average albedo, the form's albedo is rho E + rho_ms (1 - E), 1 at rho = 1") {
    using brdf::eon;
    const double r = GENERATE(0.0, 0.3, 1.0);
    auto weighted = [&](R mu) { return 2 * mu * eon::fon_albedo<R>(mu, r); };
    const R average = boost::math::quadrature::gauss_kronrod<R, 61>::integrate(weighted, R(0), R(1), 15, R(1e-18));
    const R a = 1 / (1 + eon::c1<R>() * r);
    CHECK(std::abs(static_cast<double>(average - a * (1 + eon::c2<R>() * r))) < 1e-17);
    for (double rho : {1.0, 0.6})
        for (double theta : {0.0, 40.0, 75.0, 89.5}) {
            const auto e = albedo<eon>(theta, 0, rho, {}, r);
            const double mu = std::cos(theta * boost::math::constants::pi<double>() / 180);
            const double expected = eon::albedo_of<double>(mu, brdf::params<double>{0, rho, r});
            CAPTURE(r, rho, theta, e.value, e.abs_error, expected);
            CHECK(std::abs(e.value - expected) <= e.abs_error + 4e-16);
            if (rho == 1) CHECK(std::abs(e.value - 1) <= e.abs_error + 4e-16);
        }
}
