// Microfacet compositions' albedo as one integral over N.L (microfacet/albedo.hpp): D's and
// D times Schlick's integral over L's azimuth in closed form, the complete elliptic integrals
// they use, the split-sum pair, E_avg, and the multiple-scattering compensations.
#include <catch2/catch.hpp>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <normzoo/albedo.hpp>
#include <normzoo/brdf/microfacet.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <normzoo/detail/complete_elliptic.hpp>
#include <normzoo/real.hpp>
#include <normzoo/detail/sign_changes.hpp>
#include <normzoo/microfacet/albedo.hpp>
#include <normzoo/microfacet/composition.hpp>
#include <normzoo/microfacet/multiple_scattering.hpp>
#include <normzoo/microfacet/split_sum.hpp>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "composition_checks.hpp"

using namespace normzoo;
using microfacet::composition;
using composition_checks::check_against_generic;

namespace {
// A function w(m, v) of the half vector m of L and V integrated over L's azimuth (both signs) at
// cos t_L = nl, cos t_V = nv: Gauss-Kronrod 61 in long double from L and V as vectors, on panels
// that close in on the peak at phi = pi. Its value and error estimate.
template <class W>
std::pair<long double, long double> over_azimuth(double nl, double nv, const W& w) {
    using real = long double;
    const real sl = std::sqrt(1 - real(nl) * nl), sv = std::sqrt(1 - real(nv) * nv);
    auto integrand = [&](real phi) {
        const vec3<real> l(sl * std::cos(phi), sl * std::sin(phi), nl), v(sv, 0, nv);
        return w(half_vector(l, v), v);
    };
    real total = 0, error = 0;
    const real pi = boost::math::constants::pi<real>();
    const real ends[] = {0, 2, 2.8L, 3.0L, 3.1L, 3.13L, 3.14L, 3.1415L, pi};
    for (int i = 0; i + 1 < 9; ++i) {
        real e = 0;
        total += boost::math::quadrature::gauss_kronrod<real, 61>::integrate(integrand, ends[i], ends[i + 1], 12, 1e-16L, &e);
        error += e;
    }
    return {2 * total, 2 * error + 1e-17L * total};
}

// The parameters of an isotropic D at roughness alpha, and an azimuth_point, from the cosines.
template <class T>
microfacet::ndf_params<T> isotropic(double alpha) {
    microfacet::ndf_params<T> p;
    p.alpha_x = p.alpha_y = alpha;
    return p;
}
microfacet::azimuth_point<double> azimuth_at(double nl, double nv) { return {nl, nv, nl - nv, (1 - nl) * (1 + nl), (1 - nv) * (1 + nv)}; }
}  // namespace

// D's integral over L's azimuth in closed form (distribution.hpp) against Gauss-Kronrod over the
// azimuth in long double, within its own bound and the reference's: Beckmann's on both sides of
// beta = 30 (Bessel functions, then Watson's series), GGX's beside it.
TEST_CASE("D's integral over L's azimuth: the closed forms against the integral over phi") {
    const auto [nl, nv, alpha] = GENERATE(table<double, double, double>({{0.5, 0.5, 0.3}, {0.52, 0.5, 0.01}, {0.9, 0.2, 1.0},
                                                                         {0.3, 1.0, 0.4}, {1e-3, 1e-4, 0.05}, {0.2, 0.21, 0.2},
                                                                         {0.7, 0.7001, 1e-3}, {0.999, 0.05, 0.6}}));
    const auto pl = isotropic<long double>(alpha);
    const auto p = isotropic<double>(alpha);
    const auto at = azimuth_at(nl, nv);
    auto over_phi = [&](auto part) {
        return over_azimuth(nl, nv, [&](const vec3<long double>& m, const vec3<long double>&) { return decltype(part)::d(m, pl); });
    };
    const auto beckmann = microfacet::d_beckmann::azimuthal_integral(at, p);
    const auto [b, b_error] = over_phi(microfacet::d_beckmann{});
    CAPTURE(nl, nv, alpha, beckmann.value, beckmann.error, double(b), double(b_error));
    CHECK(std::abs(beckmann.value - b) <= beckmann.error + b_error);
    if (alpha <= 1) {
        const auto ggx = microfacet::d_ggx::azimuthal_integral(at, p);
        const auto [g, g_error] = over_phi(microfacet::d_ggx{});
        CAPTURE(ggx.value, ggx.error, double(g), double(g_error));
        CHECK(std::abs(ggx.value - g) <= ggx.error + g_error);
    }
}

// Bulirsch's complete elliptic integrals (detail/complete_elliptic.hpp) against Boost.Math's
// Legendre forms in binary128 (k = sqrt(1 - kc^2) in double would lose kc below ~1e-4): K, E,
// Pi(n, k) = cel(kc, 1 - n, 1, 1), and the derivative in P against Boost's central difference
// (step 1e-9 of P: truncation ~1e-18 of the value).
TEST_CASE("complete elliptic integrals: Bulirsch's iteration against Boost.Math's K, E, Pi and Pi's differences") {
    const auto [kc, P] = GENERATE(table<double, double>({{1.0, 0.5}, {0.9, 1.0}, {0.5, 0.05}, {0.1, 0.9}, {1e-3, 1e-4},
                                                         {1e-5, 0.3}, {0.7, 1e-8}, {0.3, 0.09}, {0.02, 2.5}}));
    const quad qk = sqrt((1 - quad(kc)) * (1 + quad(kc))), qn = 1 - quad(P), h = quad(P) * 1e-9;
    const auto f = normzoo::detail::complete_elliptic(kc, P);
    const double k = double(boost::math::ellint_1(qk)), e = double(boost::math::ellint_2(qk)), c = double(boost::math::ellint_3(qk, qn));
    const double difference = double((boost::math::ellint_3(qk, qn - h) - boost::math::ellint_3(qk, qn + h)) / (2 * h));
    CAPTURE(kc, P, f.k, k, f.e, e, f.c, c, f.dc_dp, difference);
    const double eps = std::numeric_limits<double>::epsilon();
    CHECK(std::abs(f.k - k) <= 8 * eps * k);
    CHECK(std::abs(f.e - e) <= 8 * eps * e);
    CHECK(std::abs(f.c - c) <= 8 * eps * c);
    CHECK(std::abs(f.dc_dp - difference) <= 64 * eps * std::abs(difference));
}

// D (1 - V.h)^5 and F82's D V.h (1 - V.h)^6 over L's azimuth in closed form
// (microfacet/ggx_schlick_azimuth.hpp: complete elliptic integrals and residues) against
// Gauss-Kronrod over the azimuth in long double, within the two bounds; and its integral of D
// alone against d_ggx's shorter closed form. V at the normal (the azimuth does not matter), at
// grazing, the mirror direction, alpha = 1 (D flat) and 1e-3.
TEST_CASE("GGX's D times Schlick's (1 - V.h)^5 over L's azimuth: the closed form against the integral over phi") {
    const auto [nl, nv, alpha] = GENERATE(table<double, double, double>({{0.5, 0.5, 0.3}, {0.52, 0.5, 0.01}, {0.9, 0.2, 1.0},
                                                                         {0.3, 1.0, 0.4}, {0.99, 1.0, 0.01}, {1e-3, 1e-4, 0.05},
                                                                         {0.2, 0.21, 0.2}, {0.7, 0.7001, 1e-3}, {0.999, 0.05, 0.6},
                                                                         {0.05, 0.05, 1e-3}, {1e-4, 0.6, 0.1}}));
    const auto pl = isotropic<long double>(alpha);
    const auto at = azimuth_at(nl, nv);
    const auto [total, error] = over_azimuth(nl, nv, [&](const vec3<long double>& m, const vec3<long double>& v) {
        const long double f = 1 - v.dot(m);
        return microfacet::d_ggx::d(m, pl) * f * f * f * f * f;
    });
    const auto [total6, error6] = over_azimuth(nl, nv, [&](const vec3<long double>& m, const vec3<long double>& v) {
        const long double y = v.dot(m), f = 1 - y;
        return microfacet::d_ggx::d(m, pl) * y * f * f * f * f * f * f;
    });
    const double reference = double(total), reference_error = double(error);
    const auto r = microfacet::detail::ggx_schlick_azimuthal_integrals<true>(at.nl, at.nv, at.nl_minus_nv, at.sl2, at.sv2, alpha);
    const auto d = microfacet::d_ggx::azimuthal_integral(at, isotropic<double>(alpha));
    CAPTURE(nl, nv, alpha, r.d5, r.d5_error, reference, reference_error, r.d, d.value, d.error, r.d6, r.d6_error, double(total6));
    CHECK(std::abs(r.d5 - reference) <= r.d5_error + reference_error);
    CHECK(std::abs(r.d6 - double(total6)) <= r.d6_error + double(error6));
    CHECK(std::abs(r.d - d.value) <= d.error + 64 * std::numeric_limits<double>::epsilon() * d.value);
}

// With Schlick's F (F0, or F0 and F90), GGX and a G of N.L and N.V, the albedo is the same
// integral over N.L (microfacet/azimuthal_albedo.hpp) against the integral in the distribution's
// variable (h and its azimuth: no coordinate shared) at 1e-12: at normal incidence down to
// alpha = 1e-3, where Schlick's factor cancels to ~alpha^10 of D's terms at the peak, at grazing
// incidence, and at F0 = 0 (B of the split-sum pair) and 1.
TEST_CASE("E(mu, alpha) with Schlick's F as one integral over N.L, against the integral in the distribution's variable") {
    const auto id = GENERATE(as<std::string>{}, "ggx/smith-height-correlated/schlick", "ggx/smith-separable/schlick",
                             "ggx/schlick-ggx/schlick", "ggx/implicit/schlick-f90");
    auto c = composition::parse(id);
    c.f90 = 0.7;  // read by schlick-f90 alone
    const auto [alpha, mu, f0] = GENERATE(table<double, double, double>({{1e-3, 1.0, 0.0}, {1e-3, 1.0, 0.04}, {7.2e-3, 1.0, 0.0},
                                                                         {1e-3, 0.05, 0.04}, {0.05, 1e-4, 0.0}, {0.4, 0.7, 1.0},
                                                                         {1.0, 0.3, 0.04}, {0.2, 1e-3, 0.5}}));
    REQUIRE(microfacet::detail::in_closed_azimuth(c, alpha));
    const auto e = microfacet::directional_albedo(c, mu, alpha, f0);
    const auto s = microfacet::detail::stretched_albedo<microfacet::d_ggx>(c, mu, alpha, f0, albedo_settings{1e-12});
    CAPTURE(id, alpha, mu, f0, e.value, e.abs_error, s.value, s.abs_error);
    CHECK(std::abs(e.value - s.value) <= e.abs_error + s.abs_error);
    CHECK(e.abs_error <= 1e-10);
}

TEST_CASE("E(mu, alpha) with F = 1 as one integral over N.L: the generic integral elsewhere") {
    const auto id = GENERATE(as<std::string>{}, "ggx/smith-height-correlated/one", "ggx/smith-separable/one",
                             "ggx/implicit/one", "ggx/hammon/one", "beckmann/smith-height-correlated/one",
                             "beckmann/smith-separable/one", "beckmann/schlick-ggx-remapped/one");
    const auto c = composition::parse(id);
    const auto [alpha, mu] = GENERATE(table<double, double>({{1.0 / 65536, 1.0}, {1.0 / 65536, 0.3}, {1e-3, 1e-8},
                                                             {1e-3, 0.05}, {0.05, 1.0}, {0.4, 1e-4}, {0.4, 0.7}}));
    REQUIRE(microfacet::detail::in_closed_azimuth(c, alpha));
    check_against_generic(id, c, mu, alpha, 1, microfacet::directional_albedo(c, mu, alpha));
}

// Where the peak at N.L = N.V is far narrower than the ulps of N.L around it (alpha = 1.49e-8, the
// first row of a 4096^2 table): in N.L itself a node's rounding moved it against the peak and the
// error reached 21x the bound; in the offset N.L - N.V it is exact. Against the integral in the
// distribution's variable, and no gain for a G that cannot gain.
TEST_CASE("E(mu, alpha) with F = 1 as one integral over N.L: a peak narrower than the ulps of N.L") {
    const double alpha = 0.5 / 4096 * (0.5 / 4096);
    for (const char* id : {"ggx/smith-height-correlated/one", "ggx/smith-separable/one", "beckmann/smith-height-correlated/one"})
        for (double mu : {std::nextafter(0.5, 0.0), 0.3, 0.65625, 0.7, 1.0}) {
            const auto c = composition::parse(id);
            const auto e = microfacet::directional_albedo(c, mu, alpha);
            const auto s = c.d_part == microfacet::detail::index_of<microfacet::distribution_parts>("ggx")
                               ? microfacet::detail::stretched_albedo<microfacet::d_ggx>(c, mu, alpha, 1, albedo_settings{1e-12})
                               : microfacet::detail::stretched_albedo<microfacet::d_beckmann>(c, mu, alpha, 1, albedo_settings{1e-12});
            CAPTURE(id, mu, e.value, e.abs_error, s.value, s.abs_error);
            CHECK(std::abs(e.value - s.value) <= e.abs_error + s.abs_error);
            CHECK(e.value - e.abs_error <= 1);
        }
}

TEST_CASE("the albedo takes the integral over N.L only where F = 1 (GGX, Beckmann) or Schlick's (GGX), G reads N.L and N.V alone, alpha <= 1") {
    const auto [id, alpha, closed] = GENERATE(table<const char*, double, bool>({{"ggx/smith-height-correlated/one", 0.3, true},
                                                                                 {"ggx/schlick-ggx-remapped/one", 1.0, true},
                                                                                 {"ggx/smith-height-correlated/one", 1.5, false},
                                                                                 {"ggx/smith-height-correlated/schlick", 0.3, true},
                                                                                 {"ggx/hammon/schlick-f90", 1.0, true},
                                                                                 {"ggx/smith-separable/schlick", 1.5, false},
                                                                                 {"ggx/kelemen/schlick", 0.3, false},
                                                                                 {"ggx/smith-height-correlated/dielectric", 0.3, false},
                                                                                 {"ggx/kelemen/one", 0.3, false},
                                                                                 {"ggx/cook-torrance/one", 0.3, false},
                                                                                 {"beckmann/smith-height-correlated/one", 0.3, true},
                                                                                 {"beckmann/smith-separable/schlick", 0.3, false},
                                                                                 {"blinn-phong/implicit/one", 0.3, false},
                                                                                 {"ggx-aniso/smith-height-correlated/one", 0.3, false}}));
    CAPTURE(id, alpha);
    CHECK(microfacet::detail::in_closed_azimuth(composition::parse(id), alpha) == closed);
    // Schlick's F only from a tolerance of 1e-11 (its rounding floor); F = 1 at any
    const auto c = composition::parse(id);
    const bool schlick = c.f_part != microfacet::detail::index_of<microfacet::fresnel_parts>("one");
    CHECK(microfacet::detail::in_closed_azimuth(c, alpha, 1e-12) == (closed && !schlick));
}

TEST_CASE("E_avg against its closed forms at alpha = 1, and the split-sum pair adds up to the albedo") {
    const double ln2 = std::log(2.0);
    const auto hc = microfacet::average_albedo(composition::parse("ggx/smith-height-correlated/one"), 1.0);
    const auto sep = microfacet::average_albedo(composition::parse("ggx/smith-separable/one"), 1.0);
    CAPTURE(hc.value, hc.abs_error, sep.value, sep.abs_error);
    CHECK(std::abs(hc.value - 4 * (1 - ln2) / 3) <= hc.abs_error + 1e-15);  // 2 integral (1 - mu ln(1 + 1/mu)) mu
    CHECK(std::abs(sep.value - 4 * (1 - ln2) * (1 - ln2)) <= sep.abs_error + 1e-15);
    CHECK(hc.abs_error <= 1e-10);
    // F0 A + B is the albedo with Schlick's F at F0
    const auto c = composition::parse("ggx/smith-height-correlated/schlick");
    for (double f0 : {0.04, 0.5}) {
        const auto s = microfacet::split_sum(c, 0.3, 0.2);
        const auto e = microfacet::directional_albedo(c, 0.3, 0.2, f0);
        CHECK(std::abs(f0 * s.a.value + s.b.value - e.value) <= f0 * s.a.abs_error + s.b.abs_error + e.abs_error);
    }
}

TEST_CASE("the split-sum pair against two albedos apart and against the generic integral") {
    // B is the albedo with Schlick's F at F0 = 0 and A + B the albedo with F = 1, each computed
    // on its own nodes; alpha = 1.5 takes the generic integral (two albedos there too). The pair
    // comes from two channels of one pass (blinn-phong) or from A + B over N.L and B alone
    // (split_sum.hpp); the generic lobe-centred integral (albedo.hpp) shares neither's nodes.
    const auto id = GENERATE(as<std::string>{}, "ggx/smith-height-correlated/one", "beckmann/smith-separable/one",
                             "blinn-phong/implicit/one", "ggx/schlick-ggx/one");
    const auto c = composition::parse(id), schlick = composition::parse(id.substr(0, id.rfind('/')) + "/schlick");
    for (const auto& [mu, alpha] : {std::pair{1.0, 0.3}, std::pair{0.5, 0.05}, std::pair{0.02, 0.7}, std::pair{0.3, 1.5}}) {
        CAPTURE(id, mu, alpha);
        const auto s = microfacet::split_sum(c, mu, alpha);
        const auto e = microfacet::directional_albedo(c, mu, alpha, 1);
        const auto b = microfacet::directional_albedo(schlick, mu, alpha, 0);
        CHECK(std::abs(s.b.value - b.value) <= s.b.abs_error + b.abs_error);
        CHECK(std::abs(s.a.value - (e.value - b.value)) <= s.a.abs_error + e.abs_error + b.abs_error);
        CHECK(s.a.abs_error <= 1e-10);
        CHECK(s.b.abs_error <= 1e-10);
        const normzoo::albedo_settings tight{1e-12, 2000};
        const auto angle = microfacet::angle_of_cosine(mu);
        const double n = composition::node_exponent(alpha);
        const auto b_generic = normzoo::albedo<composition>(angle, n, 0, tight, alpha, schlick);
        const auto e_generic = normzoo::albedo<composition>(angle, n, 1, tight, alpha, c);
        CAPTURE(s.a.value, s.b.value, b_generic.value, e_generic.value);
        CHECK(std::abs(s.b.value - b_generic.value) <= s.b.abs_error + b_generic.abs_error);
        CHECK(std::abs(s.a.value - (e_generic.value - b_generic.value)) <= s.a.abs_error + e_generic.abs_error + b_generic.abs_error);
    }
}

TEST_CASE("the split-sum pair at 1e-13: both bounds within the tolerance") {
    // Below 1e-12 a tenth of the tolerance for A + B would meet the 1D integral's rounding floor
    // (A came out at 2.3e-13 here): split_sum.hpp then takes the two channels of one pass.
    const auto s = microfacet::split_sum(composition::parse("beckmann/smith-height-correlated/one"), 0.01, 1.0,
                                         normzoo::albedo_settings{1e-13, 400});
    CAPTURE(s.a.abs_error, s.b.abs_error);
    CHECK(s.a.abs_error <= 1e-13);
    CHECK(s.b.abs_error <= 1e-13);
}

TEST_CASE("the compensations pass the white furnace by quadrature: f + f_ms (Kulla-Conty) and Turquin's scaling") {
    const auto id = GENERATE(as<std::string>{}, "ggx/smith-height-correlated/one/kulla-conty",
                             "beckmann/smith-separable/one/kulla-conty", "ggx/smith-height-correlated/one/turquin");
    const auto c = composition::parse(id);
    for (double alpha : {0.05, 0.5, 1.0})
        for (double mu : {1.0, 0.3, 1e-3}) {
            const auto e = microfacet::compensated_albedo(c, mu, alpha);
            const auto single = microfacet::directional_albedo(c, mu, alpha);
            CAPTURE(id, alpha, mu, e.value, e.abs_error, single.value);
            CHECK(std::abs(e.value - 1) <= std::max(e.abs_error, 1e-10));
            CHECK(e.abs_error <= 1e-10);
            CHECK(single.value <= 1 + single.abs_error);  // what was compensated was a loss
        }
}

// Terms computed with another part parameter (here the index) do not hold: the albedo is that
// of the terms computed per call. Of a list, the first that holds is taken (a sweep's row: the
// terms at its inputs and at where their rounding slopes are measured).
TEST_CASE("Kulla-Conty's terms hold only for the parameters they were computed with, of a list the one that holds") {
    auto c = composition::parse("ggx/smith-height-correlated/dielectric/kulla-conty");
    c.eta = 1.5;
    auto moved = c;
    moved.eta = 1.5 * (1 + 1e-6);
    const double alpha = 0.3, mu = 0.5;
    const auto own = microfacet::compensated_albedo(moved, mu, alpha);
    const auto at_c = microfacet::kulla_conty_at(c, alpha);
    const auto other = microfacet::compensated_albedo(moved, mu, alpha, 1, {}, &at_c);
    CHECK(other.value == own.value);
    CHECK(other.abs_error == own.abs_error);
    const std::vector<microfacet::kulla_conty_terms> row{at_c, microfacet::kulla_conty_at(moved, alpha)};
    const auto listed = microfacet::compensated_albedo(moved, mu, alpha, 1, {}, row.data(), row.size());
    CHECK(listed.value == own.value);
    CHECK(listed.abs_error == own.abs_error);
    CHECK(listed.evaluations < own.evaluations);
}

// A sweep over mu shares Kulla-Conty's terms of alpha (kulla_conty_at): the same value and bound
// as computing them per call. Terms of another alpha (or F0, or tolerance) are not used: with a
// Fresnel term they would give another value; compensated_albedo computes its own instead.
TEST_CASE("Kulla-Conty's terms of alpha, computed once, give the albedo computed per call") {
    const auto c = composition::parse(GENERATE(as<std::string>{}, "ggx/smith-height-correlated/one/kulla-conty",
                                               "ggx/smith-height-correlated/schlick/kulla-conty"));
    const double alpha = 0.3, f0 = 0.5;
    const auto terms = microfacet::kulla_conty_at(c, alpha, f0);
    for (double mu : {1.0, 0.4, 0.01}) {
        CAPTURE(c.id, mu);
        const auto own = microfacet::compensated_albedo(c, mu, alpha, f0);
        const auto shared = microfacet::compensated_albedo(c, mu, alpha, f0, {}, &terms);
        CHECK(shared.value == own.value);
        CHECK(shared.abs_error == own.abs_error);
        CHECK(shared.evaluations < own.evaluations);  // the terms' work is not repeated
        for (const auto& [a, f, tol] : {std::tuple{0.6, f0, 1e-10}, std::tuple{alpha, 0.25, 1e-10}, std::tuple{alpha, f0, 1e-9}}) {
            const auto elsewhere = microfacet::kulla_conty_at(c, a, f, normzoo::albedo_settings{tol, 400});
            const auto mixed = microfacet::compensated_albedo(c, mu, alpha, f0, {}, &elsewhere);
            CHECK(mixed.value == own.value);
            CHECK(mixed.evaluations == own.evaluations);
        }
    }
}
