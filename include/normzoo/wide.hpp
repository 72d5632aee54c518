// The 50-digit number type: 50 decimal digits with a 32-bit decimal exponent range (+-6e8), for
// the closed forms that want more than binary128 and for deciding the Blinn-Phong bounds, whose
// margins (2^(-n/2) at n = 1e7) underflow every IEEE type (docs/method.md).
#pragma once
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "real.hpp"

namespace normzoo {

using wide = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<50>,
                                           boost::multiprecision::et_off>;

template <> inline constexpr const char* number_type_name<wide> = "cpp_bin_float<50>";

}  // namespace normzoo
