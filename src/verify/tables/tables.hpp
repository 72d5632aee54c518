// Every table generator of the verify command in one include, but for the error audit (its
// 100-digit references, audit/reference.hpp, cost compile time: tables/error_audit.hpp) and the
// certified tables (tables/enclosures.hpp, tables/proofs.hpp, which link Arb and MPFI).
#pragma once
#include "bounds.hpp"
#include "constants.hpp"
#include "energy.hpp"
#include "energy_claims.hpp"
#include "fresnel_visibility.hpp"
#include "grid.hpp"
#include "irradiance.hpp"
#include "montecarlo.hpp"
#include "ndf.hpp"
#include "shader_normalization.hpp"
#ifdef __FLT16_MAX__  // the shader audit needs a binary16 type (_Float16: GCC >= 12, clang >= 15)
#include "shader_precision.hpp"
#endif
#include "stability.hpp"
#include "stability_naive.hpp"
#include "zoo.hpp"
