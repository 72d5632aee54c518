// The irradiance tables (SPEC section 4): sphere and disk lights at every ratio r0/r and tilt,
// by quadrature against the closed forms and against the point light I cos t_c / r^2, with the
// convergence order observed as r0/r -> 0; and the punctual-light limit of a tiny cone for
// every BRDF form, with its observed order as the cone shrinks.
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include <normzoo/detail/parallel.hpp>
#include <normzoo/irradiance.hpp>
#include <normzoo/real.hpp>
#include <normzoo/registry.hpp>

#include "../record.hpp"
#include "energy.hpp"

namespace normzoo {

struct irradiance_settings {
    double digits = 30;  // the quadrature's bound must show this many correct digits
};

inline std::vector<double> default_irradiance_ratios() {
    std::vector<double> r;
    for (int k = 1; k <= 15; ++k) r.push_back(std::pow(10.0, -k));
    for (double x : {1e-30, 1e-100, 1e-300}) r.push_back(x);
    return r;
}

// Tilts of the light's centre from N; 90.5 and 95 degrees still see part of the larger caps.
inline std::vector<double> default_irradiance_tilts() { return {0, 30, 60, 85, 89.9, 90.5, 95}; }

namespace detail {

// The order p of a deviation d ~ C ratio^p between consecutive rows, where both deviations are
// well above what the quadrature can resolve (1e3 times their bounds); null elsewhere.
inline void observed_orders(std::vector<record>& rows, const char* x_key, const char* dev_key,
                            const char* bound_key, const std::vector<std::string>& group_keys) {
    auto group_of = [&](const record& r) {
        std::string g;
        for (const auto& k : group_keys) {
            const field_value* v = r.find(k);
            g += v && std::holds_alternative<std::string>(*v) ? std::get<std::string>(*v)
                                                             : format_number(number_field(r, k));
            g += "|";
        }
        return g;
    };
    for (std::size_t i = 0; i < rows.size(); ++i) {
        field_value order = nullptr;
        if (i > 0 && group_of(rows[i]) == group_of(rows[i - 1])) {
            const double d0 = std::abs(number_field(rows[i - 1], dev_key)), d1 = std::abs(number_field(rows[i], dev_key));
            const double b0 = number_field(rows[i - 1], bound_key), b1 = number_field(rows[i], bound_key);
            if (d0 > 1e3 * b0 && d1 > 1e3 * b1)
                order = std::log(d0 / d1) / std::log(number_field(rows[i - 1], x_key) / number_field(rows[i], x_key));
        }
        rows[i].set("observed_order", order);
    }
}

}  // namespace detail

inline record irradiance_record(light_kind kind, double ratio, double tilt, const irradiance_settings& s) {
    using std::abs;
    const auto cap = light_cap<quad>::of(kind, quad(ratio));
    const degrees_angle<quad> t(tilt);
    const auto q = cap_irradiance(cap, t);
    const auto closed = cap_irradiance_closed_form(cap, t);
    const quad pi = boost::math::constants::pi<quad>();
    const quad point = pi * quad(ratio) * quad(ratio) * (t.cos_t > 0 ? t.cos_t : quad(0));  // I cos t_c / r^2
    const quad scale = closed.value != 0 ? closed.value : quad(1);
    const quad rel = abs(q.value - closed.value) / scale;
    const quad bound = q.abs_error / (q.value != 0 ? abs(q.value) : quad(1));
    const bool agrees = abs(q.value - closed.value) <= q.abs_error + closed.abs_error;
    record r{"irradiance", {}};
    r.set("light", std::string(light_name(kind)))
        .set("ratio", ratio)
        .set("tilt_deg", tilt)
        .set("case", std::string(cap_case(cap, t)))
        .set("E_quadrature", to_decimal(q.value, 34))
        .set("E_closed_form", to_decimal(closed.value, 34))
        .set("E_point", to_decimal(point, 34))
        .set("rel_error", static_cast<double>(rel))
        .set("error_estimate", static_cast<double>(bound))
        .set("digits", digits_of(rel > bound ? rel : bound));
    if (point > 0) {
        // E r^2 / (I cos t_c) and its deviation from 1, both from the quadrature.
        const quad normalized = q.value / point;
        r.set("normalized", to_decimal(normalized, 34)).set("deviation", static_cast<double>(normalized - 1));
    } else {
        r.set("normalized", nullptr).set("deviation", nullptr);
    }
    r.set("pass", agrees && bound <= quad(std::pow(10.0, -s.digits)));
    return r;
}

// Every light, tilt and ratio (rows grouped by light and tilt, ratios in the order given).
inline std::vector<record> irradiance_table(const std::vector<light_kind>& lights, const std::vector<double>& ratios,
                                            const std::vector<double>& tilts, unsigned jobs,
                                            const irradiance_settings& s = {}) {
    struct point {
        light_kind kind;
        double ratio, tilt;
    };
    std::vector<point> points;
    for (auto k : lights)
        for (double t : tilts)
            for (double x : ratios) points.push_back({k, x, t});
    std::vector<record> out(points.size());
    detail::parallel_for(points.size(), jobs,
                         [&](std::size_t i) { out[i] = irradiance_record(points[i].kind, points[i].ratio, points[i].tilt, s); });
    detail::observed_orders(out, "ratio", "deviation", "error_estimate", {"light", "tilt_deg"});
    return out;
}

// Per light and tilt: the fewest digits, whether the point light is met exactly at every
// radius, from which ratio on it is met within the bound, and the orders seen on the way.
inline std::vector<record> irradiance_limit_summary(const std::vector<record>& rows) {
    using detail::number_field;
    using detail::text_field;
    std::vector<record> out;
    for (std::size_t i = 0; i < rows.size();) {
        std::size_t j = i;
        const std::string light = text_field(rows[i], "light");
        const double tilt = number_field(rows[i], "tilt_deg");
        double fewest = INFINITY, exact_from = std::nan(""), order_sum = 0, last_dev = std::nan("");
        int orders = 0;
        bool all_pass = true, has_point = false, exact_everywhere = true;
        for (; j < rows.size() && text_field(rows[j], "light") == light && number_field(rows[j], "tilt_deg") == tilt; ++j) {
            const record& r = rows[j];
            fewest = std::min(fewest, number_field(r, "digits"));
            all_pass = all_pass && !r.failed();
            const double dev = number_field(r, "deviation");
            if (std::isnan(dev)) continue;
            has_point = true;
            const bool within = std::abs(dev) <= number_field(r, "error_estimate") + 4 * static_cast<double>(eps<quad>());
            if (within && std::isnan(exact_from)) exact_from = number_field(r, "ratio");
            if (!within) exact_from = std::nan(""), exact_everywhere = false;
            last_dev = dev;
            const double p = number_field(r, "observed_order");
            if (!std::isnan(p)) order_sum += p, ++orders;
        }
        record s{"irradiance-limit", {}};
        s.set("light", light)
            .set("tilt_deg", tilt)
            .set("fewest_digits", fewest)
            .set("point_light_exact_at_every_ratio", has_point ? field_value(exact_everywhere) : field_value(nullptr))
            .set("within_bound_from_ratio", std::isnan(exact_from) ? field_value(nullptr) : field_value(exact_from))
            .set("deviation_at_smallest_ratio", std::isnan(last_dev) ? field_value(nullptr) : field_value(last_dev))
            .set("mean_observed_order", orders ? field_value(order_sum / orders) : field_value(nullptr))
            .set("orders_observed", static_cast<std::int64_t>(orders))
            .set("pass", all_pass);
        out.push_back(std::move(s));
        i = j;
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
inline std::vector<double> default_punctual_epsilons() {
    std::vector<double> e;
    for (int k = 1; k <= 8; ++k) e.push_back(std::pow(10.0, -k));
    return e;
}

template <class Model>
record punctual_record(const punctual_pair& pair, double e, double n, const irradiance_settings& s) {
    using std::abs;
    const quad to_rad = boost::math::constants::pi<quad>() / 180;
    const vec3<quad> lc = direction<quad>(quad(pair.lc_theta) * to_rad, quad(0));
    const vec3<quad> v = direction<quad>(quad(pair.v_theta) * to_rad, quad(pair.v_phi) * to_rad);
    const brdf::params<quad> p{quad(Model::has_exponent ? n : 0.0), quad(1)};
    const auto q = tiny_cone_radiance<Model>(lc, v, quad(e), p);
    const quad limit = boost::math::constants::pi<quad>() * Model::f(lc, v, p) * lc.z();
    const quad dev = q.value / limit - 1;
    const quad bound = q.abs_error / abs(limit);
    record r{"punctual-limit", {}};
    r.set("model", std::string(Model::id))
        .set("n", Model::has_exponent ? n : 0.0)
        .set("lc_theta_deg", pair.lc_theta)
        .set("v_theta_deg", pair.v_theta)
        .set("v_phi_deg", pair.v_phi)
        .set("epsilon", e)
        .set("cone_integral", to_decimal(q.value, 34))
        .set("point_light", to_decimal(limit, 34))
        .set("deviation", static_cast<double>(dev))
        .set("error_estimate", static_cast<double>(bound))
        .set("pass", bound <= quad(std::pow(10.0, -s.digits)) || bound <= abs(dev) * quad(1e-9));
    return r;
}

inline std::vector<record> punctual_table(const std::vector<std::string>& models, double n, unsigned jobs,
                                          const irradiance_settings& s = {}) {
    struct point {
        std::string model;
        punctual_pair pair;
        double e;
    };
    std::vector<point> points;
    for (const auto& m : models)
        for (const auto& pr : default_punctual_pairs())
            for (double e : default_punctual_epsilons()) points.push_back({m, pr, e});
    std::vector<record> out(points.size());
    detail::parallel_for(points.size(), jobs, [&](std::size_t i) {
        with_brdf(points[i].model,
                  [&](auto form) { out[i] = punctual_record<decltype(form)>(points[i].pair, points[i].e, n, s); });
    });
    detail::observed_orders(out, "epsilon", "deviation", "error_estimate",
                            {"model", "lc_theta_deg", "v_theta_deg", "v_phi_deg"});
    return out;
}

inline std::vector<table_info> irradiance_infos(const std::vector<double>& ratios) {
    std::vector<double> shown;
    for (double x : {1e-1, 1e-2, 1e-3, 1e-5, 1e-10, 1e-15, 1e-30, 1e-300})
        if (std::find(ratios.begin(), ratios.end(), x) != ratios.end()) shown.push_back(x);
    if (shown.size() < 2) shown = ratios;
    return {
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
          "pass: |quadrature - closed form| <= both bounds, and error_estimate <= 1e-30"},
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
          "(1/pi) integral L_tiny (N.L) = c_light at l_c = N; n = 32, k_s = 1",
          "cone integral in binary128: Gauss-Legendre 30 in the polar angle with 32 azimuths, against 20 with 24 "
          "(error_estimate, relative to the point value)",
          "deviation = cone integral / point value - 1; observed_order between consecutive e where resolved",
          "pass: error_estimate <= 1e-30, or below 1e-9 of the deviation (the deviation known to 9 digits)"},
         {"model", "lc_theta_deg", "v_theta_deg", "v_phi_deg", "epsilon", "deviation", "error_estimate",
          "observed_order", "pass"},
         {},
         pivot_view{{"model", "lc_theta_deg", "v_theta_deg", "v_phi_deg"}, "epsilon", default_punctual_epsilons(),
                    "deviation"}}};
}

}  // namespace normzoo
