// Compiled into every shader normzoo translates (docs/brdf-code.md#how-the-shader-runs): GLM,
// which mirrors GLSL's types and functions, and a library of GLSL's and HLSL's built-in functions
// as static members, so that a shader's unqualified call finds them first. They accept what
// GLSL 1.20 accepts and GLM does not: an int where a float goes (max(x, 0), pow(x, 5)). HLSL's
// intrinsics compute what Microsoft's reference pages say (docs/brdf-code.md#hlsl-intrinsics).
// Swizzles, arrays and HLSL's vectors are types of their own here (the translation writes
// v.xy as (v ->* normzoo_sw_xy), and float a[3] as normzoo_glsl::array<real, 3> a).
#pragma once
#include <glm/glm.hpp>

#include <cmath>
#include <type_traits>

namespace normzoo_glsl {

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

template <class X>
struct is_vector : std::false_type {};
template <glm::length_t L, class T, glm::qualifier Q>
struct is_vector<glm::vec<L, T, Q>> : std::true_type {};

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
    // f of each component (of a number: of it).
    template <class F, class X>
    static auto each(F f, const X& x) {
        auto v = c(x);
        if constexpr (std::is_arithmetic_v<decltype(v)>) {
            return real(f(v));
        } else {
            decltype(v) r;
            for (glm::length_t i = 0; i < r.length(); ++i) r[i] = f(v[i]);
            return r;
        }
    }

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
    NORMZOO_GLSL_1(isnan, isnan) NORMZOO_GLSL_1(isinf, isinf) NORMZOO_GLSL_1(all, all) NORMZOO_GLSL_1(any, any)
    NORMZOO_GLSL_1(normzoo_not, not_) NORMZOO_GLSL_1(transpose, transpose) NORMZOO_GLSL_1(determinant, determinant)
    NORMZOO_GLSL_1(inverse, inverse)
    NORMZOO_GLSL_2(pow, pow) NORMZOO_GLSL_2(min, min) NORMZOO_GLSL_2(max, max) NORMZOO_GLSL_2(mod, mod)
    NORMZOO_GLSL_2(step, step) NORMZOO_GLSL_2(dot, dot) NORMZOO_GLSL_2(cross, cross) NORMZOO_GLSL_2(distance, distance)
    NORMZOO_GLSL_2(reflect, reflect) NORMZOO_GLSL_2(atan2, atan) NORMZOO_GLSL_2(lessThan, lessThan)
    NORMZOO_GLSL_2(lessThanEqual, lessThanEqual) NORMZOO_GLSL_2(greaterThan, greaterThan)
    NORMZOO_GLSL_2(greaterThanEqual, greaterThanEqual) NORMZOO_GLSL_2(equal, equal) NORMZOO_GLSL_2(notEqual, notEqual)
    NORMZOO_GLSL_3(clamp, clamp) NORMZOO_GLSL_3(mix, mix) NORMZOO_GLSL_3(smoothstep, smoothstep)
    NORMZOO_GLSL_3(refract, refract) NORMZOO_GLSL_3(faceforward, faceforward)
#undef NORMZOO_GLSL_1
#undef NORMZOO_GLSL_2
#undef NORMZOO_GLSL_3

    // length and atan take a float too in GLSL
    template <class A>
    static real length(const A& a) {
        if constexpr (std::is_arithmetic_v<A>) return std::abs(real(a));
        else return glm::length(c(a));
    }
    template <class A>
    static auto atan(const A& a) { return glm::atan(c(a)); }
    template <class A, class B>
    static auto atan(const A& y, const B& x) { return glm::atan(c(y), c(x)); }
    template <class A>
    static auto log10(const A& a) { return each([](real x) { return std::log10(x); }, a); }

    // HLSL's intrinsics (learn.microsoft.com/windows/win32/direct3dhlsl/, each function's page):
    // saturate clamps to [0, 1]; lerp is x*(1-s) + y*s, GLSL's mix; rcp is 1/x; rsqrt 1/sqrt(x);
    // frac x - floor(x), GLSL's fract; mad a*b + c.
    template <class A>
    static auto saturate(const A& a) { return glm::clamp(c(a), real(0), real(1)); }
    template <class A, class B, class C>
    static auto lerp(const A& a, const B& b, const C& s) { return glm::mix(c(a), c(b), c(s)); }
    template <class A>
    static auto rcp(const A& a) { return real(1) / c(a); }
    template <class A, class B, class C>
    static auto mad(const A& a, const B& b, const C& x) { return c(a) * c(b) + c(x); }
    // fmod: x = i*y + f with i an integer and f of x's sign, |f| < |y| (C's fmod, truncating),
    // where GLSL's mod floors: fmod(-0.5, 2) is -0.5, mod(-0.5, 2) is 1.5.
    template <class A, class B>
    static auto fmod(const A& a, const B& b) {
        if constexpr (std::is_arithmetic_v<A> && std::is_arithmetic_v<B>) {
            return std::fmod(real(a), real(b));
        } else {
            using V = std::conditional_t<std::is_arithmetic_v<A>, decltype(c(b)), decltype(c(a))>;
            const V x(c(a)), y(c(b));
            V r;
            for (glm::length_t i = 0; i < r.length(); ++i) r[i] = std::fmod(x[i], y[i]);
            return r;
        }
    }
    // sincos(x, out s, out c)
    template <class A, class S, class C>
    static void sincos(const A& x, S& s, C& co) {
        s = S(sin(x));
        co = C(cos(x));
    }
    // HLSL's matrices are written as GLM's transposed (float3x3(r0, r1, r2) holds its rows as
    // GLM's columns), so that m[i] is row i: mul(M, v) is then GLM's v * M, and mul(v, v) a dot.
    template <class A, class B>
    static auto mul(const A& a, const B& b) {
        if constexpr (std::is_arithmetic_v<A> || std::is_arithmetic_v<B>) return c(a) * c(b);
        else if constexpr (is_vector<decltype(c(a))>::value && is_vector<decltype(c(b))>::value) return glm::dot(c(a), c(b));
        else return c(b) * c(a);
    }
};

// A swizzle, written after a value: v.xy is (v ->* normzoo_sw_xy). Its components I, the letters'
// set (xyzw, rgba, stpq: two fields of a struct named x and r are two swizzles), whether the
// translation reads it (a value) or writes it (Write: a reference), and whether its vectors are
// HLSL's.
template <bool Hlsl, bool Write, int Set, int... I>
struct swizzle {};

template <bool Hlsl, glm::length_t N, class T>
using vec_of = std::conditional_t<Hlsl, hlsl_vec<N, T>, glm::vec<N, T>>;

// Several components of a vector, written (v.xy = ..., v.zx *= ...).
template <glm::length_t L, class T, bool Hlsl, int... I>
struct swizzle_ref {
    static constexpr glm::length_t n = sizeof...(I);
    glm::vec<L, T>& v;
    operator vec_of<Hlsl, n, T>() const { return vec_of<Hlsl, n, T>(v[I]...); }
    T& operator[](int k) const {
        constexpr int index[] = {I...};
        return v[index[k < 0 ? 0 : k >= n ? n - 1 : k]];
    }
    template <class X>
    swizzle_ref& operator=(const X& x) { return apply(x, [](T& a, T b) { a = b; }); }
    template <class X>
    swizzle_ref& operator+=(const X& x) { return apply(x, [](T& a, T b) { a += b; }); }
    template <class X>
    swizzle_ref& operator-=(const X& x) { return apply(x, [](T& a, T b) { a -= b; }); }
    template <class X>
    swizzle_ref& operator*=(const X& x) { return apply(x, [](T& a, T b) { a *= b; }); }
    template <class X>
    swizzle_ref& operator/=(const X& x) { return apply(x, [](T& a, T b) { a /= b; }); }

private:
    // x (a vector of n components, or a number for all of them) is copied first: v.xy = v.yx
    template <class X, class F>
    swizzle_ref& apply(const X& x, F f) {
        glm::vec<n, T> y;
        if constexpr (std::is_arithmetic_v<X>) y = glm::vec<n, T>(T(x));
        else y = glm::vec<n, T>(x);
        int k = 0;
        (f(v[I], y[k++]), ...);
        return *this;
    }
};

template <class T, bool H, int S, int... I, std::enable_if_t<std::is_arithmetic_v<T>, int> = 0>
auto operator->*(const T& x, swizzle<H, false, S, I...>) {
    if constexpr (sizeof...(I) == 1) return x;
    else return vec_of<H, sizeof...(I), T>(((void)I, x)...);
}
template <glm::length_t L, class T, bool H, int S, int... I>
auto operator->*(const glm::vec<L, T>& v, swizzle<H, false, S, I...>) {
    constexpr int index[] = {I...};
    if constexpr (sizeof...(I) == 1) return T(v[index[0]]);
    else return vec_of<H, sizeof...(I), T>(v[I]...);
}
template <class T, bool H, int S, int I, std::enable_if_t<std::is_arithmetic_v<T>, int> = 0>
T& operator->*(T& x, swizzle<H, true, S, I>) { return x; }
template <glm::length_t L, class T, bool H, int S, int I>
T& operator->*(glm::vec<L, T>& v, swizzle<H, true, S, I>) { return v[I]; }
template <glm::length_t L, class T, bool H, int S, int I0, int I1, int... I>
swizzle_ref<L, T, H, I0, I1, I...> operator->*(glm::vec<L, T>& v, swizzle<H, true, S, I0, I1, I...>) { return {v}; }

// GLSL's and HLSL's arrays: values (copied when passed or assigned, as in a shader), with
// length(), and an index outside them reads their nearest element, where C++ would read
// outside the array (a GPU's robust access returns 0 or clamps; GLSL leaves it undefined).
template <class T, int N>
struct array {
    T v[N];
    T& operator[](int i) { return v[i < 0 ? 0 : i >= N ? N - 1 : i]; }
    const T& operator[](int i) const { return v[i < 0 ? 0 : i >= N ? N - 1 : i]; }
    static constexpr int length() { return N; }
    friend bool operator==(const array& a, const array& b) {
        for (int i = 0; i < N; ++i)
            if (!(a.v[i] == b.v[i])) return false;
        return true;
    }
    friend bool operator!=(const array& a, const array& b) { return !(a == b); }
};

// float[3](a, b, c) and float[](a, b, c)
template <class T, class... A>
array<T, int(sizeof...(A))> make_array(const A&... a) {
    return {{T(a)...}};
}

// What the BRDF returned, as three channels (a number is all three).
template <class F>
void store(double* out, const F& f) {
    if constexpr (std::is_arithmetic_v<F>) out[0] = out[1] = out[2] = double(f);
    else out[0] = double(f.x), out[1] = double(f.y), out[2] = double(f.z);
}

}  // namespace normzoo_glsl

#include "glsl_textures.hpp"

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
