// `verify --brdf FILE --against MATERIAL [--map SHADER_PARAM=MATERIAL_PARAM ...]
// [--against-tolerance X]` (docs/materials.md, "A shader's conformance to a material"): the
// user's code against the specification's material at every combination of the swept
// parameters, the material's parameters taking the values of the shader's parameters mapped to
// them (same-named ones without --map) and their defaults otherwise. The table brdf-conformance:
// per combination, the largest relative difference of f over a grid of directions and where, and
// the largest difference of the albedo with V held, with its bound, and where.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <normzoo/code/code_albedo.hpp>

#include "brdf_records.hpp"
#include "material_reference.hpp"

namespace verify {

// The shader's parameter grid[grid_index] gives the material's parameter material_index.
struct conformance_binding {
    std::size_t grid_index = 0, material_index = 0;
};

// The bindings --map gives (NAME=NAME, each side known, a colour to a colour, a number to a
// number), then every other shader parameter whose name a free parameter of the material has;
// bad_input naming the --map text or, when nothing binds, both parameter lists.
std::vector<conformance_binding> bind_conformance(const std::vector<parameter_values>& grid, const reference_material& m,
                                                  const std::vector<std::string>& maps);

// The material's values at one combination of the shader's: the bound ones from it, the others
// their defaults.
std::vector<rgb_value> material_values(const parameter_point& at, const reference_material& m,
                                       const std::vector<conformance_binding>& bindings);

// One incidence: V's angle and the shader's albedo with V held there.
struct conformance_incidence {
    double theta_deg = 0, mu = 1;
    const normzoo::code::code_albedo_result* shader_albedo = nullptr;
};

struct conformance_result {
    // f: the largest |f_code - f_material| / |f_material| over the directions and channels
    // (against 1e-9 of the largest |f_material| where f_material is smaller), and where
    double max_relative_f = 0, f_code = 0, f_material = 0, theta_l = 0, phi_l = 0, theta_v = 0;
    int f_channel = 0;
    std::size_t directions = 0;
    bool finite = true;  // no NaN or infinity in either
    // the albedo with V held: the largest |code - material| over incidences and channels, its bound
    // (the two integrals' bounds added) and where
    double albedo_difference = 0, albedo_bound = 0, albedo_code = 0, albedo_material = 0, albedo_theta = 0;
    int albedo_channel = 0;
};

// f of the code at (L, V) per channel (a number in all three).
using code_sample = std::function<rgb_value(const normzoo::vec3<double>& l, const normzoo::vec3<double>& v)>;

conformance_result compare_to_material(const code_sample& f, const reference_material& m, const std::vector<rgb_value>& values,
                                       const std::vector<conformance_incidence>& incidences, double tolerance);

// The brdf-conformance record of one combination; it fails above the tolerance.
record conformance_record(const brdf_request& o, const parameter_point& at, const conformance_result& r);

// The table's head and keys.
table_info conformance_info(const brdf_request& o, const std::vector<parameter_values>& grid,
                            const std::vector<conformance_binding>& bindings, const reference_material& m);

}  // namespace verify
