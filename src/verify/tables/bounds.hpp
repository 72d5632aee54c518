// The bounds table: the Blinn-Phong bounds (zoo/blinn_phong_bounds.hpp) decided in 50 digits
// at every exponent, with the naive margins in the same precision and in double beside them.
#pragma once
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <normzoo/zoo/blinn_phong_bounds.hpp>
#include <normzoo/decimal.hpp>
#include <normzoo/real.hpp>
#include <normzoo/wide.hpp>

#include "../record.hpp"

namespace verify {

namespace detail {

inline double log10_or_null(const wide& x) { return x > 0 ? static_cast<double>(log10(x)) : -INFINITY; }

// lower = (n + lower_offset) / (8 pi), upper = (n + upper_offset) / (8 pi)
template <class Row>
record bounds_record(const decimal& n_in, bound_margins (*margins)(const wide&), double lower_offset, double upper_offset) {
    using std::abs;
    const wide n = n_in.to<wide>();
    const bound_margins m = margins(n);
    const bool holds = m.lower_margin > 0 && m.upper_margin > 0;
    const bool equality = m.lower_margin == 0 || m.upper_margin == 0;
    // Cross-checks: the naive margins in 50 digits agree to their absolute rounding (~1e-48);
    // in double, the same naive margins (what a double-precision check would see).
    const wide naive_lower = m.norm / m.lower - 1, naive_upper = 1 - m.norm / m.upper;
    const bool consistent = abs(naive_lower - m.lower_margin) < wide(1e-45) && abs(naive_upper - m.upper_margin) < wide(1e-45);
    const double nd = n_in.to<double>(), nd_norm = Row::closed_form(nd);
    const double lo_d = nd_norm / ((nd + lower_offset) / (8 * M_PI)) - 1;
    const double up_d = 1 - nd_norm / ((nd + upper_offset) / (8 * M_PI));
    // n = 0 is where the upper bound becomes an equality (docs/conventions.md, "The zoo rows"); everywhere else strict.
    const bool expected = n_in.is_zero() ? (m.lower_margin > 0 && m.upper_margin == 0) : holds;
    record r{"bounds", {}};
    r.set("row", std::string(Row::id))
        .set("n", nd)
        .set("n_input", n_in.text())
        .set("norm", to_decimal(m.norm, 34))
        .set("lower", to_decimal(m.lower, 34))
        .set("upper", to_decimal(m.upper, 34))
        .set("lower_margin", to_decimal(m.lower_margin, 20))
        .set("upper_margin", to_decimal(m.upper_margin, 20))
        .set("lower_margin_log10", log10_or_null(m.lower_margin))
        .set("upper_margin_log10", log10_or_null(m.upper_margin))
        .set("holds", holds)
        .set("equality", equality)
        .set("lower_margin_double", lo_d)
        .set("upper_margin_double", up_d)
        .set("decided_in_double", lo_d > 0 && up_d > 0)
        .set("pass", expected && consistent);
    return r;
}

}  // namespace detail

inline table_info bounds_info() {
    table_info info{
        "bounds",
        "The Blinn-Phong normalization bounds, decided in high precision at every exponent",
        {"closed forms and margins in " + std::string(number_type_name<wide>) +
             " (50 digits, decimal exponent range +-6e8), margins rewritten without cancellation",
         "holds: both margins > 0 (strict); equality: a margin is exactly 0 (n = 0, upper bound)",
         "pass: strict for n > 0, upper equality at n = 0, and the naive 50-digit margins agree to 1e-45",
         "lower_margin_double: the naive margin in double, which underflows to 0 or below once the "
         "margin is under 1e-16",
         "n_input: the exponent as given, a decimal, read into 50 digits (exactly for up to 50 significant digits)"},
        {"row", "n_input", "lower_margin", "upper_margin", "holds", "equality", "decided_in_double", "pass"}};
    info.id_keys = {"row", "n"};
    return info;
}

// Each row at its own exponents (a scene's materials); an empty list leaves the row out.
inline std::vector<record> bounds_table(const std::vector<decimal>& blinn_phong_exponents,
                                        const std::vector<decimal>& blinn_phong_modified_exponents) {
    std::vector<record> out;
    for (const auto& n : blinn_phong_exponents)
        out.push_back(detail::bounds_record<zoo::blinn_phong>(n, blinn_phong_margins, 2, 4));
    for (const auto& n : blinn_phong_modified_exponents)
        out.push_back(detail::bounds_record<zoo::blinn_phong_modified>(n, blinn_phong_modified_margins, 6, 8));
    return out;
}

// Both rows at the same exponents.
inline std::vector<record> bounds_table(const std::vector<decimal>& exponents) { return bounds_table(exponents, exponents); }

}  // namespace verify
