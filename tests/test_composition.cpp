// Microfacet BRDFs composed from parts (microfacet/composition.hpp): parsing a composition id,
// reciprocity of every composition, two seed forms reproduced as compositions, and the albedo of
// GGX with height-correlated Smith against an independent nested Gauss-Kronrod integration and
// the white furnace.
#include <catch2/catch.hpp>

#include "sanitized.hpp"

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

TEST_CASE("composition ids: D/G/F, each part known, a Smith G only over a D with Lambda in closed form") {
    const auto c = composition::parse("ggx/smith-height-correlated/one");
    CHECK(c.id == "ggx/smith-height-correlated/one");
    for (const char* good : {"beckmann/smith-separable/schlick", "blinn-phong/implicit/schlick", "gtr/kelemen/dielectric",
                             "ggx-aniso/smith-height-correlated/conductor", "ggx/hammon/schlick-f90"})
        CHECK_NOTHROW(composition::parse(good));
    const auto [bad, names] = GENERATE(table<const char*, const char*>({{"ggx/smith/one", "'smith'"},
                                                                         {"GGX/implicit/one", "'GGX'"},
                                                                         {"ggx/implicit/schlik", "'schlik'"},
                                                                         {"ggx/implicit", "D/G/F"},
                                                                         {"ggx/implicit/one/two", "fourth part 'two'"},
                                                                         {"gtr/smith-separable/one", "no closed form"},
                                                                         {"blinn-phong/smith-height-correlated/one", "no closed form"}}));
    CAPTURE(bad);
    try {
        composition::parse(bad);
        FAIL("accepted");
    } catch (const std::invalid_argument& e) {
        CHECK(std::string(e.what()).find(names) != std::string::npos);
    }
}

TEST_CASE("the parameters each part reads: one name per parameter, asked of the composition") {
    const auto [id, parameter, read] = GENERATE(table<const char*, const char*, bool>({
        {"ggx/smith-height-correlated/one", "f0", false},
        {"ggx/smith-height-correlated/schlick", "f0", true},
        {"ggx/smith-height-correlated/schlick", "f90", false},
        {"ggx/smith-height-correlated/schlick-f90", "f90", true},
        {"ggx/smith-height-correlated/dielectric", "eta", true},
        {"ggx/smith-height-correlated/dielectric", "k", false},
        {"ggx/smith-height-correlated/conductor", "k", true},
        {"ggx-aniso/smith-height-correlated/one", "aspect", true},
        {"beckmann-aniso/smith-separable/one", "aspect", true},
        {"ggx/smith-height-correlated/one", "aspect", false},
        {"gtr/implicit/one", "gamma", true},
        {"ggx/implicit/one", "gamma", false},
        {"gtr/implicit/one", "gam", false}}));
    CAPTURE(id, parameter);
    CHECK(composition::parse(id).reads(parameter) == read);
    CHECK(composition::readers_of("eta") == "dielectric, conductor");
    CHECK(composition::readers_of("aspect") == "ggx-aniso, beckmann-aniso");
}

TEST_CASE("a composition declares the parameters its parts read, as a form declares its own") {
    const auto [id, names] = GENERATE(table<const char*, const char*>({
        {"ggx/smith-height-correlated/one", ""},
        {"ggx/smith-height-correlated/schlick-f90", "f0 f90"},
        {"gtr/implicit/conductor", "gamma f0 eta k"},
        {"beckmann-aniso/smith-separable/dielectric", "aspect f0 eta"}}));
    std::string declared;
    for (const normzoo::parameter& p : composition::parse(id).parameters()) {
        declared += (declared.empty() ? "" : " ") + std::string(p.name);
        CHECK(p.min < p.max);
        CHECK(!p.meaning.empty());
    }
    CAPTURE(id);
    CHECK(declared == names);
}

namespace {
template <class Parts>
std::vector<std::string> ids() {
    std::vector<std::string> out;
    std::apply([&](auto... part) { (out.emplace_back(decltype(part)::id), ...); }, Parts{});
    return out;
}
}  // namespace

TEST_CASE("every composition is reciprocal: f(L, V) = f(V, L)") {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    auto dir = [&] {
        const double t = 1.5 * u(rng), p = 6.28 * u(rng);
        return vec3<double>(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
    };
    int compositions = 0;
    for (const auto& d : ids<microfacet::distribution_parts>())
        for (const auto& g : ids<microfacet::masking_parts>())
            for (const auto& f : ids<microfacet::fresnel_parts>()) {
                const std::string id = d + "/" + g + "/" + f;
                composition c;
                try {
                    c = composition::parse(id);
                } catch (const std::invalid_argument&) {
                    continue;  // a Smith G over a D without Lambda
                }
                ++compositions;
                c.aspect = 0.5, c.gamma = 1.5, c.k = 3;
                for (int i = 0; i < 50; ++i) {
                    const auto l = dir(), v = dir();
                    const brdf::params<double> p{0, 0.04 + 0.5 * u(rng), 0.05 + u(rng)};
                    const double a = c.f(l, v, p), b = c.f(v, l, p);
                    CAPTURE(id, a, b);
                    CHECK(std::isfinite(a));
                    CHECK(a >= 0);
                    CHECK(a == Approx(b).epsilon(1e-12));
                }
            }
    CHECK(compositions == 7 * 13 * 5 - 3 * 2 * 5);  // blinn-phong, gtr and charlie have no closed Lambda for the two Smith G
}

TEST_CASE("two seed forms are compositions: microfacet-blinn and cook-torrance-ksk, the same albedo") {
    const double alpha = GENERATE(0.1, 0.4, 0.9);
    const double theta = GENERATE(0.0, 60.0, 85.0);
    const double f0 = 0.04, n = composition::node_exponent(alpha);
    CAPTURE(alpha, theta);
    const auto a = albedo<composition>(degrees_angle<quad>(theta), n, f0, {}, alpha, composition::parse("blinn-phong/implicit/schlick"));
    const auto b = albedo<brdf::microfacet_blinn>(theta, n, f0);
    CHECK(std::abs(a.value - b.value) <= a.abs_error + b.abs_error);
    const auto c = albedo<composition>(degrees_angle<quad>(theta), n, f0, {}, alpha, composition::parse("blinn-phong/kelemen/schlick"));
    const auto d = albedo<brdf::cook_torrance_ksk>(theta, n, f0);
    CHECK(std::abs(c.value - d.value) <= c.abs_error + d.abs_error);
}

namespace {
// The albedo by a different route: nested adaptive Gauss-Kronrod over V's polar angle and
// azimuth in long double, the integrand f (N.V) sin t_v from the composition's own f.
long double naive_albedo(const composition& c, long double mu, long double alpha) {
    using boost::math::quadrature::gauss_kronrod;
    const long double st = std::sqrt((1 - mu) * (1 + mu));
    const vec3<long double> l(st, 0, mu);
    const brdf::params<long double> p{0, 1, alpha};
    auto over_phi = [&](long double tv) {
        auto f = [&](long double phi) {
            const vec3<long double> v(std::sin(tv) * std::cos(phi), std::sin(tv) * std::sin(phi), std::cos(tv));
            return c.f(l, v, p) * v.z() * std::sin(tv);
        };
        // the lobe sits at phi = pi (V mirrors L): split there
        const long double pi = boost::math::constants::pi<long double>();
        return 2 * gauss_kronrod<long double, 61>::integrate(f, 0, pi, 15, 1e-13L);
    };
    const long double half_pi = boost::math::constants::half_pi<long double>();
    const long double mirror = std::acos(mu);
    long double sum = 0;
    const long double breaks[] = {0, mirror > 0.02L ? mirror : 0.02L, half_pi};
    for (int i = 0; i < 2; ++i) sum += gauss_kronrod<long double, 61>::integrate(over_phi, breaks[i], breaks[i + 1], 15, 1e-13L);
    return sum;
}

// E(mu) at alpha = 1 in closed form (docs/microfacet.md): 1 - mu ln(1 + 1/mu) with the
// height-correlated Smith G, 2 (1 - ln 2) / (1 + mu) with the separable one.
double albedo_at_alpha_1(bool correlated, double mu) {
    return correlated ? 1 - mu * std::log1p(1 / mu) : 2 * (1 - std::log(2.0)) / (1 + mu);
}

}  // namespace

TEST_CASE("GGX with height-correlated Smith: the albedo against an independent quadrature, and the white furnace") {
    const auto c = composition::parse("ggx/smith-height-correlated/one");
    const double alpha = GENERATE(0.3, 0.6, 1.0);
    const double mu = GENERATE(1.0, 0.5, 0.1);
    const double theta = std::acos(mu) * 180 / boost::math::constants::pi<double>();
    const auto e = albedo<composition>(degrees_angle<quad>(theta), composition::node_exponent(alpha), 1, {}, alpha, c);
    const long double naive = naive_albedo(c, static_cast<long double>(std::cos(theta * boost::math::constants::pi<double>() / 180)), alpha);
    CAPTURE(alpha, mu, e.value, e.abs_error, static_cast<double>(naive));
    CHECK(std::abs(e.value - static_cast<double>(naive)) <= e.abs_error + 1e-9);
    CHECK(e.abs_error <= 1e-10);
    // single scattering loses energy: below 1 by more than the bound for a rough surface
    CHECK(e.value + e.abs_error < 1);
}

TEST_CASE("GGX at alpha = 1 in closed form: E(mu) = 1 - mu ln(1 + 1/mu) height-correlated, 2 (1 - ln 2) / (1 + mu) separable") {
    // At alpha = 1 GGX is uniform, D = 1/pi, and Lambda(t) = (1/cos t - 1)/2: the height-correlated
    // G is 2 N.L N.V / (N.L + N.V) and the separable one 4 N.L N.V / ((1 + N.L)(1 + N.V)), so with
    // F = 1 the albedo, (1 / (4 pi mu)) times the integral of G over V, is 1 - mu ln(1 + 1/mu) and
    // 2 (1 - ln 2) / (1 + mu) (docs/microfacet.md).
    const double mu = GENERATE(1.0, 0.7, 0.5, 0.2, 0.05, 0.01);
    const double theta = std::acos(mu) * 180 / boost::math::constants::pi<double>();
    const auto at = [&](const char* id) {
        return albedo<composition>(degrees_angle<quad>(theta), 0, 1, {}, 1.0, composition::parse(id));
    };
    const double m = std::cos(theta * boost::math::constants::pi<double>() / 180);  // the direction's own cosine
    const auto hc = at("ggx/smith-height-correlated/one");
    const auto sep = at("ggx/smith-separable/one");
    CAPTURE(mu, hc.value, hc.abs_error, sep.value, sep.abs_error);
    CHECK(std::abs(hc.value - albedo_at_alpha_1(true, m)) <= hc.abs_error + 1e-15);
    CHECK(std::abs(sep.value - albedo_at_alpha_1(false, m)) <= sep.abs_error + 1e-15);
}

// The albedo in the distribution's own variable (microfacet/albedo.hpp) against the closed forms at
// alpha = 1 (docs/microfacet.md) and against the generic lobe-centred integral of albedo.hpp, which
// shares no coordinates with it, at a tolerance 1000 times tighter.
TEST_CASE("E(mu, alpha) in the distribution's variable: closed forms at alpha = 1, the generic integral elsewhere") {
    const auto [id, correlated] = GENERATE(table<const char*, bool>({{"ggx/smith-height-correlated/one", true},
                                                                      {"ggx/smith-separable/one", false}}));
    const auto c = composition::parse(id);
    for (double mu : {1.0, 0.7, 0.3, 0.1, 1e-2, 1e-3, 1e-4}) {
        // F = 1 takes the integral over N.L (azimuthal_albedo.hpp); the one in the distribution's
        // variable is checked here directly
        const auto e = microfacet::detail::stretched_albedo<microfacet::d_ggx>(c, mu, 1.0, 1, albedo_settings{});
        const double exact = albedo_at_alpha_1(correlated, mu);
        CAPTURE(id, mu, e.value, e.abs_error, exact);
        CHECK(std::abs(e.value - exact) <= e.abs_error + 1e-15);
        CHECK(e.abs_error <= 1e-10);
    }
    // (Cook-Torrance's G has its own test below: the generic integral does not split at its kinks)
    const auto other = GENERATE(as<std::string>{}, "ggx/smith-height-correlated/schlick", "beckmann/smith-separable/schlick",
                                "ggx/kelemen/dielectric", "ggx/hammon/one");
    const auto d = composition::parse(other);
    for (double alpha : {1e-3, 0.4})
        for (double mu : {1.0, 0.05, 1e-3}) check_against_generic(other, d, mu, alpha, 0.04, microfacet::directional_albedo(d, mu, alpha, 0.04));
}

namespace {
// The albedo of an f with kinks (a G that is a min(), Cook-Torrance's; F at total internal
// reflection's critical angle), by a route that shares neither the kink formulas of masking.hpp
// and composition.hpp nor the panels of stretched.hpp: nested Gauss-Kronrod 61 in long double
// over the half vector's polar angle t and azimuth phi, the integrand the composition's own
// f N.L 4 V.h sin t, split in phi where piece(N.h, V.h, N.L) changes (found by bisection on it)
// and in t where that sequence of pieces changes.
template <class Piece>
long double kinked_reference(const composition& c, long double mu, long double alpha, long double f0, const Piece& piece,
                             long double tol = 1e-14L) {
    using boost::math::quadrature::gauss_kronrod;
    using R = long double;
    const R pi = boost::math::constants::pi<R>(), sv = std::sqrt((1 - mu) * (1 + mu));
    const vec3<R> v(sv, 0, mu);
    const brdf::params<R> p{0, f0, alpha};
    auto term = [&](R ct, R st, R phi) {
        const R vh = sv * st * std::cos(phi) + mu * ct;
        return piece(ct, vh, 2 * vh * ct - mu);
    };
    // the pieces of [0, phi_max(t)] on which the term is one: their ends
    auto pieces = [&](R t) {
        const R ct = std::cos(t), st = std::sin(t);
        const R c0 = -mu * (ct * ct - st * st) / (2 * sv * st * ct);
        const R phi_max = c0 <= -1 ? pi : std::acos(c0);
        std::vector<R> ends{0};
        const int n = 64;
        R prev = 0;
        for (int i = 1; i <= n; ++i) {
            const R phi = phi_max * i / n;
            if (term(ct, st, phi) != term(ct, st, prev)) {
                R lo = prev, hi = phi;
                const int left = term(ct, st, lo);
                for (int it = 0; it < 80; ++it) {
                    const R m = (lo + hi) / 2;
                    (term(ct, st, m) == left ? lo : hi) = m;
                }
                ends.push_back((lo + hi) / 2);
            }
            prev = phi;
        }
        ends.push_back(phi_max);
        return ends;
    };
    auto over_phi = [&](R t) {
        const R ct = std::cos(t), st = std::sin(t);
        auto f = [&](R phi) {
            const vec3<R> h(st * std::cos(phi), st * std::sin(phi), ct);
            const R vh = v.dot(h);
            const vec3<R> l = 2 * vh * h - v;
            if (!(l.z() > 0 && vh > 0)) return R(0);
            return c.f(l, v, p) * l.z() * 4 * vh * st;
        };
        const auto ends = pieces(t);
        R sum = 0;
        for (std::size_t i = 0; i + 1 < ends.size(); ++i) sum += gauss_kronrod<R, 61>::integrate(f, ends[i], ends[i + 1], 10, tol / 10);
        return 2 * sum;
    };
    // breakpoints in t: t1 (phi_max leaves pi) and where the pieces' count changes
    const R t1 = std::asin(mu) / 2, t2 = pi / 2 - t1;
    std::vector<R> breaks{0, t1, t2};
    const int n = 128;
    for (int i = 1; i < n; ++i) {
        R lo = t2 * (i - 1) / n + 1e-12L, hi = t2 * i / n;
        const std::size_t left = pieces(lo).size();
        if (pieces(hi).size() == left) continue;
        for (int it = 0; it < 60; ++it) {
            const R m = (lo + hi) / 2;
            (pieces(m).size() == left ? lo : hi) = m;
        }
        breaks.push_back((lo + hi) / 2);
    }
    std::sort(breaks.begin(), breaks.end());
    R sum = 0;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
        if (breaks[i + 1] > breaks[i]) sum += gauss_kronrod<R, 61>::integrate(over_phi, breaks[i], breaks[i + 1], 10, tol);
    return sum;
}
}  // namespace

// Cook-Torrance's G is a min(): its kinks are curves across the domain, where a panel's Gauss and
// Kronrod sums can agree by chance. Through the generic integral, which does not split there, the
// bound was 1/134 of the true error at alpha = 0.4, mu = 0.05 (blinn-phong/cook-torrance/one); the
// integral in the distribution's variable puts breakpoints on them.
TEST_CASE("E(mu, alpha) with Cook-Torrance's G: against a reference split where the min() changes its term") {
    const auto [id, alpha, mu] = GENERATE(normzoo_test::thinned_under_sanitizers(2, table<const char*, double, double>({{"blinn-phong/cook-torrance/one", 0.4, 0.05},
                                                                             {"ggx/cook-torrance/schlick", 1.0, 0.1},
                                                                             {"ggx/cook-torrance/one", 0.3, 0.6},
                                                                             {"beckmann/cook-torrance/schlick", 0.5, 0.3}})));
    const auto c = composition::parse(id);
    const double f0 = 0.04;
    const auto e = microfacet::directional_albedo(c, mu, alpha, f0);
    // the term of min(1, 2 N.h N.V / V.h, 2 N.h N.L / V.h) that is least
    const long double ref = kinked_reference(c, mu, alpha, f0, [&](long double nh, long double vh, long double nl) {
        const long double a = 2 * nh * mu / vh, b = 2 * nh * nl / vh;
        return a < 1 && a <= b ? 1 : b < 1 ? 2 : 0;
    });
    CAPTURE(id, alpha, mu, e.value, e.abs_error, static_cast<double>(ref));
    CHECK(std::abs(e.value - static_cast<double>(ref)) <= e.abs_error + 1e-14);
    CHECK(e.abs_error <= 1e-10);
}

// The exact Fresnel factor at eta < 1 (light leaving the denser side: openpbr-bsdf's tables, a
// coat's underside) is 1 beyond the critical angle and has an infinite slope below it, a kink
// along a curve across the domain. Without it as a breakpoint, the whole circle's trapezoidal
// rule (stretched.hpp) took it for analytic: bounds of 2e-11 to 6e-11 against errors of 3e-10 to
// 1.2e-7 (ggx/smith-height-correlated/dielectric, eta 0.6, alpha 0.25).
TEST_CASE("E(mu, alpha) with total internal reflection (eta < 1): against a reference split at the critical angle") {
    const auto [id, eta, alpha, mu] = GENERATE(normzoo_test::thinned_under_sanitizers(3, table<const char*, double, double, double>({
        {"ggx/smith-height-correlated/dielectric", 0.6, 0.3, 0.9},
        {"ggx/smith-height-correlated/dielectric", 0.6, 0.5, 0.2},
        {"ggx/smith-separable/dielectric", 1 / 1.5, 0.3, 0.5},
        {"ggx/smith-separable/dielectric", 0.9, 1.0, 0.5},
        {"beckmann/smith-separable/conductor", 0.7, 0.4, 0.7},
        {"ggx/smith-height-correlated/dielectric", 0.6, 1.5, 0.4}})));
    auto c = composition::parse(id);
    c.eta = eta;
    const long double crit = std::sqrt((1 - static_cast<long double>(eta)) * (1 + static_cast<long double>(eta)));
    const auto e = microfacet::directional_albedo(c, mu, alpha, 1);
    // the reference at a relative 1e-12 (the check's margin): the errors this catches were 3e-10 and more
    const long double ref =
        kinked_reference(c, mu, alpha, 1, [&](long double, long double vh, long double) { return vh < crit ? 1 : 0; }, 1e-12L);
    CAPTURE(id, eta, alpha, mu, e.value, e.abs_error, static_cast<double>(ref));
    CHECK(std::abs(e.value - static_cast<double>(ref)) <= e.abs_error + 1e-12);
    CHECK(e.abs_error <= 1e-10);
}

// Below eta ~ 1e-8 the critical V.h, sqrt(1 - eta^2), rounds to 1: F is 1 at every V.h but 1, and
// a breakpoint at V.h = 1 gave NaN (eta 1e-9, found by a review).
TEST_CASE("E(mu, alpha) at an index whose critical V.h rounds to 1: F = 1's albedo") {
    for (double eta : {1e-9, 1e-300}) {
        auto c = composition::parse("ggx/smith-height-correlated/dielectric");
        c.eta = eta;
        const auto e = microfacet::directional_albedo(c, 0.5, 0.3, 1);
        const auto one = microfacet::directional_albedo(composition::parse("ggx/smith-height-correlated/one"), 0.5, 0.3, 1);
        CAPTURE(eta, e.value, e.abs_error, one.value, one.abs_error);
        CHECK(std::isfinite(e.value));
        CHECK(std::abs(e.value - one.value) <= e.abs_error + one.abs_error);
    }
}

// The kinks' root finder (detail/sign_changes.hpp): each bracketed sign change bisected to full
// precision, and a grid that does not ascend refused rather than read backwards.
TEST_CASE("sign_changes: roots of two functions on a grid, a grid that does not ascend refused") {
    auto f = [](double x, double* v) { v[0] = x * x - 2, v[1] = std::cos(x); };
    std::vector<double> grid;
    for (int i = 0; i <= 40; ++i) grid.push_back(i * 0.1);
    std::vector<double> roots = normzoo::detail::sign_changes<2>(f, grid);
    std::sort(roots.begin(), roots.end());
    REQUIRE(roots.size() == 2);
    CHECK(std::abs(roots[0] - std::sqrt(2.0)) <= 4e-16);
    CHECK(std::abs(roots[1] - std::acos(-1.0) / 2) <= 4e-16);
    std::swap(grid[10], grid[30]);
    CHECK_THROWS_AS(normzoo::detail::sign_changes<2>(f, grid), std::invalid_argument);
}

// Near grazing incidence (mu ~ 0.002 to 0.015) the kinks enter and leave the domain within mu of
// t = 0, where the grid their events are found on once ran backwards (Boost's bisect refused a
// cell: every Cook-Torrance albedo there threw). Against the generic integral at 1e-12, which
// finds the kinks in theta at each azimuth (albedo.hpp).
TEST_CASE("E(mu, alpha) with Cook-Torrance's G near grazing incidence: against the generic integral") {
    const auto [id, alpha, mu] = GENERATE(table<const char*, double, double>({{"ggx/cook-torrance/one", 0.3, 0.01},
                                                                             {"beckmann/cook-torrance/schlick", 0.01, 0.005},
                                                                             {"blinn-phong/cook-torrance/one", 0.3, 0.002}}));
    const auto c = composition::parse(id);
    const auto e = microfacet::directional_albedo(c, mu, alpha, 0.04);
    normzoo::albedo_settings tight;
    tight.tolerance = 1e-12;
    const auto g = normzoo::albedo<composition>(microfacet::angle_of_cosine(mu), composition::node_exponent(alpha), 0.04, tight, alpha, c);
    CAPTURE(id, alpha, mu, e.value, e.abs_error, g.value, g.abs_error);
    CHECK(std::abs(e.value - g.value) <= e.abs_error + g.abs_error);
    CHECK(e.abs_error <= 1e-10);
}

// At normal incidence the kink is a whole circle of half vectors, at t = 30 degrees (L's term
// 2 cos 2t falls below 1), and GGX at alpha = 1 is D = 1/pi: E = 2 (integral_0^30deg cos t sin t dt
// + integral_30deg^45deg 2 cos 2t cos t sin t dt) = 2 (1/8 + 1/16) = 3/8.
TEST_CASE("E(1, 1) of ggx/cook-torrance/one is 3/8") {
    const auto e = microfacet::directional_albedo(composition::parse("ggx/cook-torrance/one"), 1.0, 1.0);
    CAPTURE(e.value, e.abs_error);
    CHECK(std::abs(e.value - 0.375) <= e.abs_error + 1e-16);
    CHECK(e.abs_error <= 1e-10);
}

// With F = 1, GGX and a G of N.L and N.V, the albedo is one integral over N.L with D's integral
// over the azimuth in closed form (microfacet/azimuthal_albedo.hpp): against the closed forms at
// alpha = 1 and the generic integral (its own coordinates, 100 times tighter) elsewhere, down to
// the least roughness of a 128^2 table (r = 1/256) at normal incidence, where the peak is
// alpha^2 wide at N.L = 1, and to the smallest incidence cosine taken.
TEST_CASE("E(mu, alpha) with F = 1 as one integral over N.L: the closed forms at alpha = 1") {
    for (const auto& [id, correlated] : {std::pair{"ggx/smith-height-correlated/one", true}, std::pair{"ggx/smith-separable/one", false}})
        for (double mu : {1.0, 0.3, 1e-4}) {
            const auto e = microfacet::directional_albedo(composition::parse(id), mu, 1.0);
            const double exact = albedo_at_alpha_1(correlated, mu);
            CAPTURE(id, mu, e.value, e.abs_error, exact);
            CHECK(std::abs(e.value - exact) <= e.abs_error + 1e-15);
        }
}
