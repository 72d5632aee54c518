// A request (the parsed command line, or a scene) made into a plan: the table jobs to run, where
// their files go, and whether the run writes, checks or only prints (docs/architecture.md).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "scene_run.hpp"
#include "table_spec.hpp"

namespace verify {

struct run_plan {
    std::vector<const table_spec*> tables;  // in the order named, or every default table
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

// The plan of `cl`; bad_input for an option no table planned reads, a bad option of a table
// that reads its own (table_spec::check_options), an output path that cannot be written, or a
// custom grid aimed at the project's results folder. Computes nothing.
run_plan make_plan(const command_line& cl);

// The command that makes a table again, as the user types it: the table's name and the grid
// options it reads, as they were given (docs/reference.md, "The head of a table"). --jobs and
// --out change no value and are left out.
std::string table_command(const table_spec& spec, const options& o);

}  // namespace verify
