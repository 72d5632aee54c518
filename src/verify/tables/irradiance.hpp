// The irradiance tables (docs/irradiance.md): sphere and disk lights at every ratio r0/r and
// tilt, by quadrature against the closed forms and against the point light I cos t_c / r^2, with
// the convergence order observed as r0/r -> 0; and the punctual-light limit of a tiny cone for
// every BRDF form, with its observed order as the cone shrinks. Each table computes typed points
// first; the summaries and the observed orders read those, and one function per table writes
// its records.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <normzoo/decimal.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/irradiance.hpp>
#include <normzoo/real.hpp>
#include <normzoo/registry.hpp>

#include "../record.hpp"
#include "grid.hpp"

namespace verify {

struct irradiance_settings {
    double digits = 30;  // the quadrature's bound must show this many correct digits
};

inline std::vector<decimal> default_irradiance_ratios() {
    std::vector<decimal> r;
    for (int k = 1; k <= 15; ++k) r.emplace_back("1e-" + std::to_string(k));
    for (const char* x : {"1e-30", "1e-100", "1e-300"}) r.emplace_back(x);
    return r;
}

// Tilts of the light's centre from N; 90.5 and 95 degrees still see part of the larger caps.
inline std::vector<decimal> default_irradiance_tilts() {
    std::vector<decimal> t;
    for (const char* x : {"0", "30", "60", "85", "89.9", "90.5", "95"}) t.emplace_back(x);
    return t;
}

namespace detail {

// The order p of a deviation d ~ C x^p between consecutive points of a group (x the ratio or
// the cone's half-angle), where both deviations are well above what the quadrature can resolve
// (1e3 times their bounds); none elsewhere (docs/irradiance.md, "The limit r0/r -> 0").
template <class Point, class X, class Deviation, class SameGroup>
void observed_orders(std::vector<Point>& points, X x_of, Deviation deviation_of, SameGroup same_group) {
    for (std::size_t i = 0; i < points.size(); ++i) {
        std::optional<double> order;
        if (i > 0 && same_group(points[i - 1], points[i])) {
            const double d0 = std::abs(deviation_of(points[i - 1])), d1 = std::abs(deviation_of(points[i]));
            const double b0 = points[i - 1].deviation_error, b1 = points[i].deviation_error;
            if (d0 > 1e3 * b0 && d1 > 1e3 * b1) order = std::log(d0 / d1) / std::log(x_of(points[i - 1]) / x_of(points[i]));
        }
        points[i].observed_order = order;
    }
}

}  // namespace detail

// r0/r as the table takes it: its value in binary128, a bound on the relative rounding of that
// value (0 when it is the ratio itself), and the text it was given as (a decimal, or a scene's
// radius / distance).
struct ratio_input {
    quad value = 0;
    double rounding = 0;
    std::string text;
    static ratio_input of(const decimal& x) { return {x.to<quad>(), x.rounding<quad>(), x.text()}; }
};

inline std::vector<ratio_input> ratio_inputs(const std::vector<decimal>& ratios) {
    std::vector<ratio_input> out;
    for (const auto& x : ratios) out.push_back(ratio_input::of(x));
    return out;
}

// One light at one ratio and tilt: the quadrature against the closed form and the point light.
struct irradiance_point {
    light_kind light = light_kind::sphere;
    double ratio = 0, tilt_deg = 0;     // the doubles nearest the inputs (for grouping, plots)
    std::string ratio_input, tilt_input;  // the inputs as given
    const char* cap_case = "";
    quad quadrature = 0, closed_form = 0;
    quad point = 0;                   // E_point = I cos t_c / r^2, 0 below the horizon
    double rel_error = 0;             // |quadrature - closed form| / closed form
    double error_estimate = 0;        // the quadrature's bound, relative to its value (inputs' rounding included)
    double deviation_error = 0;       // the deviation's bound: the quadrature's own, plus |deviation| times
                                      // the inputs' share (E and E_point move alike with them)
    double digits = 0;                // digits shown by the larger of the two
    std::optional<quad> normalized;   // E r^2 / (I cos t_c), where the point light lights N
    std::optional<double> deviation;  // normalized - 1
    bool pass = false;
    std::optional<double> observed_order;  // against the previous ratio of the same light and tilt
};

// The quadrature's estimate covers the rounding of the inputs to binary128 (cap_irradiance); the
// closed form is taken at the same rounded inputs, so their agreement tests the quadrature.
inline irradiance_point irradiance_at(light_kind kind, const ratio_input& ratio, const decimal& tilt,
                                      const irradiance_settings& s) {
    using std::abs;
    const auto cap = light_cap<quad>::of(kind, ratio.value);
    const auto t = degrees_of<quad>(tilt);
    const auto own = cap_irradiance(cap, t);
    const quad inputs = cap_input_rounding(kind, cap, t, ratio.value, ratio.rounding, tilt);
    const quadrature::estimate<quad> q{own.value, own.abs_error + inputs, own.evaluations};
    const auto closed = cap_irradiance_closed_form(cap, t);
    const quad pi = boost::math::constants::pi<quad>();
    irradiance_point p;
    p.light = kind, p.ratio = static_cast<double>(ratio.value), p.tilt_deg = tilt.to<double>();
    p.ratio_input = ratio.text, p.tilt_input = tilt.text();
    p.cap_case = cap_case(cap, t);
    p.quadrature = q.value, p.closed_form = closed.value;
    p.point = pi * ratio.value * ratio.value * (t.cos_t > 0 ? t.cos_t : quad(0));  // I cos t_c / r^2
    const quad scale = closed.value != 0 ? closed.value : quad(1);
    const quad rel = abs(q.value - closed.value) / scale;
    const quad bound = q.abs_error / (q.value != 0 ? abs(q.value) : quad(1));
    p.rel_error = static_cast<double>(rel);
    p.error_estimate = static_cast<double>(bound);
    p.digits = digits_of(rel > bound ? rel : bound);
    if (p.point > 0) {
        // E r^2 / (I cos t_c) and its deviation from 1, both from the quadrature.
        p.normalized = q.value / p.point;
        p.deviation = static_cast<double>(*p.normalized - 1);
        p.deviation_error = static_cast<double>(own.abs_error / abs(q.value) + abs(*p.normalized - 1) * inputs / abs(q.value));
    }
    const bool agrees = abs(q.value - closed.value) <= q.abs_error + closed.abs_error;
    p.pass = agrees && bound <= quad(std::pow(10.0, -s.digits));
    return p;
}

// Every light, tilt and ratio (grouped by light and tilt, ratios in the order given), with the
// orders observed between consecutive ratios.
inline std::vector<irradiance_point> irradiance_points(const std::vector<light_kind>& lights,
                                                       const std::vector<ratio_input>& ratios,
                                                       const std::vector<decimal>& tilts, unsigned jobs,
                                                       const irradiance_settings& s = {}) {
    struct task {
        light_kind light;
        const ratio_input* ratio;
        const decimal* tilt;
    };
    std::vector<task> tasks;
    for (auto k : lights)
        for (const auto& t : tilts)
            for (const auto& x : ratios) tasks.push_back({k, &x, &t});
    std::vector<irradiance_point> out(tasks.size());
    detail::parallel_for(out.size(), jobs,
                         [&](std::size_t i) { out[i] = irradiance_at(tasks[i].light, *tasks[i].ratio, *tasks[i].tilt, s); });
    detail::observed_orders(
        out, [](const irradiance_point& p) { return p.ratio; },
        [](const irradiance_point& p) { return p.deviation ? *p.deviation : std::nan(""); },
        [](const irradiance_point& a, const irradiance_point& b) { return a.light == b.light && a.tilt_deg == b.tilt_deg; });
    return out;
}

// The irradiance table's records.
inline std::vector<record> irradiance_table(const std::vector<irradiance_point>& points) {
    std::vector<record> out;
    out.reserve(points.size());
    for (const auto& p : points) {
        record r{"irradiance", {}};
        r.set("light", std::string(light_name(p.light)))
            .set("ratio", p.ratio)
            .set("ratio_input", p.ratio_input)
            .set("tilt_deg", p.tilt_deg)
            .set("tilt_input", p.tilt_input)
            .set("case", std::string(p.cap_case))
            .set("E_quadrature", to_decimal(p.quadrature, 34))
            .set("E_closed_form", to_decimal(p.closed_form, 34))
            .set("E_point", to_decimal(p.point, 34))
            .set("rel_error", p.rel_error)
            .set("error_estimate", p.error_estimate)
            .set("digits", p.digits)
            .set("normalized", p.normalized ? field_value(to_decimal(*p.normalized, 34)) : field_value(nullptr))
            .set("deviation", optional_field(p.deviation))
            .set("pass", p.pass)
            .set("observed_order", optional_field(p.observed_order));
        out.push_back(std::move(r));
    }
    return out;
}

inline std::vector<record> irradiance_table(const std::vector<light_kind>& lights, const std::vector<ratio_input>& ratios,
                                            const std::vector<decimal>& tilts, unsigned jobs,
                                            const irradiance_settings& s = {}) {
    return irradiance_table(irradiance_points(lights, ratios, tilts, jobs, s));
}

// Per light and tilt: the fewest digits, whether the point light is met exactly at every
// radius, from which ratio on it is met within the bound, and the orders seen on the way.
struct irradiance_limit {
    light_kind light = light_kind::sphere;
    double tilt_deg = 0;
    double fewest_digits = INFINITY;
    std::optional<bool> point_light_exact_at_every_ratio;  // none where no ratio has a point light
    std::optional<double> within_bound_from_ratio;          // none where the smallest ratio is not within
    std::optional<double> deviation_at_smallest_ratio;
    std::optional<double> mean_observed_order;
    std::int64_t orders_observed = 0;
    bool pass = true;
};

// From the points of irradiance_points (grouped by light and tilt).
inline std::vector<irradiance_limit> irradiance_limit_summary(const std::vector<irradiance_point>& points) {
    std::vector<irradiance_limit> out;
    for (std::size_t i = 0; i < points.size();) {
        irradiance_limit s;
        s.light = points[i].light, s.tilt_deg = points[i].tilt_deg;
        double order_sum = 0;
        bool has_point = false, exact_everywhere = true;
        std::size_t j = i;
        // (j == i: a NaN tilt is a group of its own)
        for (; j < points.size() && (j == i || (points[j].light == s.light && points[j].tilt_deg == s.tilt_deg)); ++j) {
            const irradiance_point& p = points[j];
            s.fewest_digits = std::min(s.fewest_digits, p.digits);
            s.pass = s.pass && p.pass;
            if (!p.deviation || std::isnan(*p.deviation)) continue;
            const double dev = *p.deviation;
            has_point = true;
            const bool within = std::abs(dev) <= p.deviation_error + 4 * static_cast<double>(eps<quad>());
            if (within && !s.within_bound_from_ratio) s.within_bound_from_ratio = p.ratio;
            if (!within) s.within_bound_from_ratio.reset(), exact_everywhere = false;
            s.deviation_at_smallest_ratio = dev;
            if (p.observed_order && !std::isnan(*p.observed_order)) order_sum += *p.observed_order, ++s.orders_observed;
        }
        if (has_point) s.point_light_exact_at_every_ratio = exact_everywhere;
        if (s.orders_observed) s.mean_observed_order = order_sum / static_cast<double>(s.orders_observed);
        out.push_back(s);
        i = j;
    }
    return out;
}

// The irradiance-limit table's records.
inline std::vector<record> irradiance_limit_table(const std::vector<irradiance_limit>& limits) {
    std::vector<record> out;
    for (const auto& s : limits) {
        record r{"irradiance-limit", {}};
        r.set("light", std::string(light_name(s.light)))
            .set("tilt_deg", s.tilt_deg)
            .set("fewest_digits", s.fewest_digits)
            .set("point_light_exact_at_every_ratio", s.point_light_exact_at_every_ratio
                                                         ? field_value(*s.point_light_exact_at_every_ratio)
                                                         : field_value(nullptr))
            .set("within_bound_from_ratio", optional_field(s.within_bound_from_ratio))
            .set("deviation_at_smallest_ratio", optional_field(s.deviation_at_smallest_ratio))
            .set("mean_observed_order", optional_field(s.mean_observed_order))
            .set("orders_observed", s.orders_observed)
            .set("pass", s.pass);
        out.push_back(std::move(r));
    }
    return out;
}

// The (l_c, V) pairs of the punctual limit: polar angles in degrees, V's azimuth from l_c's.
struct punctual_pair {
    double lc_theta, v_theta, v_phi;
};
inline std::vector<punctual_pair> default_punctual_pairs() {
    return {{0, 30, 0}, {45, 40, 180}, {60, 20, 90}, {80, 75, 180}};
}
// The cone half-angles e, 1e-1 to 1e-8, as written: the head names them so.
inline std::vector<decimal> default_punctual_epsilon_inputs() {
    std::vector<decimal> e;
    for (int k = 1; k <= 8; ++k) e.emplace_back("1e-" + std::to_string(k));
    return e;
}
inline std::vector<double> default_punctual_epsilons() { return doubles_of(default_punctual_epsilon_inputs()); }
// The exponent of the forms swept in n.
inline constexpr double punctual_exponent = 32;

// "e = 1e-1 to 1e-8, four (l_c, V) pairs, n = 32": the punctual limit's grid in its head.
inline std::string punctual_grid_text() {
    return "e = " + range_text(default_punctual_epsilon_inputs()) + ", " + count_text(default_punctual_pairs().size()) +
           " (l_c, V) pairs, n = " + value_text(punctual_exponent);
}

// One form, (l_c, V) pair and cone half-angle e: the cone integral against the point light.
struct punctual_point {
    std::string model;
    double n = 0;  // 0 for a form without an exponent
    std::string_view parameter = "none";  // the form's swept parameter (n, alpha, r) and its value here
    double value = 0;
    punctual_pair pair{};
    double epsilon = 0;
    quad cone_integral = 0, point_light = 0;
    double deviation = 0;       // cone integral / point light - 1
    double deviation_error = 0;  // = error_estimate (the cone's inputs are exact)
    double error_estimate = 0;  // the cone integral's bound, relative to the point light
    bool pass = false;
    std::optional<double> observed_order;  // against the previous e of the same form and pair
};

template <class Model>
punctual_point punctual_at(const punctual_pair& pair, double e, double n, const irradiance_settings& s) {
    using std::abs;
    const quad to_rad = boost::math::constants::pi<quad>() / 180;
    const vec3<quad> lc = direction<quad>(quad(pair.lc_theta) * to_rad, quad(0));
    const vec3<quad> v = direction<quad>(quad(pair.v_theta) * to_rad, quad(pair.v_phi) * to_rad);
    // The forms swept in n at n; those indexed by a roughness (Ward's alpha, Disney's r) at the value
    // of their Monte Carlo case (a roughness of 0 is no lobe at all).
    double value = 0;
    if constexpr (brdf::has_swept_parameter<Model>())
        value = brdf::swept_parameter<Model>().name == "n" ? n : Model::monte_carlo_case.value;
    const brdf::params<double> pd = brdf::params_at<Model>(value);
    const brdf::params<quad> p{quad(Model::has_exponent ? pd.n : 0.0), quad(1), quad(pd.roughness)};
    const auto q = tiny_cone_radiance<Model>(lc, v, quad(e), p);
    const quad limit = boost::math::constants::pi<quad>() * Model::f(lc, v, p) * lc.z();
    const quad dev = q.value / limit - 1;
    const quad bound = q.abs_error / abs(limit);
    punctual_point out;
    out.model = std::string(Model::id), out.n = Model::has_exponent ? n : 0.0, out.pair = pair, out.epsilon = e;
    out.parameter = brdf::swept_parameter_name<Model>(), out.value = value;
    if (out.parameter != "n") out.n = 0;
    out.cone_integral = q.value, out.point_light = limit;
    out.deviation = static_cast<double>(dev);
    out.error_estimate = static_cast<double>(bound);
    out.deviation_error = out.error_estimate;
    out.pass = bound <= quad(std::pow(10.0, -s.digits)) || bound <= abs(dev) * quad(1e-9);
    return out;
}

// Every form, the default pairs and cone half-angles, with the orders observed between
// consecutive half-angles.
inline std::vector<punctual_point> punctual_points(const std::vector<std::string>& models, double n, unsigned jobs,
                                                   const irradiance_settings& s = {}) {
    std::vector<punctual_point> out;
    for (const auto& m : models)
        for (const auto& pr : default_punctual_pairs())
            for (double e : default_punctual_epsilons()) {
                punctual_point p;
                p.model = m, p.pair = pr, p.epsilon = e;
                out.push_back(std::move(p));
            }
    detail::parallel_for(out.size(), jobs, [&](std::size_t i) {
        with_brdf(out[i].model, [&](auto form) { out[i] = punctual_at<decltype(form)>(out[i].pair, out[i].epsilon, n, s); });
    });
    detail::observed_orders(
        out, [](const punctual_point& p) { return p.epsilon; }, [](const punctual_point& p) { return p.deviation; },
        [](const punctual_point& a, const punctual_point& b) {
            return a.model == b.model && a.pair.lc_theta == b.pair.lc_theta && a.pair.v_theta == b.pair.v_theta &&
                   a.pair.v_phi == b.pair.v_phi;
        });
    return out;
}

// The punctual-limit table's records.
inline std::vector<record> punctual_table(const std::vector<punctual_point>& points) {
    std::vector<record> out;
    out.reserve(points.size());
    for (const auto& p : points) {
        record r{"punctual-limit", {}};
        r.set("model", p.model)
            .set("n", p.n)
            .set("parameter", std::string(p.parameter))
            .set("value", p.value)
            .set("lc_theta_deg", p.pair.lc_theta)
            .set("v_theta_deg", p.pair.v_theta)
            .set("v_phi_deg", p.pair.v_phi)
            .set("epsilon", p.epsilon)
            .set("cone_integral", to_decimal(p.cone_integral, 34))
            .set("point_light", to_decimal(p.point_light, 34))
            .set("deviation", p.deviation)
            .set("error_estimate", p.error_estimate)
            .set("pass", p.pass)
            .set("observed_order", optional_field(p.observed_order));
        out.push_back(std::move(r));
    }
    return out;
}

inline std::vector<record> punctual_table(const std::vector<std::string>& models, double n, unsigned jobs,
                                          const irradiance_settings& s = {}) {
    return punctual_table(punctual_points(models, n, jobs, s));
}

inline std::vector<table_info> irradiance_infos(const std::vector<double>& ratios) {
    std::vector<double> shown;
    for (double x : {1e-1, 1e-2, 1e-3, 1e-5, 1e-10, 1e-15, 1e-30, 1e-300})
        if (std::find(ratios.begin(), ratios.end(), x) != ratios.end()) shown.push_back(x);
    if (shown.size() < 2) shown = ratios;
    std::vector<table_info> infos{
        {"irradiance",
         "Irradiance of sphere and disk lights by quadrature over the cap, against the closed forms and the point light",
         {"units: L = 1, r = 1, so r0 = ratio and I = pi ratio^2; sphere sin b = ratio, disk (facing the receiver) "
          "tan b = ratio; tilt_deg: the light centre's angle from N",
          "quadrature in binary128 over the cap in its own frame, horizon clipped: Gauss-Legendre 30 x 30 against "
          "20 x 20 (error_estimate: their difference + rounding, relative); the clipped part in v with "
          "tan(alpha) = tan(|90 deg - t|) cosh(v), which makes the azimuth limit analytic",
          "closed forms: above the horizon pi sin^2 b cos t_c; crossing it, Snyder 1996 as written in \"Moving "
          "Frostbite to physically based rendering\" (Lagarde and de Rousiers 2014), rearranged without "
          "cancellation; below, 0",
          "normalized = E r^2 / (I cos t_c) = E / E_point; deviation = normalized - 1; observed_order: "
          "ln(deviation ratio) / ln(ratio ratio) between consecutive ratios where both deviations are resolved",
          "pass: |quadrature - closed form| <= both bounds, and error_estimate <= 1e-30",
          "ratio_input, tilt_input: the inputs as given (decimals, or a scene's radius/distance); the quadrature "
          "and the closed form take them rounded to binary128, and error_estimate adds how far that rounding moves "
          "E (docs/irradiance.md, \"Inputs are decimals\")"},
         {"light", "tilt_deg", "ratio", "case", "E_quadrature", "digits", "deviation", "observed_order", "pass"},
         {},
         pivot_view{{"light", "tilt_deg"}, "ratio", shown, "deviation"}},
        {"irradiance-limit",
         "The limit r0/r -> 0 at fixed intensity: where the point light I cos t_c / r^2 is met, and how fast",
         {"per light and tilt over the ratios swept; within_bound_from_ratio: the largest ratio from which on every "
          "deviation is within the quadrature's bound (the point light is then exact to working precision)",
          "mean_observed_order over the steps where the deviation is resolved (2 for the disk: pi L r0^2 / "
          "(r^2 + r0^2) = I/r^2 (1 - (r0/r)^2 + ...))"},
         {"light", "tilt_deg", "fewest_digits", "point_light_exact_at_every_ratio", "within_bound_from_ratio",
          "deviation_at_smallest_ratio", "mean_observed_order", "pass"}},
        {"punctual-limit",
         "The punctual-light limit: a tiny cone of half-angle e against pi f(l_c, V) c_light (N.l_c), every form",
         {"KlayGE wiki \"Physically-based BRDF\": radiance c_light / sin^2 e in the cone (c_light = 1), so that "
          "(1/pi) integral L_tiny (N.L) = c_light at l_c = N; n = " + value_text(punctual_exponent) +
              ", k_s = 1; the forms indexed by a roughness "
          "(parameter alpha or r) at the value of their Monte Carlo case",
          "cone integral in binary128: Gauss-Legendre 30 in the polar angle with 32 azimuths, against 20 with 24 "
          "(error_estimate, relative to the point value)",
          "deviation = cone integral / point value - 1; observed_order between consecutive e where resolved",
          "pass: error_estimate <= 1e-30, or below 1e-9 of the deviation (the deviation known to 9 digits)"},
         {"model", "lc_theta_deg", "v_theta_deg", "v_phi_deg", "epsilon", "deviation", "error_estimate",
          "observed_order", "pass"},
         {},
         pivot_view{{"model", "lc_theta_deg", "v_theta_deg", "v_phi_deg"}, "epsilon", default_punctual_epsilons(),
                    "deviation"}}};
    table_info &irradiance = infos[0], &limit = infos[1], &punctual = infos[2];
    irradiance.id_keys = {"light_name", "light", "ratio", "tilt_deg", "case"};
    irradiance.check = {{{"E_quadrature", "error_estimate", true}},
                        {"rel_error", "error_estimate", "digits", "normalized", "deviation", "observed_order"}};
    limit.id_keys = {"light", "tilt_deg"};
    limit.check = {{}, {"fewest_digits", "deviation_at_smallest_ratio", "mean_observed_order", "orders_observed"}};
    punctual.id_keys = {"model", "n", "lc_theta_deg", "v_theta_deg", "v_phi_deg", "epsilon"};
    punctual.check = {{{"cone_integral", "error_estimate", true}}, {"deviation", "error_estimate", "observed_order"}};
    return infos;
}

}  // namespace verify
