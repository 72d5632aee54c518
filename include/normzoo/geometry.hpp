// The shading frame (docs/conventions.md), with vectors from Eigen, templated on the scalar so the
// same expression runs in double, long double and multiprecision (real.hpp gives Eigen the
// multiprecision types' traits: a test in double does not parse them).
#pragma once
#include <Eigen/Core>
#include <boost/math/constants/constants.hpp>
#include <cmath>

namespace normzoo {

template <class T>
using vec3 = Eigen::Matrix<T, 3, 1>;

// The helpers below that every f(L, V) calls form their vectors coefficient by coefficient, not as
// Eigen expressions: each expression type (L + V, its quotient by a norm, a - b, s a + t b) is a
// tree of class templates that an includer's compiler instantiates once per number type, and the
// albedo evaluates f in three (albedo.hpp); they were more than half of what g++ spent on the
// example engine test's albedo (bench/header_cost). The values are Eigen's, bit for bit: each
// coefficient is one IEEE operation either way, and the sums of squares and dot products are still
// Eigen's, over plain vectors.

template <class T>
vec3<T> normal() { return vec3<T>(T(0), T(0), T(1)); }

template <class T>
T pi() { return boost::math::constants::pi<T>(); }

// max(a.b, 0)
template <class T>
T clamped_dot(const vec3<T>& a, const vec3<T>& b) {
    const T d = a.dot(b);
    return d > 0 ? d : T(0);
}

// tan^2 of the polar angle of a unit vector, (x^2 + y^2) / z^2: exact for tiny angles (no 1 - cos^2).
template <class T>
T tan2_of(const vec3<T>& h) {
    return (h.x() * h.x() + h.y() * h.y()) / (h.z() * h.z());
}

// (sin t cos p, sin t sin p, cos t)
template <class T>
vec3<T> direction(const T& theta, const T& phi) {
    using std::cos;
    using std::sin;
    const T st = sin(theta);
    return vec3<T>(st * cos(phi), st * sin(phi), cos(theta));
}

// R = 2 (N.w) N - w, the mirror of w about N.
template <class T>
vec3<T> reflect(const vec3<T>& w, const vec3<T>& n = normal<T>()) {
    const T twice = T(2) * n.dot(w);
    return vec3<T>(twice * n.x() - w.x(), twice * n.y() - w.y(), twice * n.z() - w.z());
}

// H = normalize(L + V); a sum that is zero (or NaN) comes back as it is, as from Eigen's normalized().
template <class T>
vec3<T> half_vector(const vec3<T>& l, const vec3<T>& v) {
    using std::sqrt;
    const vec3<T> h(l.x() + v.x(), l.y() + v.y(), l.z() + v.z());
    const T z = h.squaredNorm();
    if (!(z > 0)) return h;
    const T norm = sqrt(z);
    return vec3<T>(h.x() / norm, h.y() / norm, h.z() / norm);
}

// max(a.b, 0)^n for unit vectors a, b, evaluated without the n-ulp loss of pow(a.b, n):
// 1 - a.b = |a - b|^2 / 2 is computed from the difference vector (no cancellation), and the
// power as exp(n log1p(-|a - b|^2 / 2)). At n = 0 it is the limit n -> 0+: 1 where a.b > 0 and
// 0 elsewhere (the zoo's n = 0 rows are cosine-free; a lobe keeps its support).
template <class T>
T pow_lobe(const vec3<T>& a, const vec3<T>& b, const T& n) {
    using std::exp;
    using std::log1p;
    const T c = a.dot(b);
    if (!(c > 0)) return T(0);
    if (n == 0) return T(1);
    const T one_minus_c = vec3<T>(a.x() - b.x(), a.y() - b.y(), a.z() - b.z()).squaredNorm() / 2;
    return exp(n * log1p(-one_minus_c));
}

// max(x, 0)^n for a cosine x given with 1 - x: the same stable power when the caller has 1 - x.
template <class T>
T pow_cosine(const T& one_minus_x, const T& n) {
    using std::exp;
    using std::log1p;
    if (n == 0) return T(1);
    if (!(one_minus_x < 1)) return T(0);
    return exp(n * log1p(-one_minus_x));
}

// An angle in degrees in [0, 180] as cosine and sine, each from the argument that keeps its
// relative accuracy (90 - t and 180 - t are exact in double by Sterbenz's lemma).
template <class Real>
struct degrees_angle {
    Real cos_t, sin_t, radians;
    Real from_horizon;  // |90 deg - t| in radians, from the exact difference in degrees
    // The double is the input (90 - deg and 180 - deg are exact in double where they matter).
    explicit degrees_angle(double deg) : degrees_angle(Real(deg), Real(90 - deg), Real(180 - deg)) {}
    // From the angle and its distances to 90 and 180 degrees, each rounded once from its exact
    // value (decimal.hpp's degrees_of does so from the decimal typed): cos t near grazing keeps
    // its relative accuracy.
    degrees_angle(const Real& deg, const Real& to_90, const Real& to_180) {
        using std::abs;
        using std::cos;
        using std::sin;
        const Real to_rad = boost::math::constants::pi<Real>() / 180;
        radians = deg * to_rad;
        from_horizon = abs(to_90) * to_rad;
        cos_t = deg < 45 ? cos(radians) : sin(to_90 * to_rad);
        sin_t = deg <= 135 ? sin(radians) : sin(to_180 * to_rad);
    }
};

}  // namespace normzoo
