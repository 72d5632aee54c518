// What names and compares an `energy` record, for both builders of the table: a form's
// (energy.hpp) and a composition's (src/verify/microfacet_tables.cpp), which share its name, and
// so its JUnit names and --check rule (docs/tables.md, "What --check compares").
#pragma once
#include <string>
#include <vector>

#include "../record.hpp"

namespace verify {

// A form's record is named by its parameter and angle, a composition's by its inputs as typed; a
// scene's by its material first.
inline std::vector<std::string> energy_id_keys() {
    return {"material", "model", "parameter", "value", "alpha_input", "r_input", "mu_input", "theta_input",
            "theta_deg", "f0", "f90", "eta", "k", "aspect", "gamma"};
}

inline check_rule energy_check_rule() {
    return {{{"albedo", "error_estimate", false}}, {"error_estimate", "tolerance", "evaluations", "closed_form_difference"}};
}

}  // namespace verify
