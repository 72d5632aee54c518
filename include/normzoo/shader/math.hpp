// The intrinsics a shader formula calls, for the three number types the audit uses:
//   half   binary16, every result rounded to half                 (a shader's fp16)
//   float  binary32                                                (a shader's fp32)
//   quad   binary128: the reference, the exact value of the same expression to ~1e-33
// exp2 and log2 are modelled as correctly rounded in half and float (computed in double, then
// rounded): the best a GPU can do. Hardware approximations (e.g. 2 ulp for fp32 exp2) add their
// own error on top, so the audit's errors are lower bounds for real hardware.
// pow(x, y) is lowered as GPU compilers lower it, exp2(y * log2(x)), each step rounded: its error
// grows with |y log2 x|, which is the point of auditing it. The reference uses the exact pow.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstdlib>

#include "../real.hpp"
#include "half.hpp"

namespace normzoo::shader {

inline float exp2(float x) { return static_cast<float>(std::exp2(static_cast<double>(x))); }
inline float log2(float x) { return static_cast<float>(std::log2(static_cast<double>(x))); }
inline float pow(float x, float y) { return exp2(y * log2(x)); }

inline half exp2(half x) { return half(std::exp2(static_cast<double>(x))); }
inline half log2(half x) { return half(std::log2(static_cast<double>(x))); }
inline half pow(half x, half y) { return exp2(y * log2(x)); }

inline quad exp2(const quad& x) { return boost::multiprecision::pow(quad(2), x); }
inline quad log2(const quad& x) { return boost::multiprecision::log(x) / boost::multiprecision::log(quad(2)); }
inline quad pow(const quad& x, const quad& y) { return boost::multiprecision::pow(x, y); }

// Constants as a shader writes them, in the type of `like`: pi, and decimal literals such as
// "8.656170" (exact in the reference: binary128 reads the decimal; half and float round it once).
inline float pi(float) { return static_cast<float>(M_PI); }
inline half pi(half) { return half(M_PI); }
inline quad pi(const quad&) { return boost::math::constants::pi<quad>(); }

inline float lit(float, const char* decimal) { return std::strtof(decimal, nullptr); }
inline half lit(half, const char* decimal) { return half(std::strtod(decimal, nullptr)); }
inline quad lit(const quad&, const char* decimal) { return quad(decimal); }

}  // namespace normzoo::shader
