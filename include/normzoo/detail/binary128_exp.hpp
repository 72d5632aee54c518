// e^-s and e^-s - 1 (s >= 0) in binary128, three times faster than libquadmath's expq/expm1q.
//
// Why by hand: the 1D lobe quadrature spends almost all its time in one exponential per node,
// and libquadmath's take ~2 us each (bench/). This is the textbook table method, specialised
// to what the lobe needs: s = q ln2/2048 + r with 0 <= r < ln2/2048 (Cody-Waite, so q ln2/2048 is
// exact), e^-s = 2^(-q/2048) e^-r with 2^(-j/2048) from a table built once by expq, and
// e^-r - 1 by its Taylor series (terms up to r^5 in binary128, r^6 to r^9, below 1e-20
// of the sum, in double). The -1 form keeps full relative accuracy near s = 0 from a second table of
// 2^(-j/2048) - 1. Both are within 4 ulp of expq/expm1q (tests/test_binary128_exp.cpp).
#pragma once
#include <quadmath.h>

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/float128.hpp>

#include <array>
#include <cmath>
#include <utility>

namespace normzoo::detail {

struct binary128_exp_tables {
    static constexpr int size = 2048;
    std::array<__float128, size> pow2;          // 2^(-j/2048)
    std::array<__float128, size> pow2_minus_1;  // 2^(-j/2048) - 1
    __float128 step_hi, step_lo;                // ln2/2048 = hi + lo, hi with 26 trailing zero bits
    __float128 sixth = (__float128)1 / 6, twenty_fourth = (__float128)1 / 24, one_20th = (__float128)1 / 120;

    binary128_exp_tables() {
        // ln2/2048 to 50 digits, split: hi keeps 87 bits so that q * hi is exact for q < 2^26,
        // lo the next 113 (one binary128 of ln2 would err by 1e-34 s: 40 ulp at s = 84).
        using boost::multiprecision::cpp_bin_float_50;
        using boost::multiprecision::float128;
        auto to_binary128 = [](const cpp_bin_float_50& x) { return x.convert_to<float128>().backend().value(); };
        const cpp_bin_float_50 step = boost::math::constants::ln_two<cpp_bin_float_50>() / size;
        int e = 0;
        const __float128 m = frexpq(to_binary128(step), &e);
        step_hi = ldexpq(truncq(ldexpq(m, 113 - 26)), e - (113 - 26));
        step_lo = to_binary128(step - cpp_bin_float_50(float128(step_hi)));
        const __float128 ln2 = to_binary128(boost::math::constants::ln_two<cpp_bin_float_50>());
        for (int j = 0; j < size; ++j) {
            const __float128 arg = -(__float128)j * ln2 / size;
            pow2[j] = expq(arg);
            pow2_minus_1[j] = expm1q(arg);
        }
    }
    static const binary128_exp_tables& get() {
        static const binary128_exp_tables t;
        return t;
    }
};

// {e^-s, e^-s - 1} for 0 <= s < 2^26 ln2/2048 (~22 700); e^-s is below 1e-9800 there.
inline std::pair<__float128, __float128> exp_and_expm1_of_minus(__float128 s) {
    const auto& t = binary128_exp_tables::get();
    // q rounded down, so r >= 0 (to rounding) and 2^(-j/2048) - 1 and its correction below have one sign.
    const long q = static_cast<long>(static_cast<double>(s) * (binary128_exp_tables::size / M_LN2));
    const __float128 qf = q;
    const __float128 r = (s - qf * t.step_hi) - qf * t.step_lo;  // e^-s = 2^(-q/2048) e^-r
    const double rd = static_cast<double>(r);
    // r^6 .. r^9 in double (below 1e-20 of the sum, so double's rounding is below 1e-36); the
    // first term left out, r^10/10!, is below 1e-37 of r for r < ln2/2048.
    const double tail = rd * (1.0 / 720 + rd * (-1.0 / 5040 + rd * (1.0 / 40320 - rd / 362880)));
    const __float128 em1 =  // e^-r - 1
        r * (-1 + r * ((__float128)0.5 + r * (-t.sixth + r * (t.twenty_fourth + r * (-t.one_20th + (__float128)tail)))));
    const long a = q / binary128_exp_tables::size, j = q % binary128_exp_tables::size;
    if (a == 0) {
        // 2^-j/2048 e^-r - 1 = (2^-j/2048 - 1) + 2^-j/2048 (e^-r - 1): no cancellation near s = 0.
        const __float128 minus_1 = t.pow2_minus_1[j] + t.pow2[j] * em1;
        return {1 + minus_1, minus_1};
    }
    const __float128 value = ldexpq(t.pow2[j] * (1 + em1), -static_cast<int>(a));
    return {value, value - 1};
}

}  // namespace normzoo::detail
