// The command line of `verify`, parsed and checked without running anything: main and the
// argument fuzzer (fuzz/args_fuzzer.cpp) call the same function.
#pragma once
#include <cstdint>
#include <map>
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
    // Every option given, by name ("--kind"), with its values as typed: what the tables with
    // options of their own read (lut, --brdf FILE; table_spec::check_options), and what the plan
    // compares with the tables' reads.
    std::map<std::string, std::vector<std::string>> typed;
};

struct command_line {
    options opts;
    std::vector<std::string> tables;  // known names, each once, in the order given; empty: all
    std::string scene_path, out_dir, junit_path;  // out_dir empty: the default folder
    std::string check_file;  // --check FILE: lut's engine table to check (then check is false)
    std::string brdf_file;   // --brdf FILE: plans the table brdf-file
    bool check = false, json = false;  // check: --check alone, the results compared
    std::optional<std::string> help;  // -h: print this and exit 0
    std::vector<std::string> notes;   // for stderr: an old table name mapped to its new one
};

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
