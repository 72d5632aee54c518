// The lobe engine on integrals with known answers: the value within its own error bound, the
// bound small, and the bound honest over many random cases.
#include <catch2/catch.hpp>
#include <normzoo/normzoo.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>

using normzoo::quad;
using normzoo::wide;
using normzoo::quadrature::lobe_point;
using normzoo::quadrature::lobe_quadrature;

TEST_CASE("cosine moments to the horizon: error within the estimate, estimate below 1e-32") {
    const double n = GENERATE(0.0, 1e-3, 0.1, 1.0, 7.5, 100.0, 1e4, 1e7, 1e9);
    const int k = GENERATE(0, 1, 2, 3);
    auto f = [k](const lobe_point<quad>& p) { return p.power * pow(p.cos_theta, k) * p.sin_theta; };
    const auto e = lobe_quadrature<quad>{}.integrate(f, quad(1), quad(n), boost::math::constants::half_pi<quad>());
    const wide truth = 1 / (wide(n) + k + 1);
    const double err = static_cast<double>(abs(wide(e.value) - truth) / truth);
    const double est = static_cast<double>(e.abs_error / e.value);
    CAPTURE(n, k, err, est);
    CHECK(err <= est);
    CHECK(est < 1e-32);
}

TEST_CASE("half-angle lobe on a finite range") {
    // integral over t in [0, pi/2] of cos^n(t/2) sin(t/2) = 2 (1 - 2^(-(n+1)/2)) / (n + 1)
    const double n = GENERATE(0.0, 0.5, 3.0, 250.0, 2048.0, 1e6);
    auto f = [](const lobe_point<quad>& p) { return p.power * p.sin_theta; };
    const auto e = lobe_quadrature<quad>{}.integrate(f, quad(0.5), quad(n), boost::math::constants::half_pi<quad>() / 2);
    const wide truth = 2 * (1 - pow(wide(2), -(wide(n) + 1) / 2)) / (wide(n) + 1);
    const double err = static_cast<double>(abs(wide(e.value) - truth) / truth);
    const double est = static_cast<double>(e.abs_error / e.value);
    CAPTURE(n, err, est);
    CHECK(err <= est);
    CHECK(est < 1e-32);
}

TEST_CASE("honest estimates: 2000 random exponents and weights") {
    std::mt19937_64 rng(20261121);
    std::uniform_real_distribution<double> log_n(-8, 9.5);
    std::uniform_int_distribution<int> power(0, 4);
    double worst_ratio = 0;
    for (int i = 0; i < 2000; ++i) {
        const double n = i % 50 == 0 ? 0.0 : std::pow(10.0, log_n(rng));
        const int k = power(rng);
        auto f = [k](const lobe_point<quad>& p) { return p.power * pow(p.cos_theta, k) * p.sin_theta; };
        const auto e = lobe_quadrature<quad>{}.integrate(f, quad(1), quad(n), boost::math::constants::half_pi<quad>());
        const wide truth = 1 / (wide(n) + k + 1);
        const double ratio = static_cast<double>(abs(wide(e.value) - truth) / wide(e.abs_error));
        worst_ratio = std::max(worst_ratio, ratio);
        CAPTURE(n, k);
        REQUIRE(ratio <= 1);
    }
    INFO("largest true error / estimate: " << worst_ratio);
    CHECK(worst_ratio > 1e-6);  // not absurdly pessimistic either
}

// The quick plan (a relative tolerance of 1e-9 or more): the bound still covers the error, meets
// the tolerance, and costs under half the full plan's nodes. To the horizon its lobe beyond
// x = 24 is 4e-11 of the peak: without that tail in the bound, the error was 40x the bound.
TEST_CASE("quick plan at 1e-8 in double: 2000 random lobes, bound honest and within the tolerance") {
    std::mt19937_64 rng(20261127);
    std::uniform_real_distribution<double> log_n(-8, 9.5);
    std::uniform_int_distribution<int> power(0, 4);
    const double tol = 1e-8;
    double worst_ratio = 0;
    for (int i = 0; i < 2000; ++i) {
        const double n = i % 50 == 0 ? 0.0 : std::pow(10.0, log_n(rng));
        const int k = power(rng);
        const bool half_angle = i % 3 == 0;  // cos(t/2) on t in [0, pi/2]: the range ends inside the lobe's panels
        auto f = [k](const lobe_point<double>& p) { return p.power * std::pow(p.cos_theta, k) * p.sin_theta; };
        const lobe_quadrature<double> rule(tol);
        const auto e = half_angle ? rule.integrate(f, 0.5, n, boost::math::constants::half_pi<double>() / 2)
                                  : rule.integrate(f, 1.0, n, boost::math::constants::half_pi<double>());
        const wide m = wide(n) + k + 1;
        const wide truth = half_angle ? 2 * (1 - pow(wide(2), -m / 2)) / m : 1 / m;
        const double ratio = static_cast<double>(abs(wide(e.value) - truth) / wide(e.abs_error));
        worst_ratio = std::max(worst_ratio, ratio);
        CAPTURE(n, k, half_angle, e.value, e.abs_error);
        REQUIRE(ratio <= 1);
        REQUIRE(e.abs_error <= tol * e.value);
        REQUIRE(e.evaluations <= 60);
    }
    INFO("largest true error / bound: " << worst_ratio);
    CHECK(worst_ratio > 0.1);
}

TEST_CASE("below 1e-9 the full plan: the default's value, bound and nodes") {
    const double tol = GENERATE(0.0, 1e-10, 1e-12);
    auto f = [](const lobe_point<double>& p) { return p.power * p.cos_theta * p.sin_theta; };
    const auto full = lobe_quadrature<double>{}.integrate(f, 1.0, 0.5, boost::math::constants::half_pi<double>());
    const auto e = lobe_quadrature<double>(tol).integrate(f, 1.0, 0.5, boost::math::constants::half_pi<double>());
    CHECK(e.value == full.value);
    CHECK(e.abs_error == full.abs_error);
    CHECK(e.evaluations == full.evaluations);
    CHECK(full.evaluations > 100);
}

TEST_CASE("an off-centre peak: Boost 1.74 answers 0 +- 0, the lobe engine does not") {
    // cos^n(t - 0.3) |sin(t - 0.3)| on [0, pi/2] at n = 1e7: the lobe is 3e-4 wide and no node of
    // Boost's tanh_sinh (or adaptive Gauss-Kronrod) falls in it.
    const double n = 1e7, c = 0.3;
    auto f = [&](double t) { return std::pow(std::cos(t - c), n) * std::abs(std::sin(t - c)); };
    boost::math::quadrature::tanh_sinh<double> ts;
    double err = 0;
    const double naive = ts.integrate(f, 0.0, M_PI / 2, 1e-12, &err);
    const wide truth = (2 - pow(cos(wide(c)), n + 1) - pow(sin(wide(c)), n + 1)) / (n + 1);
    INFO("Boost tanh_sinh: " << naive << " +- " << err << ", truth " << static_cast<double>(truth));
    CHECK(std::abs(naive - static_cast<double>(truth)) > 10 * err);  // confidently wrong
    // The lobe engine, told where the lobe is, integrates each side of it from its peak.
    auto g = [](const lobe_point<quad>& p) { return p.power * p.sin_theta; };
    const auto left = lobe_quadrature<quad>{}.integrate(g, quad(1), quad(n), quad(c));
    const auto right = lobe_quadrature<quad>{}.integrate(g, quad(1), quad(n), boost::math::constants::half_pi<quad>() - quad(c));
    const wide ours = wide(left.value) + wide(right.value);
    CHECK(static_cast<double>(abs(ours - truth) / truth) < 1e-32);
    CHECK(static_cast<double>(abs(ours - truth)) <= static_cast<double>(left.abs_error + right.abs_error));
}

TEST_CASE("hemisphere quadrature of (N.w)^n in long double") {
    const double n = GENERATE(0.0, 1.0, 33.0, 1e5, 1e7);
    const long double nn = n;
    auto g = [nn](const normzoo::vec3<long double>& w) {
        return normzoo::pow_lobe(normzoo::normal<long double>(), w, nn);
    };
    const auto e = normzoo::quadrature::hemisphere_quadrature<long double>(8).integrate(g, 1.0L, nn);
    const wide truth = 2 * normzoo::pi<wide>() / (wide(n) + 1);
    const double err = static_cast<double>(abs(wide(e.value) - truth) / truth);
    const double est = static_cast<double>(e.abs_error / e.value);
    CAPTURE(n, err, est);
    CHECK(err <= est);
    CHECK(est < 1e-14);
}

// The periodic trapezoid (quadrature/periodic.hpp) against a closed form: the integral over
// [0, pi] of exp(a cos x) is pi I0(a). Sharper peaks (larger a) need more nodes; the bound holds
// and meets the tolerance.
TEST_CASE("periodic trapezoid: exp(a cos x) against pi I0(a), bound honest") {
    const double a = GENERATE(0.0, 0.5, 5.0, 50.0);
    const double tol = GENERATE(1e-6, 1e-12);
    const double exact = boost::math::constants::pi<double>() * boost::math::cyl_bessel_i(0, a);
    auto f = [&](double, double c, double) { return normzoo::quadrature::estimate<double>{std::exp(a * c), 0, 1}; };
    const auto r = normzoo::quadrature::periodic_trapezoid<double>(f, 4, 1024, tol * exact);
    INFO("a = " << a << ", tol = " << tol << ": value " << r.integral.value << ", bound " << r.integral.abs_error
                << ", true " << std::abs(r.integral.value - exact) << ", evaluations " << r.integral.evaluations);
    CHECK(r.converged);
    CHECK(std::abs(r.integral.value - exact) <= r.integral.abs_error);
    CHECK(r.integral.abs_error <= 2 * tol * exact);
}

// Stopped before it converges, the bound still covers the error: T(n) against pi I0(a) with
// n fixed, where |T(n) - T(n/2)| is all the rule knows.
TEST_CASE("periodic trapezoid: the bound of an unconverged sum is honest") {
    const double a = 50;
    const std::size_t n = GENERATE(8, 16);  // at 32 intervals T(n) has reached the rounding of double
    const double exact = boost::math::constants::pi<double>() * boost::math::cyl_bessel_i(0, a);
    auto f = [&](double, double c, double) { return normzoo::quadrature::estimate<double>{std::exp(a * c), 0, 1}; };
    const auto r = normzoo::quadrature::periodic_trapezoid<double>(f, n, n, 0.0);
    INFO("n = " << n << ": bound " << r.integral.abs_error << ", true " << std::abs(r.integral.value - exact));
    CHECK_FALSE(r.converged);
    CHECK(std::abs(r.integral.value - exact) <= r.integral.abs_error);
}

TEST_CASE("periodic trapezoid: a start that is not a power of 2 up to 1024 is refused") {
    auto f = [](double, double, double) { return normzoo::quadrature::estimate<double>{1, 0, 1}; };
    for (std::size_t bad : {0, 1, 12, 2048})
        CHECK_THROWS_AS(normzoo::quadrature::periodic_trapezoid<double>(f, bad, 1024, 1e-10), std::invalid_argument);
    CHECK(normzoo::quadrature::periodic_trapezoid<double>(f, 2, 1024, 1e-10).converged);
}

// When the nodes run out, the rule says so instead of claiming the tolerance: a peak of width
// 1e-4 at x = pi cannot be resolved by 1024 intervals.
TEST_CASE("periodic trapezoid: an unresolved peak is reported, not converged") {
    auto f = [&](double, double c, double) { return normzoo::quadrature::estimate<double>{1 / (1e-8 + (1 + c)), 0, 1}; };
    const auto r = normzoo::quadrature::periodic_trapezoid<double>(f, 4, 1024, 1e-10);
    CHECK_FALSE(r.converged);
}

// Channels (quadrature/channels.hpp): two integrals from the same nodes, each with its own value
// and bound, against closed forms; the panels follow the harder channel. Over [0, 1]:
// integral of 1/(x + 1e-3) = ln(1001), of x^2 = 1/3 (which Kronrod 15 integrates exactly).
TEST_CASE("channels: two integrals on one set of nodes, each bound honest") {
    using pair = normzoo::quadrature::channels<double, 2>;
    const normzoo::quadrature::adaptive_kronrod<double, 15> rule(400);
    std::size_t calls = 0;
    auto f = [&](double x) {
        ++calls;
        pair v;
        v[0] = 1 / (x + 1e-3);
        v[1] = x * x;
        return v;
    };
    const auto r = rule.integrate(f, {0.0, 1.0}, 1e-12, 0.0);
    const double exact0 = std::log(1001.0), exact1 = 1.0 / 3;
    INFO("values " << r.value[0] << ", " << r.value[1] << "; bounds " << r.abs_error[0] << ", " << r.abs_error[1]);
    CHECK(std::abs(r.value[0] - exact0) <= r.abs_error[0]);
    CHECK(std::abs(r.value[1] - exact1) <= r.abs_error[1]);
    CHECK(r.abs_error[0] + r.abs_error[1] <= 2e-12);
    CHECK(r.abs_error[1] < 1e-15);  // x^2 is exact on every panel: only rounding
    CHECK(r.evaluations == calls);
    // the same panels as the harder channel alone
    const auto alone = rule.integrate([](double x) { return 1 / (x + 1e-3); }, {0.0, 1.0}, 1e-12, 0.0);
    CHECK(alone.value == r.value[0]);
    CHECK(alone.evaluations == r.evaluations);
    // and in the periodic rule: exp(cos x) and cos^2 x over [0, pi]
    auto g = [](double, double c, double) {
        pair v;
        v[0] = std::exp(c);
        v[1] = c * c;
        return normzoo::quadrature::estimate<pair>{v, pair{}, 1};
    };
    const auto p = normzoo::quadrature::periodic_trapezoid<double>(g, 4, 1024, 1e-13);
    const double pi = boost::math::constants::pi<double>();
    CHECK(p.converged);
    CHECK(std::abs(p.integral.value[0] - pi * boost::math::cyl_bessel_i(0, 1.0)) <= p.integral.abs_error[0]);
    CHECK(std::abs(p.integral.value[1] - pi / 2) <= p.integral.abs_error[1]);
}

// An integrand of an angle (adaptive.hpp): each node's cosine and sine from the addition formulas.
// Within 4 ulps of the library's at every node up to 2 pi (farther out, the node itself is rounded
// more than that in double), and the integral of
// exp(cos x) sin(3x)^2 over [a, b] matches the plain integrand's from the same panels.
TEST_CASE("angle integrands: node cosines and sines within 4 ulps, the same integral as f(x)") {
    const double eps = std::numeric_limits<double>::epsilon();
    double worst = 0;
    std::size_t nodes = 0;
    auto angle = [&](double x, double c, double s) {
        worst = std::max({worst, std::abs(c - std::cos(x)), std::abs(s - std::sin(x))});
        ++nodes;
        const double s3 = s * (3 - 4 * s * s);  // sin 3x
        return std::exp(c) * s3 * s3;
    };
    auto plain = [](double x) { return std::exp(std::cos(x)) * std::pow(std::sin(3 * x), 2); };
    const normzoo::quadrature::adaptive_kronrod<double, 15> rule(400);
    // The first two panels' half widths (b - a) / 4 fall in each of the series' lengths (from 3
    // terms below 0.003 to 9 at 3/4) and beyond 3/4 (the library's); bisections add narrower ones.
    const auto [a, b] = GENERATE(table<double, double>({{1.0, 1.008}, {2.0, 2.06}, {0.0, 0.1}, {-6.2, -5.9}, {0.5, 0.98},
                                                        {-2.0, -1.0}, {4.0, 5.6}, {-3.0, -0.6}, {-1.0, 2.0}, {0.3, 3.1},
                                                        {-6.0, 6.0}}));
    worst = 0;
    const auto r = rule.integrate(angle, {a, (a + b) / 2, b}, 1e-13, 0.0);
    const auto q = rule.integrate(plain, {a, (a + b) / 2, b}, 1e-13, 0.0);
    INFO("[" << a << ", " << b << "]: " << r.value << " against " << q.value << "; worst node error " << worst / eps << " ulp");
    CHECK(nodes > 0);
    CHECK(worst <= 4 * eps);
    CHECK(r.evaluations == q.evaluations);
    CHECK(std::abs(r.value - q.value) <= 1e-14 * (1 + std::abs(q.value)));
    CHECK(std::abs(r.value - q.value) <= r.abs_error + q.abs_error);
}

namespace {

// Every node and weight of normzoo's copied rule equals Boost's (the same value and sign: the
// copy keeps every bit), in the rule's order.
template <class Real, class Ours, class Boosts>
void check_rule_copy(const char* what, unsigned n) {
    using std::signbit;
    const auto& x = Ours::abscissa();
    const auto& w = Ours::weights();
    const auto& bx = Boosts::abscissa();
    const auto& bw = Boosts::weights();
    CAPTURE(what, n, normzoo::number_type_name<Real>);
    REQUIRE(x.size() == bx.size());
    REQUIRE(w.size() == bw.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        CAPTURE(i);
        CHECK((x[i] == bx[i] && signbit(x[i]) == signbit(bx[i])));
        CHECK(w[i] == bw[i]);
    }
}

template <class Real, unsigned... N>
void check_gauss_copies(std::integer_sequence<unsigned, N...>) {
    using namespace normzoo::quadrature;
    (check_rule_copy<Real, gauss_rule<Real, N>, boost::math::quadrature::gauss<Real, N>>("Gauss", N), ...);
}

template <class Real, unsigned... N>
void check_kronrod_copies(std::integer_sequence<unsigned, N...>) {
    using namespace normzoo::quadrature;
    (check_rule_copy<Real, kronrod_rule<Real, N>, boost::math::quadrature::gauss_kronrod<Real, N>>("Kronrod", N), ...);
}

template <class Real>
void check_rule_copies() {
    check_gauss_copies<Real>(std::integer_sequence<unsigned, 7, 10, 12, 15, 16, 20, 30>{});
    check_kronrod_copies<Real>(std::integer_sequence<unsigned, 15, 21, 31, 61>{});
}

}  // namespace

TEST_CASE("the Gauss and Kronrod rules normzoo copies are Boost's, bit for bit (quadrature/gauss_rules.hpp)") {
    check_rule_copies<double>();
    check_rule_copies<long double>();
    check_rule_copies<quad>();
}
