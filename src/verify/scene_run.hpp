// The tables a scene needs and nothing else, planned as table jobs (docs/command-line.md, "A
// guardrail for an engine"): the part of the plan for `./verify --scene FILE`.
#pragma once
#include <memory>

#include "plan.hpp"
#include "scene.hpp"

namespace verify {

// Each kind of table the scene asks for, as a job appended to p.jobs in the order of the
// results; what it does not need goes to p.skipped with the reason. The jobs share the scene and
// compute on `threads` threads.
void plan_scene_tables(const std::shared_ptr<const scene>& s, unsigned threads, run_plan& p);

}  // namespace verify
