// Irradiance from a sphere or disk light (docs/irradiance.md), by quadrature over the cap of
// directions the light subtends, in the cap's own frame, with the horizon clipped; the closed
// forms it must meet; and the punctual-light limit of a tiny cone (the KlayGE wiki page
// "Physically-based BRDF", after Hoffman).
//
// Units: radiance L = 1, distance r = 1, so r0 = ratio. The cap has half-angle b with
// sin b = ratio (sphere) or tan b = ratio (disk facing the receiver); its centre is tilted by
// t_c from N. Both sin b and cos b come from the ratio without 1 - cos^2 anywhere, and the
// quadrature runs in binary128, whose exponent range holds (1e-300)^2 and smaller: at
// ratio = 1e-300 the irradiance is ~3e-600 and keeps every digit.
#pragma once
#include <Eigen/Geometry>
#include <array>
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "brdf/brdf.hpp"
#include "decimal.hpp"
#include "geometry.hpp"
#include "quadrature/estimate.hpp"
#include "real.hpp"

namespace normzoo {

enum class light_kind { sphere, disk };

inline const char* light_name(light_kind k) { return k == light_kind::sphere ? "sphere" : "disk"; }

// The cap a light subtends at the receiver.
template <class Real>
struct light_cap {
    Real sin_b, cos_b, b;

    static light_cap sphere(const Real& ratio) {
        using std::asin;
        using std::sqrt;
        return {ratio, sqrt((1 - ratio) * (1 + ratio)), asin(ratio)};
    }
    static light_cap disk(const Real& ratio) {
        using std::atan;
        using std::sqrt;
        const Real h = sqrt(1 + ratio * ratio);
        return {ratio / h, 1 / h, atan(ratio)};
    }
    static light_cap of(light_kind k, const Real& ratio) { return k == light_kind::sphere ? sphere(ratio) : disk(ratio); }
};

namespace detail {

// atan(z) - z without cancellation: the series for |z| <= 1/2, else directly (<= 1.1 digit lost).
template <class Real>
Real atan_minus_identity(const Real& z) {
    using std::abs;
    using std::atan;
    if (abs(z) > Real(0.5)) return atan(z) - z;
    const Real z2 = z * z;
    Real term = z * z2, sum = 0;
    for (int k = 1; k < 200; ++k) {
        const Real add = (k % 2 ? -term : term) / (2 * k + 1);
        sum += add;
        if (abs(add) <= abs(sum) * std::numeric_limits<Real>::epsilon() / 4) break;
        term *= z2;
    }
    return sum;
}

}  // namespace detail

// E / L = integral over the cap of max(N.w, 0) d(omega), in closed form: pi sin^2 b cos t_c with
// the cap above the horizon, 0 below it, and where it crosses, the formula of Snyder ("Area
// light sources for real-time graphics", 1996) in the form of Lagarde and de Rousiers ("Moving
// Frostbite to physically based rendering", 2014):
//     x = cot b, y = -x cot t_c, w = sin t_c sqrt(1 - y^2),
//     E / L = (cos t_c acos y - x w) sin^2 b + atan(w / x),
// rewritten as cos t_c acos(y) sin^2 b + z sin^2 b + (atan z - z), z = w / x, which has no
// cancellation for a small cap (x w sin^2 b and atan z agree to O(b^3)).
// The bound returned with it is its own rounding: a few ulps of the terms' magnitudes (they
// cancel where the cap is about to set, E -> 0).
template <class Real>
quadrature::estimate<Real> cap_irradiance_closed_form(const light_cap<Real>& cap, const degrees_angle<Real>& t) {
    using std::abs;
    using std::acos;
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real s2 = cap.sin_b * cap.sin_b;
    if (t.cos_t >= cap.sin_b) {
        const Real e = boost::math::constants::pi<Real>() * s2 * t.cos_t;
        return {e, 8 * eps * e, 0};
    }
    if (t.cos_t <= -cap.sin_b) return {Real(0), Real(0), 0};
    const Real y = -cap.cos_b * t.cos_t / (cap.sin_b * t.sin_t);
    const Real w = t.sin_t * sqrt((1 - y) * (1 + y));
    const Real z = w * cap.sin_b / cap.cos_b;
    const Real t1 = t.cos_t * acos(y) * s2, t2 = z * s2, t3 = detail::atan_minus_identity(z);
    return {t1 + t2 + t3, 16 * eps * (abs(t1) + abs(t2) + abs(t3)), 0};
}

// Which closed form applies, for tables.
template <class Real>
const char* cap_case(const light_cap<Real>& cap, const degrees_angle<Real>& t) {
    if (t.cos_t >= cap.sin_b) return "above horizon";
    if (t.cos_t <= -cap.sin_b) return "below horizon";
    return "crossing horizon";
}

namespace detail {

// What a rule sums beside its value, for the error bound.
template <class Real>
struct cap_sums {
    Real l1 = 0;     // integral of |ring|
    Real terms = 0;  // integral of |a| + |bb cos phi| over the visible cap (when asked)
    Real edge = 0;   // |dE/db|: the ring at the cap's edge alpha = b (when asked)
};

// One quadrature rule over the cap: Gauss-Legendre of order A per panel in the polar angle
// alpha from the cap's centre, and of order P in the azimuth phi about it over the visible
// azimuths |phi| < phi_max(alpha), where N.w = cos(alpha) cos(t) + sin(alpha) sin(t) cos(phi) > 0.
//
// Where the horizon clips (alpha > alpha_0 = |90 deg - t|), cos(phi_max) = -cot(alpha) cot(t)
// has a square-root branch at alpha_0 and, for a thin sliver (alpha_0 << b), a near pole at
// alpha ~ -alpha_0. The substitution tan(alpha) = tan(alpha_0) cosh(v) removes both: it gives
// cos(phi_max) = -+sech(v) exactly, phi_max = pi - atan(sinh v) (centre above the horizon) or
// atan(sinh v) (below), analytic within pi/2 of the real axis; panels in v are at most 1 wide.
//
// With sensitivity set it also sums what the inputs' rounding can move: N.w = a + bb cos phi
// with a = cos(alpha) cos(t), bb = sin(alpha) sin(t), each off by a few ulps (cos t and sin t
// come rounded), so N.w errs by a few ulps of |a| + |bb cos phi|, not of |N.w|: near the horizon
// the two cancel, and for a cap about to set every point of it is near the horizon. The cap's
// radius b is off by a few ulps too, which moves E by b dE/db = b x (the ring at alpha = b).
template <unsigned A, unsigned P, class Real>
Real cap_rule(const light_cap<Real>& cap, const degrees_angle<Real>& t, cap_sums<Real>& sums, bool sensitivity) {
    using boost::math::quadrature::gauss;
    using std::abs;
    using std::acosh;
    using std::atan;
    using std::ceil;
    using std::cos;
    using std::cosh;
    using std::sin;
    using std::sinh;
    using std::tan;
    const Real pi = boost::math::constants::pi<Real>();
    const Real half_pi = boost::math::constants::half_pi<Real>();
    // The ring at alpha: the integral over |phi| < phi_max of (a + bb cos phi), times sin(alpha);
    // with `terms`, also that of |a| + |bb cos phi| (in closed form: the integral of |cos|).
    auto ring = [&](const Real& alpha, const Real& phi_max, Real* terms = nullptr) {
        const Real ca = cos(alpha), sa = sin(alpha);
        const Real a = ca * t.cos_t, bb = sa * t.sin_t;
        auto g = [&](const Real& phi) { return a + bb * cos(phi); };
        if (terms) {
            const Real abs_cos = phi_max <= half_pi ? sin(phi_max) : 2 - sin(phi_max);
            *terms = 2 * (abs(a) * phi_max + abs(bb) * abs_cos) * abs(sa);
        }
        return 2 * gauss<Real, P>::integrate(g, Real(0), phi_max) * sa;
    };
    // Integrates the ring over the polar angle, through a map from the rule's variable x in
    // [lo, hi] to (alpha, phi_max, d alpha / dx). The sums are Boost's gauss::integrate's, in
    // its order (the value is the same to the last bit), with the terms summed beside them.
    auto add = [&](const auto& map, const Real& lo, const Real& hi) {
        const auto& xi = gauss<Real, A>::abscissa();
        const auto& w = gauss<Real, A>::weights();
        const Real mid = (lo + hi) / 2, half = (hi - lo) / 2;
        Real q = 0, l1 = 0, terms = 0;
        auto at = [&](const Real& z, Real& node_terms) {
            const auto m = map(mid + half * z);
            const Real f = ring(m[0], m[1], sensitivity ? &node_terms : nullptr) * m[2];
            node_terms *= abs(m[2]);
            return f;
        };
        for (std::size_t i = 0; i < xi.size(); ++i) {
            Real tp = 0, tm = 0;
            if (i == 0 && A % 2 == 1) {
                q = at(Real(0), tp) * w[0];
                l1 = abs(q);
                terms = tp * w[0];
                continue;
            }
            const Real fp = at(xi[i], tp), fm = at(-xi[i], tm);
            q += (fp + fm) * w[i];
            l1 += (abs(fp) + abs(fm)) * w[i];
            terms += (tp + tm) * w[i];
        }
        sums.l1 += l1 * half;
        sums.terms += terms * half;
        return half * q;
    };
    using node = std::array<Real, 3>;  // alpha, phi_max, d alpha / d(variable)
    if (t.cos_t <= -cap.sin_b) return Real(0);  // below the horizon
    const Real alpha0 = t.from_horizon;
    const bool centre_above = t.cos_t > 0;
    Real total = 0;
    // Every azimuth visible: alpha < alpha_0 with the centre above the horizon.
    if (centre_above) {
        const Real end = alpha0 < cap.b ? alpha0 : cap.b;
        total += add([&](const Real& alpha) { return node{alpha, pi, Real(1)}; }, Real(0), end);
    }
    if (!(cap.b > alpha0)) {
        if (sensitivity) sums.edge = abs(ring(cap.b, pi));
        return total;
    }
    if (alpha0 == 0) {  // t = 90 deg exactly: phi_max = pi/2 at every alpha
        if (sensitivity) sums.edge = abs(ring(cap.b, pi / 2));
        return total + add([&](const Real& alpha) { return node{alpha, pi / 2, Real(1)}; }, Real(0), cap.b);
    }
    const Real tan0 = tan(alpha0);
    const Real v_end = acosh(tan(cap.b) / tan0);
    auto clipped = [&](const Real& v) {
        const Real c = cosh(v), sh = sinh(v);
        const Real alpha = atan(tan0 * c);
        const Real d_alpha = tan0 * sh / (1 + tan0 * tan0 * c * c);
        const Real phi_max = centre_above ? pi - atan(sh) : atan(sh);
        return node{alpha, phi_max, d_alpha};
    };
    const int panels = static_cast<int>(ceil(static_cast<double>(v_end)));
    for (int i = 0; i < panels; ++i)
        total += add(clipped, v_end * i / panels, v_end * (i + 1) / panels);
    if (sensitivity) {
        const node at_edge = clipped(v_end);
        sums.edge = abs(ring(cap.b, at_edge[1]));
    }
    return total;
}

}  // namespace detail

// E / L by quadrature, with an error bound: two Gauss-Legendre product rules of different
// orders (30 x 30 and 20 x 20 nodes) must agree; the bound is their difference, plus the
// rounding of the sum, plus what the rounding of the inputs (cos t_c, sin t_c, b, a few ulps
// each) moves E by: a cap crossing the horizon near setting has E far below its terms
// (cap_rule), and the error audit (docs/error-audit.md) found the bound short by up to 7x
// there before this term.
template <class Real = quad>
quadrature::estimate<Real> cap_irradiance(const light_cap<Real>& cap, const degrees_angle<Real>& t) {
    using std::abs;
    detail::cap_sums<Real> a, b;
    const Real qa = detail::cap_rule<30, 30>(cap, t, a, true);
    const Real qb = detail::cap_rule<20, 20>(cap, t, b, false);
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real inputs = 16 * eps * (a.terms + cap.b * a.edge);
    return {qa, abs(qa - qb) + 32 * eps * a.l1 + inputs, 2 * (30 * 30 + 20 * 20)};
}

// How far E / L can move when the inputs are rounded to Real (docs/irradiance.md, "Inputs are
// decimals"). The ratio, rounded by a relative ratio_rounding, moves the cap's edge by
// db = d(ratio) / cos b (sphere, sin b = ratio) or d(ratio) / (1 + ratio^2) (disk, tan b = ratio):
// a ring of solid angle 2 pi sin b db on which the integrand max(N.w, 0) is at most
// cos(t_c - b - db), the highest point of the edge. The tilt, when its angle or its distances to
// 90 and 180 degrees are not exact in Real (degrees_of rounds each once), turns the cap by at most
// pi eps radians, which moves each cosine over the cap's solid angle 2 pi (1 - cos b) by at most
// that much.
template <class Real>
Real cap_input_rounding(light_kind kind, const light_cap<Real>& cap, const degrees_angle<Real>& t, const Real& ratio,
                        double ratio_rounding, const decimal& tilt_deg) {
    using std::abs;
    using std::cos;
    using std::sin;
    const Real two_pi = boost::math::constants::two_pi<Real>();
    const Real d_ratio = abs(ratio) * Real(ratio_rounding);
    const Real db = kind == light_kind::sphere ? d_ratio / cap.cos_b : d_ratio / (1 + ratio * ratio);
    const Real top = t.radians - cap.b - db;  // the edge's highest point, from N
    const Real edge = top <= 0 ? Real(1) : (top >= boost::math::constants::half_pi<Real>() ? Real(0) : cos(top));
    const bool tilt_exact = tilt_deg.exact_in<Real>() && (decimal("90") - tilt_deg).exact_in<Real>() &&
                            (decimal("180") - tilt_deg).exact_in<Real>();
    const Real turn = tilt_exact ? Real(0) : boost::math::constants::pi<Real>() * std::numeric_limits<Real>::epsilon();
    const Real one_minus_cos_b = 2 * sin(cap.b / 2) * sin(cap.b / 2);
    return two_pi * cap.sin_b * db * edge + two_pi * one_minus_cos_b * turn;
}

// E / L at r0/r given in Real with a bound on its relative rounding (0: the ratio itself; a
// scene's radius / distance is a quotient) and the tilt of the light's centre typed in degrees:
// the quadrature at their rounding to Real, its bound widened by cap_input_rounding.
template <class Real = quad>
quadrature::estimate<Real> cap_irradiance(light_kind kind, const Real& ratio, double ratio_rounding,
                                          const decimal& tilt_deg) {
    const auto cap = light_cap<Real>::of(kind, ratio);
    const auto t = degrees_of<Real>(tilt_deg);
    auto e = cap_irradiance(cap, t);
    e.abs_error += cap_input_rounding(kind, cap, t, ratio, ratio_rounding, tilt_deg);
    return e;
}

// E / L at the decimals typed, r0/r and the tilt in degrees.
template <class Real = quad>
quadrature::estimate<Real> cap_irradiance(light_kind kind, const decimal& ratio, const decimal& tilt_deg) {
    return cap_irradiance<Real>(kind, ratio.to<Real>(), ratio.rounding<Real>(), tilt_deg);
}

// The punctual-light limit (KlayGE, "Physically-based BRDF"): a cone of half-angle e around
// l_c with radiance c_light / sin^2 e, so that (1/pi) integral L_tiny (N.L) d(omega) = c_light
// when l_c = N. Returns the integral of f(L, V) L_tiny (N.L) over the cone (c_light = 1), whose
// limit as e -> 0 is pi f(l_c, V) (N.l_c). Rules: Gauss-Legendre 30 in alpha with 32
// trapezoid azimuths, against 20 with 24; a cone wider than 0.02 rad, over which a lobe of
// exponent ~30 already varies, is cut into rings of 0.02 and gets twice the azimuths.
template <class Model, class Real = quad>
quadrature::estimate<Real> tiny_cone_radiance(const vec3<Real>& lc, const vec3<Real>& v, const Real& e,
                                              const brdf::params<Real>& p) {
    using boost::math::quadrature::gauss;
    using std::abs;
    using std::ceil;
    using std::cos;
    using std::sin;
    const Real two_pi = boost::math::constants::two_pi<Real>();
    // A frame around l_c (l_c is not N's opposite here).
    vec3<Real> u = vec3<Real>(0, 1, 0).cross(lc);
    if (u.squaredNorm() < Real(1e-20)) u = vec3<Real>(1, 0, 0).cross(lc);
    u.normalize();
    const vec3<Real> w = lc.cross(u);
    const Real s = sin(e);
    const Real radiance = 1 / (s * s);
    const int rings = e > Real(0.02) ? static_cast<int>(ceil(static_cast<double>(e / Real(0.02)))) : 1;
    const unsigned widen = rings > 1 ? 2 : 1;
    auto rule = [&](auto order, unsigned azimuths, Real& l1) {
        constexpr unsigned N = decltype(order)::value;
        azimuths *= widen;
        auto ring = [&](const Real& alpha) {
            const Real ca = cos(alpha), sa = sin(alpha);
            Real sum = 0;
            for (unsigned k = 0; k < azimuths; ++k) {
                const Real phi = two_pi * k / azimuths;
                const vec3<Real> l = ca * lc + sa * (cos(phi) * u + sin(phi) * w);
                const Real nl = l.z();
                if (nl > 0) sum += Model::f(l, v, p) * nl;
            }
            return sum * two_pi / azimuths * sa * radiance;
        };
        Real total = 0;
        for (int i = 0; i < rings; ++i) {
            Real ring_l1 = 0;
            total += gauss<Real, N>::integrate(ring, e * i / rings, e * (i + 1) / rings, &ring_l1);
            l1 += ring_l1;
        }
        return total;
    };
    Real l1 = 0, ignored = 0;
    const Real qa = rule(std::integral_constant<unsigned, 30>{}, 32, l1);
    const Real qb = rule(std::integral_constant<unsigned, 20>{}, 24, ignored);
    return {qa, abs(qa - qb) + 64 * std::numeric_limits<Real>::epsilon() * l1, rings * widen * (30 * 32 + 20 * 24)};
}

}  // namespace normzoo
