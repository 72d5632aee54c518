// The table of the shortcuts engines take instead of the exact microfacet integrals, against the
// exact integral (docs/microfacet.md, "The shortcuts, measured"; microfacet_shortcuts.cpp). The
// shortcuts themselves are the library's: the split-sum fits and the baker in
// normzoo/microfacet/split_sum_shortcuts.hpp, the visibility terms in masking.hpp, Schlick's
// Fresnel in fresnel.hpp.
#pragma once
#include "writers.hpp"

namespace verify {

table_output shortcuts_table(unsigned jobs);

}  // namespace verify
