// The tables of microfacet compositions (docs/microfacet.md): the energy of compositions named on
// the command line (`energy --model D/G/F`), the committed microfacet tables, and the baked
// tables of `verify lut` (lut.cpp), each from the library's typed results
// (normzoo/microfacet/albedo.hpp, split_sum.hpp, multiple_scattering.hpp).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <normzoo/decimal.hpp>
#include <normzoo/microfacet/composition.hpp>

#include "part_inputs.hpp"
#include "writers.hpp"

namespace verify {

// The roughness of a composition as typed: alpha, or the perceptual r with alpha = r^2.
struct roughness_input {
    normzoo::decimal value;
    bool perceptual = false;  // given as r
};

// The incident direction as typed: mu = cos t, or t in degrees.
struct incidence_input {
    normzoo::decimal value;
    bool degrees = false;  // given as theta
};

// The double an input is computed at and how far the typed decimal can be from it
// (docs/conventions.md, "Inputs are decimals"): mu from mu or from theta (formed in binary128),
// alpha from alpha or from r (alpha = r^2, rounded once more).
struct mu_value {
    double mu, delta, theta_deg;  // delta >= |mu typed - mu|
};
mu_value mu_of(const incidence_input& in);
struct alpha_value {
    double alpha, delta;  // delta >= |alpha typed - alpha|
};
alpha_value alpha_of(const roughness_input& in);

// One `energy` record per (composition, roughness, incidence): model, alpha, mu, albedo,
// error_estimate (absolute), with the inputs as typed beside them.
table_output composition_energy_table(const std::vector<std::string>& models, const std::vector<roughness_input>& roughness,
                                      const std::vector<incidence_input>& incidence, const part_inputs& parts, unsigned jobs);

// The committed tables: microfacet-energy (E(mu, alpha) of the reference compositions, the
// compensations' white furnace), microfacet-eavg, microfacet-shortcuts (every approximation against
// the exact integral).
std::vector<table_output> microfacet_tables(unsigned jobs);

}  // namespace verify
