// The enclosures table: every zoo row at the zoo's default exponents (lambert once), its
// integral enclosed rigorously by Arb (enclosure.hpp) and the normalization 1/I as a ball,
// shown beside normzoo's binary128 1D quadrature (tables/zoo.hpp) and the row's closed form in
// 80 digits, each computed independently of the other two.
//   closed_form_inside  the closed form (80 digits) lies inside the enclosure;
//   quadrature_inside   the enclosure lies inside quadrature +- its own error estimate: the
//                       quadrature's claimed bound is proved to hold (a 34-digit value cannot lie
//                       inside a 1e-40-wide enclosure; its certified error is reported too).
#pragma once
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <functional>
#include <string>
#include <vector>

#include <normzoo/certify/enclosure.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/real.hpp>
#include <normzoo/registry.hpp>

#include "../record.hpp"
#include "zoo.hpp"

namespace verify::certify {

// The certified tables read the library's certified core unqualified.
using namespace normzoo::certify;

using closed_form_real = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<80>,
                                                        boost::multiprecision::et_off>;

struct enclosure_check {
    double rel_radius_goal = 1e-40;  // the enclosure must be at least this tight
    slong digits = 45;               // printed digits of the enclosure's midpoint
};

template <class Row>
record enclosure_record(const decimal& n_in, const enclosure_check& c = {}, const enclosure_settings& s = {}) {
    const decimal n = Row::has_exponent ? n_in : decimal();
    const auto q = zoo_norm_1d<Row>(n);  // binary128, with its own error estimate (it covers n's rounding)
    const enclosure e = enclose_zoo_integral<Row>(n, static_cast<double>(1 / q.norm), s);
    const slong prec = s.prec;
    const ball& norm = e.normalization;

    // The row's closed_form, in 80 digits: its rounding (~1e-78) is far inside any enclosure,
    // so "inside" tests the closed form and not its arithmetic.
    const closed_form_real closed = Row::closed_form(n.to<closed_form_real>());
    const ball closed_ball = ball::parse(to_decimal(closed, 80), prec);
    const bool closed_inside = norm.contains(closed_ball);

    // The quadrature as the interval it claims: q (to 36 digits: exact for its 113 bits plus a
    // hair) +- its error estimate times |q|.
    ball quad_ball = ball::parse(to_decimal(q.norm, 36), prec);
    const ball quad_mid = quad_ball;
    {
        ball err = ball::parse(to_decimal(q.rel_error * abs(q.norm), 6), prec);
        arb_abs(err.get(), err.get());
        arb_add_error(quad_ball.get(), err.get());
    }
    const bool quad_inside = quad_ball.contains(norm);
    // |q - truth| / truth <= (|q - mid| + rad) / (mid - rad): an upper bound of the true error.
    ball diff = quad_mid - norm;
    arb_abs(diff.get(), diff.get());
    double certified_error = HUGE_VAL;
    {
        arf_t top;
        arf_init(top);
        ball ratio = diff / norm;
        arb_get_abs_ubound_arf(top, ratio.get(), 53);
        certified_error = arf_get_d(top, ARF_RND_UP);
        arf_clear(top);
    }
    const auto [mid_text, radius] = norm.printed(c.digits);
    const double rel_radius = norm.rel_radius();
    const bool converged = e.status == ARB_CALC_SUCCESS;
    record r{"enclosures", {}};
    r.set("row", std::string(Row::id))
        .set("n", n.to<double>())
        .set("n_input", n.text())
        .set("enclosure_mid", mid_text)
        .set("enclosure_radius", radius)
        .set("enclosure_rel_radius", rel_radius)
        .set("norm_quadrature", to_decimal(q.norm, 34))
        .set("quadrature_error_estimate", static_cast<double>(q.rel_error))
        .set("quadrature_error_certified", certified_error)
        .set("quadrature_inside", quad_inside)
        .set("norm_closed_form", to_decimal(closed, 50))
        .set("closed_form_inside", closed_inside)
        .set("literature", std::string(Row::literature))
        .set("arb_converged", converged)
        .set("seconds", e.seconds)
        .set("pass", converged && closed_inside && quad_inside && rel_radius <= c.rel_radius_goal);
    return r;
}

inline table_info enclosures_info(const enclosure_settings& s = {}, const enclosure_check& c = {}) {
    table_info info{
        "enclosures",
        "Rigorous enclosures of every zoo row's normalization, beside the quadrature and the closed form",
        {"enclosure: Arb " + std::string(arb_version) + " acb_calc_integrate of 2 pi x the reduced integrand "
             "(the row's weight() on complex balls) over t in [0, pi/2], at " + std::to_string(s.prec) +
             " bits, relative goal 2^-" + std::to_string(s.goal_bits) + "; then 1/I as a ball",
         "cos^n for non-integer n: principal branch, reported non-analytic where cos(alpha t) touches "
             "(-inf, 0] (t = pi/2 when alpha = 1), so Arb bisects towards it and bounds the last pieces by |cos|^n",
         "enclosure_mid +- enclosure_radius holds 1/I (the radius covers the printed midpoint's rounding); "
             "enclosure_rel_radius must be <= " + to_decimal(c.rel_radius_goal, 1),
         "quadrature: normzoo's binary128 1D value (as in the zoo table); quadrature_inside: the enclosure lies "
             "inside quadrature +- quadrature_error_estimate; quadrature_error_certified: its true relative "
             "error, bounded from the enclosure",
         "closed form: the row's closed_form in cpp_bin_float<80> (shown to 50 digits); closed_form_inside: it lies in the enclosure",
         "seconds: wall time of the Arb integration alone",
         "n_input: the exponent as given, a decimal: Arb takes it exactly (a ball around it), the closed form "
         "in 80 digits, the quadrature's estimate covers its rounding to binary128"},
        {"row", "n_input", "enclosure_mid", "enclosure_radius", "norm_quadrature", "quadrature_error_certified",
         "quadrature_inside", "norm_closed_form", "closed_form_inside", "seconds", "pass"},
        {"enclosure_mid", "norm_quadrature", "norm_closed_form"}};
    info.id_keys = {"row", "n"};
    info.check = {{{"enclosure_mid", "enclosure_rel_radius", true}, {"norm_quadrature", "quadrature_error_estimate", true}},
                  {"enclosure_radius", "enclosure_rel_radius", "quadrature_error_estimate", "quadrature_error_certified",
                   "seconds"}};
    return info;
}

// Every registry row at every exponent (rows without an exponent once), on `jobs` threads.
inline std::vector<record> enclosures_table(const std::vector<decimal>& exponents, unsigned jobs) {
    std::vector<std::function<record()>> tasks;
    for_each_zoo_row([&](auto row) {
        using Row = decltype(row);
        if (!Row::has_exponent) {
            tasks.push_back([] { return enclosure_record<Row>(decimal()); });
            return;
        }
        for (const auto& n : exponents) tasks.push_back([n] { return enclosure_record<Row>(n); });
    });
    std::vector<record> out(tasks.size());
    normzoo::detail::parallel_for(tasks.size(), jobs, [&](std::size_t i) {
        out[i] = tasks[i]();
        release_thread_caches();
    });
    return out;
}

}  // namespace verify::certify
