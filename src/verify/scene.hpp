// Scene files (docs/command-line.md, "A guardrail for an engine"): what one game or engine uses, read from TOML (toml++) with the
// shader's normalization expressions parsed by muparser. Every error names the file, the line
// and the key, and is bad input (exit 2).
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <normzoo/decimal.hpp>

#include "part_inputs.hpp"

namespace verify {

struct scene_material {
    std::string name, model;
    double n_min = 0, n_max = 0;        // from `exponent`, or from `gloss` with n = 2^(10 g + 1)
    normzoo::decimal n_lo, n_hi;        // the same exactly: the decimals written, or 2^(10 g + 1) to 40 digits
    std::string range_text;             // as written, for tables
    std::optional<std::string> normalization;  // the shader's expression in n
    std::function<double(double)> shader;      // it, compiled (empty without one)
    double specular = 1;
    // A microfacet composition (model "D/G/F", docs/microfacet.md): its roughness range (alpha, or
    // r with alpha = r^2), F0 and its parts' parameters, and a baked table of the engine's to check (docs/lut.md).
    bool composition = false;
    normzoo::decimal rough_lo, rough_hi;
    bool rough_is_r = false;
    part_inputs parts;              // f0, f90, eta, k, aspect, gamma as written
    std::string lut_path;           // resolved against the scene's folder; empty: none
    std::string lut_place;          // "FILE:LINE: materials[i].lut", for messages about the table
    std::string lut_kind = "dfg";   // dfg, E or Eavg
    bool lut_map_r = true;          // the table's rows index r (else alpha)
    // A BRDF given as shader code (`brdf = "file"`, docs/brdf-code.md): the file, resolved against
    // the scene's folder and as written, and its parameters as --brdf takes them (NAME=VALUE,
    // NAME=LO..HI, NAME=R,G,B).
    std::string brdf_path, brdf_written;
    std::vector<std::string> brdf_params;
    std::vector<std::string> brdf_defines, brdf_include_dirs;  // as --define and --include-dir; folders resolved
    bool brdf_fixed_view = false;                               // fixed = "view": the albedo holds V
    std::vector<std::string> brdf_textures;                     // as --texture NAME=FILE; files resolved
    std::string brdf_layout;                                    // texture_layout, as --layout
    bool code() const { return !brdf_path.empty(); }
};

struct scene_light {
    std::string name, type;  // sphere | disk
    double radius = 0, distance = 1;
    normzoo::decimal radius_input, distance_input;  // as written
    std::optional<std::pair<double, double>> tilt_deg;
    std::optional<std::pair<normzoo::decimal, normzoo::decimal>> tilt_input;  // as written
};

struct scene {
    std::string path, name;
    std::vector<scene_material> materials;
    std::vector<scene_light> lights;
    double digits = 30;                  // [tolerance] digits: zoo agreement required
    double albedo = 1e-9;                // [tolerance] albedo: energy sweep accuracy
    double normalization = 1e-6;         // [tolerance] normalization: shader expression, relative
    bool allow_energy_gain = false;      // [tolerance] allow_energy_gain: a gain is then a finding only
};

// The ids a material's model may be: every BRDF form and every zoo row (registry order).
std::vector<std::string> scene_model_ids();

// Reads and checks a scene; throws bad_input ("FILE:LINE: key: what is wrong").
scene load_scene(const std::string& path, const std::vector<std::string>& model_ids);

// The same from the text of a scene; `path` names it in messages (and is the default name).
scene load_scene_text(const std::string& toml_text, const std::string& path, const std::vector<std::string>& model_ids);

}  // namespace verify
