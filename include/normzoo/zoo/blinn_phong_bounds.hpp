// The bounds of the Blinn-Phong normalizations ("The Blinn-Phong Normalization Zoo"; docs/method.md),
// as margins rewritten so that nothing cancels, for 50-digit arithmetic:
//   blinn-phong           (n+2)/(8 pi) < norm < (n+4)/(8 pi)
//     norm/lower - 1 = 2^(-n/2) / (2 - 2^(-n/2))
//     1 - norm/upper = ((n+4)(1 - 2^(-n/2)) - n) / ((n+4)(2 - 2^(-n/2)))
//   blinn-phong-modified  (n+6)/(8 pi) < norm < (n+8)/(8 pi)
//     norm/lower - 1 = (8 - (n+6) 2^(-n/2)) / ((n+6)(n + 2^(-n/2)))
//     1 - norm/upper = (3n - (n+8)(1 - 2^(-n/2))) / ((n+8)(n + 2^(-n/2)))
// with 1 - 2^(-n/2) = -expm1(-n ln2 / 2), exact for tiny n. The numerators lose at most one
// digit, so each margin is known to ~48 digits relative and its sign is certain; the decimal
// exponent range of the 50-digit type (+-6e8) holds 2^(-n/2) at n = 1e7 (about 1e-1505150),
// far below what any IEEE type holds.
#pragma once
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <utility>

#include "../wide.hpp"
#include "blinn_phong.hpp"

namespace normzoo {

struct bound_margins {
    wide norm, lower, upper;
    wide lower_margin;  // norm / lower - 1
    wide upper_margin;  // 1 - norm / upper
};

// 2^(-n/2) and 1 - 2^(-n/2), the latter from expm1: exact for tiny n.
template <class T>
std::pair<T, T> half_power(const T& n) {
    using std::expm1;
    using std::pow;
    return {pow(T(2), -n / 2), -expm1(-n * boost::math::constants::ln_two<T>() / 2)};
}

inline bound_margins blinn_phong_margins(const wide& n) {
    const auto [p, one_minus_p] = half_power(n);
    const wide eight_pi = 8 * pi<wide>();
    return {zoo::blinn_phong::closed_form(n), (n + 2) / eight_pi, (n + 4) / eight_pi, p / (2 - p),
            ((n + 4) * one_minus_p - n) / ((n + 4) * (2 - p))};
}

inline bound_margins blinn_phong_modified_margins(const wide& n) {
    const auto [p, one_minus_p] = half_power(n);
    const wide eight_pi = 8 * pi<wide>();
    return {zoo::blinn_phong_modified::closed_form(n), (n + 6) / eight_pi, (n + 8) / eight_pi,
            (8 - (n + 6) * p) / ((n + 6) * (n + p)), (3 * n - (n + 8) * one_minus_p) / ((n + 8) * (n + p))};
}

}  // namespace normzoo
