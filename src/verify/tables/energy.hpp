// The energy sweep (docs/energy.md, docs/models.md): the directional albedo of every BRDF form of
// the registry at every value of its declared parameter (n, alpha or r; forms without one once)
// and incident angle, and per form and value the largest albedo, where it occurs and the verdict.
// Gaining energy is a finding, not a failure: a point fails only when its value cannot be trusted
// (error estimate above the tolerance, or a closed form disagrees).
//
// The sweep and its summary are typed values (albedo_point, albedo_summary); the records the
// writers take are built from them in one place per table (energy_records, energy_summary_table).
#pragma once
#include <boost/math/tools/minima.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <normzoo/albedo.hpp>
#include <normzoo/albedo_input.hpp>
#include <normzoo/decimal.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/real.hpp>
#include <normzoo/registry.hpp>

#include "../record.hpp"
#include "energy_grids.hpp"
#include "energy_keys.hpp"

namespace verify {

struct energy_settings {
    double tolerance = 1e-10;  // albedo accuracy: absolute up to 1, relative above
    double specular = 1;       // k_s, c_spec or R_s of the forms that have one (1: the white furnace)
    albedo_settings albedo() const { return {tolerance, albedo_settings{}.max_panels}; }
};

// gains when albedo - error > 1, conserves when albedo + error < 1, else neither can be told
// apart from equality (albedo 1 at normal incidence is exact for the normalized forms).
enum class albedo_verdict { conserves, equal_within_error, gains };

inline albedo_verdict judge_albedo(double albedo, double error) {
    if (albedo - error > 1) return albedo_verdict::gains;
    if (albedo + error < 1) return albedo_verdict::conserves;
    return albedo_verdict::equal_within_error;
}

inline const char* to_string(albedo_verdict v) {
    switch (v) {
        case albedo_verdict::gains: return "gains";
        case albedo_verdict::conserves: return "conserves";
        case albedo_verdict::equal_within_error: break;
    }
    return "equal within error";
}

inline const char* energy_verdict_text(double albedo, double error) { return to_string(judge_albedo(albedo, error)); }

// One point of the sweep: a form at one value of its parameter and one incident angle.
struct albedo_point {
    std::string_view model;      // the form's id
    std::string_view parameter;  // the swept parameter's name: n, alpha, r, or none
    double value = 0;            // its value (0 for none): the double nearest value_input
    double theta_deg = 0;        // the double nearest theta_input
    decimal value_input, theta_input;  // as given (docs/conventions.md, "Inputs are decimals")
    double specular = 1;         // the form's specular where it has one
    quadrature::estimate<double> albedo{};
    double tolerance = 0;               // the tolerance asked, as albedo_tolerance scales it
    std::optional<double> closed_form;  // in binary128, rounded to double, where derived
    albedo_verdict verdict = albedo_verdict::equal_within_error;
    bool trusted = true;  // error_estimate <= tolerance, and agreement with the closed form
};

// A form's albedo at value x of its swept parameter (brdf::params_at) and incident angle t, both
// as given: the direction is formed from t in binary128, and the bound covers x's rounding to
// the double the form is evaluated at (albedo_input_rounding).
template <class Form>
quadrature::estimate<double> form_albedo(const decimal& x, const degrees_angle<quad>& theta, const energy_settings& s) {
    auto at = [&](double xd) {
        const brdf::params<double> p = brdf::params_at<Form>(xd, s.specular);
        return albedo<Form>(theta, p.n, p.specular, s.albedo(), p.roughness);
    };
    auto e = at(x.to<double>());
    if constexpr (brdf::has_swept_parameter<Form>()) e.abs_error += albedo_input_rounding(at, x, e);
    return e;
}

template <class Form>
albedo_point energy_point(const decimal& x_in, const decimal& theta, const energy_settings& s) {
    using std::abs;
    const decimal x = brdf::has_swept_parameter<Form>() ? x_in : decimal();
    const brdf::params<double> p = brdf::params_at<Form>(x.to<double>(), s.specular);
    albedo_point a;
    a.model = Form::id;
    a.parameter = brdf::swept_parameter_name<Form>();
    a.value = x.to<double>();
    a.value_input = x;
    a.theta_deg = theta.to<double>();
    a.theta_input = theta;
    a.specular = p.specular;
    const auto angle = degrees_of<quad>(theta);
    a.albedo = form_albedo<Form>(x, angle, s);
    a.tolerance = albedo_tolerance(a.albedo.value, s.tolerance);
    a.verdict = judge_albedo(a.albedo.value, a.albedo.abs_error);
    a.trusted = a.albedo.abs_error <= a.tolerance;
    // The hand-derived closed forms (brdf/*.hpp), in binary128: at every incidence where there is
    // one, else at L = N; for the white furnace (specular 1) only.
    if constexpr (brdf::has_albedo_at<Form>) {
        a.closed_form = static_cast<double>(Form::albedo_at(angle.cos_t));
    } else if constexpr (brdf::has_albedo_at_normal<Form>) {
        if (theta.is_zero() && p.specular == 1) {
            // at the decimal parameter itself, in binary128 (n places the nodes only where a
            // roughness is swept)
            brdf::params<quad> exact{quad(Form::has_exponent ? p.n : 0.0), quad(1), quad(p.roughness)};
            if constexpr (brdf::has_swept_parameter<Form>()) {
                if (brdf::swept_parameter<Form>().name == "n") exact.n = x.to<quad>();
                else exact.roughness = x.to<quad>();
            }
            a.closed_form = static_cast<double>(Form::albedo_at_normal(exact));
        }
    }
    // agreement within the albedo's bound and a few ulps of the closed form's rounding to double
    if (a.closed_form)
        a.trusted = a.trusted &&
                    abs(a.albedo.value - *a.closed_form) <= a.albedo.abs_error + 4 * eps<double>() * abs(*a.closed_form);
    return a;
}

// The values a form is swept at, given its swept parameter (default: the grid it declares).
using parameter_grid = std::function<std::vector<decimal>(const brdf::parameter&)>;

// A form's declared grid, as the decimals its declaration writes (0.1 in the source is 0.1).
inline std::vector<decimal> declared_grid(const brdf::parameter& p) {
    std::vector<decimal> out;
    for (double x : p.sweep) out.push_back(decimal::shortest(x));
    return out;
}

// A grid with the exponents replaced (--n, a scene's range): the forms swept in n take them.
inline parameter_grid with_exponents(std::vector<decimal> exponents) {
    return [n = std::move(exponents)](const brdf::parameter& p) { return p.name == "n" ? n : declared_grid(p); };
}

// Every form in `models` (registry order as given) at every value of its grid and every angle.
inline std::vector<albedo_point> energy_sweep(const std::vector<std::string>& models, const std::vector<decimal>& angles,
                                              unsigned jobs, const energy_settings& s = {},
                                              const parameter_grid& grid = declared_grid) {
    std::vector<std::function<albedo_point()>> tasks;
    for (const auto& m : models)
        with_brdf(m, [&](auto form) {
            using Form = decltype(form);
            std::vector<decimal> values{decimal()};
            if constexpr (brdf::has_swept_parameter<Form>()) values = grid(brdf::swept_parameter<Form>());
            for (const auto& x : values)
                for (const auto& t : angles) tasks.push_back([x, t, s] { return energy_point<Form>(x, t, s); });
        });
    std::vector<albedo_point> out(tasks.size());
    detail::parallel_for(tasks.size(), jobs, [&](std::size_t i) { out[i] = tasks[i](); });
    return out;
}

// The sweep with its exponents given: the forms swept in n at `exponents`, the others at their grids.
inline std::vector<albedo_point> energy_sweep(const std::vector<std::string>& models, const std::vector<decimal>& exponents,
                                              const std::vector<decimal>& angles, unsigned jobs,
                                              const energy_settings& s = {}) {
    return energy_sweep(models, angles, jobs, s, with_exponents(exponents));
}

// The energy table's records: the one place its keys are written.
inline record energy_record(const albedo_point& a) {
    record r{"energy", {}};
    r.set("model", std::string(a.model))
        .set("parameter", std::string(a.parameter))
        .set("value", a.value)
        .set("value_input", a.value_input.text())
        .set("theta_deg", a.theta_deg)
        .set("theta_input", a.theta_input.text())
        .set("albedo", a.albedo.value)
        .set("error_estimate", a.albedo.abs_error)
        .set("tolerance", a.tolerance)
        .set("conserving", a.verdict != albedo_verdict::gains)
        .set("verdict", std::string(to_string(a.verdict)))
        .set("evaluations", static_cast<std::int64_t>(a.albedo.evaluations));
    if (a.specular != 1) r.set("specular", a.specular);
    if (a.closed_form) r.set("albedo_closed_form", *a.closed_form).set("closed_form_difference", a.albedo.value - *a.closed_form);
    r.set("pass", a.trusted);
    return r;
}

inline std::vector<record> energy_records(const std::vector<albedo_point>& sweep) {
    std::vector<record> out;
    out.reserve(sweep.size());
    for (const auto& a : sweep) out.push_back(energy_record(a));
    return out;
}

// The sweep's records at once (the tests, and callers that want only the table).
inline std::vector<record> energy_table(const std::vector<std::string>& models, const std::vector<decimal>& exponents,
                                        const std::vector<decimal>& angles, unsigned jobs,
                                        const energy_settings& s = {}) {
    return energy_records(energy_sweep(models, exponents, angles, jobs, s));
}

// One group of the sweep (a form at one value of its parameter) summed up over its angles.
struct albedo_summary {
    std::string_view model, parameter;
    double value = 0;
    decimal value_input;
    double max_albedo = 0, argmax_theta_deg = 0, max_albedo_error = 0;
    std::optional<double> first_gain_theta_deg, albedo_at_normal;
    bool gains = false, equal = false, trusted = true, refined = false, rising_at_last_angle = false;
    std::size_t angles = 0;
    albedo_verdict verdict() const {
        return gains ? albedo_verdict::gains : equal ? albedo_verdict::equal_within_error : albedo_verdict::conserves;
    }
};

namespace detail {

// The largest albedo near an interior grid maximum, by Brent's method on the bracket of its
// neighbours (to ~1e-6 of the bracket): the grid alone would understate a peak between angles.
// `albedo_at(t)` is the group's albedo estimate at incident angle t.
template <class AlbedoAt>
std::pair<double, quadrature::estimate<double>> refine_maximum(const AlbedoAt& albedo_at, double lo, double hi) {
    auto minus_albedo = [&](double t) { return -albedo_at(t).value; };
    const auto best = boost::math::tools::brent_find_minima(minus_albedo, lo, hi, 20);
    return {best.first, albedo_at(best.first)};
}

// The largest albedo (refined by `albedo_at` where it is interior and stands out from both
// neighbours), where it occurs, and the verdict over all angles.
template <class AlbedoAt>
albedo_summary summarize_albedo_group(std::vector<const albedo_point*> rows, const AlbedoAt& albedo_at) {
    std::stable_sort(rows.begin(), rows.end(),
                     [](const albedo_point* a, const albedo_point* b) { return a->theta_deg < b->theta_deg; });
    albedo_summary g;
    g.model = rows.front()->model;
    g.parameter = rows.front()->parameter;
    g.value = rows.front()->value;
    g.value_input = rows.front()->value_input;
    g.angles = rows.size();
    std::size_t k = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const albedo_point& r = *rows[i];
        if (r.albedo.value > rows[k]->albedo.value) k = i;
        if (r.verdict == albedo_verdict::gains && !g.gains) g.first_gain_theta_deg = r.theta_deg;
        g.gains = g.gains || r.verdict == albedo_verdict::gains;
        g.equal = g.equal || r.verdict == albedo_verdict::equal_within_error;
        g.trusted = g.trusted && r.trusted;
        if (r.theta_deg == 0) g.albedo_at_normal = r.albedo.value;
    }
    // Angles whose albedo cannot be told from the largest (within both errors) tie; the first
    // of them is reported, and a maximum is refined only where it stands out from both sides.
    auto ties = [&](std::size_t i, std::size_t j) {
        return std::abs(rows[i]->albedo.value - rows[j]->albedo.value) <= rows[i]->albedo.abs_error + rows[j]->albedo.abs_error;
    };
    for (std::size_t i = 0; i < k; ++i)
        if (ties(i, k)) {
            k = i;
            break;
        }
    g.argmax_theta_deg = rows[k]->theta_deg;
    g.max_albedo = rows[k]->albedo.value;
    g.max_albedo_error = rows[k]->albedo.abs_error;
    g.rising_at_last_angle = k + 1 == rows.size() && rows.size() > 1;
    if (k > 0 && k + 1 < rows.size() && !ties(k - 1, k) && !ties(k, k + 1)) {
        const auto [t, e] = refine_maximum(albedo_at, rows[k - 1]->theta_deg, rows[k + 1]->theta_deg);
        if (e.value > g.max_albedo)
            g.argmax_theta_deg = t, g.max_albedo = e.value, g.max_albedo_error = e.abs_error, g.refined = true;
        if (judge_albedo(e.value, e.abs_error) == albedo_verdict::gains) g.gains = true;
    }
    return g;
}

// The groups of a sweep by (form, value), in sweep order.
inline std::vector<std::vector<const albedo_point*>> albedo_groups(const std::vector<albedo_point>& sweep) {
    std::vector<std::vector<const albedo_point*>> groups;
    std::map<std::pair<std::string_view, double>, std::size_t> index;
    for (const auto& a : sweep) {
        const auto [it, fresh] = index.emplace(std::make_pair(a.model, a.value), groups.size());
        if (fresh) groups.emplace_back();
        groups[it->second].push_back(&a);
    }
    return groups;
}

}  // namespace detail

// Per form and value: the largest albedo (refined between grid angles where it is interior),
// where it occurs, and the verdict over all angles swept.
inline std::vector<albedo_summary> energy_summary(const std::vector<albedo_point>& sweep, unsigned jobs,
                                                  const energy_settings& s = {}) {
    const auto groups = detail::albedo_groups(sweep);
    std::vector<albedo_summary> out(groups.size());
    detail::parallel_for(groups.size(), jobs, [&](std::size_t i) {
        const albedo_point& first = *groups[i].front();
        with_brdf(first.model, [&](auto form) {
            using Form = decltype(form);
            energy_settings at = s;
            at.specular = first.specular;
            out[i] = detail::summarize_albedo_group(
                groups[i], [&](double t) { return form_albedo<Form>(first.value_input, degrees_angle<quad>(t), at); });
        });
    });
    return out;
}

// The energy-summary table's records: the one place its keys are written.
inline record energy_summary_record(const albedo_summary& g) {
    auto optional = [](const std::optional<double>& x) { return x ? field_value(*x) : field_value(nullptr); };
    record r{"energy-summary", {}};
    r.set("model", std::string(g.model))
        .set("parameter", std::string(g.parameter))
        .set("value", g.value)
        .set("value_input", g.value_input.text())
        .set("max_albedo", g.max_albedo)
        .set("argmax_theta_deg", g.argmax_theta_deg)
        .set("conserving", !g.gains)
        .set("verdict", std::string(to_string(g.verdict())))
        .set("max_albedo_error", g.max_albedo_error)
        .set("refined", g.refined)
        .set("rising_at_last_angle", g.rising_at_last_angle)
        .set("albedo_at_normal", optional(g.albedo_at_normal))
        .set("gain", g.max_albedo - 1)
        .set("first_gain_theta_deg", optional(g.first_gain_theta_deg))
        .set("angles", static_cast<std::int64_t>(g.angles))
        .set("pass", g.trusted);
    return r;
}

inline std::vector<record> energy_summary_table(const std::vector<albedo_summary>& summary) {
    std::vector<record> out;
    out.reserve(summary.size());
    for (const auto& g : summary) out.push_back(energy_summary_record(g));
    return out;
}

// The angles the Markdown grid shows: all when few, else those of a reading set that were swept.
inline std::vector<double> energy_md_angles(const std::vector<double>& angles) {
    if (angles.size() <= 10) return angles;
    std::vector<double> shown;
    for (double a : {0.0, 30.0, 60.0, 75.0, 85.0, 89.0, 89.5, 89.9, 89.99, 89.999})
        if (std::find(angles.begin(), angles.end(), a) != angles.end()) shown.push_back(a);
    if (shown.size() < 3)
        for (std::size_t i = 0; i < 8; ++i) shown.push_back(angles[i * (angles.size() - 1) / 7]);
    std::sort(shown.begin(), shown.end());
    shown.erase(std::unique(shown.begin(), shown.end()), shown.end());
    return shown;
}

inline table_info energy_info(const std::vector<double>& angles, const energy_settings& s = {}) {
    char tol[32];
    std::snprintf(tol, sizeof tol, "%g", s.tolerance);
    table_info info{
        "energy",
        "Directional albedo of each BRDF form at each value of its parameter against incident angle "
        "(docs/energy.md, docs/models.md)",
        {"albedo(t) = integral of f(L, V) (N.V) over V in the upper hemisphere, f evaluated from vectors (Eigen)",
         "coordinates around the lobe (N, the mirror direction R, or the half vector H with Jacobian 4 L.H), the "
         "horizon cut in closed form; nested adaptive Gauss-Kronrod (15 points in azimuth, 31 in polar angle), "
         "graded in ln(angle) at the lobe width, the 1/(L.H) pole and the horizon transition",
         "each node in double, escalated to long double or binary128 where its condition number (near grazing "
         "incidence) would cost accuracy; the node's rounding bound enters the error estimate",
         std::string("error_estimate: sum of |Kronrod - Gauss| over panels + node error bounds + truncated lobe "
                     "tail; tolerance ") + tol + " absolute, relative where the albedo exceeds 1",
         "verdict: gains if albedo - error > 1, conserves if albedo + error < 1, else equal within error",
         "pass: error_estimate <= tolerance, and agreement with the hand-derived closed form where there is one "
         "(at normal incidence; at every angle for ashikhmin-shirley-diffuse)",
         "parameter and value: each form's declared parameter (n: exponent, alpha: Ward roughness, nodes placed "
         "with the Phong-Beckmann exponent 2/alpha^2 - 2; r: Disney roughness, EON's roughness for eon) at each value of its grid; "
         "none: a form without one, once; anisotropic: Ward a_x = alpha, a_y = alpha/2, Ashikhmin-Shirley "
         "n_u = n, n_v = 4n, x and u in the plane of incidence",
         "grids: " + energy_grids_text(),
         "k_s = c_spec = R_s = 1 (white furnace for the Fresnel forms); rho_s = R_d = 1, Ashikhmin-Shirley R_s = 0 "
         "in the diffuse term; EON's rho = 1",
         "value_input, theta_input: the inputs as given, decimals; the direction is formed from theta_input in "
         "binary128; the form is evaluated at the double nearest value_input, and error_estimate adds the "
         "albedo's change across that rounding (its slope over a relative step of 1e-6, doubled; docs/energy.md, "
         "\"Inputs are decimals\")"},
        {"model", "parameter", "value", "theta_deg", "albedo", "error_estimate", "verdict", "pass"},
        {"albedo"},
        pivot_view{{"model", "parameter", "value"}, "theta_deg", energy_md_angles(angles), "albedo"}};
    info.id_keys = energy_id_keys();
    info.check = energy_check_rule();
    return info;
}

inline table_info energy_summary_info() {
    table_info info{
        "energy-summary",
        "Largest directional albedo per BRDF form and parameter value, where it occurs, and the verdict",
        {"max over the swept angles; where the maximum is interior it is refined by Brent's method between the "
         "neighbouring angles (refined = true)",
         "rising_at_last_angle: the largest albedo is at the most grazing angle swept (the supremum lies "
         "towards 90 degrees)",
         "verdict over all angles: gains if any albedo - error > 1; conserving = not gains",
         "pass: every albedo of the group is trusted"},
        {"model", "parameter", "value", "max_albedo", "argmax_theta_deg", "verdict", "gain", "first_gain_theta_deg",
         "albedo_at_normal", "rising_at_last_angle", "pass"},
        {"max_albedo", "albedo_at_normal"}};
    info.id_keys = {"material", "model", "parameter", "value"};
    info.check = {{{"max_albedo", "max_albedo_error", false}, {"gain", "max_albedo_error", false},
                   {"albedo_at_normal", "max_albedo_error", false}},
                  {"max_albedo_error"}};
    return info;
}

}  // namespace verify
