// OpenPBR Surface 1.1's coat absorption and darkening and its fuzz (docs/materials.md, "OpenPBR
// Surface 1.1"): anchors computed independently of the library's routes (Boost's Gauss-Kronrod, the
// interfaced Lambertian's exact albedo, EON's closed form), the LTC fuzz lobe's normalization, the
// furnace with fuzz over a white base, and f(L, V) integrated over L against each lobe's albedo.
#include <catch2/catch.hpp>

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>

#include <normzoo/material/openpbr.hpp>

#include "openpbr_over_l.hpp"

namespace {

namespace mat = normzoo::material;
using boost::math::quadrature::gauss_kronrod;

// 2 int_0^1 F(mu, eta) mu dmu by Boost, split at the critical cosine where eta < 1.
double fresnel_average_boost(double eta) {
    auto f = [&](double mu) { return 2 * mu * mat::openpbr_coat::fresnel(mu, eta); };
    const double c = eta < 1 ? std::sqrt(1 - eta * eta) : 0.5;
    return gauss_kronrod<double, 61>::integrate(f, 0, c, 15, 1e-15) + gauss_kronrod<double, 61>::integrate(f, c, 1, 15, 1e-15);
}

mat::openpbr white_dielectric(double r) {
    mat::openpbr m;
    m.in.base_color = mat::grey(1), m.in.specular_roughness = r;
    return m;
}

}  // namespace

TEST_CASE("openpbr coat: E_F exact, K_r is the internal E_F(1/eta), d'Eon's fit within 0.2 %") {
    const double eta = GENERATE(1.0, 1.2, 1.5, 1.6, 2.0, 3.0);
    const auto e = mat::openpbr_coat::fresnel_average_exact(eta);
    INFO("eta " << eta);
    CHECK(std::abs(e.value - fresnel_average_boost(eta)) <= e.abs_error + 1e-14);
    CHECK(e.abs_error <= 1e-12);
    // Stokes: the hemispherical reflectance from inside is 1 - (1 - E_F(eta)) / eta^2
    CHECK(std::abs(1 - (1 - e.value) / (eta * eta) - fresnel_average_boost(1 / eta)) <= 1e-12);
    if (eta > 1) CHECK(std::abs(mat::openpbr_coat::deon_fresnel_average_fit(eta) - e.value) <= 0.002 * e.value + 2e-3);
}

TEST_CASE("openpbr coat: with C = 1 over a Lambertian and a smooth coat, Delta gives the interfaced Lambertian") {
    // specular_weight 0: no base specular (eta' = 1), so r_b = 1 and K = K_r; E_b = rho. The exact
    // albedo of a Lambertian rho under a smooth dielectric (Elias 2001; d'Eon 2021):
    // F(mu) + (1 - F(mu)) rho (1 - K_i) / (1 - rho K_i), K_i the internal diffuse reflectance.
    const double rho = GENERATE(0.0, 0.3, 0.8);
    const double mu = GENERATE(1.0, 0.5, 0.25);
    mat::openpbr m;
    m.in.base_color = mat::grey(rho), m.in.specular_weight = 0;
    m.in.coat_weight = 1, m.in.coat_roughness = 1e-4, m.in.coat_ior = 1.5;
    const auto e = mat::openpbr_albedo(m, mu);
    const double f = mat::openpbr_coat::fresnel(mu, 1.5), k_i = fresnel_average_boost(1 / 1.5);
    const double exact = f + (1 - f) * rho * (1 - k_i) / (1 - rho * k_i);
    INFO("rho " << rho << " mu " << mu);
    CHECK(std::abs(e.whole.value[0] - exact) <= e.whole.abs_error[0] + 1e-12);
    CHECK(e.whole.abs_error[0] <= 1e-10);
    // coat_darkening 0: the undarkened F + (1 - F) E_b (the specification's E_c at normal incidence)
    m.in.coat_darkening = 0;
    const auto u = mat::openpbr_albedo(m, mu);
    CHECK(std::abs(u.whole.value[0] - (f + (1 - f) * rho)) <= u.whole.abs_error[0] + 1e-12);
}

TEST_CASE("openpbr coat: the absorption weight 1 changes nothing, EON weighted by 1 is its closed form") {
    const double mu = GENERATE(1.0, 0.6, 0.1);
    const double rd = GENERATE(0.0, 0.5, 1.0);
    mat::openpbr m;
    m.in.base_color = {0.9, 0.5, 0.2}, m.in.base_diffuse_roughness = rd, m.in.base_metalness = 0.4;
    m.in.specular_color = {1, 0.7, 0.9}, m.in.coat_weight = 0.7, m.in.coat_roughness = 0.4;
    std::size_t n = 0;
    normzoo::albedo_settings s;
    s.tolerance = 1e-11;
    const auto t = mat::openpbr_terms(m, mu, s);
    const auto p = mat::detail::openpbr_base_albedos(m, mu, t, true, s, n);  // the weighted routes, weight 1
    INFO("mu " << mu << " r " << rd);
    for (std::size_t j = 0; j < 3; ++j)
        for (std::size_t k = 0; k < 3; ++k)
            CHECK(std::abs(p.weighted[j].value[k] - p.plain[j].value[k]) <=
                  p.weighted[j].abs_error[k] + p.plain[j].abs_error[k]);
}

TEST_CASE("openpbr coat: Lambert under an absorbing coat is 2 rho int h(x) x dx (Boost)") {
    const double mu = GENERATE(1.0, 0.3);
    const double eta = GENERATE(1.0, 1.6);
    const mat::rgb color = {0.9, 0.4, 0.05}, rho = {0.8, 0.6, 1.0};
    auto h = [&](double x) { return mat::openpbr_coat::absorption_half(color, x, eta); };
    // T = h(N.L) h(N.V) is coat_color at normal incidence (coat_color = tau^2)
    for (std::size_t k = 0; k < 3; ++k) CHECK(std::abs(h(1.0)[k] * h(1.0)[k] - color[k]) <= 1e-15);
    const auto e = mat::openpbr_coat::eon_weighted_albedo(rho, 0, mu, h, 1e-12);
    for (std::size_t k = 0; k < 3; ++k) {
        const double q = gauss_kronrod<double, 61>::integrate([&](double x) { return 2 * rho[k] * h(x)[k] * x; }, 0, 1, 15, 1e-15);
        INFO("mu " << mu << " eta " << eta << " channel " << k);
        CHECK(std::abs(e.value[k] - q) <= e.abs_error[k] + 1e-14);
        CHECK(e.abs_error[k] <= 1e-11);
    }
}

TEST_CASE("openpbr fuzz: the LTC lobe integrates to 1 within its bound") {
    const double mu = GENERATE(1.0, 0.7, 0.3, 0.05, 1e-3);
    const double alpha = GENERATE(0.01, 0.1, 0.5, 1.0);
    const auto n = mat::openpbr_fuzz::ltc_normalization(mu, alpha);
    INFO("mu " << mu << " alpha " << alpha << " a " << mat::openpbr_fuzz::ltc_a(mu, alpha));
    CHECK(std::abs(n.value - 1) <= n.abs_error);
    CHECK(n.abs_error <= 1e-10);
}

TEST_CASE("openpbr fuzz: over a white base the layer preserves, the lobe's albedo is F fuzz_color E_fuzz") {
    const double mu = GENERATE(1.0, 0.5, 0.1);
    const double fr = GENERATE(0.1, 0.5, 1.0);
    auto m = white_dielectric(0.5);
    m.in.fuzz_weight = 0.7, m.in.fuzz_roughness = fr;
    const auto e = mat::openpbr_albedo(m, mu);
    INFO("mu " << mu << " fuzz_roughness " << fr);
    CHECK(std::abs(e.whole.value[0] - 1) <= e.whole.abs_error[0]);
    CHECK(e.whole.abs_error[0] <= 1e-10);
    CHECK(std::abs(e.lobes[4].value[0] - 0.7 * mat::openpbr_fuzz::e_fuzz(mu, fr)) <= e.lobes[4].abs_error[0]);
    // and under a coat (white coat_color, darkening on: E_b = 1 so Delta = 1)
    m.in.coat_weight = 0.6, m.in.coat_roughness = 0.3;
    const auto c = mat::openpbr_albedo(m, mu);
    CHECK(std::abs(c.whole.value[0] - 1) <= c.whole.abs_error[0]);
    // a coloured fuzz over a white base: 1 - F E_fuzz (1 - fuzz_color)
    m.in.fuzz_color = {0.2, 0.6, 1};
    const auto t = mat::openpbr_albedo(m, mu);
    for (std::size_t k = 0; k < 3; ++k)
        CHECK(std::abs(t.whole.value[k] - (1 - 0.7 * mat::openpbr_fuzz::e_fuzz(mu, fr) * (1 - m.in.fuzz_color[k]))) <=
              t.whole.abs_error[k]);
}

TEST_CASE("openpbr layers: f(L, V)'s lobes integrate to their albedos, absorbing coat, darkening and fuzz") {
    mat::openpbr m;
    m.in.base_color = {0.9, 0.5, 0.2}, m.in.base_metalness = 0.3, m.in.base_diffuse_roughness = 0.6;
    m.in.specular_roughness = 0.8, m.in.specular_color = {1, 0.7, 0.9};
    m.in.coat_weight = 0.5, m.in.coat_roughness = 0.9, m.in.coat_color = {0.5, 1, 0.8}, m.in.coat_ior = 1.3;
    m.in.fuzz_weight = 0.4, m.in.fuzz_color = {0.9, 0.6, 0.3}, m.in.fuzz_roughness = 0.9;
    normzoo_test::check_lobes_over_l(m, 0.6, 1e-8);
    // the darkening darkens this (non-white) base
    CHECK(mat::openpbr_terms(m, 0.6).values().darkening[0] < 1);
}

TEST_CASE("openpbr film: a white dielectric under a film keeps 1 per channel, the film colours its specular") {
    const double r = GENERATE(0.25, 0.75);
    const double mu = GENERATE(0.2, 0.9);
    INFO("roughness " << r << " mu " << mu);
    auto m = white_dielectric(r);
    m.in.thin_film_weight = 1, m.in.thin_film_thickness = 0.3, m.in.thin_film_ior = 1.8;
    const auto e = mat::openpbr_albedo(m, mu);
    const auto plain = mat::openpbr_albedo(white_dielectric(r), mu);
    double moved = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        // the diffuse takes 1 - E_spec of its own channel: the whole is 1 whatever the film does
        CHECK(std::abs(e.whole.value[k] - 1) <= e.whole.abs_error[k]);
        CHECK(e.whole.abs_error[k] <= 1e-10);
        moved = std::max(moved, std::abs(e.lobes[1].value[k] - plain.lobes[1].value[k]));
    }
    CHECK(moved > 1e-3);
    CHECK(mat::max_value(e.lobes[1].value) - std::min({e.lobes[1].value[0], e.lobes[1].value[1], e.lobes[1].value[2]}) > 1e-4);
}

TEST_CASE("openpbr film: f(L, V)'s lobes integrate to their albedos under a film, a metal and an absorbing coat") {
    mat::openpbr m;
    m.in.base_color = {0.9, 0.6, 0.3}, m.in.base_metalness = 0.5, m.in.specular_roughness = 0.5;
    m.in.coat_weight = 0.5, m.in.coat_color = {0.8, 0.9, 1}, m.in.coat_roughness = 0.5;
    m.in.thin_film_weight = 0.7, m.in.thin_film_thickness = 0.4, m.in.thin_film_ior = 1.5;
    REQUIRE(!m.film_kinks().empty());  // the film's clamps are breakpoints here
    // the lobes whose F the film changes (the diffuse reads E_spec, which the specular's checks)
    normzoo_test::check_lobes_over_l(m, 0.6, 1e-8, {1, 2});
}
