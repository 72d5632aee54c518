// The tables a scene's run makes, one kind per function, in three translation units so that
// none compiles more than three tables: scene_zoo.cpp (zoo, bounds, irradiance), scene_energy.cpp
// (energy, energy-summary, shader-normalization) and scene_run.cpp (the compositions, the baked
// tables and the code, through the command's compiled functions; and the order of them all).
#pragma once
#include <string>
#include <vector>

#include "scene.hpp"
#include "scene_run.hpp"
#include "writers.hpp"

namespace verify::scene_parts {

// What every table of a scene's run shares: the scene, the threads, the command and head its
// tables show, and where the tables and the skipped ones go, in the order they are added.
struct scene_run {
    const scene& s;
    unsigned jobs;
    std::string command, head;
    std::vector<table_output>& out;
    std::vector<skipped_table>& skipped;
};

void add_zoo_table(const scene_run& run);
void add_bounds_table(const scene_run& run);
void add_irradiance_table(const scene_run& run);
void add_energy_tables(const scene_run& run);

}  // namespace verify::scene_parts
