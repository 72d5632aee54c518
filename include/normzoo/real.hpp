// The number types normzoo computes with, and how it prints them.
//
//   quad   : IEEE binary128 (113-bit significand, eps 1.9e-34) through GCC's __float128.
//            Chosen by measurement for the 1D zoo integrals: its transcendental functions cost
//            0.5-1 us, about 10x less than cpp_bin_float_50 and 3x less than MPFR at 40 digits
//            (docs/method.md), and the zoo integrals reach 33+ correct digits in it.
//   wide   : 50 decimal digits, in wide.hpp (not here: its parsing costs every includer ~0.1 GB).
//   longd  : x87 extended (64-bit significand), for the 2D vector integrals (>= 14 digits).
#pragma once
#include <boost/multiprecision/eigen.hpp>  // Eigen's traits of these types: vec3<quad>, vec3<wide>
#include <boost/multiprecision/float128.hpp>
#include <cmath>
#include <iomanip>
#include <limits>
#include <locale>
#include <sstream>
#include <string>

namespace normzoo {

using quad = boost::multiprecision::float128;
using longd = long double;

template <class Real>
inline constexpr const char* number_type_name = "unknown";
template <> inline constexpr const char* number_type_name<double> = "binary64 (double)";
template <> inline constexpr const char* number_type_name<long double> = "x87 extended (long double)";
template <> inline constexpr const char* number_type_name<quad> = "binary128 (__float128)";

template <class Real>
Real eps() { return std::numeric_limits<Real>::epsilon(); }

// Scientific notation with `digits` significant digits; the same bytes on every run.
template <class Real>
std::string to_decimal(const Real& x, int digits) {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out << std::scientific << std::setprecision(digits - 1) << x;
    return out.str();
}

// Correct digits implied by a relative error (capped at what the type can hold).
template <class Real>
double digits_of(const Real& rel_error) {
    using std::log10;
    const double cap = std::numeric_limits<Real>::digits10 + 3;
    if (!(rel_error > 0)) return cap;
    const double d = -static_cast<double>(log10(rel_error));
    return d < cap ? d : cap;
}

}  // namespace normzoo
