// A grid in words, made from its values: the text a table's head shows after its command
// (docs/reference.md, "The head of a table"), so that a grid changed is a text changed and
// there is no second copy of its values to keep in step.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <normzoo/decimal.hpp>

#include "../library_names.hpp"

namespace verify {

// A double as the source files write one: the fewest digits that read back as it, plainly from
// 0.01 up to 1e4 (0.05, 89.99, 2048), else as a power of ten (1e-3, 1e4, 2.5e-7).
inline std::string value_text(double x) {
    char text[48];
    const double magnitude = std::abs(x);
    if (x == 0 || (magnitude >= 0.01 && magnitude < 1e4)) {
        for (int decimals = 0; decimals <= 20; ++decimals) {
            std::snprintf(text, sizeof text, "%.*f", decimals, x);
            if (std::strtod(text, nullptr) == x) return text;
        }
    }
    for (int digits = 0; digits <= 16; ++digits) {
        std::snprintf(text, sizeof text, "%.*e", digits, x);
        if (std::strtod(text, nullptr) == x) break;
    }
    // "2.5e-07" -> "2.5e-7", "1e+04" -> "1e4"
    std::string s = text;
    const std::size_t e = s.find('e');
    const int exponent = std::atoi(s.c_str() + e + 1);
    return s.substr(0, e) + "e" + std::to_string(exponent);
}

// A count of a few things in words ("four metals"), in digits from 13 on.
inline std::string count_text(std::size_t count) {
    static const char* const words[] = {"no",    "one",  "two", "three",  "four",  "five",  "six",
                                        "seven", "eight", "nine", "ten", "eleven", "twelve"};
    return count < sizeof words / sizeof *words ? words[count] : std::to_string(count);
}

namespace detail {

// A value of a grid: its text (a decimal's as written, a double's as value_text writes it) and
// its exact value, so that steps are compared exactly (0.2 - 0.1 is 0.3 - 0.2).
struct grid_item {
    std::string text;
    decimal value;
};

inline std::vector<grid_item> grid_items(const std::vector<decimal>& grid) {
    std::vector<grid_item> items;
    for (const auto& x : grid) items.push_back({x.text(), x});
    return items;
}

inline std::vector<grid_item> grid_items(const std::vector<double>& grid) {
    std::vector<grid_item> items;
    for (double x : grid) items.push_back({value_text(x), decimal::shortest(x)});
    return items;
}

// The runs a list's text shortens: integers counting by one (0, 1, ..., 89) or doubling (1, 2, 4,
// ..., 2048), shown by their first terms and their last; other values by a constant step (0.1 to
// 1 by 0.1) or by factors of ten (1e-1 to 1e-15 by decades), shown as a range.
enum class run_kind { counting, doubling, decades, stepped };

inline bool is_integer(const decimal& x) { return x.is_zero() || x.exponent() >= 0; }

// Whether b follows a in a run of kind k whose first two terms are first, second.
inline bool follows(run_kind k, const decimal& first, const decimal& second, const decimal& a, const decimal& b) {
    switch (k) {
        case run_kind::counting: return is_integer(a) && is_integer(b) && b - a == decimal("1");
        case run_kind::doubling: return is_integer(a) && is_integer(b) && a > decimal("0") && b - a == a;
        case run_kind::decades:  // the same digits a power of ten up, or down, as the run's first step
            return !a.is_zero() && a.negative() == b.negative() && a.coefficient() == b.coefficient() &&
                   std::abs(b.exponent() - a.exponent()) == 1 &&
                   b.exponent() - a.exponent() == second.exponent() - first.exponent();
        case run_kind::stepped: return b - a == second - first && !(second - first).is_zero();
    }
    return false;
}

inline std::size_t run_length(const std::vector<grid_item>& v, std::size_t i, run_kind k) {
    if (i + 1 >= v.size()) return 1;
    std::size_t j = i + 1;
    while (j < v.size() && follows(k, v[i].value, v[i + 1].value, v[j - 1].value, v[j].value)) ++j;
    return j - i;
}

// A run shortened only from five values on: four are all shown anyway ("1, 10, 100, 1000";
// Ward's "0.1, 0.3, 0.5, 0.7, 1" keeps its 1 in the list).
inline constexpr std::size_t shortest_run = 5;

inline std::string list_text(const std::vector<grid_item>& v) {
    std::string out;
    for (std::size_t i = 0; i < v.size();) {
        if (!out.empty()) out += ", ";
        run_kind kind = run_kind::counting;
        std::size_t length = 1;
        for (run_kind k : {run_kind::counting, run_kind::doubling, run_kind::decades, run_kind::stepped})
            if (run_length(v, i, k) > length) kind = k, length = run_length(v, i, k);
        if (length < shortest_run) {
            out += v[i++].text;
            continue;
        }
        const std::string& last = v[i + length - 1].text;
        switch (kind) {
            case run_kind::counting: out += v[i].text + ", " + v[i + 1].text + ", ..., " + last; break;
            case run_kind::doubling: out += v[i].text + ", " + v[i + 1].text + ", " + v[i + 2].text + ", ..., " + last; break;
            case run_kind::decades: out += v[i].text + " to " + last + " by decades"; break;
            case run_kind::stepped:
                out += v[i].text + " to " + last + " by " + value_text((v[i + 1].value - v[i].value).to<double>());
                break;
        }
        i += length;
    }
    return out;
}

}  // namespace detail

// Every value of a grid, its runs shortened: "0, 0.1, 0.5, 1, 2, 4, ..., 2048, 1e4, 1e5",
// "0, 1, ..., 89, 89.5, 89.9, 89.99", "1e-4, 1e-3, 0.01, 0.05, 0.1 to 1 by 0.1".
inline std::string list_text(const std::vector<decimal>& grid) { return detail::list_text(detail::grid_items(grid)); }
inline std::string list_text(const std::vector<double>& grid) { return detail::list_text(detail::grid_items(grid)); }

// A grid by its ends, where the head names only those: "1e-1 to 1e-8".
inline std::string range_text(const decimal& first, const decimal& last) { return first.text() + " to " + last.text(); }
inline std::string range_text(double first, double last) { return value_text(first) + " to " + value_text(last); }
template <class Grid>
std::string range_text(const Grid& grid) {
    return range_text(grid.front(), grid.back());
}

}  // namespace verify
