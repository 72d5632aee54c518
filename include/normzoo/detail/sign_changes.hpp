// Where each of N continuous functions of one variable changes sign along a grid: for each grid
// cell whose ends hold finite values of opposite signs, the root bracketed there, bisected to
// full precision (Boost.Math's bisect). f(x, values) writes the N values at x, +inf where one is
// undefined. Two roots of one function within one cell cancel: the grid must be finer than their
// spacing. The grid ascends strictly (std::invalid_argument otherwise: a cell taken backwards
// would bracket a root twice, and Boost's bisect refuses it). The albedo integrals find a G's
// kinks with it (microfacet/stretched.hpp, albedo.hpp).
#pragma once
#include <boost/math/tools/roots.hpp>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace normzoo::detail {

template <std::size_t N, class F>
std::vector<double> sign_changes(const F& f, const std::vector<double>& grid) {
    std::vector<double> roots;
    if (grid.empty()) return roots;
    for (std::size_t g = 1; g < grid.size(); ++g)
        if (!(grid[g] > grid[g - 1])) throw std::invalid_argument("sign_changes: the grid does not ascend");
    std::array<double, N> before{}, after{};
    f(grid[0], before.data());
    for (std::size_t g = 1; g < grid.size(); ++g) {
        f(grid[g], after.data());
        for (std::size_t k = 0; k < N; ++k) {
            if (!(std::isfinite(before[k]) && std::isfinite(after[k])) || (before[k] > 0) == (after[k] > 0)) continue;
            auto component = [&](double x) {
                std::array<double, N> values{};
                f(x, values.data());
                return values[k];
            };
            const auto bracket = boost::math::tools::bisect(component, grid[g - 1], grid[g], boost::math::tools::eps_tolerance<double>());
            roots.push_back((bracket.first + bracket.second) / 2);
        }
        before = after;
    }
    return roots;
}

}  // namespace normzoo::detail
