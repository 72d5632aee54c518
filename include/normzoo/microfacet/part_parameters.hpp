// The parameters the microfacet parts read beyond the roughness alpha (docs/microfacet.md#part-parameters),
// declared once: each part lists those it reads in its `parameters` (composition::reads), and the
// command's options, scene keys and records take their names, meanings, ranges and defaults here.
#pragma once
#include "../parameter.hpp"

namespace normzoo::microfacet {

inline constexpr parameter f0_parameter{"f0", "F0, the reflectance at normal incidence, in [0, 1]", 0, 1, {}, 1};
inline constexpr parameter f90_parameter{"f90", "F90 of schlick-f90, in [0, 1] (default 1)", 0, 1, {}, 1};
inline constexpr parameter eta_parameter{
    "eta", "the index of dielectric and conductor, in (0, 1000] (default: from F0)", 0, 1000, {}, 0, true};
inline constexpr parameter k_parameter{"k", "the extinction coefficient of conductor, in [0, 1000] (default 0)", 0, 1000, {}, 0};
inline constexpr parameter aspect_parameter{
    "aspect", "alpha_y / alpha_x of ggx-aniso and beckmann-aniso, in [0.01, 100] (default 1)", 0.01, 100, {}, 1};
inline constexpr parameter gamma_parameter{"gamma", "the exponent of gtr, in [0.5, 10] (default 2: ggx)", 0.5, 10, {}, 2};

}  // namespace normzoo::microfacet
