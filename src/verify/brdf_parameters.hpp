// The values a --brdf run gives each parameter of a shader file (docs/brdf-code.md#parameters):
// its default, or what --param gives: NAME=VALUE, NAME=LO..HI (a float's, in --steps values), or
// NAME=A,B,C (a float's or a bool's list). A bool is true, false, 1 or 0; a color R,G,B. Values
// are decimals as typed, and a sweep's are computed from them exactly: 0.1..0.5 in 5 values is
// 0.1, 0.2, 0.3, 0.4, 0.5, each the double nearest it. Bad input throws bad_input naming --param
// NAME (or --steps).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <normzoo/decimal.hpp>

#include "brdf_file/brdf_file.hpp"

namespace verify {

struct parameter_values {
    const shader_parameter* p = nullptr;
    std::vector<std::vector<double>> values;  // each one slot, or three for a color
    std::vector<std::string> texts;           // each as shown: its shortest decimal, true or false, or r,g,b
    std::string given;                        // for the tables' heads: "0.1..0.5 in 5 values", "0.1, 0.3", "0.3"
    bool swept() const { return values.size() > 1; }
};

// The values of each of s's parameters, in declaration order, from the --param texts given.
std::vector<parameter_values> parameter_grid(const shader_source& s, const std::vector<std::string>& params, std::size_t steps);

// lo + (hi - lo) k / (n - 1) for k = 0 .. n - 1, each computed exactly from the decimals and
// rounded once to the nearest double (n >= 2).
std::vector<double> sweep_values(const normzoo::decimal& lo, const normzoo::decimal& hi, std::size_t n);

// The shortest decimal text that reads back as x ("0.3", "1e-05").
std::string shortest_text(double x);

}  // namespace verify
