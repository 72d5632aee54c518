// Running one case of the error audit and judging it (docs/error-audit.md, "How a case is
// judged"): the library's value and error estimate against the reference value.
//
// Per case: the true error t and the estimate e (both relative to the true value), and u, the
// spacing of the value's type at the value, relative. A case fails when e < t. Its ratio e / t
// is infinite where t = 0 (an exact answer: counted apart). It is too pessimistic when
// e / max(t, u) > 1e6: below the spacing u no estimate can be asked to follow the true error,
// so an estimate of a few ulps on an exact answer is not a defect.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <normzoo/albedo.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/irradiance.hpp>
#include <normzoo/normalization.hpp>
#include <normzoo/real.hpp>
#include <normzoo/wide.hpp>
#include <normzoo/registry.hpp>

#include "cases.hpp"
#include "reference.hpp"

namespace verify {

// A case run: what was drawn, and how its estimate compares with the truth.
struct audit_result {
    audit_case drawn;
    double true_error = 0;  // |value - truth| / |truth|
    double estimate = 0;    // the suite's bound on it, relative to |truth| too
    double spacing = 0;     // the spacing of the value's type at the value, relative to |truth|
    std::string value, truth;

    bool exact() const { return true_error == 0; }
    bool fails() const { return estimate < true_error; }
    double ratio_to_true() const { return estimate / true_error; }  // inf where exact
    double pessimism() const { return estimate / std::max(true_error, spacing); }
};

namespace detail {

// The spacing of T at x, relative to x: 2^-digits / m with x = m 2^e, m in [0.5, 1).
template <class T>
double relative_spacing(const T& x) {
    using std::frexp;
    int e = 0;
    const double m = std::abs(static_cast<double>(frexp(x, &e)));
    return m > 0 ? std::ldexp(1.0, -std::numeric_limits<T>::digits) / m : 0.0;
}

// The result of the case from the value, its bound relative to the truth, and the truth
// (R wide enough to hold the value exactly).
template <class R, class T>
audit_result audit_judge(const audit_case& c, const T& value, const R& relative_bound, const R& truth, double scale) {
    using std::abs;
    audit_result out;
    out.drawn = c;
    const R v(value);
    out.true_error = static_cast<double>(abs(v - truth) / abs(truth));
    // below a thousand ulps of the truth's own type the difference is the truth's rounding
    if (out.true_error < 1e3 * static_cast<double>(std::numeric_limits<R>::epsilon())) out.true_error = 0;
    out.estimate = static_cast<double>(relative_bound) * scale;
    out.spacing = relative_spacing(value) * static_cast<double>(abs(v / truth));
    out.value = to_decimal(value, std::numeric_limits<T>::max_digits10);
    out.truth = to_decimal(truth, 40);
    return out;
}

template <class Row, class Real, bool TwoD>
audit_result audit_zoo(audit_case c, double scale) {
    c.n = Row::has_exponent ? c.n : 0.0;
    normalization_estimate<Real> q;
    if constexpr (TwoD) q = zoo_norm_2d<Row, Real>(c.n);
    else q = zoo_norm_1d<Row, Real>(c.n);
    return audit_judge(c, q.norm, wide(q.rel_error), audit_zoo_truth<Row>(c.n), scale);  // rel_error: relative to the truth
}

// The cap quadrature, or (family irradiance-closed-form) the library's rewritten closed form.
inline audit_result audit_light(const audit_case& c, double scale) {
    const light_kind kind = c.member == "sphere" ? light_kind::sphere : light_kind::disk;
    const auto cap = light_cap<quad>::of(kind, quad(c.ratio));
    const degrees_angle<quad> tilt(c.tilt_deg);
    const auto e = c.family == audit_family::irradiance_closed_form ? cap_irradiance_closed_form(cap, tilt)
                                                                     : cap_irradiance<quad>(cap, tilt);
    const audit_reference truth = audit_light_truth(kind, c.ratio, c.tilt_deg);
    return audit_judge(c, e.value, audit_reference(e.abs_error) / abs(truth), truth, scale);
}

template <class Form>
audit_result audit_albedo(audit_case c, double scale) {
    c.n = Form::has_exponent ? c.n : 0.0;
    const auto e = albedo<Form>(0, c.n, 1);
    const wide truth = audit_albedo_truth(Form::id, wide(c.n));
    return audit_judge(c, e.value, wide(e.abs_error) / abs(truth), truth, scale);
}

}  // namespace detail

// Runs one case: the suite's value and estimate against the truth.
inline audit_result run_audit_case(const audit_case& c, const audit_settings& s) {
    audit_result out;
    out.drawn = c;
    switch (c.family) {
        case audit_family::zoo_1d_quad:
        case audit_family::zoo_1d_double:
        case audit_family::zoo_2d:
            with_zoo_row(c.member, [&](auto row) {
                using Row = decltype(row);
                if (c.family == audit_family::zoo_1d_quad) out = detail::audit_zoo<Row, quad, false>(c, s.estimate_scale);
                if (c.family == audit_family::zoo_1d_double) out = detail::audit_zoo<Row, double, false>(c, s.estimate_scale);
                if (c.family == audit_family::zoo_2d) out = detail::audit_zoo<Row, longd, true>(c, s.estimate_scale);
            });
            break;
        case audit_family::irradiance_sphere:
        case audit_family::irradiance_disk:
        case audit_family::irradiance_closed_form: out = detail::audit_light(c, s.estimate_scale); break;
        case audit_family::albedo_normal:
            with_brdf(c.member, [&](auto form) { out = detail::audit_albedo<decltype(form)>(c, s.estimate_scale); });
            break;
    }
    return out;
}

// Draws the cases and runs them on `jobs` threads, in the order drawn.
inline std::vector<audit_result> run_audit(const audit_settings& s, unsigned jobs) {
    const auto cases = audit_cases(s);
    std::vector<audit_result> out(cases.size());
    detail::parallel_for(cases.size(), jobs, [&](std::size_t i) { out[i] = run_audit_case(cases[i], s); });
    return out;
}

}  // namespace verify
