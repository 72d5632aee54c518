// Default parameter grids of the tables.
#pragma once
#include <cmath>
#include <vector>

#include <normzoo/check.hpp>  // default_energy_exponents, default_energy_angles

namespace normzoo {

// The zoo's default exponents: small, powers of two, and up to 1e7.
inline std::vector<double> default_zoo_exponents() {
    return {0, 0.1, 0.5, 1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 1e4, 1e5, 1e6, 1e7};
}

// n = 0 and `count` exponents log-spaced from `from` to `to`, both ends included.
inline std::vector<double> log_grid_with_zero(double from, double to, int count) {
    std::vector<double> n{0};
    const double a = std::log10(from), b = std::log10(to);
    for (int k = 0; k < count; ++k) n.push_back(std::pow(10.0, a + (b - a) * k / (count - 1)));
    n.back() = to;
    return n;
}

inline std::vector<double> default_bounds_exponents() { return log_grid_with_zero(1e-6, 1e7, 1000); }

}  // namespace normzoo
