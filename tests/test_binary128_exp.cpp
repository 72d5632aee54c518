// The hand-made binary128 exponential of the lobe quadrature against libquadmath, in ulps.
#include <catch2/catch.hpp>
#include <normzoo/detail/binary128_exp.hpp>
#include <random>

namespace {
double ulps(__float128 got, __float128 want) {
    if (got == want) return 0;
    int e = 0;
    frexpq(want, &e);
    return static_cast<double>(fabsq(got - want) / ldexpq(1, e - 113));
}
}  // namespace

TEST_CASE("e^-s and e^-s - 1 within 4 ulp of expq and expm1q") {
    const double log_lo = GENERATE(-30.0, -6.0, -3.0, 0.0);
    const double log_hi = log_lo == 0.0 ? 3.9 : log_lo + 3;  // up to s = 8000
    std::mt19937_64 rng(static_cast<unsigned long>(1000 + log_lo));
    std::uniform_real_distribution<double> u(log_lo, log_hi), frac(0, 1);
    double worst_exp = 0, worst_expm1 = 0;
    for (int i = 0; i < 20000; ++i) {
        // a binary128 argument with bits below double's
        const __float128 s = (__float128)std::pow(10.0, u(rng)) * (1 + (__float128)frac(rng) * (__float128)1e-20);
        const auto [value, minus_1] = normzoo::detail::exp_and_expm1_of_minus(s);
        worst_exp = std::max(worst_exp, ulps(value, expq(-s)));
        worst_expm1 = std::max(worst_expm1, ulps(minus_1, expm1q(-s)));
    }
    CAPTURE(log_lo, worst_exp, worst_expm1);
    CHECK(worst_exp <= 4);
    if (log_hi < 0) CHECK(worst_expm1 <= 4);  // beyond s ~ 1, e^-s - 1 is checked through e^-s
}
