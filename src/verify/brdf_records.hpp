// The records of a --brdf run (docs/records.md, `brdf` and `brdf-checks`), each built in one
// place from the library's typed results, with the reason a failing one fails in words.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <normzoo/code/code_albedo.hpp>
#include <normzoo/code/code_checks.hpp>

#include "brdf_file/compiled_shader.hpp"
#include "brdf_parameters.hpp"
#include "brdf_run.hpp"
#include "record.hpp"

namespace verify {

// One combination of the parameters' values: index[k] picks grid[k]'s.
struct parameter_point {
    const std::vector<parameter_values>& grid;
    const std::vector<std::size_t>& index;
};

// What one incidence of a brdf record computed: the albedo in double and in float, and float
// against double around its lobe.
struct albedo_results {
    normzoo::code::code_albedo_result albedo, albedo_fp32;
    normzoo::code::precision_result precision;
    // where the code declares reduced precision: the albedo with those values in binary16, and
    // binary16 against double (docs/brdf-code.md#precision)
    std::optional<normzoo::code::code_albedo_result> albedo_fp16;
    std::optional<normzoo::code::precision_result> precision_fp16;
    // what the double program did for the albedo that a GPU leaves undefined, by kind, and in how
    // many evaluations (docs/brdf-code.md#gpu-undefined-operations)
    std::array<gpu_undefined_seen, gpu_undefined_kinds> undefined{};
    std::size_t undefined_evaluations = 0;
    // With --texture: how far the albedo moves as the textures' texels move within what their
    // storage holds (NaN where that was not finite); error_estimate adds it.
    std::optional<double> texture_storage_bound;
};

// The parameters' values at one combination, as fields param_NAME: a float as a number, a bool as
// a boolean, a color as its text r,g,b.
void set_parameters(record& r, const parameter_point& at);

// A record of `table` about the file: its material (a scene's), its file.
record file_record(const brdf_request& o, const char* table);

// A brdf record at one incidence theta_deg.
record albedo_record(const brdf_request& o, const parameter_point& at, double theta_deg, const albedo_results& a);

// A brdf-checks record: reciprocity at one combination of the parameters' values.
record reciprocity_record(const brdf_request& o, const parameter_point& at, const normzoo::code::reciprocity_result& rec);

// A brdf-checks record: the albedos as the swept parameter `name` moves (its values as shown, each
// with its albedo), at the first incidence.
record normalization_record(const brdf_request& o, const std::string& name,
                            const std::vector<std::pair<std::string, normzoo::quadrature::estimate<double>>>& points,
                            double theta_deg);

// A tolerance as a person writes it: 1e-9, 0.001.
std::string tolerance_text(double x);

}  // namespace verify
