// normzoo: numeric verification of shading-model normalization. The whole library in one include:
// geometry, the zoo rows and NDFs, the BRDF forms and their registry, quadrature, normalization,
// albedo, irradiance, Monte Carlo, exact decimal inputs, the microfacet parts with their albedo,
// split sum and multiple scattering, the shader formulas, BRDFs given as code and the
// engine-facing checks; not the certified core (certify/: it needs Arb and MPFI). No table,
// record or writer is here (those are the verify command's, src/verify/); an engine's test that
// needs one check includes normzoo/check.hpp and the form's own header instead
// (docs/architecture.md).
#pragma once
#include "albedo.hpp"
#include "albedo_input.hpp"
#include "check.hpp"
#include "code/code_albedo.hpp"
#include "code/code_checks.hpp"
#include "decimal.hpp"
#include "geometry.hpp"
#include "irradiance.hpp"
#include "microfacet/albedo.hpp"
#include "microfacet/composition.hpp"
#include "microfacet/multiple_scattering.hpp"
#include "microfacet/split_sum.hpp"
#include "microfacet/split_sum_shortcuts.hpp"
#include "microfacet/split_sum_to.hpp"
#include "zoo/blinn_phong.hpp"
#include "zoo/blinn_phong_bounds.hpp"
#include "zoo/lambert.hpp"
#include "zoo/phong.hpp"
#include "montecarlo.hpp"
#include "ndf_integrals.hpp"
#include "normalization.hpp"
#include "quadrature/adaptive.hpp"
#include "quadrature/estimate.hpp"
#include "quadrature/hemisphere.hpp"
#include "quadrature/periodic.hpp"
#include "quadrature/lobe.hpp"
#include "real.hpp"
#include "registry.hpp"
#include "shader/formulas.hpp"
#include "shader/half.hpp"
#include "shader/math.hpp"
#include "version.hpp"
