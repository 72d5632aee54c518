// Default parameter grids of the tables.
#pragma once
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <vector>

#include <normzoo/decimal.hpp>

#include <normzoo/check.hpp>  // default_energy_exponents, default_energy_angles

#include "../library_names.hpp"
#include "grid_text.hpp"

namespace verify {

// A grid as the decimals written (docs/conventions.md, "Inputs are decimals").
inline std::vector<decimal> decimals(std::initializer_list<const char*> texts) {
    std::vector<decimal> out;
    for (const char* t : texts) out.emplace_back(t);
    return out;
}

// The zoo's default exponents: small, powers of two, and up to 1e7.
inline std::vector<decimal> default_zoo_exponents() {
    return decimals({"0", "0.1", "0.5", "1", "2", "4", "8", "16", "32", "64", "128", "256", "512", "1024", "2048", "1e4",
                     "1e5", "1e6", "1e7"});
}

// n = 0 and `count` exponents log-spaced from `from` to `to`, both ends included, each the decimal
// of 6 significant digits nearest the log-spaced point (the grid is the decimals, as printed);
// its text from the same three numbers.
struct log_grid_with_zero {
    double from, to;
    int count;
    std::vector<decimal> values() const {
        std::vector<decimal> n{decimal("0")};
        const double a = std::log10(from), b = std::log10(to);
        for (int k = 0; k < count; ++k) {
            char text[32];
            std::snprintf(text, sizeof text, "%.6g", k + 1 == count ? to : std::pow(10.0, a + (b - a) * k / (count - 1)));
            n.emplace_back(text);
        }
        return n;
    }
    std::string text() const {
        return "0 and " + std::to_string(count) + " log-spaced from " + value_text(from) + " to " + value_text(to);
    }
};

inline constexpr log_grid_with_zero default_bounds_grid{1e-6, 1e7, 1000};

inline std::vector<decimal> default_bounds_exponents() { return default_bounds_grid.values(); }

// The decimals a grid of doubles was written as (0.1 for the double nearest 0.1).
inline std::vector<decimal> shortest_decimals(const std::vector<double>& grid) {
    std::vector<decimal> out;
    for (double x : grid) out.push_back(decimal::shortest(x));
    return out;
}

inline std::vector<decimal> shortest_decimals(std::initializer_list<double> grid) {
    return shortest_decimals(std::vector<double>(grid));
}

// The energy sweep's default angles, as written: 0, 1, ..., 89, 89.5, 89.9, 89.99 degrees.
inline std::vector<decimal> default_energy_angle_inputs() { return shortest_decimals(default_energy_angles()); }

// The doubles nearest a grid's decimals (for the library calls whose input is a double).
inline std::vector<double> doubles_of(const std::vector<decimal>& grid) {
    std::vector<double> out;
    for (const auto& x : grid) out.push_back(x.to<double>());
    return out;
}


}  // namespace verify
