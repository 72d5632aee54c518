// What an engine's own tests call: checks of a shader's code against normzoo's exact values,
// each returning a typed verdict with its numbers and their error bounds.
//   check_value                        a number the engine uses (a baked constant, a table entry)
//                                      against normzoo's reference value and its error bound
//   check_energy<Form>                 a form's largest directional albedo over incident angles
//                                      at one value of its parameter, where, and whether it
//                                      conserves energy (docs/conventions.md)
//   check_shader_normalization<Form>   a shader's expression for a form's constant, against the
//                                      exact factor over an exponent range, and the largest
//                                      directional albedo it gives (docs/energy.md)
// Include the header of the form checked (normzoo/brdf/*.hpp) beside this one.
#pragma once
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "albedo.hpp"
#include "quadrature/estimate.hpp"
#include "real.hpp"

namespace normzoo {

// A value checked against a reference known within reference_error: the difference is certain
// to exceed the tolerance (too_far), certain not to (within), or cannot be told (undecided,
// when the reference's own bound straddles the tolerance).
struct value_verdict {
    enum class outcome { within, too_far, undecided };
    double value, reference, reference_error;
    double abs_error;  // |value - reference|
    double rel_error;  // abs_error / |reference| (inf when the reference is 0 and the value is not)
    double tolerance;  // on abs_error
    outcome result;
    bool within() const { return result == outcome::within; }
    std::string describe() const {
        char buf[256];
        std::snprintf(buf, sizeof buf, "%.17g against %.17g +- %.2g: off by %.3g (relative %.3g), %s %.3g", value,
                      reference, reference_error, abs_error, rel_error,
                      result == outcome::within    ? "within"
                      : result == outcome::too_far ? "beyond"
                                                   : "cannot be told from",
                      tolerance);
        return buf;
    }
};

namespace detail {
// The true difference lies in [d - reference_error, d + reference_error].
inline value_verdict decide_value(double value, double reference, double reference_error, double d,
                                  double tolerance) {
    const double rel = reference != 0 ? d / std::abs(reference) : (d == 0 ? 0.0 : INFINITY);
    value_verdict::outcome o = value_verdict::outcome::undecided;
    if (d + reference_error <= tolerance) o = value_verdict::outcome::within;
    else if (d - reference_error > tolerance || !(d == d)) o = value_verdict::outcome::too_far;
    return {value, reference, reference_error, d, rel, tolerance, o};
}
}  // namespace detail

// |value - reference| <= tolerance, decided with the reference's bound.
inline value_verdict check_value(double value, double reference, double reference_error, double tolerance) {
    return detail::decide_value(value, reference, reference_error, std::abs(value - reference), tolerance);
}

// The same against a value with its bound as the library's integrals return it, the difference
// taken in the reference's own precision (a binary128 reference is not first rounded to double).
template <class Real>
value_verdict check_value(double value, const quadrature::estimate<Real>& reference, double tolerance) {
    using std::abs;
    const double d = static_cast<double>(abs(Real(value) - reference.value));
    return detail::decide_value(value, static_cast<double>(reference.value),
                                static_cast<double>(abs(reference.abs_error)), d, tolerance);
}

// The energy sweep's exponents (docs/energy.md): the grid the exponent forms declare
// (brdf::energy_exponents: powers of two to 2048, then 1e4 and 1e5).
inline std::vector<double> default_energy_exponents() {
    return {std::begin(brdf::energy_exponents), std::end(brdf::energy_exponents)};
}

// Incident angles in degrees: every degree from 0 to 89, then towards grazing incidence.
inline std::vector<double> default_energy_angles() {
    std::vector<double> t;
    for (int d = 0; d < 90; ++d) t.push_back(d);
    for (double g : {89.5, 89.9, 89.99}) t.push_back(g);
    return t;
}

// A form's energy at one value of its parameter (n, alpha or r, as the form declares).
struct energy_verdict {
    double value;         // the parameter's value
    double max_albedo;    // the largest directional albedo over the angles checked
    double albedo_error;  // its bound
    double at_theta_deg;  // where (the first of the angles that tie with it within their bounds)
    bool conserving;      // no angle's albedo exceeds 1 by more than its bound
    bool trusted;         // every albedo met the tolerance asked
    std::string describe() const {
        char buf[256];
        std::snprintf(buf, sizeof buf, "largest albedo %.12g +- %.2g at %.6g deg (value %.6g): %s", max_albedo,
                      albedo_error, at_theta_deg, value, conserving ? "conserves energy" : "gains energy");
        return buf;
    }
};

template <class Form>
energy_verdict check_energy(double value, const std::vector<double>& angles = default_energy_angles(),
                            double specular = 1, const albedo_settings& s = {}) {
    const brdf::params<double> p = brdf::params_at<Form>(value, specular);
    energy_verdict v{value, -INFINITY, 0, 0, true, true};
    for (double t : angles) {
        const auto e = albedo<Form>(t, p.n, p.specular, s, p.roughness);
        v.trusted = v.trusted && e.abs_error <= albedo_tolerance(e.value, s.tolerance);
        v.conserving = v.conserving && !(e.value - e.abs_error > 1);
        if (e.value > v.max_albedo + e.abs_error + v.albedo_error)
            v.max_albedo = e.value, v.albedo_error = e.abs_error, v.at_theta_deg = t;
    }
    return v;
}

struct shader_normalization_verdict {
    double max_rel_error;  // the signed relative error of largest magnitude, expression / exact - 1
    double at_n;
    double max_albedo;     // the largest albedo the shader's constant gives over the range
    double albedo_error;   // its bound
    double at_n_albedo, at_theta_deg;
    bool conserving;       // max_albedo - albedo_error <= 1
    bool trusted;          // every albedo within its tolerance
    std::string describe() const {
        char buf[256];
        std::snprintf(buf, sizeof buf,
                      "relative error %.6g at n = %.6g; largest albedo %.12g +- %.2g at n = %.6g, %.6g deg (%s)",
                      max_rel_error, at_n, max_albedo, albedo_error, at_n_albedo, at_theta_deg,
                      conserving ? "conserves energy" : "gains energy");
        return buf;
    }
};

// The exponents a range is swept at: the given grid's points inside it, and both ends (doubles,
// or the decimals a scene writes).
template <class T>
std::vector<T> exponents_in_range(const std::vector<T>& grid, const T& lo, const T& hi) {
    std::vector<T> n{lo};
    for (const T& x : grid)
        if (x > lo && x < hi) n.push_back(x);
    if (hi > lo) n.push_back(hi);
    return n;
}

template <class Form>
shader_normalization_verdict check_shader_normalization(const std::function<double(double)>& expression, double n_lo,
                                                        double n_hi, double specular = 1,
                                                        const std::vector<double>& angles = default_energy_angles(),
                                                        const albedo_settings& s = {}) {
    auto rel = [&](double n) { return expression(n) / static_cast<double>(Form::exact_constant(quad(n))) - 1; };
    // The relative error: 400 log-spaced exponents and the ends, then Brent in ln n around the worst.
    const double a = std::log(std::max(n_lo, 1e-6)), b = std::log(std::max(n_hi, 1e-6));
    std::vector<double> n_grid{n_lo, n_hi};
    for (int i = 0; i <= 400 && b > a; ++i) n_grid.push_back(std::exp(a + (b - a) * i / 400));
    double worst_n = n_lo, worst = rel(n_lo);
    std::size_t k = 0;
    for (std::size_t i = 0; i < n_grid.size(); ++i)
        if (std::abs(rel(n_grid[i])) > std::abs(worst)) worst = rel(n_grid[i]), worst_n = n_grid[i], k = i;
    if (k > 2 && k + 1 < n_grid.size()) {
        const double lo = std::log(n_grid[k - 1]), hi = std::log(n_grid[k + 1]);
        const auto r = boost::math::tools::brent_find_minima([&](double x) { return -std::abs(rel(std::exp(x))); }, lo, hi, 40);
        if (std::abs(rel(std::exp(r.first))) > std::abs(worst)) worst_n = std::exp(r.first), worst = rel(worst_n);
    }
    // The albedo with the shader's constant: the form's albedo times expression / constant.
    shader_normalization_verdict v{worst, worst_n, -INFINITY, 0, 0, 0, true, true};
    auto exponents = exponents_in_range(default_energy_exponents(), n_lo, n_hi);
    exponents.push_back(worst_n);
    for (double n : exponents)
        for (double t : angles) {
            const auto e = albedo<Form>(t, n, specular, s);
            const double scale = expression(n) / static_cast<double>(Form::constant(quad(n)));
            const double value = scale * e.value, error = std::abs(scale) * e.abs_error;
            v.trusted = v.trusted && e.abs_error <= albedo_tolerance(e.value, s.tolerance);
            // (a value above the best by less than both bounds is a tie: the first one stays)
            if (value > v.max_albedo + error + v.albedo_error)
                v.max_albedo = value, v.albedo_error = error, v.at_n_albedo = n, v.at_theta_deg = t;
        }
    v.conserving = v.max_albedo - v.albedo_error <= 1;
    return v;
}

}  // namespace normzoo
