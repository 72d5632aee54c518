// The reduced-precision part of the prelude (docs/brdf-code.md#precision): the types the
// translation gives what the code declares mediump, lowp, half or min16float, and the library
// the binary16 program calls. In the double and float programs those types are the program's own
// (hreal is real); in the binary16 program (namespace normzoo_half) they are _Float16, whose
// every operation GCC rounds to binary16 (round to nearest even, overflow to Inf, subnormals
// kept), while float stays fp32. Mixed operations promote as GLSL and HLSL do: _Float16 * float
// is float by C++'s own conversions; the operators below do the same for GLM's vectors.
#pragma once
#include "glsl_prelude.hpp"

#include <algorithm>

namespace normzoo_glsl {

// An operand's precision: 0 no floating type (int, bool), 1 binary16, 2 fp32.
template <class X>
struct precision_of : std::integral_constant<int, 0> {};
template <>
struct precision_of<float> : std::integral_constant<int, 2> {};
template <>
struct precision_of<_Float16> : std::integral_constant<int, 1> {};
template <glm::length_t L, class T, glm::qualifier Q>
struct precision_of<glm::vec<L, T, Q>> : precision_of<T> {};
template <glm::length_t L, class T>
struct precision_of<hlsl_vec<L, T>> : precision_of<T> {};
template <glm::length_t C, glm::length_t R, class T, glm::qualifier Q>
struct precision_of<glm::mat<C, R, T, Q>> : precision_of<T> {};

// A binary16 value (a scalar, or GLM's vector or matrix of them) as fp32, the rest as it is.
inline float widen(_Float16 x) { return float(x); }
template <glm::length_t L>
glm::vec<L, float> widen(const glm::vec<L, _Float16>& x) { return glm::vec<L, float>(x); }
template <glm::length_t L>
hlsl_vec<L, float> widen(const hlsl_vec<L, _Float16>& x) { return hlsl_vec<L, float>(glm::vec<L, float>(x)); }
template <glm::length_t C, glm::length_t R>
glm::mat<C, R, float> widen(const glm::mat<C, R, _Float16>& x) { return glm::mat<C, R, float>(x); }
template <class X>
const X& widen(const X& x) { return x; }

// An fp32 result rounded to binary16 (bools and ints as they are).
inline _Float16 narrow(float x) { return _Float16(x); }
template <glm::length_t L>
glm::vec<L, _Float16> narrow(const glm::vec<L, float>& x) { return glm::vec<L, _Float16>(x); }
template <glm::length_t L>
hlsl_vec<L, _Float16> narrow(const hlsl_vec<L, float>& x) { return hlsl_vec<L, _Float16>(glm::vec<L, _Float16>(x)); }
template <glm::length_t C, glm::length_t R>
glm::mat<C, R, _Float16> narrow(const glm::mat<C, R, float>& x) { return glm::mat<C, R, _Float16>(x); }
template <class X>
X narrow(const X& x) { return x; }

// The built-in functions of the binary16 program: fp32's (library<float>) on the arguments made
// fp32, the result rounded to binary16 where the most precise floating argument is binary16
// (GLSL ES 3.20 sec. 4.7.3: a built-in function's result has the highest precision of its
// arguments). fp32 and back is a correct rounding for sqrt and the arithmetic ones, since 24 bits
// are at least 2 * 11 + 2 (Figueroa, "When is double rounding innocuous?", 1995).
struct half_library : library<float> {
    using base = library<float>;
    template <class F, class... A>
    static auto apply(F f, const A&... a) {
        constexpr int p = std::max({0, precision_of<A>::value...});
        if constexpr (p == 1) return narrow(f(widen(a)...));
        else return f(widen(a)...);
    }
#define NORMZOO_HALF_FN(name) \
    template <class... A> static auto name(const A&... a) { return apply([](const auto&... x) { return base::name(x...); }, a...); }
    NORMZOO_HALF_FN(abs) NORMZOO_HALF_FN(sign) NORMZOO_HALF_FN(floor) NORMZOO_HALF_FN(ceil) NORMZOO_HALF_FN(fract)
    NORMZOO_HALF_FN(frac) NORMZOO_HALF_FN(round) NORMZOO_HALF_FN(trunc) NORMZOO_HALF_FN(sqrt) NORMZOO_HALF_FN(inversesqrt)
    NORMZOO_HALF_FN(rsqrt) NORMZOO_HALF_FN(exp) NORMZOO_HALF_FN(exp2) NORMZOO_HALF_FN(log) NORMZOO_HALF_FN(log2)
    NORMZOO_HALF_FN(sin) NORMZOO_HALF_FN(cos) NORMZOO_HALF_FN(tan) NORMZOO_HALF_FN(asin) NORMZOO_HALF_FN(acos)
    NORMZOO_HALF_FN(sinh) NORMZOO_HALF_FN(cosh) NORMZOO_HALF_FN(tanh) NORMZOO_HALF_FN(radians) NORMZOO_HALF_FN(degrees)
    NORMZOO_HALF_FN(normalize) NORMZOO_HALF_FN(isnan) NORMZOO_HALF_FN(isinf) NORMZOO_HALF_FN(all) NORMZOO_HALF_FN(any)
    NORMZOO_HALF_FN(normzoo_not) NORMZOO_HALF_FN(transpose) NORMZOO_HALF_FN(determinant) NORMZOO_HALF_FN(inverse)
    NORMZOO_HALF_FN(pow) NORMZOO_HALF_FN(min) NORMZOO_HALF_FN(max) NORMZOO_HALF_FN(mod) NORMZOO_HALF_FN(step)
    NORMZOO_HALF_FN(dot) NORMZOO_HALF_FN(cross) NORMZOO_HALF_FN(distance) NORMZOO_HALF_FN(reflect) NORMZOO_HALF_FN(atan2)
    NORMZOO_HALF_FN(lessThan) NORMZOO_HALF_FN(lessThanEqual) NORMZOO_HALF_FN(greaterThan) NORMZOO_HALF_FN(greaterThanEqual)
    NORMZOO_HALF_FN(equal) NORMZOO_HALF_FN(notEqual) NORMZOO_HALF_FN(clamp) NORMZOO_HALF_FN(mix) NORMZOO_HALF_FN(smoothstep)
    NORMZOO_HALF_FN(refract) NORMZOO_HALF_FN(faceforward) NORMZOO_HALF_FN(length) NORMZOO_HALF_FN(atan)
    NORMZOO_HALF_FN(log10) NORMZOO_HALF_FN(saturate) NORMZOO_HALF_FN(lerp) NORMZOO_HALF_FN(rcp) NORMZOO_HALF_FN(mad)
    NORMZOO_HALF_FN(fmod) NORMZOO_HALF_FN(mul)
#undef NORMZOO_HALF_FN
    // sincos(x, out s, out c): each out parameter takes its own type's rounding on assignment
    template <class A, class S, class C>
    static void sincos(const A& x, S& s, C& co) {
        s = S(sin(x));
        co = C(cos(x));
    }
};

// A swizzle of a binary16 number (h.xxx), which is not arithmetic to std::is_arithmetic.
template <bool H, int S, int... I>
auto operator->*(const _Float16& x, swizzle<H, false, S, I...>) {
    if constexpr (sizeof...(I) == 1) return x;
    else return vec_of<H, sizeof...(I), _Float16>(((void)I, x)...);
}
template <bool H, int S, int I>
_Float16& operator->*(_Float16& x, swizzle<H, true, S, I>) { return x; }

// What the binary16 program returns, as three channels.
inline void store(double* out, _Float16 f) { out[0] = out[1] = out[2] = double(f); }
template <glm::length_t L>
void store(double* out, const glm::vec<L, _Float16>& f) { store(out, glm::vec<L, float>(f)); }

}  // namespace normzoo_glsl

// GLM's vector operators take one number type; a binary16 vector beside an fp32 vector or number
// is fp32 (the binary16 one widened, as GLSL promotes mediump to highp); beside an int it stays
// binary16 (NORMZOO_GLSL_MIXED_OPERATORS(_Float16)).
#define NORMZOO_HALF_MIXED_OPERATOR(op)                                                                                       \
    template <glm::length_t L> glm::vec<L, float> operator op(const glm::vec<L, _Float16>& a, const glm::vec<L, float>& b) { \
        return glm::vec<L, float>(a) op b;                                                                                 \
    }                                                                                                                       \
    template <glm::length_t L> glm::vec<L, float> operator op(const glm::vec<L, float>& a, const glm::vec<L, _Float16>& b) { \
        return a op glm::vec<L, float>(b);                                                                                 \
    }                                                                                                                       \
    template <glm::length_t L> glm::vec<L, float> operator op(const glm::vec<L, _Float16>& a, float b) {                   \
        return glm::vec<L, float>(a) op b;                                                                                 \
    }                                                                                                                       \
    template <glm::length_t L> glm::vec<L, float> operator op(float a, const glm::vec<L, _Float16>& b) {                   \
        return a op glm::vec<L, float>(b);                                                                                 \
    }                                                                                                                       \
    template <glm::length_t L> glm::vec<L, float> operator op(const glm::vec<L, float>& a, _Float16 b) {                   \
        return a op float(b);                                                                                              \
    }                                                                                                                       \
    template <glm::length_t L> glm::vec<L, float> operator op(_Float16 a, const glm::vec<L, float>& b) {                   \
        return float(a) op b;                                                                                              \
    }
#define NORMZOO_HALF_MIXED_OPERATORS \
    NORMZOO_HALF_MIXED_OPERATOR(+) NORMZOO_HALF_MIXED_OPERATOR(-) NORMZOO_HALF_MIXED_OPERATOR(*) NORMZOO_HALF_MIXED_OPERATOR(/)
