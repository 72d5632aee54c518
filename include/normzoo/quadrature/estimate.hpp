// A value with the suite's own bound on its error.
#pragma once
#include <cstddef>

namespace normzoo::quadrature {

template <class Real>
struct estimate {
    Real value{0};
    Real abs_error{0};          // bound on |value - truth|: never below the true error
    std::size_t evaluations{0}; // integrand calls spent
};

}  // namespace normzoo::quadrature
