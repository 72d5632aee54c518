// A rough dielectric interface's albedo, reflection plus transmission (microfacet/rough_dielectric.hpp):
// against the BRDF's own albedo, Walter et al.'s BTDF integrated over L, and the index-matched
// interface's closed form.
#include <catch2/catch.hpp>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <normzoo/microfacet/albedo.hpp>
#include <normzoo/microfacet/composition.hpp>
#include <normzoo/microfacet/multiple_scattering.hpp>
#include <normzoo/microfacet/rough_dielectric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace normzoo;
using microfacet::composition;

namespace {

// Walter et al. 2007's BTDF times |N.L| (eqs. 21, 17 and 16; pbrt-v4's half-vector conventions:
// h_t along -(V + eta L), turned to face N, V.h > 0 and L.h < 0), GGX and Smith's separable G in
// long double, integrated over L below the horizon in the angle b from -V and the azimuth g about
// it: breakpoints where the horizon cuts g, where h_t lies in the surface (N.h_t = 0: D jumps
// there) and where V.h_t = 0 (the cone V.L = -1/eta above eta = 1, V.L = -eta below).
long double transmission_over_l(long double alpha, long double eta, long double mu) {
    using boost::math::quadrature::gauss_kronrod;
    const long double pi = 3.141592653589793238462643383279503L, sv = std::sqrt((1 - mu) * (1 + mu)), a2 = alpha * alpha;
    auto lambda = [&](long double z2) { return (-1 + std::sqrt(1 + a2 * (1 - z2) / z2)) / 2; };
    auto fresnel = [&](long double c) -> long double {
        const long double g2 = eta * eta - 1 + c * c;
        if (g2 < 0) return 1;
        const long double g = std::sqrt(g2), a = (g - c) / (g + c), b = (c * (g + c) - 1) / (c * (g - c) + 1);
        return a * a * (1 + b * b) / 2;
    };
    auto f = [&](long double b, long double g) -> long double {
        const long double cb = std::cos(b), sb = std::sin(b), cg = std::cos(g);
        const long double lx = -sv * cb + sb * cg * mu, ly = sb * std::sin(g), lz = -mu * cb - sb * cg * sv;
        if (!(lz < 0)) return 0;
        long double hx = -(sv + eta * lx), hy = -eta * ly, hz = -(mu + eta * lz);
        const long double n = std::sqrt(hx * hx + hy * hy + hz * hz);
        hx /= n, hy /= n, hz /= n;
        if (hz < 0) hx = -hx, hy = -hy, hz = -hz;
        const long double vh = sv * hx + mu * hz, lh = lx * hx + ly * hy + lz * hz;
        if (!(vh > 0 && lh < 0)) return 0;
        const long double c2 = hz * hz, k = a2 + (1 - c2) / c2, d = a2 / (pi * c2 * c2 * k * k);
        const long double g2 = 1 / ((1 + lambda(mu * mu)) * (1 + lambda(lz * lz)));
        const long double den = vh + eta * lh;
        return vh * -lh / mu * eta * eta * (1 - fresnel(vh)) * g2 * d / (den * den) * sb;
    };
    auto inner = [&](long double b) {
        const long double cb = std::cos(b), sb = std::sin(b);
        long double g_max = pi;
        if (sv * sb > mu * cb) g_max = std::acos(-mu * cb / (sv * sb));
        std::vector<long double> gs{0, g_max};
        if (sv * sb > 0) {
            const long double k = (mu / eta - mu * cb) / (sv * sb);
            if (k > -1 && k < 1 && std::acos(k) < g_max) gs.push_back(std::acos(k));
        }
        std::sort(gs.begin(), gs.end());
        long double sum = 0;
        for (std::size_t i = 0; i + 1 < gs.size(); ++i)
            if (gs[i + 1] > gs[i]) sum += 2 * gauss_kronrod<long double, 31>::integrate([&](long double g) { return f(b, g); }, gs[i], gs[i + 1], 10, 1e-12L);
        return sum;
    };
    const long double tv = std::acos(mu), q = std::acos(std::min(1.0L, mu / eta));
    std::vector<long double> bs{0, std::asin(mu), eta > 1 ? std::acos(1 / eta) : std::acos(eta), pi};
    for (long double b : {tv + q, tv - q, q - tv})
        if (b > 0 && b < pi) bs.push_back(b);
    std::sort(bs.begin(), bs.end());
    long double sum = 0;
    for (std::size_t i = 0; i + 1 < bs.size(); ++i)
        if (bs[i + 1] > bs[i]) sum += gauss_kronrod<long double, 31>::integrate(inner, bs[i], bs[i + 1], 10, 1e-12L);
    return sum;
}

}  // namespace

// The reflection channel against the composition's own albedo (GGX's map, reflection alone), the
// transmission against the BTDF over L (to ~1e-11: its nested Kronrod at 1e-12), both in and out
// of the denser side, with total internal reflection below eta = 1, and narrow lobes.
TEST_CASE("a rough dielectric's reflection and transmission: against the BRDF's albedo and Walter's BTDF over L") {
    struct point {
        double alpha, eta, mu;
    };
    // the last three: narrow lobes, where G1's turn at either horizon is a panel's end (without
    // it E_R erred by 1.3e-10 against a bound of 2.5e-11 at the first); the BTDF over L is not
    // taken there (its lobe is narrower than the integral over L resolves)
    const point p = GENERATE(point{0.5, 1.5, 0.5}, point{1, 1.5, 0.9}, point{0.25, 2.5, 0.2}, point{0.3, 0.6667, 0.7},
                             point{0.5, 0.6667, 0.3}, point{0.7, 0.4, 0.6}, point{0.000344712, 0.47599763, 0.245321},
                             point{0.000344712, 0.6, 0.245321}, point{1e-4, 1.5, 0.01});
    CAPTURE(p.alpha, p.eta, p.mu);
    const auto r = microfacet::rough_dielectric_albedo_of<15>(p.alpha, p.eta, p.mu, 1e-10, 400);
    CHECK(r.reflection.abs_error <= 1e-10);
    CHECK(r.transmission.abs_error <= 1e-10);
    composition c = composition::parse("ggx/smith-separable/dielectric");
    c.eta = p.eta;
    albedo_settings s;
    s.tolerance = 1e-11;
    const auto reflection = microfacet::directional_albedo(c, p.mu, p.alpha, 0.04, s);
    CHECK(std::abs(r.reflection.value - reflection.value) <= r.reflection.abs_error + reflection.abs_error);
    if (p.alpha >= 0.1) {
        const double over_l = double(transmission_over_l(p.alpha, p.eta, p.mu));
        CAPTURE(r.transmission.value, over_l);
        CHECK(std::abs(r.transmission.value - over_l) <= r.transmission.abs_error + 2e-11);
    }
    // the composition's fourth part takes the same route, at the index F0 gives or eta
    c.transmission = true;
    const auto whole = microfacet::directional_albedo(c, p.mu, p.alpha, 0.04, {});
    CHECK(whole.value == r.reflection.value + r.transmission.value);
}

// At eta = 1 nothing reflects (F = 0) and every h sends L_t = -V: E = G1(V)^2 times the projected
// area of the facets facing V, mu (1 + Lambda(V)), so E = 1 / (1 + Lambda(V)) exactly, narrow lobe
// or grazing view; and the average 2 int mu / (1 + Lambda(mu)) dmu against the same closed form
// integrated by Boost's Gauss-Kronrod.
TEST_CASE("a rough dielectric at eta = 1: E = 1 / (1 + Lambda(V)), and its average") {
    struct point {
        double alpha, mu;
    };
    const point p = GENERATE(point{1e-4, 0.5}, point{0.01, 1e-3}, point{0.3, 0.05}, point{0.5, 1}, point{1, 0.2}, point{1, 1e-3});
    CAPTURE(p.alpha, p.mu);
    const double sv2 = (1 - p.mu) * (1 + p.mu);
    const double lambda = (-1 + std::sqrt(1 + p.alpha * p.alpha * sv2 / (p.mu * p.mu))) / 2;
    const auto r = microfacet::rough_dielectric_albedo_of<15>(p.alpha, 1.0, p.mu, 1e-10, 400);
    CHECK(r.reflection.value == 0);
    CHECK(std::abs(r.transmission.value - 1 / (1 + lambda)) <= r.transmission.abs_error);
    CHECK(r.transmission.abs_error <= 1e-10);
    if (p.mu == 1) {
        composition c = composition::parse("ggx/smith-separable/dielectric/transmission");
        c.eta = 1;
        albedo_settings s;
        s.tolerance = 1e-9;
        const auto avg = microfacet::average_albedo(c, p.alpha, 0.04, s);
        auto g1 = [&](double m) { return 1 / (1 + (-1 + std::sqrt(1 + p.alpha * p.alpha * (1 - m * m) / (m * m))) / 2); };
        const double closed = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
            [&](double m) { return m > 0 ? 2 * m * g1(m) : 0.0; }, 0.0, 1.0, 15, 1e-14);
        CHECK(std::abs(avg.value - closed) <= avg.abs_error + 1e-13);
    }
}

TEST_CASE("the transmitting interface is GGX with Smith's separable G and the exact dielectric F only") {
    for (const char* id : {"ggx/smith-height-correlated/dielectric/transmission", "beckmann/smith-separable/dielectric/transmission",
                           "ggx/smith-separable/schlick/transmission"})
        CHECK_THROWS_WITH(composition::parse(id), Catch::Contains("ggx/smith-separable/dielectric/transmission"));
    CHECK(composition::parse("ggx/smith-separable/dielectric/transmission").transmission);
}
