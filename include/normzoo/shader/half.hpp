// normzoo::shader::half: IEEE binary16 (11-bit significand, 5-bit exponent) as a shader's half
// (HLSL min16float / half with native fp16, GLSL mediump on fp16 hardware) computes it: every
// operation rounds its result to binary16, to nearest even.
//
// Storage is GCC's _Float16 (x86-64 since GCC 12, no -m flag needed: without AVX512-FP16 the
// arithmetic is emulated through float). GCC 12's C++ front end has no -fexcess-precision=standard
// ("unimplemented for C++"), and the C standard lets _Float16 arithmetic carry excess precision,
// so normzoo does not rely on the compiler's choice: each operator below computes in float and
// rounds the result to _Float16 explicitly. That is exactly the binary16 result: float carries
// 24 >= 2 * 11 + 2 significand bits, so rounding a float +, -, *, / or sqrt of two halves to half
// never double-rounds wrongly (Figueroa 1995). The tests check 1 + 2^-11 + 2^-11 == 1, which
// excess precision would get wrong.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>

namespace normzoo::shader {

class half {
public:
    half() = default;
    // Implicit from a number, as a shader's literal or input: rounded once to binary16.
    half(double x) : v_(static_cast<_Float16>(x)) {}  // NOLINT(google-explicit-constructor)
    half(int x) : v_(static_cast<_Float16>(static_cast<float>(x))) {}  // NOLINT
    // Never implicitly back to float: `n + 2` must pick half's +, not float's.
    explicit operator float() const { return static_cast<float>(v_); }
    explicit operator double() const { return static_cast<double>(v_); }

    friend half operator+(half a, half b) { return from(float(a) + float(b)); }
    friend half operator-(half a, half b) { return from(float(a) - float(b)); }
    friend half operator*(half a, half b) { return from(float(a) * float(b)); }
    friend half operator/(half a, half b) { return from(float(a) / float(b)); }
    friend half operator-(half a) { return from(-float(a)); }
    friend bool operator==(half a, half b) { return float(a) == float(b); }
    friend bool operator!=(half a, half b) { return !(a == b); }
    friend bool operator<(half a, half b) { return float(a) < float(b); }

    // The largest finite value, the smallest normal, the smallest subnormal.
    static half max() { return bits(0x7bff); }             // 65504
    static half min_normal() { return bits(0x0400); }      // 2^-14
    static half denorm_min() { return bits(0x0001); }      // 2^-24
    static constexpr int digits = 11;

    std::uint16_t to_bits() const {
        std::uint16_t b;
        std::memcpy(&b, &v_, sizeof b);
        return b;
    }
    static half bits(std::uint16_t b) {
        half h;
        std::memcpy(&h.v_, &b, sizeof b);
        return h;
    }

private:
    static half from(float x) {
        half h;
        h.v_ = static_cast<_Float16>(x);  // float -> binary16, round to nearest even
        return h;
    }
    _Float16 v_ = 0;
};

inline bool isnan(half h) { return std::isnan(float(h)); }
inline bool isinf(half h) { return std::isinf(float(h)); }

}  // namespace normzoo::shader
