// The normalization zoo (docs/conventions.md, "The zoo rows"; docs/method.md): every row, at every exponent, three ways:
//   1D  the reduced integrand in binary128 by the lobe quadrature (>= 32 correct digits),
//   2D  the vector expression over the hemisphere in long double (>= 14 correct digits),
//   and the closed form. A record passes when both quadratures agree with the closed form
//   within their own error bounds and those bounds meet the digits asked for.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <normzoo/detail/parallel.hpp>
#include <normzoo/zoo/zoo_row.hpp>
#include <normzoo/normalization.hpp>
#include <normzoo/quadrature/hemisphere.hpp>
#include <normzoo/quadrature/lobe.hpp>
#include <normzoo/decimal.hpp>
#include <normzoo/real.hpp>
#include <normzoo/wide.hpp>
#include <normzoo/registry.hpp>

#include "../record.hpp"

namespace verify {

struct zoo_settings {
    double digits_1d = 32;   // required correct digits of the 1D value (its bound must show them)
    double digits_2d = 14;   // the same for the 2D vector integral
    unsigned azimuths = default_zoo_azimuths;  // trapezoid nodes in the azimuth of the 2D integral (V = N: any count is exact)
};

template <class Row>
record zoo_record(const decimal& n_in, const zoo_settings& s) {
    using std::abs;
    const decimal n = Row::has_exponent ? n_in : decimal();
    // Both quadratures at the decimal n (their bounds cover its rounding to binary128 and to
    // long double); the closed form in 50 digits from the same decimal, rounded to binary128.
    const auto q1 = zoo_norm_1d<Row>(n);
    const auto q2 = zoo_norm_2d<Row>(n, s.azimuths);
    const quad closed = static_cast<quad>(Row::closed_form(n.to<wide>()));
    const quad rel1 = abs(q1.norm - closed) / closed;
    const longd rel2 = abs(q2.norm - longd(closed)) / longd(closed);
    // The closed form is itself rounded (a few ulps): agreement is judged with that added.
    const bool ok1 = rel1 <= q1.rel_error + 8 * eps<quad>() && q1.rel_error <= quad(std::pow(10.0, -s.digits_1d));
    const bool ok2 = rel2 <= q2.rel_error + 8 * eps<longd>() && q2.rel_error <= std::pow(10.0L, -s.digits_2d);
    record r{"zoo", {}};
    r.set("row", std::string(Row::id))
        .set("n", n.to<double>())
        .set("n_input", n.text())
        .set("norm_quadrature", to_decimal(q1.norm, 34))
        .set("norm_closed_form", to_decimal(closed, 34))
        .set("norm_quadrature_2d", to_decimal(q2.norm, 18))
        .set("rel_error", static_cast<double>(rel1))
        .set("error_estimate", static_cast<double>(q1.rel_error))
        .set("digits", digits_of(rel1))
        .set("rel_error_2d", static_cast<double>(rel2))
        .set("error_estimate_2d", static_cast<double>(q2.rel_error))
        .set("digits_2d", digits_of(rel2))
        .set("evaluations", static_cast<std::int64_t>(q1.evaluations))
        .set("evaluations_2d", static_cast<std::int64_t>(q2.evaluations))
        .set("pass", ok1 && ok2);
    return r;
}

inline table_info zoo_info(const zoo_settings& s = {}) {
    table_info info{
        "zoo",
        "The normalization zoo: each row's normalization by 1D quadrature, 2D vector quadrature and closed form",
        {"1D: reduced integrand in " + std::string(number_type_name<quad>) +
             ", Laplace substitution x = k (-ln cos theta), k the integrand's measured decay rate in [n+1, n+8], " +
             quadrature::detail::describe_plan<quad>() + " (Boost.Math gauss)",
         "2D: vector expression (Eigen) in " + std::string(number_type_name<longd>) +
             ", same polar substitution with " + quadrature::detail::describe_plan<longd>() +
             ", periodic trapezoid with " + std::to_string(s.azimuths) +
             " azimuths checked against half of them",
         "error_estimate: |rule A - rule B| + (4 + x_last/8) ulp x L1 norm + tail bound, relative, for 1/integral",
         "pass: |quadrature - closed form| <= estimate + 8 ulp, and estimate <= 1e-" +
             std::to_string(static_cast<int>(s.digits_1d)) + " (1D), 1e-" +
             std::to_string(static_cast<int>(s.digits_2d)) + " (2D)",
         "rows without an exponent (lambert) appear once, at n = 0",
         "n_input: the exponent as given, a decimal; both quadratures take it rounded to their type and "
         "their estimates include the effect of that rounding; the closed form is evaluated at it in " +
             std::string(number_type_name<wide>) + " (docs/conventions.md, \"Inputs are decimals\")"},
        {"row", "n_input", "norm_quadrature", "norm_closed_form", "norm_quadrature_2d", "digits", "digits_2d",
         "error_estimate", "pass"}};
    info.id_keys = {"row", "n"};
    info.check = {{{"norm_quadrature", "error_estimate", true}, {"norm_quadrature_2d", "error_estimate_2d", true}},
                  {"rel_error", "error_estimate", "digits", "rel_error_2d", "error_estimate_2d", "digits_2d", "evaluations",
                   "evaluations_2d"}};
    return info;
}

// Every registry row at every exponent (rows without an exponent once), on `jobs` threads.
inline std::vector<record> zoo_table(const std::vector<decimal>& exponents, unsigned jobs, const zoo_settings& s = {}) {
    std::vector<std::function<record()>> tasks;
    for_each_zoo_row([&](auto row) {
        using Row = decltype(row);
        if (!Row::has_exponent) {
            tasks.push_back([&s] { return zoo_record<Row>(decimal(), s); });
            return;
        }
        for (const auto& n : exponents) tasks.push_back([n, &s] { return zoo_record<Row>(n, s); });
    });
    std::vector<record> out(tasks.size());
    detail::parallel_for(tasks.size(), jobs, [&](std::size_t i) { out[i] = tasks[i](); });
    return out;
}

}  // namespace verify
