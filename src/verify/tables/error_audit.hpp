// The error-bar audit: random cases with known answers, where every error estimate the suite
// reports must be at least the true error, and not absurdly larger.
//
// Families (one summary per family and number type):
//   zoo-1d      every zoo row by the 1D lobe quadrature, in binary128 and in double
//   zoo-2d      every zoo row by the 2D vector quadrature, in long double
//   irradiance  sphere and disk lights by the cap quadrature (binary128), tilts above and
//               across the horizon, r0/r log-uniform down to 1e-300
//   albedo      every BRDF form's directional albedo at normal incidence (double)
// Exponents are log-uniform over [1e-6, 1e7], with one draw in seven an exact small one
// (0, 0.5, 1, ..., 64). The true answers are closed forms in more precision than the value
// checked: the zoo's formulas in 50 digits; for the lights, pi sin^2 b cos t_c above the horizon
// and Snyder's formula in its original form (as written by Lagarde and de Rousiers, with the
// cancellation the library's rewritten form avoids) in 100 digits across it; for the albedos,
// closed forms derived here in u = (N.H)^2, independently of brdf/*.hpp's.
//
// Reproducible: std::mt19937_64 (its output sequence is fixed by the C++ standard), one stream
// per family seeded with seed + family index, uniforms in [0, 1) from the top 53 bits of each
// output (std::uniform_real_distribution is left to each standard library).
//
// Per case: the true error t and the estimate e (both relative to the true value), and u, the
// spacing of the value's type at the value, relative. A case fails when e < t. Its ratio e / t
// is infinite where t = 0 (an exact answer: counted apart). It is too pessimistic when
// e / max(t, u) > 1e6: below the spacing u no estimate can be asked to follow the true error,
// so an estimate of a few ulps on an exact answer is not a defect.
#pragma once
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <normzoo/albedo.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/irradiance.hpp>
#include <normzoo/real.hpp>
#include <normzoo/registry.hpp>

#include "../record.hpp"
#include "zoo.hpp"

namespace normzoo {

// 100 decimal digits: the reference for the lights, whose original closed form cancels.
using audit_reference = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<100>,
                                                      boost::multiprecision::et_off>;

enum class audit_family {
    zoo_1d_quad,
    zoo_1d_double,
    zoo_2d,
    irradiance_sphere,
    irradiance_disk,
    irradiance_closed_form,
    albedo_normal
};

inline constexpr audit_family audit_families[] = {
    audit_family::zoo_1d_quad,     audit_family::zoo_1d_double,          audit_family::zoo_2d,
    audit_family::irradiance_sphere, audit_family::irradiance_disk, audit_family::irradiance_closed_form,
    audit_family::albedo_normal};

inline const char* audit_family_name(audit_family f) {
    switch (f) {
        case audit_family::zoo_1d_quad:
        case audit_family::zoo_1d_double: return "zoo-1d";
        case audit_family::zoo_2d: return "zoo-2d";
        case audit_family::irradiance_sphere: return "irradiance-sphere";
        case audit_family::irradiance_disk: return "irradiance-disk";
        case audit_family::irradiance_closed_form: return "irradiance-closed-form";
        case audit_family::albedo_normal: return "albedo-normal";
    }
    return "";
}

inline const char* audit_number_type(audit_family f) {
    switch (f) {
        case audit_family::zoo_1d_double:
        case audit_family::albedo_normal: return "double";
        case audit_family::zoo_2d: return "long double";
        default: return "binary128";
    }
}

struct audit_settings {
    std::uint64_t seed = 20240607;
    std::size_t cases = 10000;        // at least this many in all, shared among the families below
    double pessimism_limit = 1e6;     // e / max(t, u) above this is a defect
    double estimate_scale = 1;        // tests only: 0.1 makes every estimate dishonest by 10x
    double albedo_max_n = 1e7;
};

// The share of the cases each family gets (they add up to 1).
inline double audit_share(audit_family f) {
    switch (f) {
        case audit_family::zoo_1d_quad: return 0.28;
        case audit_family::zoo_1d_double: return 0.16;
        case audit_family::zoo_2d: return 0.16;
        case audit_family::irradiance_sphere:
        case audit_family::irradiance_disk: return 0.11;
        case audit_family::irradiance_closed_form: return 0.06;
        case audit_family::albedo_normal: return 0.12;
    }
    return 0;
}

// One case to run: a member of a family (zoo row, light, BRDF form) and its parameters.
struct audit_case {
    audit_family family = audit_family::zoo_1d_quad;
    std::string member;
    double n = 0;         // exponent (zoo, albedo)
    double ratio = 0;     // r0 / r (lights)
    double tilt_deg = 0;  // tilt of the light's centre from N
    // filled in by run_audit_case:
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

// Uniform in [0, 1) from the top 53 bits: the same numbers on every platform.
inline double audit_uniform(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1p-53; }

inline double audit_log_uniform(std::mt19937_64& g, double lo, double hi) {
    return std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * audit_uniform(g));
}

// An exponent: one draw in seven an exact small one (0, 0.5, ..., 64), else log-uniform.
inline double audit_exponent(std::mt19937_64& g, double max_n) {
    if (audit_uniform(g) < 1.0 / 7) return std::floor(audit_uniform(g) * 129) / 2;
    return audit_log_uniform(g, 1e-6, max_n);
}

// The spacing of T at x, relative to x: 2^-digits / m with x = m 2^e, m in [0.5, 1).
template <class T>
double relative_spacing(const T& x) {
    using std::frexp;
    int e = 0;
    const double m = std::abs(static_cast<double>(frexp(x, &e)));
    return m > 0 ? std::ldexp(1.0, -std::numeric_limits<T>::digits) / m : 0.0;
}

// Fills the case's error fields from the value, its bound relative to the truth, and the truth
// (R wide enough to hold the value exactly).
template <class R, class T>
void audit_judge(audit_case& c, const T& value, const R& relative_bound, const R& truth, double scale) {
    using std::abs;
    const R v(value);
    c.true_error = static_cast<double>(abs(v - truth) / abs(truth));
    // below a thousand ulps of the truth's own type the difference is the truth's rounding
    if (c.true_error < 1e3 * static_cast<double>(std::numeric_limits<R>::epsilon())) c.true_error = 0;
    c.estimate = static_cast<double>(relative_bound) * scale;
    c.spacing = relative_spacing(value) * static_cast<double>(abs(v / truth));
    c.value = to_decimal(value, std::numeric_limits<T>::max_digits10);
    c.truth = to_decimal(truth, 40);
}

template <class Row, class Real, bool TwoD>
void audit_zoo(audit_case& c, double scale) {
    const double n = Row::has_exponent ? c.n : 0.0;
    c.n = n;
    normalization_estimate<Real> q;
    if constexpr (TwoD) q = zoo_norm_2d<Row, Real>(n);
    else q = zoo_norm_1d<Row, Real>(n);
    audit_judge(c, q.norm, wide(q.rel_error), Row::closed_form(wide(n)), scale);  // rel_error: relative to the truth
}

// E / L for a cap of half-angle b (sin b and cot b given) tilted by t_c: the closed forms in
// their original, unrewritten shape. Above the horizon pi sin^2 b cos t_c; across it
//     x = cot b, y = -x cot t_c, w = sin t_c sqrt(1 - y^2),
//     E / L = (cos t_c acos y - x w) sin^2 b + atan(w / x).
inline audit_reference audit_cap_truth(const audit_reference& sin_b, const audit_reference& cot_b, double tilt_deg) {
    using std::acos;
    using std::atan;
    using std::cos;
    using std::sin;
    using std::sqrt;
    const audit_reference pi = boost::math::constants::pi<audit_reference>();
    const audit_reference t = audit_reference(tilt_deg) * pi / 180;
    const audit_reference ct = cos(t), st = sin(t), s2 = sin_b * sin_b;
    if (ct >= sin_b) return pi * s2 * ct;
    if (ct <= -sin_b) return audit_reference(0);
    const audit_reference y = -cot_b * ct / st;
    const audit_reference w = st * sqrt(1 - y * y);
    return (ct * acos(y) - cot_b * w) * s2 + atan(w / cot_b);
}

// The cap quadrature, or (family irradiance-closed-form) the library's rewritten closed form.
inline void audit_light(audit_case& c, double scale) {
    using std::sqrt;
    const light_kind kind = c.member == "sphere" ? light_kind::sphere : light_kind::disk;
    const auto cap = light_cap<quad>::of(kind, quad(c.ratio));
    const degrees_angle<quad> tilt(c.tilt_deg);
    const auto e = c.family == audit_family::irradiance_closed_form ? cap_irradiance_closed_form(cap, tilt)
                                                                     : cap_irradiance<quad>(cap, tilt);
    const audit_reference r(c.ratio);
    // sphere: sin b = r0/r; disk facing the receiver: tan b = r0/r
    const audit_reference sin_b = kind == light_kind::sphere ? r : r / sqrt(1 + r * r);
    const audit_reference cot_b = kind == light_kind::sphere ? sqrt((1 - r) * (1 + r)) / r : 1 / r;
    const audit_reference truth = audit_cap_truth(sin_b, cot_b, c.tilt_deg);
    audit_judge(c, e.value, audit_reference(e.abs_error) / abs(truth), truth, scale);
}

// The albedo at L = N in closed form, derived in u = (N.H)^2: there N.H = L.H = cos(t_v / 2),
// N.V = 2u - 1 and sin t_v dt_v = 2 du, so a form K (N.H)^(2a) has
//     rho = 4 pi K G(a),   G(a) = integral over u in [1/2, 1] of u^a (2u - 1) du
//         = 2 (1 - 2^-(a+2)) / (a+2) - (1 - 2^-(a+1)) / (a+1).
// A mirror lobe at L = N is (N.V)^n: rho = 2 pi K / (n + 2).
inline wide audit_one_minus_two_power_over(const wide& b) {  // (1 - 2^-b) / b, ln 2 at b = 0
    using std::expm1;
    using std::log;
    const wide ln2 = log(wide(2));
    return b == 0 ? ln2 : wide(-expm1(-b * ln2) / b);
}
inline wide audit_albedo_truth(const std::string& form, const wide& n) {
    using std::pow;
    const wide pi = boost::math::constants::pi<wide>();
    auto g = [](const wide& a) { return 2 * audit_one_minus_two_power_over(a + 2) - audit_one_minus_two_power_over(a + 1); };
    if (form == "lambert" || form == "phong-modified") return wide(1);
    if (form == "phong") return (n + 1) / (n + 2);
    if (form == "blinn-phong") return (n + 2) / (2 - pow(wide(2), -n / 2)) * g(n / 2);  // K = (n+2) / (4 pi (2 - 2^(-n/2)))
    if (form == "blinn-phong-modified")
        return 4 * pi * ((n + 2) * (n + 4) / (8 * pi * (pow(wide(2), -n / 2) + n))) * g(n / 2);
    if (form == "blinn-phong-modified-approx") return (n + 8) / 2 * g(n / 2);
    if (form == "microfacet-blinn") return (n + 2) / 2 * g(n / 2);          // F(1, x) = 1
    if (form == "minimalist-cook-torrance") return (n + 1) / 2 * g((n - 3) / 2);  // c^n / c^3
    if (form == "cook-torrance-ksk") return (n + 2) * 4 / 8 * g((n - 2) / 2);     // (n+2)/(2 pi) c^n / (4 c^2)
    return wide(std::numeric_limits<double>::quiet_NaN());
}

template <class Form>
void audit_albedo(audit_case& c, double scale) {
    const double n = Form::has_exponent ? c.n : 0.0;
    c.n = n;
    const auto e = albedo<Form>(0, n, 1);
    const wide truth = audit_albedo_truth(Form::id, wide(n));
    audit_judge(c, e.value, wide(e.abs_error) / abs(truth), truth, scale);
}

inline audit_case audit_new_case(audit_family f, std::string member, double n) {
    audit_case c;
    c.family = f, c.member = std::move(member), c.n = n;
    return c;
}

// The family's cases, drawn from its own stream.
inline std::vector<audit_case> audit_draw(audit_family f, const audit_settings& s) {
    std::mt19937_64 g(s.seed + static_cast<std::uint64_t>(f));
    std::vector<audit_case> out;
    const double share = audit_share(f) * static_cast<double>(s.cases);
    auto per = [&](std::size_t members) { return static_cast<std::size_t>(std::ceil(share / static_cast<double>(members))); };
    switch (f) {
        case audit_family::zoo_1d_quad:
        case audit_family::zoo_1d_double:
        case audit_family::zoo_2d: {
            // a row without an exponent has one answer: one case
            std::size_t with_exponent = 0;
            for_each_zoo_row([&](auto row) { with_exponent += decltype(row)::has_exponent; });
            for_each_zoo_row([&](auto row) {
                using Row = decltype(row);
                const std::size_t count = Row::has_exponent ? per(with_exponent) : 1;
                for (std::size_t i = 0; i < count; ++i) out.push_back(audit_new_case(f, Row::id, Row::has_exponent ? audit_exponent(g, 1e7) : 0.0));
            });
            break;
        }
        case audit_family::irradiance_sphere:
        case audit_family::irradiance_disk:
        case audit_family::irradiance_closed_form: {
            const std::size_t count = per(1);
            for (std::size_t i = 0; i < count; ++i) {
                // the closed form's cases alternate between the two lights
                const bool sphere = f == audit_family::irradiance_closed_form ? i % 2 == 0 : f == audit_family::irradiance_sphere;
                const double top = sphere ? 0.999 : 10;
                audit_case c = audit_new_case(f, sphere ? "sphere" : "disk", 0);
                // half the cases cross the horizon: only where the cap is wider than a double can
                // resolve about 90 degrees (r0/r >= 1e-12)
                const bool crossing = audit_uniform(g) < 0.5;
                c.ratio = audit_log_uniform(g, crossing ? 1e-12 : 1e-300, top);
                const double b_deg = (sphere ? std::asin(c.ratio) : std::atan(c.ratio)) * 180 / boost::math::constants::pi<double>();
                const double u = audit_uniform(g);
                // across: the band 90 +- b, kept a millionth of b from its ends; above: up to 90 - b
                c.tilt_deg = crossing ? 90 + b_deg * (2 * u - 1) * 0.999999 : (90 - b_deg) * u;
                out.push_back(c);
            }
            break;
        }
        case audit_family::albedo_normal: {
            std::size_t with_exponent = 0;
            for_each_zoo_brdf([&](auto form) { with_exponent += decltype(form)::has_exponent; });
            for_each_zoo_brdf([&](auto form) {
                using Form = decltype(form);
                const std::size_t count = Form::has_exponent ? per(with_exponent) : 1;
                for (std::size_t i = 0; i < count; ++i)
                    out.push_back(audit_new_case(f, Form::id, Form::has_exponent ? audit_exponent(g, s.albedo_max_n) : 0.0));
            });
            break;
        }
    }
    return out;
}

}  // namespace detail

// Every family's cases, in a fixed order.
inline std::vector<audit_case> audit_cases(const audit_settings& s) {
    std::vector<audit_case> all;
    for (audit_family f : audit_families) {
        auto part = detail::audit_draw(f, s);
        all.insert(all.end(), part.begin(), part.end());
    }
    return all;
}

// Runs one case: the suite's value and estimate against the truth.
inline void run_audit_case(audit_case& c, const audit_settings& s) {
    switch (c.family) {
        case audit_family::zoo_1d_quad:
        case audit_family::zoo_1d_double:
        case audit_family::zoo_2d:
            with_zoo_row(c.member, [&](auto row) {
                using Row = decltype(row);
                if (c.family == audit_family::zoo_1d_quad) detail::audit_zoo<Row, quad, false>(c, s.estimate_scale);
                if (c.family == audit_family::zoo_1d_double) detail::audit_zoo<Row, double, false>(c, s.estimate_scale);
                if (c.family == audit_family::zoo_2d) detail::audit_zoo<Row, longd, true>(c, s.estimate_scale);
            });
            break;
        case audit_family::irradiance_sphere:
        case audit_family::irradiance_disk:
        case audit_family::irradiance_closed_form: detail::audit_light(c, s.estimate_scale); break;
        case audit_family::albedo_normal:
            with_brdf(c.member, [&](auto form) { detail::audit_albedo<decltype(form)>(c, s.estimate_scale); });
            break;
    }
}

inline std::vector<audit_case> run_audit(const audit_settings& s, unsigned jobs) {
    auto cases = audit_cases(s);
    detail::parallel_for(cases.size(), jobs, [&](std::size_t i) { run_audit_case(cases[i], s); });
    return cases;
}

// ---- Summaries ----

struct audit_summary {
    std::string family, number_type;
    std::size_t cases = 0, exact = 0, failures = 0, pessimistic = 0;
    double min_ratio = 0, q01 = 0, q50 = 0, q99 = 0, max_ratio = 0;  // e / t over the inexact cases
    double max_pessimism = 0;                                         // e / max(t, u)
    bool pass() const { return failures == 0 && pessimistic == 0; }
};

namespace detail {
// The q-quantile by nearest rank of sorted values.
inline double quantile(const std::vector<double>& sorted, double q) {
    if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::size_t rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
    rank = rank < 1 ? 1 : rank > sorted.size() ? sorted.size() : rank;
    return sorted[rank - 1];
}
}  // namespace detail

inline audit_summary summarize_audit(const std::vector<const audit_case*>& cases, std::string family,
                                     std::string number_type, double pessimism_limit) {
    audit_summary s{std::move(family), std::move(number_type)};
    std::vector<double> ratios;
    for (const auto* c : cases) {
        ++s.cases;
        s.failures += c->fails();
        const double p = c->pessimism();
        s.max_pessimism = std::max(s.max_pessimism, p);
        s.pessimistic += p > pessimism_limit;
        if (c->exact()) ++s.exact;
        else ratios.push_back(c->ratio_to_true());
    }
    std::sort(ratios.begin(), ratios.end());
    s.min_ratio = detail::quantile(ratios, 0);
    s.q01 = detail::quantile(ratios, 0.01);
    s.q50 = detail::quantile(ratios, 0.5);
    s.q99 = detail::quantile(ratios, 0.99);
    s.max_ratio = ratios.empty() ? s.min_ratio : ratios.back();
    return s;
}

// Per family and number type, in the order of audit_families, then all of them together.
inline std::vector<audit_summary> audit_summaries(const std::vector<audit_case>& cases, double pessimism_limit) {
    std::vector<audit_summary> out;
    std::vector<const audit_case*> all;
    for (audit_family f : audit_families) {
        std::vector<const audit_case*> part;
        for (const auto& c : cases)
            if (c.family == f) part.push_back(&c);
        if (!part.empty()) out.push_back(summarize_audit(part, audit_family_name(f), audit_number_type(f), pessimism_limit));
    }
    for (const auto& c : cases) all.push_back(&c);
    out.push_back(summarize_audit(all, "all", "all", pessimism_limit));
    return out;
}

inline table_info error_audit_info(const audit_settings& s) {
    return {"error-audit",
            "Error bars audited: the suite's error estimate against the true error over random cases with known answers",
            {"cases: " + std::to_string(s.cases) + " or more, seed " + std::to_string(s.seed) +
                 ", std::mt19937_64 one stream per family (seed + family index), uniforms from the top 53 bits",
             "exponents log-uniform on [1e-6, 1e7], one in seven exact in {0, 0.5, ..., 64}; lights: r0/r log-uniform "
             "on [1e-300, 0.999] (sphere) or [1e-300, 10] (disk), half the cases across the horizon (r0/r >= 1e-12)",
             "zoo-1d: zoo_norm_1d in binary128 and double; zoo-2d: zoo_norm_2d in long double; truth: the zoo's closed "
             "forms in cpp_bin_float<50>",
             "irradiance: cap_irradiance in binary128; truth: pi sin^2 b cos t_c, or Snyder's formula in its original "
             "form across the horizon, in cpp_bin_float<100>",
             "albedo-normal: albedo() at theta = 0 (tolerance 1e-10) in double; truth: closed forms derived in u = (N.H)^2, "
             "in cpp_bin_float<50>",
             "ratio = estimate / true error (both relative to the truth); exact: true error 0 (ratio infinite, apart)",
             "failures: estimate < true error; pessimistic: estimate / max(true error, spacing of the value's type) > " +
                 to_decimal(s.pessimism_limit, 1) + "; pass: neither"},
            {"family", "number_type", "cases", "exact", "failures", "min_ratio", "ratio_q01", "ratio_q50", "ratio_q99",
             "max_ratio", "max_pessimism", "pessimistic", "pass"}};
}

inline std::vector<record> error_audit_table(const std::vector<audit_summary>& summaries) {
    std::vector<record> out;
    for (const auto& s : summaries) {
        record r{"error-audit", {}};
        r.set("family", s.family)
            .set("number_type", s.number_type)
            .set("cases", static_cast<std::int64_t>(s.cases))
            .set("exact", static_cast<std::int64_t>(s.exact))
            .set("failures", static_cast<std::int64_t>(s.failures))
            .set("min_ratio", s.min_ratio)
            .set("ratio_q01", s.q01)
            .set("ratio_q50", s.q50)
            .set("ratio_q99", s.q99)
            .set("max_ratio", s.max_ratio)
            .set("max_pessimism", s.max_pessimism)
            .set("pessimistic", static_cast<std::int64_t>(s.pessimistic))
            .set("pass", s.pass());
        out.push_back(std::move(r));
    }
    return out;
}

// Per family and member, the case closest to failing and the most pessimistic one.
inline table_info error_audit_extremes_info() {
    return {"error-audit-extremes",
            "Error audit: per family and member, the case with the smallest ratio and the most pessimistic one",
            {"as error-audit; n, ratio, tilt_deg are the case's parameters (0 where they do not apply)"},
            {"family", "number_type", "member", "which", "n", "ratio", "tilt_deg", "true_error", "estimate", "spacing",
             "estimate_over_true"},
            {"n", "ratio", "tilt_deg"}};
}

inline std::vector<record> error_audit_extremes(const std::vector<audit_case>& cases) {
    std::vector<record> out;
    std::vector<std::pair<audit_family, std::string>> keys;
    for (const auto& c : cases)
        if (std::find(keys.begin(), keys.end(), std::make_pair(c.family, c.member)) == keys.end())
            keys.emplace_back(c.family, c.member);
    for (const auto& [f, m] : keys) {
        const audit_case *tightest = nullptr, *loosest = nullptr;
        for (const auto& c : cases) {
            if (c.family != f || c.member != m) continue;
            if (!c.exact() && (!tightest || c.ratio_to_true() < tightest->ratio_to_true())) tightest = &c;
            if (!loosest || c.pessimism() > loosest->pessimism()) loosest = &c;
        }
        auto add = [&](const audit_case* c, const char* which) {
            if (!c) return;
            record r{"error-audit-extremes", {}};
            r.set("family", std::string(audit_family_name(f)))
                .set("number_type", std::string(audit_number_type(f)))
                .set("member", m)
                .set("which", std::string(which))
                .set("n", c->n)
                .set("ratio", c->ratio)
                .set("tilt_deg", c->tilt_deg)
                .set("true_error", c->true_error)
                .set("estimate", c->estimate)
                .set("spacing", c->spacing)
                .set("estimate_over_true", c->exact() ? field_value(nullptr) : field_value(c->ratio_to_true()))
                .set("pessimism", c->pessimism())
                .set("value", c->value)
                .set("truth", c->truth)
                .set("fails", c->fails());
            out.push_back(std::move(r));
        };
        add(tightest, "smallest ratio");
        add(loosest, "most pessimistic");
    }
    return out;
}

// The distribution of log10(estimate / true error) per family and number type, in bins of
// width 1/4 from -2 to 10 (the first and last bins also take what lies beyond; exact cases
// apart, in `exact` of error-audit).
inline table_info error_audit_histogram_info() {
    return {"error-audit-histogram",
            "Error audit: histogram of log10(estimate / true error) per family and number type",
            {"bins of width 0.25 from -2 to 10; the end bins hold what lies beyond; exact answers are not binned"},
            {"family", "number_type", "log10_low", "log10_high", "count"}};
}

inline std::vector<record> error_audit_histogram(const std::vector<audit_case>& cases) {
    constexpr double lo = -2, hi = 10, width = 0.25;
    const int bins = static_cast<int>((hi - lo) / width);
    std::vector<record> out;
    for (audit_family f : audit_families) {
        std::vector<std::int64_t> count(bins, 0);
        bool any = false;
        for (const auto& c : cases) {
            if (c.family != f || c.exact()) continue;
            any = true;
            int b = static_cast<int>(std::floor((std::log10(c.ratio_to_true()) - lo) / width));
            b = b < 0 ? 0 : b >= bins ? bins - 1 : b;
            ++count[b];
        }
        if (!any) continue;
        for (int b = 0; b < bins; ++b) {
            record r{"error-audit-histogram", {}};
            r.set("family", std::string(audit_family_name(f)))
                .set("number_type", std::string(audit_number_type(f)))
                .set("log10_low", lo + width * b)
                .set("log10_high", lo + width * (b + 1))
                .set("count", count[b]);
            out.push_back(std::move(r));
        }
    }
    return out;
}

}  // namespace normzoo
