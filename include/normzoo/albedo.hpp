// Directional albedo (docs/method.md, docs/energy.md):
//     rho(t_i) = integral over V in the upper hemisphere of f(L, V) (N.V) d(omega_V),
// with f evaluated from vectors, L at polar angle t_i in the xz-plane.
//
// Coordinates follow the lobe (brdf::lobe_kind): polar angle theta around a pole P and azimuth
// phi from the side of N, so the peak sits at theta = 0 for every incidence:
//   normal  P = N, V = the direction itself
//   mirror  P = R (mirror of L), V = the direction; (R.V)^n vanishes beyond theta = 90 degrees
//   half    P = N, the direction is H, V = 2 (L.H) H - L, d(omega_V) = 4 (L.H) d(omega_H)
// The horizon N.V = 0 is then a curve theta_max(phi) in closed form (both reduce to
// cos t cos x + sin t cos(phi) sin x = 0, x = theta or 2 theta):
//   mirror  theta_max = min(90 deg, atan2(cos t, -sin t cos phi))
//   half    theta_max = atan2(cos t, -sin t cos phi) / 2
// atan2 keeps it exact at grazing incidence, where cos t is tiny and the cut comes within
// cos t / 4 of the lobe's centre for phi near 180 degrees.
//
// Scales the integrand has, and how each is met (quadrature/adaptive.hpp does the rest):
//   the lobe, cos^n theta: width 1/sqrt(n+1); truncated where it falls below e^-150
//   a pole of 1/(L.H) at distance atan2(cos t, sin t |cos phi|) from theta = 0 (half lobes)
//   the cut theta_max, and in phi a transition of width ~cot t around phi = 90 degrees
//   a square root at the cut where f carries 1/sqrt(N.V) (Ward): theta = end (2x - x^2) there
// Both integrals are graded: a plain panel near 0, then u = ln(x) in panels of width <= 2,
// where each of these features is O(1) wide whatever n and t are.
//
// Precision per node. Near grazing incidence f(L, V) is ill-conditioned in V: with V a unit
// vector, L + V ~ 2 (L.H) H carries V's rounding eps / (L.H), so 1/(L.H)^3 errs by ~eps/(L.H)^2
// (2e-8 in double at t = 89.99 deg) and (N.H)^n by ~n theta eps / (L.H). Each node estimates
// that condition number and is evaluated in double, long double or binary128, whichever keeps
// it well below the tolerance; the node's error (condition x eps x value) enters the bound.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "brdf/brdf.hpp"
#include "detail/kinks_vh.hpp"
#include "detail/sign_changes.hpp"
#include "geometry.hpp"
#include "lobe_albedo.hpp"
#include "quadrature/adaptive.hpp"
#include "quadrature/estimate.hpp"
#include "quadrature/graded.hpp"
#include "real.hpp"

namespace normzoo {

struct albedo_settings {
    double tolerance = 1e-10;      // on |rho - truth|, absolute up to rho = 1 and relative beyond
    std::size_t max_panels = 400;  // per adaptive integral
};

// The accuracy asked of an albedo: absolute where rho <= 1 (the energy question), relative
// where a model blows up at grazing incidence (rho ~ 1 / cos t).
template <class Real>
Real albedo_tolerance(const Real& rho, double tolerance) {
    using std::abs;
    return Real(tolerance) * (abs(rho) > 1 ? abs(rho) : Real(1));
}

// An incident direction in Real from its angle in binary128 (cos t keeps its relative accuracy
// up to 89.999... through degrees_angle; each type then rounds the same direction once).
template <class Real>
struct incidence {
    Real cos_t, sin_t;
    vec3<Real> l;
    explicit incidence(const degrees_angle<quad>& t) : cos_t(static_cast<Real>(t.cos_t)), sin_t(static_cast<Real>(t.sin_t)) {
        l = vec3<Real>(sin_t, 0, cos_t);
    }
};

namespace detail {

// The albedo integrand of one model at one incidence, in one number type.
template <class Model, class T>
struct albedo_integrand {
    Model model;  // the form: an empty type, or one whose parts are chosen at run time (microfacet/composition.hpp)
    incidence<T> in;
    vec3<T> pole, e1, e2;
    brdf::params<T> p;

    albedo_integrand(const degrees_angle<quad>& theta, double n, double specular, double roughness = 0,
                     const Model& m = Model{})
        : model(m), in(theta), p{T(n), T(specular), T(roughness)} {
        e1 = vec3<T>(1, 0, 0);
        e2 = vec3<T>(0, 1, 0);
        pole = normal<T>();
        if (Model::lobe == brdf::lobe_kind::mirror) {
            pole = vec3<T>(-in.sin_t, 0, in.cos_t);  // R
            e1 = vec3<T>(in.cos_t, 0, in.sin_t);     // towards N, orthogonal to R
        }
    }

    // f (N.V) times the Jacobian and sin(theta): the integrand at (theta, phi), given the
    // cosine and sine of theta. H (or V) only has to be as accurate as the node's position,
    // while V = 2 (L.H) H - L has to be formed in T. Coefficient by coefficient, as geometry.hpp
    // says why.
    T operator()(const T& c, const T& s, double cos_phi, double sin_phi) const {
        const T cp(cos_phi), sp(sin_phi);
        const vec3<T> d(c * pole.x() + s * (cp * e1.x() + sp * e2.x()), c * pole.y() + s * (cp * e1.y() + sp * e2.y()),
                        c * pole.z() + s * (cp * e1.z() + sp * e2.z()));
        vec3<T> v = d;
        T jacobian = 1;
        if constexpr (Model::lobe == brdf::lobe_kind::half) {
            const T lh = in.l.dot(d);
            const T twice = 2 * lh;
            v = vec3<T>(twice * d.x() - in.l.x(), twice * d.y() - in.l.y(), twice * d.z() - in.l.z());
            jacobian = 4 * lh;
        }
        const T nv = v.z();
        if (!(nv > 0)) return T(0);
        return model.f(in.l, v, p) * nv * jacobian * s;
    }

    // A bound on the relative error of the integrand at a node, in units of the number type's
    // epsilon, from L.H and N.V at the node. N.V, formed from V, errs by a few ulps absolutely:
    // ~eps / (N.V) relatively, large along the horizon cut. Half lobes: V's rounding turns
    // H = (L + V)/|L + V| by ~2 eps / (L.H), which moves (N.H)^n by n tan(theta) times that,
    // 1/(L.H)^k by k/(L.H) times that, and Schlick's term at F0 by 5 min(1/F0, 1/(1 - L.H))
    // times the change of L.H. Mirror lobes: 1 - R.V errs by ~eps theta, the exponent n ln(R.V) by ~n tan(theta) eps.
    static double condition(double theta, double c, double lh, double nv, double n, double specular) {
        double k = 16 + 4 / nv;
        if constexpr (Model::lobe == brdf::lobe_kind::half) {
            double turn = 8 + 8 * n * theta / c + 8 * Model::inverse_lh_power / lh;
            // (1 - F0)(1 - L.H)^4 / (F0 + (1 - F0)(1 - L.H)^5) is below both: finite at F0 = 0 (B)
            if (Model::fresnel && specular < 1) turn += 32 * std::min(1 / specular, 1 / std::max(1 - lh, eps<double>()));
            k += turn / lh;
        } else {
            k += 4 * n * theta / c;
        }
        return k;
    }
};

// The polar angles theta in (0, end) of H at azimuth phi where V.H = cos t cos theta + sin t
// sin theta cos phi equals one of the values kink_vm(cos t, cos theta, vm) writes (+inf: none).
template <class KinkVm>
void kinks_in_theta(KinkVm kink_vm, double cos_t, double sin_t, double cos_phi, double end, std::vector<double>& out) {
    // at most Cook-Torrance's 3 and a critical angle's one
    auto differences = [&](double theta, double d[4]) {
        const double c = std::cos(theta);
        const int n = kink_vm(cos_t, c, d);
        const double vh = cos_t * c + sin_t * std::sin(theta) * cos_phi;
        for (int i = 0; i < 4; ++i) d[i] = i < n ? d[i] - vh : std::numeric_limits<double>::infinity();
    };
    if (!(end > 0)) return;
    constexpr int cells = 128;
    std::vector<double> grid(cells + 1);
    for (int g = 0; g <= cells; ++g) grid[std::size_t(g)] = end * g / cells;
    const std::vector<double> roots = sign_changes<4>(differences, grid);
    out.insert(out.end(), roots.begin(), roots.end());
}

// The polar angle beyond which the lobe's cos^n falls below e^-150 of its peak: pi/2 where the
// lobe is not cut (a lobe about N, no exponent, or tails heavier than e^(-n theta^2)).
template <class Model>
double albedo_lobe_end(double n) {
    using std::asin;
    using std::expm1;
    using std::sqrt;
    double lobe_end = boost::math::constants::half_pi<double>();
    if (Model::lobe != brdf::lobe_kind::normal && n > 0 && !brdf::heavy_tailed<Model>) {
        const double one_minus_cos = -expm1(-150 / n);
        if (one_minus_cos < 0.5) lobe_end = 2 * asin(sqrt(one_minus_cos / 2));
    }
    return lobe_end;
}

// The generic albedo integral of one model at one incidence (the coordinates and scales at the top
// of this file): its nodes, the inner integral in theta at one azimuth, the outer one in the azimuth.
template <class Model>
struct albedo_integral {
    using estimate = quadrature::estimate<double>;
    static constexpr brdf::lobe_kind kind = Model::lobe;

    const Model& model;
    double n, specular, tol;
    std::size_t max_panels;
    albedo_integrand<Model, double> in_double;
    albedo_integrand<Model, long double> in_long;
    albedo_integrand<Model, quad> in_quad;
    double cos_t, sin_t;
    double width, lobe_end;  // the lobe's width, and where it is cut (albedo_lobe_end)
    // The node errors' budgets: the weights of all nodes add up to the area of the (theta, psi)
    // domain, at most pi^2, so the node errors total at most tol/4 x albedo + pi^2 x tol/64 < tol/2
    // x max(1, albedo).
    double relative_budget, absolute_budget;

    albedo_integral(const degrees_angle<quad>& theta, double n_, double specular_, const albedo_settings& s,
                    double roughness, const Model& m)
        : model(m), n(n_), specular(specular_), tol(s.tolerance), max_panels(s.max_panels),
          in_double(theta, n, specular, roughness, model), in_long(theta, n, specular, roughness, model),
          in_quad(theta, n, specular, roughness, model), cos_t(in_double.in.cos_t), sin_t(in_double.in.sin_t),
          width(1 / std::sqrt(n + 1)), lobe_end(albedo_lobe_end<Model>(n)), relative_budget(tol / 4),
          absolute_budget(tol / 64) {}

    // One node: evaluated in double, then again in long double or binary128 if its error bound
    // (condition number x eps x value) is not small, relative to the value or absolutely.
    estimate node(double theta, double cos_phi, double sin_phi) const {
        using std::abs;
        using std::cos;
        using std::sin;
        using integrand = albedo_integrand<Model, double>;
        // L.H and N.V at the node (for the half lobe the direction is H; else it is V)
        const double c = cos(theta), st = sin(theta), along = st * cos_phi;
        const double lh = cos_t * c + sin_t * along;
        const double nv = kind == brdf::lobe_kind::half     ? 2 * lh * c - cos_t
                          : kind == brdf::lobe_kind::mirror ? cos_t * c + sin_t * along
                                                            : c;
        const double condition = integrand::condition(theta, c, lh, abs(nv), n, specular);
        auto small = [&](double value, double unit) {
            const double e = condition * unit * abs(value);
            return e <= relative_budget * abs(value) || e <= absolute_budget;
        };
        double value = in_double(c, st, cos_phi, sin_phi), unit = eps<double>();
        if (!small(value, unit)) {
            // long double trigonometry serves both: the node's position is a double
            const long double cl = std::cos(static_cast<long double>(theta));
            const long double sl = std::sin(static_cast<long double>(theta));
            value = static_cast<double>(in_long(cl, sl, cos_phi, sin_phi)), unit = eps<long double>();
            if (!small(value, unit))
                value = static_cast<double>(in_quad(quad(cl), quad(sl), cos_phi, sin_phi)),
                unit = static_cast<double>(eps<quad>());
        }
        // The value's own error: its conditioning, plus rounding of the result to double.
        return {value, (condition * unit + eps<double>()) * abs(value), 1};
    }

    // The horizon's polar angle theta_max at azimuth phi (in closed form: the top of this file).
    double horizon(double cos_phi) const {
        using std::atan2;
        const double half_pi = boost::math::constants::half_pi<double>();
        double theta_max = half_pi;
        if (kind == brdf::lobe_kind::mirror) theta_max = std::min(half_pi, atan2(cos_t, -sin_t * cos_phi));
        if (kind == brdf::lobe_kind::half) theta_max = atan2(cos_t, -sin_t * cos_phi) / 2;
        return theta_max;
    }

    // The kinks of f in theta at azimuth phi, which the inner integral makes breakpoints.
    std::vector<double> theta_kinks(double cos_phi, double theta_max) const {
        using std::atan2;
        // max(N.L, N.V): N.V = N.L at tan theta = tan t cos phi (from (L.H)(N.H) = N.L), for cos phi > 0
        std::vector<double> kinks;
        if constexpr (brdf::kink_where_cosines_equal<Model> && kind == brdf::lobe_kind::half)
            if (cos_phi > 0) kinks.push_back(atan2(sin_t * cos_phi, cos_t));
        // about N, the direction's own polar angle is theta: N.V = N.L at theta = t
        if constexpr (brdf::kink_where_cosines_equal<Model> && kind == brdf::lobe_kind::normal) {
            const double t = atan2(sin_t, cos_t);
            if (t > 0 && t < theta_max) kinks.push_back(t);
        }
        // A min() in f (Cook-Torrance's G), or F's critical angle: where V.H(theta) = cos t cos
        // theta + sin t sin theta cos phi meets the values kink_vm gives at cos theta, or the
        // critical V.H, found by the sign changes of the difference on a grid and bisection.
        if constexpr (brdf::kinks_at_run_time<Model> && kind == brdf::lobe_kind::half) {
            const auto kink_vm = model.kink_vm();
            const double critical = model.critical_vh();
            if (kink_vm || critical > 0)
                detail::kinks_in_theta([&](double nv, double nm, double* vm) { return detail::kinks_vh(kink_vm, critical, nv, nm, vm, 4); },
                                       cos_t, sin_t, cos_phi, theta_max, kinks);
        }
        return kinks;
    }

    // The inner integral over theta in (0, end) by Kronrod Points-point panels, graded from
    // `smallest` (docs/energy.md, "The scales, and grading").
    template <unsigned Points>
    estimate graded_in_theta(double cos_phi, double sin_phi, double end, double theta_max, double smallest,
                             const std::vector<double>& kinks) const {
        auto g = [&](double theta) { return node(theta, cos_phi, sin_phi); };
        // f N.V ~ sqrt(N.V) at the cut (Ward): theta = end (2x - x^2), x in [0, 1], where
        // end - theta = end (1 - x)^2 makes it smooth in x; near 0, theta ~ 2 end x keeps the
        // lobe's grading.
        if constexpr (brdf::sqrt_at_horizon<Model>) {
            if (end == theta_max && kinks.empty()) {
                auto in_x = [&](double x) {
                    const double one_minus = 1 - x;
                    estimate e = g(end * x * (1 + one_minus));
                    const double jacobian = 2 * end * one_minus;
                    return estimate{e.value * jacobian, e.abs_error * jacobian, e.evaluations};
                };
                return quadrature::graded_integral<double, Points>(in_x, smallest / (8 * end), 1.0, tol / 32, tol / 8,
                                                                   max_panels, false);
            }
        }
        return quadrature::graded_integral<double, Points>(g, smallest / 4, end, tol / 32, tol / 8, max_panels, false, kinks);
    }

    // The integral over theta at one azimuth, up to the horizon or the lobe's cut.
    estimate inner(double cos_phi, double sin_phi) const {
        using std::abs;
        using std::atan2;
        const double theta_max = horizon(cos_phi);
        const double end = std::min(lobe_end, theta_max);
        double smallest = std::min(width, end);
        if (kind == brdf::lobe_kind::half) smallest = std::min(smallest, atan2(cos_t, sin_t * abs(cos_phi)));
        const std::vector<double> kinks = theta_kinks(cos_phi, theta_max);
        // Kronrod 31 in theta, or 15 where few digits are asked: on the panels the lobe sets, 31
        // points meet 1e-10 with few bisections, and 15 meet 1e-8 with fewer evaluations than 31
        // (docs/energy.md, "The scales, and grading").
        estimate r = tol >= 1e-8 ? graded_in_theta<15>(cos_phi, sin_phi, end, theta_max, smallest, kinks)
                                 : graded_in_theta<31>(cos_phi, sin_phi, end, theta_max, smallest, kinks);
        if (end < theta_max) {  // the lobe's tail: below e^-150 of the peak; 1/cos t for what else can grow
            const estimate at_end = node(end, cos_phi, sin_phi);
            r.abs_error += abs(at_end.value) * (theta_max - end) * (16 + 16 / cos_t);
            r.evaluations += 1;
        }
        return r;
    }

    // The configuration is symmetric in phi -> -phi: twice the integral over [0, pi], taken as
    // the two sides of phi = 90 degrees in psi = |phi - 90 deg|, graded at the transition width.
    estimate over_azimuth() const {
        using std::cos;
        using std::sin;
        const double half_pi = boost::math::constants::half_pi<double>();
        const double psi0 = cos_t / sin_t / 4;
        estimate total{0, 0, 0};
        for (int sign : {-1, 1}) {
            auto outer = [&](double psi) {
                // phi = 90 deg + sign psi: cos phi = -sign sin psi, sin phi = cos psi
                estimate e = inner(-sign * sin(psi), cos(psi));
                e.value *= 2;
                e.abs_error *= 2;
                return e;
            };
            const double x0 = psi0 < half_pi / 32 ? psi0 : half_pi;
            const auto side = quadrature::graded_integral<double, 15>(outer, x0, half_pi, tol / 4, tol / 4, max_panels);
            total.value += side.value;
            total.abs_error += side.abs_error;
            total.evaluations += side.evaluations;
        }
        return total;
    }
};

}  // namespace detail

// roughness: for the forms indexed by one (brdf/ward.hpp, brdf/disney.hpp, microfacet/composition.hpp); their n
// places the nodes only (the Phong-Beckmann exponent of their lobe, or 0 for a lobe about N). `model`: the
// form itself, for a form whose parts are chosen at run time (a composition); the others are empty types. The incident angle is given
// in binary128 (degrees_of of a decimal, or a double's degrees_angle); the parameters are the
// doubles given (inputs typed as decimals: albedo_input.hpp).
template <class Model>
quadrature::estimate<double> albedo(const degrees_angle<quad>& theta, double n_in, double specular = 1,
                                    const albedo_settings& s = {}, double roughness = 0, const Model& model = Model{}) {
    using std::abs;
    // Forms with Blinn-Phong's lobe: the integral in the lobe's mass (lobe_albedo.hpp), where validated.
    if constexpr (has_blinn_phong_lobe<Model>) {
        const double cos_t = static_cast<double>(theta.cos_t), sin_t = static_cast<double>(theta.sin_t);
        if (in_lobe_mass(n_in, cos_t)) return lobe_albedo<Model>(cos_t, sin_t, n_in, specular, s.tolerance, s.max_panels);
    }
    const double n = Model::has_exponent ? n_in : 0.0;
    const detail::albedo_integral<Model> integral(theta, n, specular, s, roughness, model);
    // At normal incidence an isotropic form's inner integral is the same at every azimuth: the
    // albedo is 2 pi times it, one integral in theta.
    if (integral.sin_t == 0 && !brdf::anisotropic(model)) {
        const double two_pi = boost::math::constants::two_pi<double>();
        const quadrature::estimate<double> e = integral.inner(1.0, 0.0);
        return {two_pi * e.value, two_pi * e.abs_error + 2 * eps<double>() * two_pi * abs(e.value), e.evaluations};
    }
    return integral.over_azimuth();
}

// At an incident angle in degrees given as a double: the angle that double holds.
template <class Model>
quadrature::estimate<double> albedo(double theta_deg, double n, double specular = 1, const albedo_settings& s = {},
                                    double roughness = 0) {
    return albedo<Model>(degrees_angle<quad>(theta_deg), n, specular, s, roughness);
}

}  // namespace normzoo
