// The Fresnel parts (microfacet/fresnel.hpp) against the limits every one must meet and against
// the textbook Fresnel equations written again here with Snell's law (and std::complex for the
// conductor), an independent route to the same numbers.
#include <catch2/catch.hpp>

#include <normzoo/microfacet/fresnel.hpp>
#include <normzoo/real.hpp>

#include <complex>
#include <iostream>
#include <random>
#include <string>

using namespace normzoo::microfacet;
using R = long double;

namespace {

// Unpolarized reflectance from air into a medium of complex index m, at cos i = c: the s and p
// amplitudes with cos t from Snell's law (m sin t = sin i).
R textbook(R c, std::complex<R> m) {
    const std::complex<R> s2 = (1 - c * c) / (m * m);
    const std::complex<R> ct = std::sqrt(R(1) - s2);
    const std::complex<R> rs = (c - m * ct) / (c + m * ct);
    const std::complex<R> rp = (m * c - ct) / (m * c + ct);
    return (std::norm(rs) + std::norm(rp)) / 2;
}

}  // namespace

TEST_CASE("Fresnel limits: F(1) = F0, F(0) = 1 (F90 for schlick-f90)") {
    fresnel_params<R> p;
    p.f0 = R(0.04), p.f90 = R(0.7), p.eta = R(1.5), p.k = R(0);
    CHECK(fresnel_schlick::eval(R(1), p) == p.f0);
    CHECK(fresnel_schlick::eval(R(0), p) == 1);
    CHECK(fresnel_schlick_f90::eval(R(1), p) == p.f0);
    CHECK(fresnel_schlick_f90::eval(R(0), p) == p.f90);
    CHECK(fresnel_one::eval(R(0.3), p) == 1);
    const R eta = GENERATE(R(1.2), R(1.5), R(2.5));
    p.eta = eta;
    CAPTURE(static_cast<double>(eta));
    CHECK(fresnel_dielectric::eval(R(1), p) == Approx(static_cast<double>(f0_of_eta(eta))).epsilon(1e-15));
    CHECK(fresnel_dielectric::eval(R(0), p) == Approx(1).epsilon(1e-15));
    p.k = R(3);
    const R normal = ((eta - 1) * (eta - 1) + 9) / ((eta + 1) * (eta + 1) + 9);
    CHECK(fresnel_conductor::eval(R(1), p) == Approx(static_cast<double>(normal)).epsilon(1e-15));
    CHECK(fresnel_conductor::eval(R(0), p) == Approx(1).epsilon(1e-15));
}

TEST_CASE("Fresnel: the exact forms against the textbook equations, dielectrics and conductors") {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
        fresnel_params<R> p;
        p.eta = R(1.05 + 3 * u(rng));
        p.k = i % 2 ? R(0) : R(5 * u(rng));
        const R c = R(u(rng));
        const R expected = textbook(c, {p.eta, p.k});
        const R got = p.k == 0 ? fresnel_dielectric::eval(c, p) : fresnel_conductor::eval(c, p);
        CAPTURE(static_cast<double>(p.eta), static_cast<double>(p.k), static_cast<double>(c));
        CHECK(std::abs(static_cast<double>(got - expected)) <= 1e-15);
        worst = std::max(worst, std::abs(static_cast<double>(got - expected)));
        // a conductor without absorption is a dielectric
        if (p.k == 0) CHECK(std::abs(static_cast<double>(fresnel_conductor::eval(c, p) - got)) <= 1e-15);
    }
    std::cout << "Fresnel against the textbook equations, 2000 cases: largest difference " << worst << "\n";
    // Leaving a denser medium: total internal reflection beyond the critical angle.
    fresnel_params<R> inside;
    inside.eta = R(1) / R(1.5);
    CHECK(fresnel_dielectric::eval(R(0.5), inside) == 1);  // sin i = 0.87 > 1/1.5
    CHECK(fresnel_dielectric::eval(R(0.9), inside) < 1);
}

// Below eta = 1 with k = 0, sqrt(t0^2) for a^2 + b^2 could round below -t0, and a = sqrt((a^2 + b^2
// + t0) / 2) took the root of a negative number: NaN in binary128 at 6,321 of 600,000 angles (an
// energy sweep's albedo came out NaN). Every type, every angle, is finite and the dielectric's.
TEMPLATE_TEST_CASE("a conductor without absorption is the dielectric below eta = 1 as well, in every type", "", double, R,
                   normzoo::quad) {
    using T = TestType;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    int off = 0;
    for (double eta : {0.01, 0.5, 0.9, 1.5})
        for (int i = 0; i < 20000; ++i) {
            fresnel_params<T> p;
            p.eta = T(eta), p.k = T(0), p.f0 = T(0.04);
            const T c = T(u(rng));
            const T f = fresnel_conductor::eval(c, p), d = fresnel_dielectric::eval(c, p);
            using std::abs;
            if (!(abs(static_cast<double>(f - d)) <= 1e-12)) ++off;  // NaN counts
        }
    CHECK(off == 0);
}

TEST_CASE("Schlick against the exact dielectric, eta from 1.2 to 2.5: zero at both ends, the largest gap between") {
    double worst = 0, at_eta = 0, at_c = 0;
    for (int e = 0; e <= 130; ++e) {
        fresnel_params<R> p;
        p.eta = R(1.2) + R(e) / 100;
        p.f0 = f0_of_eta(p.eta);
        for (int k = 0; k <= 2000; ++k) {
            const R c = R(k) / 2000;
            const double gap = static_cast<double>(fresnel_schlick::eval(c, p) - fresnel_dielectric::eval(c, p));
            if (std::abs(gap) > std::abs(worst)) worst = gap, at_eta = static_cast<double>(p.eta), at_c = static_cast<double>(c);
        }
        CHECK(std::abs(static_cast<double>(fresnel_schlick::eval(R(1), p) - fresnel_dielectric::eval(R(1), p))) <= 1e-15);
        CHECK(std::abs(static_cast<double>(fresnel_schlick::eval(R(0), p) - fresnel_dielectric::eval(R(0), p))) <= 1e-15);
    }
    std::cout << "Schlick - exact dielectric: largest " << worst << " at eta = " << at_eta << ", cos = " << at_c << "\n";
    CHECK(worst != 0);
}

TEST_CASE("Fresnel parts by id, in any real type") {
    for (const char* id : {"one", "schlick", "schlick-f90", "dielectric", "conductor"}) {
        CAPTURE(id);
        bool finite = false;
        CHECK(with_fresnel(id, [&](auto part) {
            fresnel_params<normzoo::quad> p;
            p.k = 2;
            finite = std::isfinite(static_cast<double>(decltype(part)::eval(normzoo::quad(0.5), p)));
        }));
        CHECK(finite);
    }
    CHECK_FALSE(with_fresnel("schlik", [](auto) {}));
}
