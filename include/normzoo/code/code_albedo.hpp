// The directional albedo of a BRDF given as code (docs/brdf-code.md#the-black-box-integrator):
//     rho_c(t) = integral over the upper hemisphere of f_c(L, V) (N.V) d(omega_V),  c = R, G, B,
// with L at polar angle t in the xz-plane, and what f returned that is not a reflectance.
//
// The lobe is found first (lobe_search.hpp). The integral is then taken in polar coordinates
// (theta, phi) about that pole P, with phi measured from the side of N:
//   V = cos theta P + sin theta (cos phi e1 + sin phi e2),  e1 = (N - (N.P) P) / |...|,  e2 = e1 x P,
// so N.V = cos theta P_z + sin theta cos phi s, s = |P_xy|, and the horizon is the curve
//   theta_max(phi) = atan2(P_z, -s cos phi)                   (in (0, pi); pi/2 when P = N).
// Every scale sits where the built-in forms' integral (albedo.hpp) has it: the lobe at theta = 0,
// graded from a quarter of its width; the horizon's transition around phi = +-90 degrees, of
// width P_z / s, graded in psi = |phi -+ 90 deg|. Code declares no symmetry, so phi runs over the
// whole circle: four sides of 90 degrees each.
//
// Kinks. A kink inside a panel fools the rules' error estimate (quadrature/adaptive.hpp), so the
// rules check their bisections, and the kinks shader code commonly has are breakpoints where
// each ray (fixed phi) crosses them: the curves R.V = 0 (max(R.V, 0)), N.V = N.L
// (max(N.L, N.V)), L.V = 0, and the plane through N orthogonal to L's azimuth (Oren-Nayar's
// max(cos(phi_L - phi_V), 0)).
//
// The bound: the adaptive rules' |Kronrod - Gauss| over every panel (quadrature/adaptive.hpp),
// plus each node's rounding. The direction V is formed in double, so f sees V to a few ulps and
// N.V to ~eps/(N.V) relatively; and a lobe of width w changes by up to ~1/w of its value per
// radian that V moves (a Gaussian's steepest relative slope near its peak, a GGX tail's 4/theta
// beyond it). Per node: (16 + 4/(N.V) + 4/w) eps |value|. The last term is what the audit found
// missing at w = 1.3e-5 (docs/brdf-code.md#the-audit): code cannot be evaluated in a wider type,
// as the built-in forms are where they are ill-conditioned, so the bound must say so.
//
// Isolated non-finite values (docs/brdf-code.md#isolated-non-finite-directions). Where f returns
// NaN or Inf at a direction, f is probed on small circles about it (isolated_limit). When every
// probe is finite the direction is isolated, as V = N is for a normalize of V's projection on the
// surface: f is not finite on a set of measure zero there, and the node takes f's value next to it,
// its bound growing by how much the probes differ. Otherwise no albedo is given.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "../albedo.hpp"
#include "../geometry.hpp"
#include "../quadrature/estimate.hpp"
#include "../quadrature/graded.hpp"
#include "brdf_code.hpp"
#include "lobe_search.hpp"

namespace normzoo::code {

struct code_albedo_result {
    std::array<quadrature::estimate<double>, 3> channel{};  // R, G, B (all three equal for a number)
    bool triple = false;      // f returned three channels that differ somewhere
    found_lobe lobe;
    problems found;           // non-finite and negative values met
    std::size_t evaluations = 0;  // of f, all passes and the search included
    // The largest channel: the one that decides whether energy is conserved.
    const quadrature::estimate<double>& largest() const {
        std::size_t k = 0;
        for (std::size_t c = 1; c < 3; ++c)
            if (channel[c].value > channel[k].value) k = c;
        return channel[k];
    }
    bool finite() const { return !found.non_finite; }
    // The albedo is a number: f was finite, or not finite only at isolated directions, which the
    // integral excludes (found.non_finite_isolated() says so).
    bool usable() const { return !found.non_finite || found.non_finite_isolated(); }
};

namespace detail {

struct pole_frame {
    vec3<double> p, e1, e2;
    double pz, s;
};

inline pole_frame frame_about(const vec3<double>& pole) {
    pole_frame f;
    f.p = pole.normalized();
    f.pz = f.p.z();
    f.s = std::hypot(f.p.x(), f.p.y());
    if (f.s < 1e-12) {
        f.p = vec3<double>(0, 0, 1), f.pz = 1, f.s = 0;
        f.e1 = vec3<double>(1, 0, 0), f.e2 = vec3<double>(0, 1, 0);
    } else {
        // From P's azimuth a: P = (s cos a, s sin a, P_z), e1 = (-P_z cos a, -P_z sin a, s), e2 =
        // (-sin a, cos a, 0), orthonormal to rounding even when P is within 1e-5 of N (where
        // N - (N.P) P cancels and the integral lost 1e-13).
        const double ca = f.p.x() / f.s, sa = f.p.y() / f.s;
        f.e1 = vec3<double>(-f.pz * ca, -f.pz * sa, f.s);
        f.e2 = vec3<double>(-sa, ca, 0);
    }
    return f;
}

// A curve a.V = b on which shader code commonly has a kink.
struct plane {
    vec3<double> a;
    double b;
};

// The integral over the hemisphere of g(V) about the frame's pole, g returning one channel of
// f (N.V) and an error it carries beyond rounding (an isolated non-finite value's); unit: the
// epsilon of the type f is evaluated in.
template <class G>
quadrature::estimate<double> hemisphere_about(const G& g, const pole_frame& fr, const std::vector<plane>& kink_planes,
                                              double width, double tol, std::size_t max_panels, double unit) {
    using estimate = quadrature::estimate<double>;
    const double pi = std::acos(-1.0), half_pi = pi / 2;
    auto inner = [&](double cos_phi, double sin_phi) -> estimate {
        const double theta_max = fr.s > 0 ? std::atan2(fr.pz, -fr.s * cos_phi) : half_pi;
        const vec3<double> across = cos_phi * fr.e1 + sin_phi * fr.e2;
        auto node = [&](double theta) -> estimate {
            const double c = std::cos(theta), st = std::sin(theta);
            const double nv = c * fr.pz + st * cos_phi * fr.s;
            if (!(nv > 0)) return {0, 0, 0};
            const vec3<double> v = (c * fr.p + st * across).normalized();
            const std::pair<double, double> gv = g(v);
            const double value = gv.first * st;
            return {value, (16 + 4 / nv + 4 / width) * unit * std::abs(value) + gv.second * st, 1};
        };
        std::vector<double> kinks;
        for (const plane& k : kink_planes) {
            // a.V = b along the ray: A cos theta + B sin theta = b
            const double A = k.a.dot(fr.p), B = k.a.dot(across), m = std::hypot(A, B);
            if (!(m > std::abs(k.b))) continue;
            const double centre = std::atan2(B, A), half = std::acos(k.b / m);
            for (double th : {centre - half, centre + half, centre - half + 2 * pi, centre + half - 2 * pi})
                if (th > 0 && th < theta_max) kinks.push_back(th);
        }
        auto r = quadrature::graded_integral<double, 31>(node, std::min(width, theta_max) / 4, theta_max, tol / 64,
                                                         tol / 16, max_panels, true, kinks);
        return r;
    };
    const double psi0 = fr.s > 0 ? fr.pz / fr.s / 4 : half_pi;
    const double x0 = psi0 < half_pi / 32 ? psi0 : half_pi;
    estimate total{0, 0, 0};
    for (int sigma : {-1, 1})
        for (int tau : {-1, 1}) {
            // phi = tau (90 deg + sigma psi): cos phi = -sigma sin psi, sin phi = tau cos psi
            auto outer = [&](double psi) { return inner(-sigma * std::sin(psi), tau * std::cos(psi)); };
            const auto side = quadrature::graded_integral<double, 15>(outer, x0, half_pi, tol / 8, tol / 8, max_panels, true);
            total.value += side.value;
            total.abs_error += side.abs_error;
            total.evaluations += side.evaluations;
        }
    return total;
}

// f next to a direction v where it is not finite: f at six directions on each of three circles
// about v, of angular radius 1e-3, 1e-5 and 1e-7 rad (1e-2, 1e-3 and 1e-4 in float, whose
// directions resolve no less), those below the horizon left out. When every probe is finite, v is
// an isolated direction: the value is the innermost circle's mean and its error the largest
// distance from that mean on the two inner circles. None when a probe is not finite as well: f is
// then not finite on a set that circles this small cannot step over (a region, a band wider than
// the innermost radius). Curves (V = N, a plane) are stepped over: the probes' azimuths are off
// the frame's axes. `calls` counts the probes.
struct limit_value {
    rgb value{}, error{};
};

template <class T, class F>
std::optional<limit_value> isolated_limit(const F& f, const vec3<double>& l, const vec3<double>& v, std::size_t& calls) {
    constexpr std::array<double, 3> radii =
        std::is_same_v<T, float> ? std::array<double, 3>{1e-2, 1e-3, 1e-4} : std::array<double, 3>{1e-3, 1e-5, 1e-7};
    const auto t = tangents(v);
    std::array<std::vector<rgb>, 3> circle;
    for (std::size_t k = 0; k < radii.size(); ++k)
        for (int j = 0; j < 6; ++j) {
            const double psi = 0.5 + std::acos(-1.0) * j / 3;
            const vec3<double> w = turned(v, std::cos(psi) * t[0] + std::sin(psi) * t[1], radii[k]);
            if (!(w.z() > 0)) continue;
            ++calls;
            const sample x = call<T>(f, l, w);
            for (double c : x.value)
                if (!std::isfinite(c)) return std::nullopt;
            circle[k].push_back(x.value);
        }
    if (circle[2].empty()) return std::nullopt;
    limit_value out;
    for (const rgb& x : circle[2])
        for (int c = 0; c < 3; ++c) out.value[c] += x[c] / static_cast<double>(circle[2].size());
    for (std::size_t k = 1; k < 3; ++k)
        for (const rgb& x : circle[k])
            for (int c = 0; c < 3; ++c) out.error[c] = std::max(out.error[c], std::abs(x[c] - out.value[c]));
    return out;
}

// The albedo with f's first argument held at L (code_albedo).
template <class T, class F>
code_albedo_result light_held_albedo(const F& f, const degrees_angle<quad>& theta, const albedo_settings& s) {
    const vec3<double> l(static_cast<double>(theta.sin_t), 0, static_cast<double>(theta.cos_t));
    code_albedo_result r;
    std::size_t calls = 0;
    // f (N.V) at v in each channel, with the error it carries: 0, or an isolated non-finite value's
    auto channels = [&](const vec3<double>& v, problems& p) {
        ++calls;
        const sample x = call<T>(f, l, v);
        if (x.triple && (x.value[0] != x.value[1] || x.value[1] != x.value[2])) r.triple = true;
        std::pair<rgb, rgb> c{screened(x, v, p), rgb{}};
        const bool finite = std::all_of(x.value.begin(), x.value.end(), [](double y) { return std::isfinite(y); });
        if (!finite && !p.non_finite_spread) {
            if (const auto near = isolated_limit<T>(f, l, v, calls)) {
                c = {near->value, near->error};
                if (std::any_of(c.first.begin(), c.first.end(), [](double y) { return y < 0; })) p.negative.note(v);
            } else {
                p.non_finite_spread = true;
            }
        }
        for (int k = 0; k < 3; ++k) c.first[k] *= v.z(), c.second[k] *= v.z();
        return c;
    };
    auto largest = [&](const vec3<double>& v) {
        const rgb c = channels(v, r.found).first;
        return std::max({c[0], c[1], c[2]});
    };
    r.lobe = find_lobe(largest, l, s.tolerance);
    const detail::pole_frame fr = detail::frame_about(r.lobe.pole);
    // The clamps shaders write: max(R.V, 0) (a Phong lobe), max(N.L, N.V) (Ashikhmin-Shirley),
    // max(L.V, 0), and max(cos(phi_L - phi_V), 0) (Oren-Nayar), whose kink is the plane through N
    // orthogonal to L's azimuth.
    const vec3<double> r_dir = reflect(l);
    std::vector<detail::plane> kinks{{r_dir, 0}, {vec3<double>(0, 0, 1), l.z()}, {l, 0}};
    if (l.x() != 0 || l.y() != 0) kinks.push_back({vec3<double>(l.x(), l.y(), 0).normalized(), 0});
    // One pass while the channels agree; three once they are seen to differ (here or in the search).
    for (int k = 0; k < (r.triple ? 3 : 1); ++k) {
        auto g = [&](const vec3<double>& v) {
            const auto c = channels(v, r.found);
            return std::pair<double, double>(c.first[k], c.second[k]);
        };
        r.channel[k] = detail::hemisphere_about(g, fr, kinks, r.lobe.width, s.tolerance, s.max_panels,
                                               std::numeric_limits<T>::epsilon());
    }
    if (!r.triple) r.channel[1] = r.channel[2] = r.channel[0];
    r.evaluations = calls;
    return r;
}

}  // namespace detail

// The albedo of f at the angle theta of the direction held fixed (L by default; V, the integral
// over L, with fixed_direction::view), f evaluated in T (double, or float for what a GPU
// computes). s.tolerance is absolute up to an albedo of 1, as for the built-in forms.
template <class T = double, class F>
code_albedo_result code_albedo(const F& f, const degrees_angle<quad>& theta, const albedo_settings& s = {},
                               fixed_direction fixed = fixed_direction::light) {
    if (fixed == fixed_direction::view) return detail::light_held_albedo<T>(view_held<F>{f}, theta, s);
    return detail::light_held_albedo<T>(f, theta, s);
}

}  // namespace normzoo::code
