// The values of V.h where an integrand has kinks at one point of an albedo integral
// (docs/microfacet.md, "Total internal reflection"): those a kink function writes (Cook-Torrance's
// G, masking.hpp; a thin film's weights, material/albedo.hpp), then one constant value, F's
// critical V.h at total internal reflection (microfacet/composition.hpp, critical_vh).
#pragma once
#include <stdexcept>

namespace normzoo::detail {

// kink_vm(a, b, vm) -> how many it wrote (nullptr: none), then `critical` where > 0; vm holds
// `capacity` values, which the two together must not exceed (a composition's G writes at most 3,
// a film's weights come with no critical angle).
template <class KinkVm>
int kinks_vh(KinkVm kink_vm, double critical, double a, double b, double vm[], int capacity) {
    int n = kink_vm ? kink_vm(a, b, vm) : 0;
    if (critical > 0) {
        if (n >= capacity) throw std::logic_error("kinks_vh: more kinks in V.h than the integral takes as breakpoints");
        vm[n++] = critical;
    }
    return n;
}

}  // namespace normzoo::detail
