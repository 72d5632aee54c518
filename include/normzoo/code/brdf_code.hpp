// A BRDF given as code (docs/brdf-code.md): any callable f(L, V, N, X, Y) that returns a number or
// an RGB triple, the shape of the BRDF() function of Disney's BRDF Explorer. normzoo knows nothing
// else about it: no lobe, no exponent, no closed form. The frame is the suite's (docs/conventions.md):
// N = z, X = x (the tangent, in the plane of incidence), Y = y; L and V are unit vectors.
//
// The callable is called with Eigen vectors of one scalar type: double always, float where the
// float evaluation is asked for (a generic lambda, or an overload taking vec3<float>).
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>

#include "../geometry.hpp"

namespace normzoo::code {

using rgb = std::array<double, 3>;

namespace detail {
template <class R, class = void>
struct is_triple : std::false_type {};
template <class R>
struct is_triple<R, std::void_t<decltype(std::declval<const R&>()[2])>> : std::true_type {};
}  // namespace detail

// The direction an albedo holds fixed (docs/brdf-code.md#the-direction-held-fixed). light: the
// integral over V of f(L, V) (N.V), the light's reflected fraction; view: the integral over L of
// f(L, V) (N.L), what engines' furnace tests and split-sum tables compute. The two are equal where
// f is reciprocal.
enum class fixed_direction { light, view };

inline const char* fixed_name(fixed_direction d) { return d == fixed_direction::light ? "light" : "view"; }

// f with L and V exchanged: an integrator that holds its first argument fixed then holds V.
template <class F>
struct view_held {
    const F& f;
    template <class V>
    auto operator()(const V& l, const V& v, const V& n, const V& x, const V& y) const {
        return f(v, l, n, x, y);
    }
};

// What f returns at one pair of directions: three channels (a number is all three), and whether
// it returned three.
struct sample {
    rgb value{};
    bool triple = false;
};

// f(L, V, N, X, Y) in the scalar type T (the directions are formed in double and rounded once).
template <class T, class F>
sample call(const F& f, const vec3<double>& l, const vec3<double>& v) {
    const vec3<T> lt = l.cast<T>(), vt = v.cast<T>();
    const vec3<T> n(T(0), T(0), T(1)), x(T(1), T(0), T(0)), y(T(0), T(1), T(0));
    const auto r = f(lt, vt, n, x, y);
    using R = std::decay_t<decltype(r)>;
    sample s;
    if constexpr (detail::is_triple<R>::value) {
        s.triple = true;
        for (int c = 0; c < 3; ++c) s.value[c] = static_cast<double>(r[c]);
    } else {
        const double d = static_cast<double>(r);
        s.value = {d, d, d};
    }
    return s;
}

// Where a function returned something that is not a reflectance: NaN or an infinity, or a
// negative value. The first direction met and how many evaluations did so.
struct problem {
    std::optional<vec3<double>> first;  // V at the first such evaluation (L is the incidence's)
    std::size_t count = 0;
    void note(const vec3<double>& v) {
        if (!first) first = v;
        ++count;
    }
    void merge(const problem& o) {
        if (!first) first = o.first;
        count += o.count;
    }
    explicit operator bool() const { return count > 0; }
};

struct problems {
    problem non_finite, negative;
    // A non-finite value whose neighbourhood is not finite either (code_albedo.hpp's
    // isolated_limit): f is NaN or Inf on more than a set of measure zero, so no albedo is given.
    bool non_finite_spread = false;
    void merge(const problems& o) {
        non_finite.merge(o.non_finite);
        negative.merge(o.negative);
        non_finite_spread = non_finite_spread || o.non_finite_spread;
    }
    // f was NaN or Inf only at isolated directions: the albedo over the others is given, flagged.
    bool non_finite_isolated() const { return non_finite && !non_finite_spread; }
};

// A sample made safe to integrate: non-finite channels count as 0 (the result is then reported
// as non-finite, not as a number); negative ones are kept and noted.
inline rgb screened(const sample& s, const vec3<double>& v, problems& p) {
    rgb out = s.value;
    bool bad = false, negative = false;
    for (double& c : out) {
        if (!std::isfinite(c)) c = 0, bad = true;
        else if (c < 0) negative = true;
    }
    if (bad) p.non_finite.note(v);
    if (negative) p.negative.note(v);
    return out;
}

}  // namespace normzoo::code
