// `verify lut`: the tables engines bake, exact (docs/lut.md). A table of the command like the
// others (specs/lut.cpp), named only, with options of its own, declared in command_line.cpp:
//   verify lut --kind dfg|E|Eavg [--model ID] (--size N | --alpha LIST | --r LIST, --mu LIST)
//              [--f0 X] [--f90 X] [--eta X] [--k X] [--aspect X] [--gamma X] [--map r|alpha | --layout KEY=VALUE,... | --preset ENGINE]
//              [--format csv|json|png8|png16|exr|exr-half|h|ktx2|ktx2-zstd|dds] [--out DIR] [--json]
//   verify lut --check FILE --kind dfg|E|Eavg [--model ID] [--map r|alpha | --layout KEY=VALUE,... | --preset ENGINE | --detect]
//              [--tolerance X] [--out DIR] [--json]
// Exit 0, 1 (a checked table is off by more than its tolerance), 2 (bad input: bad_input).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "part_inputs.hpp"
#include "writers.hpp"

namespace verify {

// The lut-check records of an engine's table (one per channel); throws bad_input naming the file.
// kind: dfg, E or Eavg; model: a composition id already checked, with its F0 and parts'
// parameters (checked too); perceptual: rows index r.
table_output check_lut_file(const std::string& path, const std::string& kind, const std::string& model, const part_inputs& parts,
                            bool perceptual, std::optional<double> tolerance, unsigned jobs);

// lut's options in o.typed, checked in the order their messages come; bad_input for the first bad one.
void check_lut_options(const options& o);

// The table made (lut_make.hpp), or an engine's table checked (--check FILE; lut_check.hpp).
std::vector<table_output> lut_tables(const options& o);

}  // namespace verify
