// The split-sum shortcuts of microfacet/split_sum_shortcuts.hpp against the exact pair (A, B) of
// the composition each stands for (microfacet/split_sum.hpp), as results/microfacet-shortcuts.md
// measures them over the 32 x 32 texel centres (docs/microfacet.md, "The shortcuts, measured"):
// within the largest error that table reports, at a few texels; and, over the whole grid, the
// fits' largest and rms errors as the table prints them (four digits), which a changed
// coefficient moves. The visibility shortcuts and Schlick's Fresnel are parts, tested with them
// (test_composition.cpp, test_fresnel.cpp).
#include <catch2/catch.hpp>

#include <normzoo/microfacet/split_sum.hpp>
#include <normzoo/microfacet/split_sum_shortcuts.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

namespace mf = normzoo::microfacet;

namespace {

// Texel i of 32 (docs/lut.md, "Texel centres"): the table's grid in mu and in r or gloss.
double centre(int i) { return (i + 0.5) / 32; }

mf::split_sum_value exact(std::string_view id, double mu, double alpha) {
    return mf::split_sum(mf::composition::parse(id), mu, alpha);
}

// A number as the table's Markdown shows it (writers.cpp: four significant digits).
std::string four_digits(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", x);
    return buf;
}

// The largest and rms |fit - exact| of A and of B over the 32 x 32 texel centres, mu = centre(i)
// and the fit's variable x = centre(j) at alpha = Fit::alpha(x).
template <class Fit>
struct grid_errors {
    double max_a = 0, max_b = 0, rms_a = 0, rms_b = 0;
    grid_errors(std::string_view reference) {
        const auto c = mf::composition::parse(reference);
        for (int j = 0; j < 32; ++j)
            for (int i = 0; i < 32; ++i) {
                const auto e = mf::split_sum(c, centre(i), Fit::alpha(centre(j)));
                const auto f = Fit::eval(centre(j), centre(i));
                const double da = f.a - e.a.value, db = f.b - e.b.value;
                max_a = std::max(max_a, std::abs(da)), max_b = std::max(max_b, std::abs(db));
                rms_a += da * da, rms_b += db * db;
            }
        rms_a = std::sqrt(rms_a / 1024), rms_b = std::sqrt(rms_b / 1024);
    }
};

}  // namespace

TEST_CASE("EnvBRDFApprox: within its committed largest error of both exact pairs, at texel centres") {
    using fit = mf::env_brdf_approx;
    // The largest |error| of A and B over the grid (results/microfacet-shortcuts.md), rounded up.
    const auto [reference, max_a, max_b] = GENERATE(table<const char*, double, double>({
        {"ggx/schlick-ggx/schlick", 0.18, 0.21},
        {"ggx/smith-height-correlated/schlick", 0.44, 0.085},
    }));
    const int i = GENERATE(0, 7, 20, 31), j = GENERATE(0, 10, 31);  // mu = centre(i), r = centre(j)
    const double r = centre(j), mu = centre(i);
    CAPTURE(reference, r, mu);
    const auto e = exact(reference, mu, fit::alpha(r));
    const auto f = fit::eval(r, mu);
    CHECK(std::abs(f.a - e.a.value) <= max_a);
    CHECK(std::abs(f.b - e.b.value) <= max_b);
}

TEST_CASE("Lazarov 2013: within its committed largest error of its BRDF, and close where it was meant to hold") {
    using fit = mf::lazarov_2013;
    const int i = GENERATE(0, 7, 20, 31), j = GENERATE(0, 10, 31);  // mu = centre(i), g = centre(j)
    const double g = centre(j), mu = centre(i);
    CAPTURE(g, mu);
    const auto e = exact(fit::made_for, mu, fit::alpha(g));
    const auto f = fit::eval(g, mu);
    CHECK(std::abs(f.a - e.a.value) <= 0.63);
    CHECK(std::abs(f.b - e.b.value) <= 0.18);
    // Its gloss is Blinn-Phong's power 8192^g = 2/alpha^2 - 2.
    CHECK(2 / (fit::alpha(g) * fit::alpha(g)) - 2 == Approx(std::pow(8192.0, g)).epsilon(1e-12));
    // Glossy and near normal incidence, A within 0.01 (docs/microfacet.md).
    if (i == 31 && j == 31) CHECK(std::abs(f.a - e.a.value) <= 0.01);
}

TEST_CASE("the fits' largest and rms errors over the 32 x 32 texel centres are the committed table's") {
    // results/microfacet-shortcuts.md, as printed: max_abs_error and rms_error of A, then of B.
    SECTION("EnvBRDFApprox against Schlick-GGX, k = alpha/2") {
        const grid_errors<mf::env_brdf_approx> w(mf::env_brdf_approx::made_for);
        CHECK(four_digits(w.max_a) == "0.1784");
        CHECK(four_digits(w.rms_a) == "0.07022");
        CHECK(four_digits(w.max_b) == "0.2049");
        CHECK(four_digits(w.rms_b) == "0.02841");
    }
    SECTION("Lazarov 2013 against blinn-phong/schlick-beckmann/schlick") {
        const grid_errors<mf::lazarov_2013> w(mf::lazarov_2013::made_for);
        CHECK(four_digits(w.max_a) == "0.623");
        CHECK(four_digits(w.rms_a) == "0.2722");
        CHECK(four_digits(w.max_b) == "0.1713");
        CHECK(four_digits(w.rms_b) == "0.01726");
    }
}

TEST_CASE("Monte Carlo baker: within its committed largest error at each N, at texel centres") {
    using baker = mf::monte_carlo_baker;
    // N, and the largest |error| of A and B over the grid (results/microfacet-shortcuts.md), rounded up.
    const auto [samples, max_a, max_b] = GENERATE(table<unsigned, double, double>({
        {64u, 0.045, 0.022},
        {256u, 0.021, 0.0081},
        {1024u, 0.0092, 0.0025},
        {4096u, 0.0045, 0.00066},
    }));
    const int i = GENERATE(0, 10, 31), j = GENERATE(3, 16, 31);  // mu = centre(i), r = centre(j)
    const double r = centre(j), mu = centre(i);
    CAPTURE(samples, r, mu);
    const auto e = exact(baker::made_for, mu, r * r);
    const auto m = baker::eval(float(r), float(mu), samples);
    CHECK(std::abs(double(m.a) - e.a.value) <= max_a);
    CHECK(std::abs(double(m.b) - e.b.value) <= max_b);
}

TEST_CASE("Monte Carlo baker: the Hammersley points' radical inverse reverses i's bits") {
    CHECK(mf::detail::reverse_bits(0u) == 0u);
    CHECK(mf::detail::reverse_bits(1u) == 0x80000000u);
    CHECK(mf::detail::reverse_bits(6u) == 0x60000000u);
    CHECK(mf::detail::reverse_bits(0x80000000u) == 1u);
    CHECK(mf::detail::reverse_bits(0x12345678u) == 0x1E6A2C48u);
}
