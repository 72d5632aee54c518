// Finding the lobe of a BRDF given as code (docs/brdf-code.md#the-black-box-integrator).
//
// A built-in form declares where its peak lies and how wide it is (brdf/brdf.hpp); code does not,
// so the integrator looks. g(V) is the integrand's largest channel, f(L, V) (N.V), at one
// incidence L. The search evaluates g at the normal N, the mirror direction R, L itself and on a
// grid over the hemisphere (16 polar x 32 azimuthal, polar angles evenly spaced), climbs from the
// grid's best point, from R and from N by a pattern search on the sphere down to 1e-9 rad, and
// measures each peak's width: the smallest angle, over 8 directions around the peak, at which g
// falls below e^(-1/2) of its peak (doubling from 1e-7 rad). The pole the integral is centred on is
// the narrowest peak whose mass, peak x width^2, is not negligible against the tolerance: a lobe
// that narrow would slip between the nodes of a rule centred elsewhere, a broad one cannot.
//
// What it cannot see: a peak narrower than the grid's spacing (0.05 rad) that lies neither at N,
// at R nor on the climb from the grid's best point. Reflectance models put their peaks there
// (specular at R, diffuse and retro-reflective lobes towards N and L); docs/brdf-code.md says so.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>  // cross

#include "../geometry.hpp"

namespace normzoo::code {

struct found_lobe {
    vec3<double> pole{0, 0, 1};  // where the integral's polar angle is measured from
    double peak = 0;             // g at the pole
    double width = 0;            // angle at which g falls to e^(-1/2) of its peak (pi/2: no lobe)
    std::size_t evaluations = 0; // spent finding it
};

namespace detail {

// Two unit tangents at v, orthogonal to each other.
inline std::array<vec3<double>, 2> tangents(const vec3<double>& v) {
    const vec3<double> a = std::abs(v.x()) < 0.9 ? vec3<double>(1, 0, 0) : vec3<double>(0, 1, 0);
    const vec3<double> t1 = (a - a.dot(v) * v).normalized();
    return {t1, v.cross(t1)};
}

// The direction at angle a from v towards the unit tangent t.
inline vec3<double> turned(const vec3<double>& v, const vec3<double>& t, double a) {
    return (std::cos(a) * v + std::sin(a) * t).normalized();
}

template <class G>
struct searcher {
    const G& g;
    std::size_t calls = 0;
    double at(const vec3<double>& v) {
        if (!(v.z() > 0)) return 0;
        ++calls;
        const double x = g(v);
        return std::isfinite(x) ? x : 0;
    }
    // Pattern search: the best of four neighbours at the current step, halving the step when
    // none improves.
    vec3<double> climb(vec3<double> v, double& gv) {
        gv = at(v);
        double step = 0.05;
        for (int iteration = 0; iteration < 600 && step > 1e-9; ++iteration) {
            const auto t = tangents(v);
            bool moved = false;
            for (const vec3<double>& d : {t[0], t[1], vec3<double>(-t[0]), vec3<double>(-t[1])}) {
                const vec3<double> w = turned(v, d, step);
                const double gw = at(w);
                if (gw > gv) {
                    v = w, gv = gw, moved = true;
                    break;
                }
            }
            if (!moved) step /= 2;
        }
        return v;
    }
    double width(const vec3<double>& v, double gv) {
        if (!(gv > 0)) return std::acos(-1.0) / 2;
        const auto t = tangents(v);
        const double level = gv * std::exp(-0.5);
        double w = std::acos(-1.0) / 2;
        for (int k = 0; k < 8; ++k) {
            const double phi = std::acos(-1.0) * k / 4;
            const vec3<double> d = std::cos(phi) * t[0] + std::sin(phi) * t[1];
            for (double a = 1e-7; a < w; a *= 2) {
                if (at(turned(v, d, a)) < level) {
                    w = a;
                    break;
                }
            }
        }
        return w;
    }
};

}  // namespace detail

// g(V): the integrand's largest channel at V (0 below the horizon is taken care of here); l: the
// incident direction; tolerance: the albedo's, which decides which peaks matter.
template <class G>
found_lobe find_lobe(const G& g, const vec3<double>& l, double tolerance) {
    detail::searcher<G> s{g};
    const double half_pi = std::acos(-1.0) / 2, two_pi = 4 * half_pi;
    const vec3<double> n(0, 0, 1), r = reflect(l);
    vec3<double> best = n;
    double best_g = s.at(n);
    auto consider = [&](const vec3<double>& v) {
        const double x = s.at(v);
        if (x > best_g) best = v, best_g = x;
    };
    consider(r);
    consider(l);
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 32; ++j) consider(direction((i + 0.5) / 16 * half_pi, two_pi * j / 32));

    struct peak {
        vec3<double> v;
        double g, width;
    };
    std::vector<peak> peaks;
    for (const vec3<double>& start : {best, vec3<double>(r.z() > 0 ? r : n), n}) {
        double gv = 0;
        const vec3<double> v = s.climb(start, gv);
        peaks.push_back({v, gv, s.width(v, gv)});
    }
    // The narrowest peak that carries mass; the highest when none does.
    const peak* chosen = &*std::max_element(peaks.begin(), peaks.end(), [](const peak& a, const peak& b) { return a.g < b.g; });
    for (const peak& p : peaks)
        if (p.g * p.width * p.width > tolerance / 16 && p.width < chosen->width) chosen = &p;
    return {chosen->v, chosen->g, chosen->width, s.calls};
}

}  // namespace normzoo::code
