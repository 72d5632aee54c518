// Compiled into every shader normzoo translates (docs/brdf-code.md#how-the-shader-runs): GLM,
// which mirrors GLSL's types and functions, and a library of GLSL's built-in functions as static
// members, so that a shader's unqualified call finds them first. They accept what GLSL 1.20
// accepts and GLM does not: an int where a float goes (max(x, 0), pow(x, 5)). HLSL's names
// (saturate, lerp, frac, rsqrt, atan2, mul) are here too, for the plain HLSL files.
#pragma once
#define GLM_FORCE_SWIZZLE  // v.xyz() (GLM's function form: the translation writes the parentheses)
#include <glm/glm.hpp>

#include <cmath>
#include <type_traits>

namespace normzoo_glsl {

template <class real>
struct library {
    // An int or the other floating type where GLSL converts it to float.
    // An HLSL vector as GLM's own, so that GLM's overloads for vectors are the ones chosen.
    template <class X>
    static auto c(const X& x) {
        if constexpr (std::is_arithmetic_v<X>) return real(x);
        else if constexpr (is_hlsl<X>(0)) return static_cast<const typename X::base&>(x);
        else return x;
    }
    template <class X>
    static constexpr bool is_hlsl(decltype(sizeof(typename X::base))) { return true; }
    template <class X>
    static constexpr bool is_hlsl(...) { return false; }

#define NORMZOO_GLSL_1(name, glm_name) \
    template <class A> static auto name(const A& a) { return glm::glm_name(c(a)); }
#define NORMZOO_GLSL_2(name, glm_name) \
    template <class A, class B> static auto name(const A& a, const B& b) { return glm::glm_name(c(a), c(b)); }
#define NORMZOO_GLSL_3(name, glm_name) \
    template <class A, class B, class C> static auto name(const A& a, const B& b, const C& x) { return glm::glm_name(c(a), c(b), c(x)); }

    NORMZOO_GLSL_1(abs, abs) NORMZOO_GLSL_1(sign, sign) NORMZOO_GLSL_1(floor, floor) NORMZOO_GLSL_1(ceil, ceil)
    NORMZOO_GLSL_1(fract, fract) NORMZOO_GLSL_1(frac, fract) NORMZOO_GLSL_1(round, round) NORMZOO_GLSL_1(trunc, trunc)
    NORMZOO_GLSL_1(sqrt, sqrt) NORMZOO_GLSL_1(inversesqrt, inversesqrt) NORMZOO_GLSL_1(rsqrt, inversesqrt)
    NORMZOO_GLSL_1(exp, exp) NORMZOO_GLSL_1(exp2, exp2) NORMZOO_GLSL_1(log, log) NORMZOO_GLSL_1(log2, log2)
    NORMZOO_GLSL_1(sin, sin) NORMZOO_GLSL_1(cos, cos) NORMZOO_GLSL_1(tan, tan) NORMZOO_GLSL_1(asin, asin)
    NORMZOO_GLSL_1(acos, acos) NORMZOO_GLSL_1(sinh, sinh) NORMZOO_GLSL_1(cosh, cosh) NORMZOO_GLSL_1(tanh, tanh)
    NORMZOO_GLSL_1(radians, radians) NORMZOO_GLSL_1(degrees, degrees) NORMZOO_GLSL_1(normalize, normalize)
    NORMZOO_GLSL_2(pow, pow) NORMZOO_GLSL_2(min, min) NORMZOO_GLSL_2(max, max) NORMZOO_GLSL_2(mod, mod)
    NORMZOO_GLSL_2(step, step) NORMZOO_GLSL_2(dot, dot) NORMZOO_GLSL_2(cross, cross) NORMZOO_GLSL_2(distance, distance)
    NORMZOO_GLSL_2(reflect, reflect) NORMZOO_GLSL_2(atan2, atan)
    NORMZOO_GLSL_3(clamp, clamp) NORMZOO_GLSL_3(mix, mix) NORMZOO_GLSL_3(lerp, mix) NORMZOO_GLSL_3(smoothstep, smoothstep)
    NORMZOO_GLSL_3(refract, refract) NORMZOO_GLSL_3(faceforward, faceforward)
#undef NORMZOO_GLSL_1
#undef NORMZOO_GLSL_2
#undef NORMZOO_GLSL_3

    // length and atan take a float too in GLSL
    template <class A>
    static real length(const A& a) {
        if constexpr (std::is_arithmetic_v<A>) return std::abs(real(a));
        else return glm::length(a);
    }
    template <class A>
    static auto atan(const A& a) { return glm::atan(c(a)); }
    template <class A, class B>
    static auto atan(const A& y, const B& x) { return glm::atan(c(y), c(x)); }
    template <class A>
    static auto saturate(const A& a) { return glm::clamp(c(a), real(0), real(1)); }
    template <class A, class B>
    static auto mul(const A& a, const B& b) { return c(a) * c(b); }
};

// HLSL converts a scalar to a vector implicitly (return 0; float3 c = 1;); GLM's vectors take
// one only explicitly. The HLSL translation's vector types are these.
template <glm::length_t L, class T>
struct hlsl_vec : glm::vec<L, T> {
    using base = glm::vec<L, T>;
    using base::base;
    hlsl_vec() = default;
    hlsl_vec(const base& b) : base(b) {}
    hlsl_vec(T s) : base(s) {}
    hlsl_vec(int s) : base(T(s)) {}
};

// What the BRDF returned, as three channels (a number is all three).
template <class F>
void store(double* out, const F& f) {
    if constexpr (std::is_arithmetic_v<F>) out[0] = out[1] = out[2] = double(f);
    else out[0] = double(f.x), out[1] = double(f.y), out[2] = double(f.z);
}

}  // namespace normzoo_glsl

// GLSL lets an int stand for a float beside a vector (v * 2); GLM's operators do not.
#define NORMZOO_GLSL_MIXED_OPERATORS(real)                                                              \
    template <glm::length_t L> glm::vec<L, real> operator*(const glm::vec<L, real>& v, int s) { return v * real(s); } \
    template <glm::length_t L> glm::vec<L, real> operator*(int s, const glm::vec<L, real>& v) { return real(s) * v; } \
    template <glm::length_t L> glm::vec<L, real> operator/(const glm::vec<L, real>& v, int s) { return v / real(s); } \
    template <glm::length_t L> glm::vec<L, real> operator/(int s, const glm::vec<L, real>& v) { return real(s) / v; } \
    template <glm::length_t L> glm::vec<L, real> operator+(const glm::vec<L, real>& v, int s) { return v + real(s); } \
    template <glm::length_t L> glm::vec<L, real> operator+(int s, const glm::vec<L, real>& v) { return real(s) + v; } \
    template <glm::length_t L> glm::vec<L, real> operator-(const glm::vec<L, real>& v, int s) { return v - real(s); } \
    template <glm::length_t L> glm::vec<L, real> operator-(int s, const glm::vec<L, real>& v) { return real(s) - v; }
