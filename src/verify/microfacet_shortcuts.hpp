// The shortcuts engines take instead of the exact microfacet integrals (docs/microfacet.md, "The
// shortcuts, measured"), each as engines write it, and the table of their errors against the
// exact integral (microfacet_shortcuts.cpp).
#pragma once
#include <utility>

#include "writers.hpp"

namespace verify {

// Karis 2014, "Physically Based Shading on Mobile" (EnvBRDFApprox, after Lazarov 2013): the
// split-sum pair (A, B) as a fit in the perceptual roughness r and mu.
std::pair<double, double> env_brdf_approx(double r, double mu);

// The split-sum pair as engines bake it: n samples of GGX importance sampling at Hammersley points,
// height-correlated Smith visibility, accumulated in float (the loop of Karis 2013's IntegrateBRDF
// with Filament's visibility); alpha = r^2.
std::pair<float, float> monte_carlo_split_sum(float r, float mu, unsigned samples);

table_output shortcuts_table(unsigned jobs);

}  // namespace verify
