// The Blinn-Phong bound claims (docs/conventions.md) as margins that must be > 0 for n in (0, N]:
//   blinn-phong           (n+2)/(8 pi) < norm < (n+4)/(8 pi)
//   blinn-phong-modified  (n+6)/(8 pi) < norm < (n+8)/(8 pi)
// each margin (norm/lower - 1, 1 - norm/upper) written, with p = 2^(-n/2), in a form whose
// interval extension stays tight: the forms of tables/bounds.hpp with the numerators
// multiplied out so that n never cancels against itself, e.g. (n+4)(1-p) - n = 4 - (n+4) p
// (an interval n - n is twice the box wide, never 0). The upper margins are exactly 0 at
// n = 0 (where the upper bound is an equality); there the proof is by monotonicity.
#pragma once
#include <array>

#include "dual.hpp"

namespace normzoo::certify {

namespace forms {

template <class T>
T blinn_phong_lower(const T& n) {  // norm / ((n+2)/(8 pi)) - 1
    const T p = exp2(-n / 2);
    return p / (2 - p);
}
template <class T>
T blinn_phong_upper(const T& n) {  // 1 - norm / ((n+4)/(8 pi))
    const T p = exp2(-n / 2);
    return (4 - (n + 4) * p) / ((n + 4) * (2 - p));
}
template <class T>
T blinn_phong_modified_lower(const T& n) {  // norm / ((n+6)/(8 pi)) - 1
    const T p = exp2(-n / 2);
    return (8 - (n + 6) * p) / ((n + 6) * (n + p));
}
template <class T>
T blinn_phong_modified_upper(const T& n) {  // 1 - norm / ((n+8)/(8 pi))
    const T p = exp2(-n / 2);
    return (2 * n - 8 + (n + 8) * p) / ((n + 8) * (n + p));
}

}  // namespace forms

struct bound_claim {
    const char* id;          // "blinn-phong-upper"
    const char* row;         // the zoo row whose normalization it bounds
    const char* statement;   // what is proved, for people
    const char* form;        // the margin as evaluated
    int bound_offset;        // the bound is (n + offset) / (8 pi)
    bool is_upper;           // margin = 1 - norm/bound (upper) or norm/bound - 1 (lower)
    bool equality_at_zero;   // the margin is exactly 0 at n = 0
    interval (*margin)(const interval&);
    dual (*margin_dual)(const dual&);
};

inline const std::array<bound_claim, 4>& bound_claims() {
    static const std::array<bound_claim, 4> claims = {{
        {"blinn-phong-lower", "blinn-phong", "(n+2)/(8 pi) < norm for every n in [0, N]",
         "p / (2 - p), p = 2^(-n/2)", 2, false, false, forms::blinn_phong_lower<interval>, forms::blinn_phong_lower<dual>},
        {"blinn-phong-upper", "blinn-phong", "norm < (n+4)/(8 pi) for every n in (0, N], = at n = 0",
         "(4 - (n+4) p) / ((n+4)(2 - p))", 4, true, true, forms::blinn_phong_upper<interval>, forms::blinn_phong_upper<dual>},
        {"blinn-phong-modified-lower", "blinn-phong-modified", "(n+6)/(8 pi) < norm for every n in [0, N]",
         "(8 - (n+6) p) / ((n+6)(n + p))", 6, false, false, forms::blinn_phong_modified_lower<interval>,
         forms::blinn_phong_modified_lower<dual>},
        {"blinn-phong-modified-upper", "blinn-phong-modified", "norm < (n+8)/(8 pi) for every n in (0, N], = at n = 0",
         "(2n - 8 + (n+8) p) / ((n+8)(n + p))", 8, true, true, forms::blinn_phong_modified_upper<interval>,
         forms::blinn_phong_modified_upper<dual>},
    }};
    return claims;
}

}  // namespace normzoo::certify
