// A table of the command, declared once (docs/architecture.md, "Adding a table"): its name and
// help, the grid options it reads, whether a run without names includes it, and how it is
// computed into table_outputs. Each spec is one file under specs/; table_specs() lists them in
// the order a full run takes them, and the command line, the plan, the heads' commands and the
// docs' lists of tables are derived from that list.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "writers.hpp"

namespace verify {

struct table_spec {
    const char* name;  // as typed: ./verify NAME
    const char* help;  // one line for --help
    // The grid options it reads, as typed ("--n"): those given appear in its head's command.
    std::vector<std::string> reads;
    std::function<std::vector<table_output>(const options&)> run;
    bool in_default_run = true;  // false: run only when named (it takes minutes, or its records carry timings)
    const char* unit = "tasks";  // what its progress line counts
    // A table with options of its own (lut, --brdf FILE; docs/architecture.md, "Tables with options
    // of their own"): checks them, as typed in options::typed, before anything is computed
    // (bad_input). Such a table runs alone: every option given must be one it reads.
    std::function<void(const options&)> check_options = {};
    bool writes_by_default = true;     // false: printed, and written only to a folder --out names
    const char* planned_by = nullptr;  // the option that plans it ("--brdf"), never named as a table
};

// Every table, in the order of a full run (specs/registry.cpp).
const std::vector<table_spec>& table_specs();

// The spec named `name`, or nullptr.
const table_spec* find_table_spec(const std::string& name);

// Shared by the specs: a grid's text, the default's or the exponents given with --n.
std::string grid_text(const options& o, const std::string& default_text);

}  // namespace verify
