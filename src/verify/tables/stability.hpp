// The stress table (docs/stability.md): every integrand across its whole domain, each value checked
// against a reference computed another way, or refused with the reason it has no answer in its
// number type. Exponents from 0 to 1e9, incidence to 90 - 1e-6 degrees, r0/r down to the
// smallest subnormal double. stability_naive.hpp shows where the textbook formulations break.
#pragma once
#include <boost/math/special_functions/fpclassify.hpp>
#include <cmath>
#include <functional>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <normzoo/albedo.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/irradiance.hpp>
#include <normzoo/real.hpp>
#include <normzoo/wide.hpp>
#include <normzoo/registry.hpp>

#include "../record.hpp"
#include "zoo.hpp"

namespace verify {

// The stress grids: each parameter to the ends of its range.
inline std::vector<double> stability_exponents() {
    return {0, 1e-12, 1e-6, 0.1, 1, 10, 100, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
}
inline std::vector<double> stability_angles() { return {0, 89, 89.99, 89.9999, 90 - 1e-6}; }
inline std::vector<double> stability_albedo_exponents() { return {16, 1e6}; }
inline std::vector<double> stability_ratios() {
    // 1e-160: r0^2 underflows a double; 1e-310 and 5e-324: the ratio itself is subnormal
    return {1e-1, 1e-4, 1e-8, 1e-16, 1e-100, 1e-160, 1e-300, 1e-308, 1e-310, 5e-324};
}
inline std::vector<double> stability_tilts() { return {0, 60, 90}; }

namespace detail {

inline record stability_record(const char* family, const std::string& integrand, const char* parameter, double at,
                               const std::string& setting, const char* type) {
    record r{"stability", {}};
    r.set("family", std::string(family))
        .set("integrand", integrand)
        .set("parameter", std::string(parameter))
        .set("at", at)
        .set("setting", setting)
        .set("number_type", std::string(type));
    return r;
}

// A value checked against a reference: pass when |value - reference| <= estimate + the
// reference's own bound, and the value is finite.
template <class T>
void set_checked(record& r, const T& value, const T& estimate, const T& reference, const T& reference_bound,
                 const char* reference_kind, int digits) {
    using std::abs;
    const T scale = reference != 0 ? abs(reference) : T(1);
    const T true_error = abs(value - reference);
    const bool finite = boost::math::isfinite(value) && boost::math::isfinite(estimate);
    r.set("status", std::string("ok"))
        .set("value", to_decimal(value, digits))
        .set("reference", to_decimal(reference, digits))
        .set("reference_kind", std::string(reference_kind))
        .set("rel_error", static_cast<double>(true_error / scale))
        .set("error_estimate", static_cast<double>(estimate / scale))
        .set("reason", nullptr)
        .set("pass", finite && true_error <= estimate + reference_bound);
}

inline void set_refused(record& r, const std::string& reason, bool justified) {
    r.set("status", std::string("refused"))
        .set("value", nullptr)
        .set("reference", nullptr)
        .set("reference_kind", nullptr)
        .set("rel_error", nullptr)
        .set("error_estimate", nullptr)
        .set("reason", reason)
        .set("pass", justified);
}

inline std::string fmt(const char* f, double x) {
    char b[64];
    std::snprintf(b, sizeof b, f, x);
    return b;
}

// Zoo: 1 / integral by the lobe rule in binary128 and in double, against the closed form in
// 50 digits.
template <class Row>
std::vector<record> zoo_stability(double n) {
    const wide closed = Row::closed_form(wide(n));
    std::vector<record> out;
    const std::string setting = Row::has_exponent ? "" : "no exponent";
    {
        auto r = stability_record("zoo", Row::id, "n", n, setting, "binary128");
        const auto e = zoo_norm_1d<Row>(n);
        const wide v(e.norm);
        set_checked<wide>(r, v, wide(e.rel_error) * abs(v), closed, wide(0), "closed form, 50 digits", 34);
        out.push_back(std::move(r));
    }
    {
        auto r = stability_record("zoo", Row::id, "n", n, setting, "double");
        const auto e = zoo_norm_1d<Row, double>(n);
        const wide v(e.norm);
        set_checked<wide>(r, v, wide(e.rel_error) * abs(v), closed, wide(0), "closed form, 50 digits", 17);
        out.push_back(std::move(r));
    }
    return out;
}

// Albedo: at normal incidence against the hand-derived closed form, for Lambert against 1 at
// every angle, elsewhere against the same integrator at a 100x tighter tolerance (no closed
// form is known there).
template <class Model>
record albedo_stability(double theta, double n) {
    using std::abs;
    auto r = stability_record("albedo", Model::id, "theta_deg", theta, Model::has_exponent ? fmt("n = %g", n) : "",
                              "double");
    const auto e = albedo<Model>(theta, n);
    if (theta == 0 || !Model::has_exponent) {
        const double closed = static_cast<double>(Model::albedo_at_normal(brdf::params<quad>{quad(n)}));
        set_checked<double>(r, e.value, e.abs_error, closed, 2 * eps<double>() * abs(closed),
                            theta == 0 ? "closed form at normal incidence" : "closed form (1 at every angle)", 17);
    } else {
        albedo_settings tight;
        tight.tolerance = albedo_settings{}.tolerance / 100;
        const auto ref = albedo<Model>(theta, n, 1, tight);
        set_checked<double>(r, e.value, e.abs_error, ref.value, ref.abs_error, "same integrator, tolerance 1e-12", 17);
    }
    return r;
}

// Irradiance: binary128 quadrature against the closed form (both in binary128, computed
// independently); in double, refused where E / L is below the normal range of a double.
inline std::vector<record> irradiance_stability(light_kind kind, double ratio, double tilt) {
    const auto cap = light_cap<quad>::of(kind, quad(ratio));
    const degrees_angle<quad> t(tilt);
    const auto q = cap_irradiance(cap, t);
    const auto closed = cap_irradiance_closed_form(cap, t);
    const std::string setting = fmt("tilt %g deg", tilt);
    std::vector<record> out;
    auto r = stability_record("irradiance", light_name(kind), "r0/r", ratio, setting, "binary128");
    set_checked<quad>(r, q.value, q.abs_error, closed.value, closed.abs_error, "closed form, binary128", 34);
    out.push_back(std::move(r));
    auto d = stability_record("irradiance", light_name(kind), "r0/r", ratio, setting, "double");
    const quad smallest = std::numeric_limits<double>::min();
    if (closed.value != 0 && abs(closed.value) < smallest) {
        set_refused(d, "E/L = " + to_decimal(closed.value, 3) + " is below the smallest normal double (2.2e-308): "
                       "no double answer; binary128 carries it",
                    abs(q.value) < smallest);
    } else {
        // the binary128 value rounded to double: its bound plus half an ulp
        const double v = static_cast<double>(q.value);
        set_checked<quad>(d, quad(v), q.abs_error + quad(eps<double>() * std::abs(v)), closed.value, closed.abs_error,
                          "closed form, binary128", 17);
    }
    out.push_back(std::move(d));
    return out;
}

}  // namespace detail

inline std::vector<record> stability_table(unsigned jobs) {
    std::vector<std::function<std::vector<record>()>> cases;
    // the slow cases (albedos near grazing) first, so that the threads finish together
    for_each_zoo_brdf([&](auto form) {
        using Model = decltype(form);
        for (double n : Model::has_exponent ? stability_albedo_exponents() : std::vector<double>{0})
            for (double theta : stability_angles())
                cases.push_back([theta, n] { return std::vector<record>{detail::albedo_stability<Model>(theta, n)}; });
    });
    for_each_zoo_row([&](auto row) {
        using Row = decltype(row);
        for (double n : Row::has_exponent ? stability_exponents() : std::vector<double>{0})
            cases.push_back([n] { return detail::zoo_stability<Row>(n); });
    });
    for (auto kind : {light_kind::sphere, light_kind::disk})
        for (double tilt : stability_tilts())
            for (double ratio : stability_ratios())
                cases.push_back([=] { return detail::irradiance_stability(kind, ratio, tilt); });
    std::vector<std::vector<record>> parts(cases.size());
    detail::parallel_for(cases.size(), jobs, [&](std::size_t i) { parts[i] = cases[i](); });
    std::vector<record> out;
    for (auto& p : parts)
        for (auto& r : p) out.push_back(std::move(r));
    return out;
}

inline table_info stability_info() {
    table_info info{
        "stability",
        "Every integrand across its whole domain: checked against a reference, or refused with the reason",
        {"zoo: 1/integral by the lobe rule (lobe.hpp) in binary128 and in double, n = 0, 1e-12, 1e-6, 0.1, 1, "
         "10, ..., 1e9; reference: the closed form in 50 digits (cpp_bin_float_50)",
         "albedo: every BRDF form at theta = 0, 89, 89.99, 89.9999, 90 - 1e-6 degrees, n = 16 and 1e6, tolerance "
         "1e-10; reference: the closed form at normal incidence (and 1 for Lambert at every angle), elsewhere "
         "the same integrator at tolerance 1e-12",
         "irradiance: sphere and disk, r0/r = 1e-1 to 1e-308 and the subnormal doubles 1e-310 and 5e-324, tilt "
         "0, 60, 90 degrees, by quadrature in binary128; reference: the closed form in binary128; in double, "
         "refused where E/L is below the smallest normal double",
         "rel_error: |value - reference| / |reference|; error_estimate: the value's own bound, relative",
         "pass: the value is finite and |value - reference| <= its bound + the reference's bound; a refusal "
         "passes when the quantity is indeed outside the type's range"},
        {"family", "integrand", "parameter", "at", "setting", "number_type", "status", "rel_error",
         "error_estimate", "reason", "pass"},
        {"at"},
        std::nullopt,
        std::pair<std::string, std::string>{"status", "refused"}};
    info.id_keys = {"family", "integrand", "parameter", "at", "setting", "number_type"};
    return info;
}

}  // namespace verify
