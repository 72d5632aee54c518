// The tables of microfacet compositions (docs/microfacet.md): the energy of compositions named on
// the command line (`energy --model D/G/F`), the committed microfacet tables, and the baked
// tables of `verify lut` (lut_exact.cpp), each from the library's typed results
// (normzoo/microfacet/albedo.hpp, split_sum.hpp, multiple_scattering.hpp).
#pragma once
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <normzoo/albedo_input.hpp>
#include <normzoo/decimal.hpp>
#include <normzoo/microfacet/composition.hpp>
#include <normzoo/microfacet/multiple_scattering.hpp>

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
// bad_input where c's parts are not defined at the roughness typed (charlie-sheen above alpha = 1).
void refuse_outside_fit(const normzoo::microfacet::composition& c, const roughness_input& in);
// bad_input, beginning with `where`, for a transmitting interface (D/G/F/transmission) at F0 = 1
// with no index (a mirror) or at alpha > 1, where its integral was not made for.
void refuse_outside_interface(const normzoo::microfacet::composition& c, double f0, double alpha, const std::string& where);
// Whether the decimal r is a double and so is r^2 (its product's remainder, by fma, is 0): an
// alpha computed from it rounds nothing.
bool squares_exactly(const normzoo::decimal& r);

// F0 as typed (default 1) and how far the double is from it.
struct f0_value {
    double f0 = 1, delta = 0;  // delta >= |f0 typed - f0|
};
inline f0_value f0_of(const part_inputs& p) {
    if (!p.f0) return {};
    const double f0 = p.f0->to<double>();
    return {f0, p.f0->rounding<double>() * f0};
}

// The keys of a composition's inputs beyond roughness and incidence (docs/records.md): `f0` where
// the albedo depends on F0 (a Schlick part, or an exact one not given eta; none for the split-sum
// pair, whose F0 is its linear variable: pass no f0), and each parameter given that a part reads,
// as the double computed with and, like F0 where typed, as typed (NAME_input).
void set_part_keys(record& r, const normzoo::microfacet::composition& c, const part_inputs& p, std::optional<double> f0);

// The largest value the rounding slope of parameter q may step to (F90 <= 1).
inline double rounding_upper(const part_parameter& q) {
    return std::string(q.max) == "1" ? 1.0 : std::numeric_limits<double>::infinity();
}

// How far the double a parameter is computed at can be from x typed, as a parameter of q:
// x's rounding to double and that of the product the part forms with it.
inline double parameter_delta(const part_parameter& q, const normzoo::decimal& x) {
    const double v = x.to<double>();
    int exponent = 0;
    const bool power_of_two = std::frexp(v, &exponent) == 0.5;
    return (x.rounding<double>() + (power_of_two ? 0.0 : q.formed_rounding)) * std::abs(v);
}

// How far the rounding of p's decimals to double can move value_at(c) (a composition's albedo or
// a texel): albedo_input_rounding over each parameter that c reads.
template <class ValueAt>
double part_inputs_rounding(const normzoo::microfacet::composition& c, const part_inputs& p,
                            const normzoo::quadrature::estimate<double>& at, const ValueAt& value_at) {
    double moved = 0;
    for (const auto& q : part_parameters()) {
        const auto& x = p.*q.input;
        if (!x || !c.reads(q.name)) continue;
        moved += normzoo::albedo_input_rounding(
            [&](double v) {
                auto moved_c = c;
                moved_c.*q.member = v;
                return value_at(moved_c);
            },
            x->to<double>(), parameter_delta(q, *x), at, rounding_upper(q));
    }
    return moved;
}

// Kulla-Conty's terms that the points of one row (composition c at one alpha) share: at the
// row's alpha and F0, and at each input that rounding moves (alpha by alpha_delta, F0 by
// f0_delta, the parameters of p that c reads) where albedo_input_rounding steps it
// (normzoo::input_rounding_step). Empty unless c has Kulla-Conty's compensation.
std::vector<normzoo::microfacet::kulla_conty_terms> kulla_conty_row(const normzoo::microfacet::composition& c, double alpha,
                                                                    double alpha_delta, double f0, double f0_delta,
                                                                    const part_inputs& p);

// The table of composition_energy_table (an `energy` table, as the forms' is), and that of its
// records on the committed grid and a scene's (microfacet-energy).
table_info composition_energy_info();
table_info microfacet_energy_info();

// One `energy` record per (composition, roughness, incidence): model, alpha, mu, albedo,
// error_estimate (absolute), with the inputs as typed beside them.
table_output composition_energy_table(const std::vector<std::string>& models, const std::vector<roughness_input>& roughness,
                                      const std::vector<incidence_input>& incidence, const part_inputs& parts, unsigned jobs);

// The grid of microfacet-energy, as written: the visibility shortcuts are measured on it too.
std::vector<normzoo::decimal> microfacet_energy_alphas();
std::vector<normzoo::decimal> microfacet_energy_mus();

// The committed tables: microfacet-energy (E(mu, alpha) of the reference compositions, the
// compensations' white furnace), microfacet-eavg, microfacet-shortcuts (every approximation against
// the exact integral).
std::vector<table_output> microfacet_tables(unsigned jobs);

}  // namespace verify
