// The checks of a BRDF given as code beyond its albedo (docs/brdf-code.md#checks): Helmholtz
// reciprocity, float against double, and whether a parameter changes the albedo (normalization).
// Each returns a typed result with where it was decided; the albedo and its sign and finiteness
// are code_albedo.hpp's.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "../geometry.hpp"
#include "../quadrature/estimate.hpp"
#include <Eigen/Geometry>  // cross

#include "brdf_code.hpp"

namespace normzoo::code {

// The directions the pointwise checks visit: polar angles evenly spaced in (0, 90) degrees, the
// horizon and the normal excluded, azimuths evenly spaced on the circle.
inline std::vector<vec3<double>> check_directions(int polar, int azimuth) {
    std::vector<vec3<double>> d;
    const double half_pi = std::acos(-1.0) / 2;
    for (int i = 0; i < polar; ++i)
        for (int j = 0; j < azimuth; ++j) d.push_back(direction((i + 0.5) / polar * half_pi, 4 * half_pi * j / azimuth));
    return d;
}

// Where two evaluations differ most, relatively: |a - b| / max(|a|, |b|, floor) over channels.
// Two NaNs, or the same infinity, do not differ: that f is not finite there is the albedo's
// finding (values = non-finite), not a difference between the two evaluations.
struct worst_pair {
    double relative = 0;
    vec3<double> l{0, 0, 1}, v{0, 0, 1};
    double a = 0, b = 0;  // the two values there (the channel that differs most)
    std::size_t pairs = 0;
};

inline void compare(worst_pair& w, const sample& a, const sample& b, const vec3<double>& l, const vec3<double>& v,
                    double floor) {
    ++w.pairs;
    for (int c = 0; c < 3; ++c) {
        const double x = a.value[c], y = b.value[c];
        double r;
        if (!std::isfinite(x) || !std::isfinite(y)) r = ((std::isnan(x) && std::isnan(y)) || x == y) ? 0 : HUGE_VAL;
        else r = std::abs(x - y) / std::max({std::abs(x), std::abs(y), floor});
        if (r > w.relative) w.relative = r, w.l = l, w.v = v, w.a = x, w.b = y;
    }
}

// Helmholtz reciprocity, f(L, V) = f(V, L), over every pair of a grid of directions (12 x 24 by
// default: 82,944 pairs, each evaluated both ways in double).
struct reciprocity_result {
    worst_pair worst;
    double tolerance = 1e-9;  // relative, far above double's rounding, far below a missing 1/(N.L)
    bool reciprocal() const { return worst.relative <= tolerance; }
};

template <class F>
reciprocity_result check_reciprocity(const F& f, int polar = 12, int azimuth = 24, double tolerance = 1e-9) {
    reciprocity_result r;
    r.tolerance = tolerance;
    const auto d = check_directions(polar, azimuth);
    for (const auto& l : d)
        for (const auto& v : d) compare(r.worst, call<double>(f, l, v), call<double>(f, v, l), l, v, 1e-300);
    return r;
}

// f evaluated in float (what a GPU computes) against double, at one incidence, over a grid of
// outgoing directions (32 x 64 by default) and around a given pole (the lobe's). A difference is a
// breakdown where it exceeds `tolerance` relative to the double value, or to a millionth of the
// largest double value seen (`floor` of it), whichever is larger (values far below the peak do not
// count).
struct precision_result {
    worst_pair worst;
    double tolerance = 1e-3;
    bool breaks_down() const { return worst.relative > tolerance; }
};

// binary16 (docs/brdf-code.md#precision): its unit roundoff is 2^-11 (4.9e-4); a breakdown is an
// error above 2^-4 (128 of them: mediump code written with care stays near or below 0.05 up to
// 89 degrees, a cancellation or an overflow goes far above), against the double value or a
// thousandth of the largest (binary16's normal range ends 2^-14 below 1). Its albedo is
// integrated to 1e-3 at least, binary16's own precision, with 40 panels at most per adaptive
// integral (not 400): its values are a staircase that no refinement makes smooth.
constexpr double binary16_tolerance = 0x1p-4;
constexpr double binary16_floor = 1e-3;
constexpr double binary16_albedo_tolerance = 1e-3;
constexpr std::size_t binary16_albedo_panels = 40;

template <class F>
precision_result compare_float(const F& f, const vec3<double>& l, const vec3<double>& pole, int polar = 32,
                               int azimuth = 64, double tolerance = 1e-3, double floor = 1e-6) {
    std::vector<vec3<double>> d = check_directions(polar, azimuth);
    // rings around the pole at angles 1e-4 .. 0.3 rad
    const vec3<double> a = std::abs(pole.x()) < 0.9 ? vec3<double>(1, 0, 0) : vec3<double>(0, 1, 0);
    const vec3<double> t1 = (a - a.dot(pole) * pole).normalized(), t2 = pole.cross(t1);
    d.push_back(pole);
    for (double angle = 1e-4; angle < 0.3; angle *= 2)
        for (int k = 0; k < 8; ++k) {
            const double phi = std::acos(-1.0) * k / 4;
            const vec3<double> v = (std::cos(angle) * pole + std::sin(angle) * (std::cos(phi) * t1 + std::sin(phi) * t2)).normalized();
            if (v.z() > 0) d.push_back(v);
        }
    std::vector<sample> exact;
    double largest = 0;
    for (const auto& v : d) {
        exact.push_back(call<double>(f, l, v));
        for (double c : exact.back().value)
            if (std::isfinite(c)) largest = std::max(largest, std::abs(c));
    }
    precision_result r;
    r.tolerance = tolerance;
    for (std::size_t i = 0; i < d.size(); ++i) compare(r.worst, exact[i], call<float>(f, l, d[i]), l, d[i], floor * largest);
    return r;
}

// Whether a parameter changes the albedo at one incidence: the albedos at its values are all
// equal within their bounds (the spread is below the sum of the two bounds that frame it), or
// the two values that differ most, with how much and by how much more than their bounds.
struct normalization_result {
    std::size_t values = 0;
    std::size_t lowest = 0, highest = 0;  // the indices of the least and largest albedo
    double spread = 0;                    // largest - least
    double bound = 0;                     // the two bounds added
    bool normalized() const { return spread <= bound; }
};

inline normalization_result check_normalization(const std::vector<quadrature::estimate<double>>& albedos) {
    normalization_result r;
    r.values = albedos.size();
    if (albedos.empty()) return r;
    for (std::size_t i = 1; i < albedos.size(); ++i) {
        if (albedos[i].value < albedos[r.lowest].value) r.lowest = i;
        if (albedos[i].value > albedos[r.highest].value) r.highest = i;
    }
    r.spread = albedos[r.highest].value - albedos[r.lowest].value;
    r.bound = albedos[r.highest].abs_error + albedos[r.lowest].abs_error;
    return r;
}

}  // namespace normzoo::code
