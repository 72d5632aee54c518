// The table of the shortcuts engines take instead of the exact microfacet integrals, against the
// exact integral (docs/microfacet.md, "The shortcuts, measured"; microfacet_shortcuts.cpp). The
// shortcuts themselves are the library's: the split-sum fits and the baker in
// normzoo/microfacet/split_sum_shortcuts.hpp, the visibility terms in masking.hpp, Schlick's
// Fresnel in fresnel.hpp.
#pragma once
#include <normzoo/microfacet/split_sum_shortcuts.hpp>

#include "writers.hpp"

namespace verify {

// The baker `verify lut --monte-carlo` writes (lut_make.cpp): the library's, at r, mu and N samples.
inline normzoo::microfacet::split_sum_pair<float> monte_carlo_split_sum(float r, float mu, unsigned samples) {
    return normzoo::microfacet::monte_carlo_baker::eval(r, mu, samples);
}

table_output shortcuts_table(unsigned jobs);

}  // namespace verify
