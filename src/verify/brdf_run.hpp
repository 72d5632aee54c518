// `verify --brdf FILE`: a BRDF given as shader code, checked (docs/brdf-code.md); the table job
// brdf-file (specs/brdf_file.cpp), its options declared in command_line.cpp:
//   verify --brdf FILE [--include-dir DIR ...] [--define NAME[=VALUE] ...] [--texture NAME=FILE ...] [--layout KEYS]
//          [--param NAME=VALUE|LO..HI|A,B,C ...] [--steps N] [--theta LIST | --mu LIST]
//          [--fixed light|view] [--reciprocity-tolerance X] [--tolerance X] [--time-limit S]
//          [--against MATERIAL [--map SHADER_PARAM=MATERIAL_PARAM ...] [--against-tolerance X]]
//          [--json] [--junit FILE] [--out DIR]
// Exit 0 (every verdict passes), 1 (one fails: gains energy, non-finite or negative values, not
// reciprocal, fp32 breakdown, unlike the material --against names), 2 (bad input: the file, a
// parameter, an option).
#pragma once
#include <string>
#include <vector>

#include <normzoo/code/brdf_code.hpp>
#include <normzoo/decimal.hpp>

#include "command_line.hpp"
#include "writers.hpp"

namespace verify {

// What to check of a shader file: the command line's --brdf, or a scene's material.
struct brdf_request {
    std::string file;                  // the path to read
    std::string shown_file;            // as written (a scene's, relative to it); empty: file
    std::string material;              // the scene material's name: a key of every record; empty: none
    std::string command;               // the tables' command line; empty: ./verify --brdf FILE
    std::vector<std::string> params;   // NAME=VALUE, NAME=LO..HI or NAME=A,B,C, as given (brdf_parameters.hpp)
    std::vector<std::string> defines;  // --define NAME[=VALUE], as given
    std::vector<std::string> include_dirs;  // --include-dir DIR, as given
    std::vector<std::string> textures;      // --texture NAME=FILE, as given (brdf_textures.hpp)
    std::string layout;                     // --layout, as given: how every --texture's file is read
    std::size_t steps = 5;             // values of a range
    std::vector<normzoo::decimal> theta, mu;  // incidences (default 0, 15, ..., 75, 85, 89 degrees)
    double tolerance = 1e-10;
    double eval_seconds = 600;         // per albedo point
    normzoo::code::fixed_direction fixed = normzoo::code::fixed_direction::light;  // the direction the albedo holds
    double reciprocity_tolerance = 1e-9;  // relative
    bool allow_energy_gain = false;    // a scene's: a gain is reported, not failed
    // --against MATERIAL: the code against the library's material (brdf_conformance.hpp), its
    // parameters bound by --map SHADER_PARAM=MATERIAL_PARAM (or by name), failing above
    // against_tolerance (relative for f, absolute for the albedo)
    std::string against;
    std::vector<std::string> maps;
    double against_tolerance = 1e-6;
};

// The tables brdf (albedo against incidence, with verdicts) and brdf-checks (reciprocity,
// normalization). Throws bad_input for a bad file or parameter.
std::vector<table_output> brdf_tables(const brdf_request& r, bool quiet);

// The request of --brdf FILE from its options in o.typed; bad_input for a bad number.
brdf_request brdf_request_of(const options& o);

// The tables of --brdf FILE, each with its console report (its Markdown on stdout when it is not
// written).
std::vector<table_output> brdf_file_tables(const options& o);

}  // namespace verify
