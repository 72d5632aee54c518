// The formula of each zoo row, BRDF form and NDF a table shows, from the registry's strings, for
// the head of its Markdown (docs/reference.md, "The head of a table"; the notation is
// docs/conventions.md's).
#pragma once
#include <string>
#include <vector>

#include "record.hpp"

namespace verify {

// One line per distinct id under the keys "row", "model" and "ndf", in order of first
// appearance: "`phong`: (R.V)^n; normalization (n+1)/(2 pi)". Ids the registry does not know
// are left out.
std::vector<std::string> formula_lines(const std::vector<record>& records);

}  // namespace verify
