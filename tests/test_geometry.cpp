// The vector expressions against the reduced integrands, pointwise and in 50 digits: this is
// what makes the 2D and 1D integrals two independent routes to the same number.
#include <catch2/catch.hpp>
#include <normzoo/normzoo.hpp>

using normzoo::wide;

TEST_CASE("pow_lobe keeps full precision where pow(cos, n) loses n ulps") {
    const double n = GENERATE(1.0, 1e3, 1e5, 1e7);
    const double t = 1 / std::sqrt(n);  // inside the lobe
    const auto a = normzoo::normal<double>();
    const auto b = normzoo::direction(t, 0.3);
    const wide truth = exp(wide(n) * log(cos(wide(t))));
    const double stable = normzoo::pow_lobe(a, b, n);
    const double naive = std::pow(a.dot(b), n);
    CAPTURE(n, stable, naive);
    CHECK(static_cast<double>(abs(wide(stable) - truth) / truth) < 64 * 2.3e-16);
    if (n >= 1e5) CHECK(static_cast<double>(abs(wide(naive) - truth) / truth) > 1e-12);
}

TEST_CASE("reflect and half_vector") {
    const auto l = normzoo::direction(0.7, 1.1);
    const auto r = normzoo::reflect(l);
    CHECK(r.z() == Approx(l.z()));
    CHECK(r.x() == Approx(-l.x()));
    const auto h = normzoo::half_vector(l, normzoo::normal<double>());
    CHECK(h.norm() == Approx(1.0));
    CHECK(h.z() == Approx(std::cos(0.35)));
}

template <class Row>
void check_row_pointwise(const wide& t, const wide& phi, const wide& n) {
    const auto omega = normzoo::direction(t, phi);
    const wide from_vectors = Row::rdf(omega, normzoo::normal<wide>(), n) * sin(t);
    const wide reduced = normzoo::reduced_integrand<Row>(t, n);
    CAPTURE(Row::id, static_cast<double>(t), static_cast<double>(n));
    CHECK(static_cast<double>(abs(from_vectors - reduced)) <= static_cast<double>(1e-44 * (abs(reduced) + 1e-300)));
}

TEST_CASE("every row: the vector expression with V = N equals its reduced 1D integrand") {
    const double t = GENERATE(1e-4, 0.01, 0.3, 0.8, 1.2, 1.5);
    const double phi = GENERATE(0.0, 2.0, 5.5);
    const double n = GENERATE(0.0, 0.1, 3.0, 64.0, 1e4);
    normzoo::for_each_zoo_row([&](auto row) { check_row_pointwise<decltype(row)>(wide(t), wide(phi), wide(n)); });
}
