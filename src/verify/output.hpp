// The output stage: the computed tables written (atomically), or compared with their committed
// copies (--check); the docs that cite them refreshed or checked; JUnit, the --json document and
// the console's summary. The only stage of a table run that writes (docs/architecture.md).
#pragma once
#include <vector>

#include "command_line.hpp"
#include "plan.hpp"
#include "writers.hpp"

namespace verify {

// Everything the run produces from `outputs`, the tables its plan's jobs computed (and, with
// --json, the plan's skipped ones); returns whether a check failed (exit 1).
bool deliver(const command_line& cl, const run_plan& plan, const std::vector<table_output>& outputs);

}  // namespace verify
