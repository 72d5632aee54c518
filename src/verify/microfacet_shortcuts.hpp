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

// Lazarov 2013, "Getting More Physical in Call of Duty: Black Ops II": Black Ops II's
// environment BRDF (normalized Blinn-Phong of power 8192^g, Schlick's Smith visibility with
// k = 2 / sqrt(pi (power + 2)), Schlick's Fresnel) as a fit in gloss g and mu, written as the
// split-sum pair: the shader's a0 + F0 (a1 - a0) is F0 A + B with A = a1 - a0, B = a0 (before
// its saturate).
std::pair<double, double> lazarov_2013(double gloss, double mu);

// The roughness alpha of Black Ops II's gloss g: the Blinn-Phong power 8192^g is n = 2/alpha^2 - 2.
double lazarov_alpha(double gloss);

// The split-sum pair as engines bake it: n samples of GGX importance sampling at Hammersley points,
// height-correlated Smith visibility, accumulated in float (the loop of Karis 2013's IntegrateBRDF
// with Filament's visibility); alpha = r^2.
std::pair<float, float> monte_carlo_split_sum(float r, float mu, unsigned samples);

table_output shortcuts_table(unsigned jobs);

}  // namespace verify
