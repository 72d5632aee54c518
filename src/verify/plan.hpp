// A request (the parsed command line, or a scene) made into a plan: the table jobs to run, the
// tables left out and why, where their files go, and whether the run writes, checks or only
// prints (docs/architecture.md).
#pragma once
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "table_spec.hpp"
#include "writers.hpp"

namespace verify {

struct scene;

// A table the run does not make, and why (a scene's run lists them: --json's "skipped").
struct skipped_table {
    std::string table, reason;
};

// What the run computes for one table, or for a group of tables computed together (a scene's
// energy, energy-summary and shader-normalization): its name and unit on the progress line, and
// the computation, which owns or shares everything it reads.
struct table_job {
    std::string name;
    std::string unit = "tasks";
    std::function<std::vector<table_output>()> run;
};

struct run_plan {
    std::vector<table_job> jobs;            // in the order of the results
    std::vector<skipped_table> skipped;     // decided with the jobs, in the order of the results
    std::string out_dir;                    // where the files go, or are compared (--check)
    std::string custom_grid;                // the first grid option given, or empty (the canonical grids)
    std::string scene_name;                 // in the JUnit suites' names (a scene's, or --brdf's file)
    bool writes = false;                    // stage and commit the files
    bool prints = false;                    // a table that is written only to --out (lut, --brdf) prints otherwise
    bool project_results = false;           // out_dir is the project's results/: the docs' citations follow it
};

// Every name in table_specs() but those an option plans (brdf-file), and those a run without
// names leaves out, for the parser.
std::vector<std::string> table_names();
std::vector<std::string> named_only_tables();

// The plan of `cl` and of its scene `sc` (loaded from cl.scene_path, or null): the tables
// named, the default ones, or those the scene needs (scene_run.hpp); bad_input for an option no
// table planned reads, a bad option of a table that reads its own (table_spec::check_options),
// an output path that cannot be written, or a custom grid aimed at the project's results folder.
// Computes nothing; the jobs share the scene, so it lives as long as they do.
run_plan make_plan(const command_line& cl, std::shared_ptr<const scene> sc);

// The command that makes a table again, as the user types it: the table's name and the grid
// options it reads, as they were given (docs/reference.md, "The head of a table"). --jobs and
// --out change no value and are left out.
std::string table_command(const table_spec& spec, const options& o);

}  // namespace verify
