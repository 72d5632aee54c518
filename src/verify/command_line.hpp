// The command line of `verify`, parsed and checked without running anything: main and the
// argument fuzzer (fuzz/args_fuzzer.cpp) call the same function.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <normzoo/decimal.hpp>

#include "part_inputs.hpp"

namespace CLI {
class App;
}

namespace verify {

// The parameters of the tables, each list checked (docs/command-line.md, "Command reference"); empty: the table's default.
struct options {
    // Numbers exactly as typed (docs/conventions.md, "Inputs are decimals").
    std::vector<normzoo::decimal> exponents;  // --n
    std::string exponents_text;
    std::vector<normzoo::decimal> angles;     // --theta, degrees
    std::string angles_text;
    std::vector<std::string> models;  // --model; empty: every BRDF form
    std::vector<std::string> lights;  // --light; empty: sphere and disk
    std::vector<normzoo::decimal> ratios, tilts;  // --ratio, --tilt (degrees)
    std::string ratios_text, tilts_text;
    std::optional<std::uint64_t> seed, cases;  // --seed, --cases (the audit); empty: its defaults
    // Microfacet compositions (--model D/G/F in energy): --alpha or --r, --mu, --f0 and the parts'
    // parameters (--f90, --eta, --k, --aspect, --gamma)
    std::vector<normzoo::decimal> roughness;  // alpha, or r when roughness_is_r
    bool roughness_is_r = false;
    std::string roughness_text;
    std::vector<normzoo::decimal> mus;  // --mu, cosines of the incident angle
    std::string mus_text;
    part_inputs parts;  // --f0, --f90, --eta, --k, --aspect, --gamma
    unsigned jobs = 1;
};

struct command_line {
    options opts;
    std::vector<std::string> tables;  // known names, each once, in the order given; empty: all
    std::string scene_path, out_dir, junit_path;  // out_dir empty: the default folder
    bool check = false, json = false;
    std::optional<std::string> help;  // -h: print this and exit 0
    std::vector<std::string> notes;   // for stderr: an old table name mapped to its new one
};

// Before parsing: an option that takes a value followed by nothing or by another option name
// (CLI11 would report the stray value after it instead, or take the option name as the value).
void refuse_missing_values(const CLI::App& app, int argc, const char* const* argv, const std::string& prefix);

// CLI11 takes the argument after an option as its value even when it is another option: `--out
// --json` would write into a folder named "--json". bad_input (after `prefix`) for a value that
// begins with "--" or is an option's name (a path so named can be given as ./--json), and for an
// empty path (--out, --junit, --scene, --check), which would silently mean none.
void refuse_forgotten_values(const CLI::App& app, const std::string& prefix);

// The options of the parts' parameters (--f90, --eta, --k, --aspect, --gamma; part_parameters()),
// added to `app` with their text in `texts` (which must outlive the parse), and read from it into
// p: one decimal each, in its range, else bad_input beginning with `prefix`. Read returns the
// names of the options given.
void add_part_options(CLI::App& app, std::vector<std::string>& texts, const std::string& help_prefix);
std::vector<std::string> read_part_options(const CLI::App& app, const std::vector<std::string>& texts, part_inputs& p,
                                           const std::string& prefix);

// argv as main gets it; `tables` are the names the command knows (its registry of tables), of
// which `named_only` run only when named. Throws bad_input (exit 2) with a message naming the
// bad option or value.
command_line parse_command_line(int argc, const char* const* argv, const std::vector<std::string>& tables,
                                const std::vector<std::string>& named_only = {});

}  // namespace verify
