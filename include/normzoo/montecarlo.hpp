// An independent Monte Carlo estimate of the directional albedo, the way renderers test their
// BSDFs (pbrt's and Mitsuba's chi-square and furnace tests): V drawn from a mixture of cosine-
// weighted hemisphere sampling and the form's own lobe (Phong lobe around R, or the Blinn
// distribution over H mapped to V with its 1 / (4 L.H)), weighted by the mixture's density
// (the balance heuristic). Nothing is shared with albedo.hpp but the BRDF itself.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstdint>
#include <random>

#include "albedo.hpp"
#include "brdf/brdf.hpp"
#include "geometry.hpp"

namespace normzoo {

struct monte_carlo_estimate {
    double mean;
    double standard_error;
    std::uint64_t samples;
};

namespace detail {

// Two unit vectors completing w to an orthonormal frame (Frisvad's construction, with the
// Duff et al. sign fix).
inline void frame_around(const vec3<double>& w, vec3<double>& a, vec3<double>& b) {
    const double sign = std::copysign(1.0, w.z());
    const double p = -1 / (sign + w.z());
    const double q = w.x() * w.y() * p;
    a = vec3<double>(1 + sign * w.x() * w.x() * p, sign * q, -sign * w.x());
    b = vec3<double>(q, sign + w.y() * w.y() * p, -w.y());
}

}  // namespace detail

// `n_in` is the lobe exponent (for the modern forms indexed by roughness, the exponent that shapes
// the lobe proposal: the Phong-Beckmann mapping of alpha); `roughness` is passed to f.
template <class Model>
monte_carlo_estimate albedo_monte_carlo(double theta_deg, double n_in, double specular, std::uint64_t samples,
                                        std::uint64_t seed, double roughness = 0) {
    using std::cos;
    using std::pow;
    using std::sin;
    using std::sqrt;
    const double pi = boost::math::constants::pi<double>();
    const double n = Model::has_exponent ? n_in : 0.0;
    const incidence<double> in{degrees_angle<quad>(theta_deg)};
    const vec3<double> l = in.l, nrm = normal<double>();
    const vec3<double> axis = Model::lobe == brdf::lobe_kind::mirror ? reflect(l) : nrm;
    vec3<double> ax, ay;
    detail::frame_around(axis, ax, ay);
    const brdf::params<double> p{n, specular, roughness};
    const bool mix = Model::lobe != brdf::lobe_kind::normal;

    std::mt19937_64 rng(seed);
    auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1p-53; };  // [0, 1), 53 bits
    auto lobe_density = [&](const vec3<double>& v) {
        if (Model::lobe == brdf::lobe_kind::mirror) {
            const double c = axis.dot(v);
            return c > 0 ? (n + 1) / (2 * pi) * pow(c, n) : 0.0;
        }
        const vec3<double> h = half_vector(l, v);
        const double lh = l.dot(h);
        return lh > 0 ? (n + 1) / (2 * pi) * pow(h.z(), n) / (4 * lh) : 0.0;
    };

    double mean = 0, m2 = 0;  // Welford
    for (std::uint64_t i = 1; i <= samples; ++i) {
        const double u1 = uniform(), u2 = uniform(), phi = 2 * pi * uniform();
        vec3<double> v;
        if (!mix || u1 < 0.5) {
            const double r2 = mix ? 2 * u1 : u1;  // reuse u1 as the choice and the sample
            const double r = sqrt(r2);
            v = vec3<double>(r * cos(phi), r * sin(phi), sqrt(1 - r2));
        } else {
            const double c = pow(u2, 1 / (n + 1)), s = sqrt(1 - c * c);
            const vec3<double> d = c * axis + s * (cos(phi) * ax + sin(phi) * ay);
            v = Model::lobe == brdf::lobe_kind::half ? vec3<double>(2 * l.dot(d) * d - l) : d;
        }
        double x = 0;
        if (v.z() > 0) {
            const double density_cos = v.z() / pi;
            const double density = mix ? (density_cos + lobe_density(v)) / 2 : density_cos;
            x = Model::f(l, v, p) * v.z() / density;
        }
        const double delta = x - mean;
        mean += delta / static_cast<double>(i);
        m2 += delta * (x - mean);
    }
    const double variance = samples > 1 ? m2 / static_cast<double>(samples - 1) : 0;
    return {mean, sqrt(variance / static_cast<double>(samples)), samples};
}

}  // namespace normzoo
