// The double program's built-in functions with the operations a GPU leaves undefined noted
// (docs/brdf-code.md#gpu-undefined-operations): the CPU's libm returns a number for some of them
// (pow(-2, 2) is 4), a GPU need not. Each call notes what it saw in undefined_seen, which the
// program's entry normzoo_undefined_double returns and clears after each evaluation; the value is
// still the CPU's. Division by zero is the host's: FE_DIVBYZERO around each evaluation.
#pragma once
#include "glsl_prelude.hpp"

namespace normzoo_glsl {

// The operations, one bit each, in the order of compiled_shader.hpp's gpu_undefined_names.
enum undefined_op : unsigned {
    op_pow = 1u << 0,          // x < -1e-12, or x = 0 and y <= 0
    op_sqrt = 1u << 1,         // x < 0
    op_inversesqrt = 1u << 2,  // x <= 0
    op_log = 1u << 3,          // x <= 0 (log, log2, log10)
    op_asin_acos = 1u << 4,    // |x| > 1
    op_atan = 1u << 5,         // atan(y, x) with x = y = 0
    op_normalize = 1u << 6,    // a zero vector
};

inline thread_local unsigned undefined_seen = 0;

template <class real>
struct checked_library : library<real> {
    using base = library<real>;
    // p of some component of x (of x, a number)
    template <class X, class P>
    static bool any(const X& x, P p) {
        const auto v = base::c(x);
        if constexpr (std::is_arithmetic_v<decltype(v)>) {
            return p(real(v));
        } else {
            for (glm::length_t i = 0; i < v.length(); ++i)
                if (p(real(v[i]))) return true;
            return false;
        }
    }
    // p of some pair of components of x and y, a number paired with each component
    template <class X, class Y, class P>
    static bool any2(const X& x, const Y& y, P p) {
        const auto a = base::c(x);
        const auto b = base::c(y);
        constexpr bool sa = std::is_arithmetic_v<decltype(a)>, sb = std::is_arithmetic_v<decltype(b)>;
        if constexpr (sa && sb) {
            return p(real(a), real(b));
        } else if constexpr (sa) {
            return any(b, [&](real u) { return p(real(a), u); });
        } else if constexpr (sb) {
            return any(a, [&](real u) { return p(u, real(b)); });
        } else {
            for (glm::length_t i = 0; i < a.length(); ++i)
                if (p(real(a[i]), real(b[i]))) return true;
            return false;
        }
    }
    static void note(bool seen, unsigned op) {
        if (seen) undefined_seen |= op;
    }

    // A base within 1e-12 below 0 is 0 rounded: 1 - dot(V, H) at L = V is -2.2e-16 in double
    // (docs/brdf-code.md#gpu-undefined-operations says what that leaves out).
    template <class A, class B>
    static auto pow(const A& a, const B& b) {
        note(any2(a, b, [](real x, real y) { return x < real(-1e-12) || (x == 0 && y <= 0); }), op_pow);
        return base::pow(a, b);
    }
#define NORMZOO_CHECKED_1(name, op, test)                  \
    template <class A>                                     \
    static auto name(const A& a) {                         \
        note(any(a, [](real x) { return test; }), op);     \
        return base::name(a);                              \
    }
    NORMZOO_CHECKED_1(sqrt, op_sqrt, x < 0)
    NORMZOO_CHECKED_1(inversesqrt, op_inversesqrt, x <= 0)
    NORMZOO_CHECKED_1(rsqrt, op_inversesqrt, x <= 0)
    NORMZOO_CHECKED_1(log, op_log, x <= 0)
    NORMZOO_CHECKED_1(log2, op_log, x <= 0)
    NORMZOO_CHECKED_1(log10, op_log, x <= 0)
    NORMZOO_CHECKED_1(asin, op_asin_acos, x < -1 || x > 1)
    NORMZOO_CHECKED_1(acos, op_asin_acos, x < -1 || x > 1)
#undef NORMZOO_CHECKED_1
    template <class A>
    static auto atan(const A& a) { return base::atan(a); }
    template <class A, class B>
    static auto atan(const A& y, const B& x) {
        note(any2(y, x, [](real u, real v) { return u == 0 && v == 0; }), op_atan);
        return base::atan(y, x);
    }
    template <class A, class B>
    static auto atan2(const A& y, const B& x) {
        note(any2(y, x, [](real u, real v) { return u == 0 && v == 0; }), op_atan);
        return base::atan2(y, x);
    }
    template <class A>
    static auto normalize(const A& a) {
        note(!any(a, [](real x) { return x != 0; }), op_normalize);
        return base::normalize(a);
    }
};

}  // namespace normzoo_glsl
