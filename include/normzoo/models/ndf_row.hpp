// What every microfacet normal distribution (NDF) row has. The modern NDFs take a roughness
// alpha, not an exponent n: their tables are indexed by alpha, and the Phong-Beckmann mapping
// n = 2/alpha^2 - 2 (Walter et al. 2007) relates the two where a table needs both.
//
// An NDF row is a small value type with:
//   id, expression, non_projected, g1_formula, literature   strings for tables and docs
//   d(h, alpha)             D(h) from the unit vector h (tan^2 from its components: no 1 - cos^2)
//   lambda(cos_v, sin_v, alpha)   Smith's Lambda for a view at polar angle t_v
//   g1(cos_v, sin_v, alpha) = 1 / (1 + Lambda), Smith's masking
//   non_projected(alpha)    the integral of D(h) over the hemisphere (not weighted by N.h), in
//                           closed form; the projected integral (weighted by N.h) is 1 by design
#pragma once
#include <cmath>

#include "zoo_row.hpp"

namespace normzoo::models {

// tan^2 of the polar angle of a unit vector, (x^2 + y^2) / z^2: exact for tiny angles.
template <class T>
T tan2_of(const vec3<T>& h) {
    return (h.x() * h.x() + h.y() * h.y()) / (h.z() * h.z());
}

}  // namespace normzoo::models
