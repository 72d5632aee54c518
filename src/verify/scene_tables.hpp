// The tables a scene's run makes, one kind per function, in three translation units so that
// none compiles more than three tables: scene_zoo.cpp (zoo, bounds, irradiance), scene_energy.cpp
// (energy, energy-summary, shader-normalization) and scene_run.cpp (the compositions, the baked
// tables and the code, through the command's compiled functions; and the order of them all).
// Each function plans its kind: from the scene alone it decides whether the run needs it, and
// appends either a job that computes it or the skipped entries with their reasons.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "plan.hpp"
#include "scene.hpp"
#include "writers.hpp"

namespace verify::scene_parts {

// What every job of a scene's run shares, captured by value: the scene, the threads, the command
// and head its tables show, and its name on the progress line ("scene FILE").
struct scene_run {
    std::shared_ptr<const scene> s;
    unsigned jobs;
    std::string command, head, step;
};

// The job named `table` on the progress line ("scene FILE: table") that runs `compute`.
inline table_job scene_job(const scene_run& run, const std::string& table,
                           std::function<std::vector<table_output>()> compute) {
    return {run.step + ": " + table, "tasks", std::move(compute)};
}

void plan_zoo_table(const scene_run& run, run_plan& p);
void plan_bounds_table(const scene_run& run, run_plan& p);
void plan_irradiance_table(const scene_run& run, run_plan& p);
void plan_energy_tables(const scene_run& run, run_plan& p);

}  // namespace verify::scene_parts
