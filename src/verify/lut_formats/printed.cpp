// What a printed decimal holds (printed.hpp).
#include "printed.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace verify {

printed_digits digits_of(const std::string& text) {
    const auto e = text.find_first_of("eE");
    const std::string mantissa = text.substr(0, e);
    // an exponent beyond any double's is clamped: the digits after the point stay a long
    const long exponent = e == std::string::npos ? 0 : std::clamp(std::strtol(text.c_str() + e + 1, nullptr, 10), -100000L, 100000L);
    const auto dot = mantissa.find('.');
    printed_digits d;
    d.decimals = (dot == std::string::npos ? 0 : long(mantissa.size() - dot - 1)) - exponent;
    bool leading = true;
    for (char ch : mantissa)
        if (ch >= '0' && ch <= '9') {
            leading = leading && ch == '0';
            d.significant += !leading;
        }
    return d;
}

double printed_precision(double v, const printed_digits& column) {
    const double fixed = 0.5 * std::pow(10.0, double(-column.decimals));
    // a float's half spacing below its normal range, 2^-150: a subnormal, or 0 where it underflowed
    const double float_floor = column.significant <= 9 ? 0x1p-150 : 0.0;
    if (v == 0) return std::max(fixed, float_floor);
    const double magnitude = std::floor(std::log10(std::abs(v)));
    const double digits = std::max(fixed, 0.5 * std::pow(10.0, magnitude - double(column.significant) + 1));
    return column.significant <= 9 ? std::max({digits, 0x1p-24 * std::abs(v), float_floor}) : digits;
}

}  // namespace verify
