// A declared parameter: what a BRDF form, a microfacet part (and so a composition) says it reads,
// one representation for all (docs/architecture.md, "Adding a model"). The command line, scenes,
// records and docs take names, meanings, ranges and defaults from these declarations.
#pragma once
#include <array>
#include <cstddef>
#include <string_view>

namespace normzoo {

// A list of values, constexpr (the grids a parameter declares).
struct value_list {
    const double* values = nullptr;
    std::size_t size = 0;
    template <std::size_t N>
    constexpr value_list(const double (&v)[N]) : values(v), size(N) {}
    constexpr value_list() = default;
    constexpr const double* begin() const { return values; }
    constexpr const double* end() const { return values + size; }
    constexpr bool empty() const { return size == 0; }
};

struct parameter {
    std::string_view name;     // "n", "alpha", "r", "specular", "f0", "eta", ...
    std::string_view meaning;  // for people
    double min, max;           // its range, [min, max], or (min, max] where min_open
    value_list sweep;          // the values the energy sweep takes; empty: held at `held`
    double held = 0;           // its value where it is not swept or not given (1 for a specular: the white furnace)
    bool min_open = false;
    // A material's colour is three numbers, each in [min, max] (docs/materials.md); a number is 1.
    int components = 1;
    // A choice among named forms ("smith-separable,smith-height-correlated"), the first the
    // default: not a number (min, max and held are unused); empty for a number.
    std::string_view choices = {};
};

// What a model or part that reads no parameter declares.
inline constexpr std::array<parameter, 0> no_parameters{};

// Whether a list of declared parameters has one named `name`.
template <class Parameters>
constexpr bool declares(const Parameters& list, std::string_view name) {
    for (const parameter& p : list)
        if (p.name == name) return true;
    return false;
}

}  // namespace normzoo
