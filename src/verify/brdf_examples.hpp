// The tables of BRDFs given as code (docs/brdf-code.md):
//   brdf-examples  each file of examples/brdfs/ against the built-in form it writes out, and its
//                  verdicts (default run; --check compares it)
//   code-audit     the black-box integrator against every built-in form passed as an opaque
//                  callable, on the energy table's forms and parameters (run only when named)
#pragma once
#include <vector>

#include "writers.hpp"

namespace verify {

std::vector<table_output> brdf_example_tables(unsigned jobs);
std::vector<table_output> code_audit_tables(unsigned jobs);

}  // namespace verify
