// The D and G parts of a microfacet BRDF (microfacet/distribution.hpp, microfacet/masking.hpp):
// each D's projected normalization and each exact Lambda against the masking equation, by
// quadrature; each Smith G against the closed forms the literature writes for GGX and Beckmann;
// the limits and the symmetry every G must have; and how far the shortcuts are from exact Smith.
#include <catch2/catch.hpp>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <normzoo/microfacet/distribution.hpp>
#include <normzoo/microfacet/masking.hpp>
#include <normzoo/microfacet/distribution.hpp>
#include <normzoo/ndf_integrals.hpp>
#include <normzoo/quadrature/slope.hpp>

#include <iostream>
#include <random>
#include <vector>

using namespace normzoo;
using namespace normzoo::microfacet;
using R = long double;

namespace {

vec3<R> direction_of(R theta, R phi) {
    using std::cos;
    using std::sin;
    return vec3<R>(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
}

// Integral over the hemisphere of g(m) D(m) dm: the polar angle in the log-slope variable of
// quadrature/slope.hpp (its scale alpha), the azimuth by adaptive Gauss-Kronrod between the
// given kinks of g (an isotropic D with an azimuth-free g needs no azimuth: pass none).
template <class D, class G>
R hemisphere_integral(const ndf_params<R>& p, const G& g, R scale, bool azimuth_free) {
    const R two_pi = boost::math::constants::two_pi<R>();
    auto polar = [&](const quadrature::slope_point<R>& s) {
        const R theta = std::atan2(s.sin_t, s.cos_t);
        if (azimuth_free) return D::d(direction_of(theta, R(0)), p) * g(direction_of(theta, R(0))) * two_pi * s.sin_t;
        auto in_phi = [&](R phi) {
            const auto m = direction_of(theta, phi);
            return D::d(m, p) * g(m);
        };
        const R value = boost::math::quadrature::gauss_kronrod<R, 31>::integrate(in_phi, R(0), two_pi, 12, R(1e-15));
        return value * s.sin_t;
    };
    return quadrature::slope_integral<R>(polar, scale).value;
}

// The same with the kink of max(o.m, 0) in the polar angle, where tan t = cot t_o (azimuth-free).
template <class D>
R visible_area(const ndf_params<R>& p, const vec3<R>& o) {
    const R st_o = std::sqrt(o.x() * o.x() + o.y() * o.y()), phi_o = std::atan2(o.y(), o.x());
    auto polar = [&](const quadrature::slope_point<R>& s) {
        const R theta = std::atan2(s.sin_t, s.cos_t);
        // o.m = st_o sin t cos(phi - phi_o) + ct_o cos t: zero where cos(phi - phi_o) = -x
        const R x = st_o > 0 ? o.z() * s.cos_t / (st_o * s.sin_t) : R(2);
        auto in_phi = [&](R phi) {
            const auto m = direction_of(theta, phi);
            const R om = o.dot(m);
            return om > 0 ? D::d(m, p) * om : R(0);
        };
        std::vector<R> breaks{phi_o - boost::math::constants::pi<R>()};
        if (x < 1) {
            const R c = std::acos(-x);
            breaks.push_back(phi_o - c);
            breaks.push_back(phi_o + c);
        }
        breaks.push_back(phi_o + boost::math::constants::pi<R>());
        R value = 0;
        for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
            value += boost::math::quadrature::gauss_kronrod<R, 31>::integrate(in_phi, breaks[i], breaks[i + 1], 12, R(1e-15));
        return value * s.sin_t;
    };
    std::vector<R> kinks;
    if (st_o > 0) kinks.push_back(o.z() / st_o);
    return quadrature::slope_integral<R>(polar, std::max(p.alpha_x, p.alpha_y), kinks).value;
}

template <class D>
ndf_params<R> params(R ax, R ay, R gamma = 2) {
    ndf_params<R> p;
    p.alpha_x = ax, p.alpha_y = D::isotropic ? ax : ay, p.gamma = gamma;
    return p;
}

}  // namespace

TEST_CASE("every D is normalized: the integral of D (N.m) over the hemisphere is 1") {
    auto check_part = [](auto part, R ax, R ay, R gamma) {
        using D = decltype(part);
        const auto p = params<D>(ax, ay, gamma);
        const R value = hemisphere_integral<D>(p, [](const vec3<R>& m) { return m.z(); }, std::max(p.alpha_x, p.alpha_y),
                                               D::isotropic);
        CAPTURE(std::string(D::id), static_cast<double>(ax), static_cast<double>(ay), static_cast<double>(gamma),
                static_cast<double>(value - 1));
        CHECK(std::abs(static_cast<double>(value - 1)) < 1e-12);
    };
    for (R a : {R(0.05), R(0.3), R(0.8)}) {
        check_part(d_blinn_phong{}, a, a, 2);
        check_part(d_beckmann{}, a, a, 2);
        check_part(d_ggx{}, a, a, 2);
        for (R gamma : {R(1), R(1.5), R(3)}) check_part(d_gtr{}, a, a, gamma);
        check_part(d_ggx_aniso{}, a, a / 3, 2);
        check_part(d_beckmann_aniso{}, a / 2, a, 2);
    }
}

TEST_CASE("each exact Lambda meets the masking equation: cos t_o (1 + Lambda(o)) = integral of max(o.m, 0) D") {
    auto check_part = [](auto part, R ax, R ay, R theta, R phi) {
        using D = decltype(part);
        const auto p = params<D>(ax, ay);
        const auto o = direction_of(theta, phi);
        const R area = visible_area<D>(p, o);
        const R expected = o.z() * (1 + D::lambda(o, p));
        CAPTURE(std::string(D::id), static_cast<double>(ax), static_cast<double>(ay), static_cast<double>(theta),
                static_cast<double>(phi), static_cast<double>(area / expected - 1));
        CHECK(std::abs(static_cast<double>(area / expected - 1)) < 1e-10);
    };
    for (R theta : {R(0.2), R(1.0), R(1.45)})
        for (R phi : {R(0), R(0.7), R(1.5707963267948966)}) {
            check_part(d_beckmann{}, R(0.4), R(0.4), theta, phi);
            check_part(d_ggx{}, R(0.4), R(0.4), theta, phi);
            check_part(d_ggx_aniso{}, R(0.6), R(0.15), theta, phi);
            check_part(d_beckmann_aniso{}, R(0.15), R(0.5), theta, phi);
        }
}

TEST_CASE("the D parts agree where they coincide") {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 500; ++i) {
        const auto m = direction_of(R(1.5 * u(rng)), R(6.28 * u(rng)));
        const R a = R(0.02 + u(rng));
        const auto p = params<d_ggx_aniso>(a, a);
        CHECK(d_ggx_aniso::d(m, p) == Approx(static_cast<double>(d_ggx::d(m, p))).epsilon(1e-14));
        CHECK(d_beckmann_aniso::d(m, p) == Approx(static_cast<double>(d_beckmann::d(m, p))).epsilon(1e-14));
        CHECK(d_ggx_aniso::lambda(m, p) == Approx(static_cast<double>(d_ggx::lambda(m, p))).epsilon(1e-14));
        // GTR at gamma = 2 is GGX; Beckmann's part is its D and Lambda as published (written out here)
        CHECK(d_gtr::d(m, p) == Approx(static_cast<double>(d_ggx::d(m, p))).epsilon(1e-13));
        const R st = std::sqrt(m.x() * m.x() + m.y() * m.y()), c2 = m.z() * m.z();
        CHECK(d_beckmann::d(m, p) == Approx(std::exp(-st * st / (c2 * a * a)) / (M_PI * a * a * c2 * c2)).epsilon(1e-14));
        const R cot = m.z() / (st * a);  // Heitz 2014: Lambda = (e^(-m^2) / (m sqrt(pi)) - erfc(m)) / 2, m = 1 / (a tan t)
        if (st > 1e-3)
            CHECK(d_beckmann::lambda(m, p) ==
                  Approx((std::exp(-cot * cot) / (cot * std::sqrt(M_PI)) - std::erfc(cot)) / 2).epsilon(1e-12));
    }
}

namespace {
// GGX's Smith G in the forms the literature writes them, beside the Lambda route of the parts:
// Walter et al. 2007's G1 = 2 N.V / (N.V + sqrt(a^2 + (1 - a^2) (N.V)^2)), and the height-correlated
// visibility of Heitz 2014 as "Moving Frostbite to PBR" writes it.
R ggx_g1_walter(R c, R a) { return 2 * c / (c + std::sqrt(a * a + (1 - a * a) * c * c)); }
R ggx_height_correlated(R nl, R nv, R a) {
    const R a2 = a * a;
    const R v = R(0.5) / (nl * std::sqrt(nv * nv * (1 - a2) + a2) + nv * std::sqrt(nl * nl * (1 - a2) + a2));
    return 4 * nl * nv * v;
}
shading<R> ggx_shading(R nl, R nv, R a) {
    shading<R> s;
    s.nl = nl, s.nv = nv, s.alpha = a;
    const auto p = params<d_ggx>(a, a);
    s.lambda_l = d_ggx::lambda(direction_of(std::acos(nl), R(0)), p);
    s.lambda_v = d_ggx::lambda(direction_of(std::acos(nv), R(0)), p);
    return s;
}
}  // namespace

TEST_CASE("the Smith G parts with GGX's Lambda are the closed forms of the literature") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 1000; ++i) {
        const R nl = R(1e-3 + u(rng)) / R(1.001), nv = R(1e-3 + u(rng)) / R(1.001), a = R(0.01 + u(rng));
        const auto s = ggx_shading(nl, nv, a);
        CAPTURE(static_cast<double>(nl), static_cast<double>(nv), static_cast<double>(a));
        CHECK(g_smith_separable::g(s) == Approx(static_cast<double>(ggx_g1_walter(nl, a) * ggx_g1_walter(nv, a))).epsilon(1e-14));
        CHECK(g_smith_height_correlated::g(s) == Approx(static_cast<double>(ggx_height_correlated(nl, nv, a))).epsilon(1e-14));
    }
}

// Black Ops II's visibility as Lazarov 2013 writes it, in the Blinn-Phong power n:
// V = 1 / ((N.L (1 - k) + k)(N.V (1 - k) + k)), k = 2 / sqrt(pi (n + 2)); G = V N.L N.V.
TEST_CASE("schlick-beckmann is Lazarov 2013's visibility at the power n = 2/alpha^2 - 2") {
    for (R n : {R(1), R(10), R(100), R(1000), R(8190)}) {
        const R alpha = std::sqrt(2 / (n + 2)), k = 2 / std::sqrt(boost::math::constants::pi<R>() * (n + 2));
        for (int i = 1; i <= 20; ++i)
            for (int j = 1; j <= 20; ++j) {
                shading<R> s;
                s.nl = R(i) / 20, s.nv = R(j) / 20, s.alpha = alpha;
                const R lazarov = s.nl * s.nv / ((s.nl * (1 - k) + k) * (s.nv * (1 - k) + k));
                CAPTURE(static_cast<double>(n), static_cast<double>(s.nl), static_cast<double>(s.nv));
                CHECK(static_cast<double>(g_schlick_beckmann::g(s)) == Approx(static_cast<double>(lazarov)).epsilon(1e-15));
            }
    }
}

TEST_CASE("every G: 1 for a smooth surface seen from N, symmetric in L and V, within [0, 1] (but Kelemen's)") {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(0, 1);
    std::apply(
        [&](auto... part) {
            (
                [&](auto g_part) {
                    using G = decltype(g_part);
                    CAPTURE(std::string(G::id));
                    auto s = ggx_shading(R(1), R(1), R(0.3));
                    // charlie-sheen's fitted Lambda is not 0 at the normal (1e-8 at alpha = 0.3): G is within 1e-7 of 1
                    CHECK(static_cast<double>(G::g(s)) == Approx(1).epsilon(G::id == "charlie-sheen" ? 1e-7 : 1e-15));
                    for (int i = 0; i < 200; ++i) {
                        const R nl = R(0.01 + u(rng)) / R(1.01), nv = R(0.01 + u(rng)) / R(1.01);
                        auto a = ggx_shading(nl, nv, R(0.01 + u(rng)));
                        // the half vector's cosines of a configuration with these N.L and N.V
                        a.vm = R(0.5 + u(rng) / 2), a.nm = std::max(nl, nv);
                        auto b = a;
                        std::swap(b.nl, b.nv);
                        std::swap(b.lambda_l, b.lambda_v);
                        CHECK(static_cast<double>(G::g(a)) == Approx(static_cast<double>(G::g(b))).epsilon(1e-15));
                        if (G::id != "kelemen") CHECK((G::g(a) >= 0 && G::g(a) <= 1));
                    }
                }(part),
                ...);
        },
        masking_parts{});
}

TEST_CASE("the shortcuts against exact height-correlated Smith for GGX: largest error of G / (4 N.L N.V)") {
    // Reported, as the audit of the shortcuts will be: the largest relative error of each and where.
    for (const char* id : {"schlick-ggx", "schlick-ggx-remapped", "hammon", "smith-height-correlated-fast", "smith-separable"}) {
        double worst = 0, at_nl = 0, at_nv = 0, at_a = 0;
        with_masking(id, [&](auto part) {
            for (int i = 1; i <= 100; ++i)
                for (int j = 1; j <= 100; ++j)
                    for (R a : {R(0.05), R(0.1), R(0.25), R(0.5), R(0.75), R(1)}) {
                        const R nl = R(i) / 100, nv = R(j) / 100;
                        const auto s = ggx_shading(nl, nv, a);
                        const double rel = static_cast<double>(decltype(part)::g(s) / g_smith_height_correlated::g(s) - 1);
                        if (std::abs(rel) > std::abs(worst))
                            worst = rel, at_nl = static_cast<double>(nl), at_nv = static_cast<double>(nv), at_a = static_cast<double>(a);
                    }
        });
        std::cout << id << " / exact height-correlated Smith (GGX) - 1: largest " << worst << " at N.L = " << at_nl
                  << ", N.V = " << at_nv << ", alpha = " << at_a << "\n";
        CHECK(worst != 0);
    }
    CHECK_FALSE(with_masking("smith", [](auto) {}));
    CHECK(with_distribution("gtr", [](auto) {}));
    CHECK_FALSE(with_distribution("GGX", [](auto) {}));
}
