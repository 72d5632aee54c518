// The split-sum pair to a tolerance asked per value (microfacet/split_sum_to.hpp): its values lie
// within their bounds of the pair at 1e-12 (split_sum.hpp) on a grid with the edges, the edges'
// limits are what the quadrature tends to, the check of the bounds catches a broken one, and a
// panel's nodes computed at once are each node's values; and the table material-blend's two ways
// of mixing a compensated metal and dielectric against their closed forms in the split-sum terms.
#include <normzoo/microfacet/split_sum.hpp>
#include <normzoo/microfacet/split_sum_to.hpp>
#include <verify/tables/material_blend.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace mf = normzoo::microfacet;

// The grid, with the texels a corner-aligned table has at its edges (0) and next to them.
const std::vector<double> mus{0, 1e-8, 1e-4, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 1};
const std::vector<double> alphas{0, 1e-8, 1e-4, 0.01, 0.1, 0.3, 0.6, 1};

// The tolerances a check asks (a hundredth of 8-bit, 16-bit and half storage; 1e-10 as the
// tables are made), and a pair of different ones, as a half table's small A beside a large B.
const std::vector<mf::split_sum_tolerance> tolerances{
    {1e-10, 1e-10}, {0.5 / 65535 / 100, 0.5 / 65535 / 100}, {0.5 / 255 / 100, 0.5 / 255 / 100}, {1e-10, 2e-6}};

// How far each value is from the reference, in units of the two bounds added (<= 1: honest), with
// the bounds divided by `shrink` (1: as returned). Edges (mu or alpha 0) are not on the reference's
// domain: their limits are tested below.
double worst_ratio(const mf::composition& c, const mf::split_sum_tolerance& tol, double shrink) {
    double worst = 0;
    for (double alpha : alphas)
        for (double mu : mus) {
            if (mu == 0 || alpha == 0) continue;
            const auto v = mf::split_sum_to(c, mu, alpha, tol);
            const auto ref = mf::split_sum(c, mu, alpha, normzoo::albedo_settings{1e-12, 4000});
            CAPTURE(mu, alpha, tol.a, tol.b, v.a.value, v.a.abs_error, ref.a.value, v.b.value, v.b.abs_error, ref.b.value);
            CHECK(v.a.abs_error <= 2 * tol.a);  // what was asked, give or take the rounding terms
            CHECK(v.b.abs_error <= 2 * tol.b);
            worst = std::max(worst, std::abs(v.a.value - ref.a.value) / (v.a.abs_error / shrink + ref.a.abs_error));
            worst = std::max(worst, std::abs(v.b.value - ref.b.value) / (v.b.abs_error / shrink + ref.b.abs_error));
        }
    return worst;
}

}  // namespace

TEST_CASE("split_sum_to: every value within its bound of the pair at 1e-12, at the tolerances a check asks") {
    const auto id = GENERATE(as<std::string>{}, "ggx/smith-height-correlated/one", "ggx/smith-separable/one", "ggx/hammon/one");
    const auto c = mf::composition::parse(id);
    for (const auto& tol : tolerances) {
        CAPTURE(id, tol.a, tol.b);
        CHECK(worst_ratio(c, tol, 1) <= 1);
    }
}

TEST_CASE("split_sum_to: the check of the bounds catches a bound 1000x too small") {
    // The same comparison with every returned bound divided by 1000 fails somewhere: the test
    // above would see a bound that is not a bound.
    const auto c = mf::composition::parse("ggx/smith-height-correlated/one");
    CHECK(worst_ratio(c, {0.5 / 255 / 100, 0.5 / 255 / 100}, 1000) > 1);
}

TEST_CASE("split_sum_to: elsewhere it is split_sum at the least tolerance") {
    // Beckmann has no closed form of Schlick's factor over the azimuth; alpha > 1 leaves the 1D integral
    for (const auto& [id, alpha] : {std::pair<std::string, double>{"beckmann/smith-height-correlated/one", 0.3},
                                    std::pair<std::string, double>{"ggx/smith-height-correlated/one", 1.5}}) {
        const auto c = mf::composition::parse(id);
        const auto v = mf::split_sum_to(c, 0.4, alpha, {1e-6, 1e-8});
        const auto ref = mf::split_sum(c, 0.4, alpha, normzoo::albedo_settings{1e-8, 400});
        CAPTURE(id);
        CHECK(v.a.value == ref.a.value);
        CHECK(v.b.value == ref.b.value);
    }
    CHECK_THROWS_AS(mf::split_sum_to(mf::composition::parse("ggx/smith-height-correlated/one"), 0.5, 0.3, {0, 1e-6}),
                    std::invalid_argument);
    CHECK_THROWS_AS(mf::split_sum_to(mf::composition::parse("ggx/smith-height-correlated/one"), 1e-9, 0.3, {1e-6, 1e-6}),
                    std::invalid_argument);
}

TEST_CASE("split_sum_to at alpha = 0: the mirror's pair, what the quadrature tends to") {
    const auto c = mf::composition::parse("ggx/smith-height-correlated/one");
    for (double mu : {0.01, 0.1, 0.5, 0.9, 1.0}) {
        const auto limit = mf::split_sum_to(c, mu, 0, {1e-10, 1e-10});
        CHECK(limit.b.value == Approx(std::pow(1 - mu, 5)).margin(1e-15));
        CHECK(limit.a.value + limit.b.value == Approx(1).margin(1e-15));
        // the quadrature at alpha = eps tends to it, about as fast as alpha / mu
        for (double eps : {1e-8, 1e-6}) {
            const auto q = mf::split_sum(c, mu, eps);
            CAPTURE(mu, eps, q.a.value, limit.a.value, q.b.value, limit.b.value);
            CHECK(std::abs(q.a.value - limit.a.value) <= q.a.abs_error + limit.a.abs_error + 100 * eps / mu);
            CHECK(std::abs(q.b.value - limit.b.value) <= q.b.abs_error + limit.b.abs_error + 100 * eps / mu);
        }
    }
}

TEST_CASE("split_sum_to at mu = 0: the grazing limit, what the quadrature tends to") {
    const auto id = GENERATE(as<std::string>{}, "ggx/smith-height-correlated/one", "ggx/smith-separable/one");
    const auto c = mf::composition::parse(id);
    for (double alpha : {0.01, 0.1, 0.5, 1.0}) {
        const auto limit = mf::split_sum_to(c, 0, alpha, {1e-10, 1e-10});
        CHECK(limit.a.abs_error <= 2e-10);
        CHECK(limit.b.abs_error <= 2e-10);
        // the quadrature at mu = 1e-6 and 1e-8: 100x closer to the limit at the 100x smaller mu
        const auto far = mf::split_sum(c, 1e-6, alpha), near = mf::split_sum(c, 1e-8, alpha);
        const double far_a = std::abs(far.a.value - limit.a.value), near_a = std::abs(near.a.value - limit.a.value);
        const double far_b = std::abs(far.b.value - limit.b.value), near_b = std::abs(near.b.value - limit.b.value);
        CAPTURE(id, alpha, limit.a.value, limit.b.value, far_a, near_a, far_b, near_b);
        CHECK(near_a <= far_a / 30 + near.a.abs_error + limit.a.abs_error);
        CHECK(near_b <= far_b / 30 + near.b.abs_error + limit.b.abs_error);
        CHECK(near_a <= 1e-6);
        CHECK(near_b <= 1e-6);
        if (id == "ggx/smith-height-correlated/one") {
            // G Lambda(V) -> 1 and mu (1 + Lambda(mu)) -> alpha / 2: with F = 1 the albedo at grazing is 1
            CHECK(std::abs(limit.a.value + limit.b.value - 1) <= limit.a.abs_error + limit.b.abs_error);
            // alpha = 1: D = 1/pi, V.h of the visible normals has density 2y on [0, 1]: B = E[(1 - y)^5] = 1/21
            if (alpha == 1.0) CHECK(std::abs(limit.b.value - 1.0 / 21) <= limit.b.abs_error);
        }
    }
}

TEST_CASE("split_sum_to at mu = 0 and alpha = 0: A's limit 0, B without one, other G refused at the edges") {
    const auto c = mf::composition::parse("ggx/smith-height-correlated/one");
    const auto corner = mf::split_sum_to(c, 0, 0, {1e-10, 1e-10});
    CHECK(corner.a.value == 0);
    CHECK(corner.b.value - corner.b.abs_error == 0);  // [0, 1]: every limit along a path to the corner
    CHECK(corner.b.value + corner.b.abs_error == 1);
    for (const char* id : {"ggx/schlick-ggx/one", "ggx/implicit/one"}) {
        CHECK_THROWS_AS(mf::split_sum_to(mf::composition::parse(id), 0, 0.3, {1e-10, 1e-10}), std::invalid_argument);
        CHECK_THROWS_AS(mf::split_sum_to(mf::composition::parse(id), 0.5, 0, {1e-10, 1e-10}), std::invalid_argument);
    }
    // Beckmann: the mirror's limit holds (Lambda -> 0), the grazing one is derived for GGX only
    const auto beckmann = mf::composition::parse("beckmann/smith-height-correlated/one");
    CHECK(mf::split_sum_to(beckmann, 0.5, 0, {1e-10, 1e-10}).b.value == Approx(1.0 / 32));
    CHECK_THROWS_AS(mf::split_sum_to(beckmann, 0, 0.3, {1e-10, 1e-10}), std::invalid_argument);
}

// A panel's nodes at once (ggx_schlick_azimuth.hpp, detail/complete_elliptic.hpp: their iterations
// side by side, each stopping at its own step) give each node's result bit for bit: nodes whose
// elliptic moduli kc need from 2 to 7 iterations share one panel, in both orders.
TEST_CASE("split_sum_to's nodes at once: each the node alone, bit for bit") {
    namespace d = normzoo::microfacet::detail;
    const auto [nv, alpha] = GENERATE(table<double, double>({{0.5, 0.3}, {1e-4, 0.01}, {0.999, 1.0}, {0.02, 1e-3}}));
    std::array<double, 15> nl, x, sl;
    for (std::size_t i = 0; i < nl.size(); ++i) {
        nl[i] = std::pow(10.0, -4.0 * double(i) / 14);  // 1 down to 1e-4: kc = (N.L + N.V) / (1 + L.V) spans decades
        x[i] = nl[i] - nv, sl[i] = std::sqrt((1 - nl[i]) * (1 + nl[i]));
    }
    const double sv = std::sqrt((1 - nv) * (1 + nv));
    for (const bool reversed : {false, true}) {
        if (reversed) std::reverse(nl.begin(), nl.end()), std::reverse(x.begin(), x.end()), std::reverse(sl.begin(), sl.end());
        const auto together = d::ggx_schlick_azimuthal_integrals_at<15>(nl, nv, x, sl, sv, alpha);
        for (std::size_t i = 0; i < nl.size(); ++i) {
            using one = std::array<double, 1>;
            const auto alone = d::ggx_schlick_azimuthal_integrals_at<1>(one{nl[i]}, nv, one{x[i]}, one{sl[i]}, sv, alpha)[0];
            CAPTURE(nv, alpha, nl[i], reversed, together[i].d5, alone.d5);
            CHECK(together[i].d == alone.d);
            CHECK(together[i].d5 == alone.d5);
            CHECK(together[i].d5_error == alone.d5_error);
        }
    }
}

// The table material-blend (tables/material_blend.hpp) against its closed forms in the split-sum
// terms, computed apart from compensated_albedo: E_ss(F0) = F0 A + B is linear in F0, so
//   Turquin      C(F0) = (F0 A + B)(1 + F0 k), k = 1/E1 - 1: a parabola in F0, and mixing F0 by m
//                differs from mixing results by -A k m (1 - m) (c - 0.04)^2;
//   Kulla-Conty  C(F0) = F0 A + B + s(F0) (1 - E1), s = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),
//                F_avg = F0 + (1 - F0)/21 (Schlick's, in closed form): the difference is
//                (1 - E1) (s(mixed F0) - m s(c) - (1 - m) s(0.04));
//   Fdez-Aguera  C(F0) = (F0 A + B) / (1 - F_avg (1 - E1)), F_avg as above: the difference is
//                that of C at the three F0.
TEST_CASE("material-blend: mixing F0 against mixing results, by the split-sum terms") {
    const auto [comp, r, c, m_index, mu_index] = GENERATE(table<std::string, double, double, std::size_t, std::size_t>(
        {{"turquin", 0.5, 1, 1, 0}, {"turquin", 1, 0.5, 0, 2}, {"turquin", 0.25, 1, 2, 1},
         {"kulla-conty", 0.5, 1, 1, 0}, {"kulla-conty", 1, 1, 1, 0}, {"kulla-conty", 0.75, 0.5, 2, 2},
         {"fdez-aguera", 0.5, 1, 1, 0}, {"fdez-aguera", 1, 0.5, 0, 2}}));
    namespace grid = verify::material_blend_grid;
    const double m = grid::metallics()[m_index], mu = grid::mus()[mu_index], alpha = r * r, d = grid::dielectric_f0;
    const auto row = verify::blend_record(verify::blend_group_at(comp, r, c), m_index, mu_index);
    const double difference = row.number("difference"), bound = row.number("error_estimate");
    const auto pair = mf::split_sum(mf::composition::parse("ggx/smith-height-correlated/schlick"), mu, alpha);
    const auto e1 = mf::directional_albedo(mf::composition::parse("ggx/smith-height-correlated/one"), mu, alpha);
    double expected = 0, expected_bound = 0;
    if (comp == "turquin") {
        const double k = 1 / e1.value - 1;
        expected = -pair.a.value * k * m * (1 - m) * (c - d) * (c - d);
        expected_bound = std::abs(expected) * (pair.a.abs_error / pair.a.value + 2 * e1.abs_error / (e1.value * k));
    } else if (comp == "fdez-aguera") {
        auto c_of = [&](double f0) {
            const double f_avg = f0 + (1 - f0) / 21;
            return (f0 * pair.a.value + pair.b.value) / (1 - f_avg * (1 - e1.value));
        };
        expected = c_of(m * c + (1 - m) * d) - m * c_of(c) - (1 - m) * c_of(d);
        expected_bound = 4 * (pair.a.abs_error + pair.b.abs_error + e1.abs_error);
    } else {
        const auto e_avg = mf::average_albedo(mf::composition::parse("ggx/smith-height-correlated/one"), alpha);
        auto s = [&](double f0) {
            const double f_avg = f0 + (1 - f0) / 21;
            return f_avg * f_avg * e_avg.value / (1 - f_avg * (1 - e_avg.value));
        };
        const double curve = s(m * c + (1 - m) * d) - m * s(c) - (1 - m) * s(d);
        expected = (1 - e1.value) * curve;
        expected_bound = std::abs(curve) * e1.abs_error + 8 * (1 - e1.value) * e_avg.abs_error;
    }
    INFO(comp << " r " << r << " c " << c << " m " << m << " mu " << mu << ": " << difference << " +- " << bound
              << " against " << expected << " +- " << expected_bound);
    CHECK(std::abs(difference - expected) <= bound + expected_bound + 1e-15);
    CHECK(std::abs(difference) > bound);  // the two ways part wherever the metal and the dielectric differ
}

TEST_CASE("material-blend: without a compensation the two ways agree (single scattering is linear in F0)") {
    const auto [r, mu] = GENERATE(table<double, double>({{0.25, 1}, {0.75, 0.125}, {1, 0.5}}));
    const auto single = mf::composition::parse("ggx/smith-height-correlated/schlick");
    const double alpha = r * r, c = 0.5, m = 0.25, d = verify::material_blend_grid::dielectric_f0;
    const auto metal = mf::compensated_albedo(single, mu, alpha, c);
    const auto dielectric = mf::compensated_albedo(single, mu, alpha, d);
    const auto mixed = mf::compensated_albedo(single, mu, alpha, m * c + (1 - m) * d);
    const double difference = mixed.value - (m * metal.value + (1 - m) * dielectric.value);
    CHECK(std::abs(difference) <= mixed.abs_error + metal.abs_error + dielectric.abs_error + 1e-15);
}
