// Where the textbook formulations break (docs/stability.md): each integrand of the stress table computed
// the way a first attempt would, in double, against the same references. A formulation "breaks"
// at the first parameter (in the direction of the stress) where it loses half of double's digits
// (relative error above 1e-8), returns zero or a non-finite value; the record says what
// normzoo does instead. These records are findings, not checks: they have no "pass".
#pragma once
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "stability.hpp"

namespace verify {

namespace detail {

// One naive formulation over a stress grid: its relative error at each point.
struct naive_sweep {
    const char* family;
    std::string integrand;
    const char* formulation;
    const char* instead;  // what normzoo does
    const char* parameter;
    std::vector<double> at;
    std::function<double(double)> value;      // the naive value at a grid point
    std::function<long double(double)> reference;  // the reference there (long double: its range holds E ~ 1e-647)
    std::function<bool(double)> reported_ok = {};  // false where the naive rule's own error claim is below its error
};

inline record naive_record(const naive_sweep& s) {
    std::optional<double> breaks_at, error_there, confidently_wrong_at;
    std::string how;
    double worst = 0;
    for (double x : s.at) {
        const double v = s.value(x);
        const long double ref = s.reference(x);
        const double rel = static_cast<double>(ref != 0 ? std::abs(v - ref) / std::abs(ref) : std::abs(v));
        const bool finite = std::isfinite(v);
        worst = finite ? std::max(worst, rel) : INFINITY;
        if (s.reported_ok && !confidently_wrong_at && !s.reported_ok(x)) confidently_wrong_at = x;
        if (!breaks_at && (!finite || rel > 1e-8 || (v == 0 && ref != 0))) {
            breaks_at = x;
            if (finite) error_there = rel;
            how = !finite ? "non-finite" : v == 0 ? "returns 0" : "inaccurate";
        }
    }
    record r{"stability-naive", {}};
    r.set("family", std::string(s.family))
        .set("integrand", s.integrand)
        .set("formulation", std::string(s.formulation))
        .set("parameter", std::string(s.parameter))
        .set("breaks_at", optional_field(breaks_at))
        .set("how", breaks_at ? field_value(how) : field_value(nullptr))
        .set("rel_error_there", optional_field(error_there))
        .set("worst_rel_error", optional_field(std::isfinite(worst) ? std::optional<double>(worst) : std::nullopt))
        .set("confidently_wrong_at", optional_field(confidently_wrong_at))
        .set("normzoo_instead", std::string(s.instead));
    return r;
}

template <class Row>
void zoo_naive(std::vector<naive_sweep>& out) {
    if (!Row::has_exponent) return;
    const std::vector<double> grid = stability_exponents();
    auto closed = [](double n) { return static_cast<long double>(Row::closed_form(wide(n))); };
    // pow of a cosine: cos^n carries n times the cosine's rounding
    out.push_back({"zoo", Row::id, "pow(cos theta, n) (in normzoo's own rule)",
                   "cos^n = exp(-n s) with s = -ln cos theta the integration variable: no power of a rounded cosine",
                   "n", grid,
                   [](double n) {
                       return zoo_norm_1d_of<Row, double>(n, [n](const quadrature::lobe_point<double>& p) {
                           return std::pow(p.cos_theta, n) * Row::weight(p.cos_theta, p.sin_theta);
                       }).norm;
                   },
                   closed});
    // sin from 1 - cos^2: the lobe sits at theta ~ 1/sqrt(n), where 1 - cos^2 cancels
    out.push_back({"zoo", Row::id, "sin theta = sqrt(1 - cos^2 theta) (in normzoo's own rule)",
                   "sin theta = sqrt(-e (2 + e)) with e = expm1(-s): no cancellation near the peak",
                   "n", grid,
                   [](double n) {
                       return zoo_norm_1d_of<Row, double>(n, [](const quadrature::lobe_point<double>& p) {
                           return p.power * Row::weight(p.cos_theta, std::sqrt(1 - p.cos_theta * p.cos_theta));
                       }).norm;
                   },
                   closed});
    // one rule over the whole interval in t, as a CAS or SciPy user would write it
    auto g = [](double n) {
        return [n](double t) {
            const double a = Row::lobe_alpha;
            return std::pow(std::cos(a * t), n) * Row::weight(std::cos(a * t), std::sin(a * t));
        };
    };
    auto tanh_sinh = [g](double n, double& reported) {
        boost::math::quadrature::tanh_sinh<double> rule;
        return rule.integrate(g(n), 0.0, pi<double>() / 2, std::sqrt(eps<double>()), &reported);
    };
    auto gauss_kronrod = [g](double n, double& reported) {
        return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(g(n), 0.0, pi<double>() / 2, 15,
                                                                              std::sqrt(eps<double>()), &reported);
    };
    const char* instead = "Laplace variable x = (n + m) s: the lobe is e^-x on fixed panels whatever n";
    auto whole = [&](const char* name, auto rule) {
        auto norm = [rule](double n) {
            double reported = 0;
            return 1 / (2 * pi<double>() * rule(n, reported));
        };
        // its own error claim, carried to 1/(2 pi I) to first order
        auto honest = [rule, closed](double n) {
            double reported = 0;
            const double i = rule(n, reported);
            const long double truth = 1 / (2 * pi<long double>() * closed(n));
            return !(std::abs(i - truth) > reported + 4 * eps<double>() * std::abs(truth));
        };
        out.push_back({"zoo", Row::id, name, instead, "n", grid, norm, closed, honest});
    };
    whole("Boost tanh_sinh over the whole interval on pow(cos, n) w", tanh_sinh);
    whole("Boost gauss_kronrod 61 (adaptive) over the whole interval on pow(cos, n) w", gauss_kronrod);
}

// The albedo by one fixed product rule over the whole hemisphere of V (Gauss-Legendre 64 x 64),
// with L from the angle in radians: the rule cannot see a lobe narrower than its nodes.
template <class Model>
void albedo_naive(std::vector<naive_sweep>& out) {
    if (!Model::has_exponent) return;
    for (double n : stability_albedo_exponents()) {
        auto value = [n](double theta) {
            using rule = boost::math::quadrature::gauss<double, 64>;
            const double t = theta * pi<double>() / 180;
            const vec3<double> l(std::sin(t), 0, std::cos(t));
            const brdf::params<double> p{n, 1};
            auto in_phi = [&](double th) {
                return rule::integrate([&](double ph) {
                    const vec3<double> v(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
                    return Model::f(l, v, p) * std::cos(th) * std::sin(th);
                }, 0.0, pi<double>()) * 2;
            };
            return rule::integrate(in_phi, 0.0, pi<double>() / 2);
        };
        auto reference = [n](double theta) -> long double {
            if (theta == 0) return static_cast<long double>(Model::albedo_at_normal(brdf::params<quad>{quad(n)}));
            return albedo<Model>(theta, n).value;
        };
        out.push_back({"albedo", std::string(Model::id) + ", n = " + fmt("%g", n),
                       "Gauss-Legendre 64 x 64 over the hemisphere, L from radians",
                       "coordinates centred on the lobe, horizon cut in closed form (atan2), graded panels, "
                       "per-node precision by condition number",
                       "theta_deg", stability_angles(), value, reference});
    }
}

// The sphere's irradiance from pi (1 - cos^2 b) cos t, cos b = sqrt(1 - (r0/r)^2), in double;
// and the right formula pi (r0/r)^2 cos t, but in double's range.
inline void irradiance_naive(std::vector<naive_sweep>& out) {
    auto exact = [](double ratio) {
        const auto cap = light_cap<quad>::sphere(quad(ratio));
        return static_cast<long double>(cap_irradiance_closed_form(cap, degrees_angle<quad>(0)).value);
    };
    out.push_back({"irradiance", "sphere, tilt 0", "pi (1 - cos^2 b), cos b = sqrt(1 - (r0/r)^2), double",
                   "sin b = r0/r directly, never 1 - cos^2", "r0/r", stability_ratios(),
                   [](double ratio) {
                       const double c = std::sqrt(1 - ratio * ratio);
                       return pi<double>() * (1 - c * c);
                   },
                   exact});
    out.push_back({"irradiance", "sphere, tilt 0", "pi (r0/r)^2, double",
                   "binary128, whose exponent range holds (5e-324)^2", "r0/r", stability_ratios(),
                   [](double ratio) { return pi<double>() * ratio * ratio; }, exact});
}

}  // namespace detail

inline std::vector<record> stability_naive_table(unsigned jobs) {
    std::vector<detail::naive_sweep> sweeps;
    for_each_zoo_row([&](auto row) { detail::zoo_naive<decltype(row)>(sweeps); });
    for_each_zoo_brdf([&](auto form) { detail::albedo_naive<decltype(form)>(sweeps); });
    detail::irradiance_naive(sweeps);
    std::vector<record> out(sweeps.size());
    detail::parallel_for(sweeps.size(), jobs, [&](std::size_t i) { out[i] = detail::naive_record(sweeps[i]); });
    return out;
}

inline table_info stability_naive_info() {
    return {"stability-naive",
            "Where the textbook formulations break, and what normzoo does instead",
            {"each formulation in double over the stress grid of the stability table, against the same references",
             "breaks_at: the first grid point where the relative error exceeds 1e-8 (half of double's digits), the "
             "value is 0 or not finite; null if never",
             "confidently_wrong_at: the first point where the rule's own error estimate is below its true error",
             "findings, not checks: these records have no pass"},
            {"family", "integrand", "formulation", "breaks_at", "how", "rel_error_there", "confidently_wrong_at",
             "normzoo_instead"}};
}

}  // namespace verify
