// An option's value that is rather an option (docs/command-line.md, "Command reference"): CLI11
// takes the argument after an option as its value even when it is another option, so `--out
// --json` would write into a folder named "--json". The parser (command_line.cpp) refuses these.
#pragma once
#include <set>
#include <string>

namespace CLI {
class App;
}

namespace verify {

// Every option name of app, long (--name) and short (-n).
std::set<std::string> option_names(const CLI::App& app);

// Whether an argument taken as a value is rather an option: it begins with "--" or is a name.
bool option_like(const std::string& value, const std::set<std::string>& names);

// Before parsing: an option that takes a value followed by nothing or by another option name
// (CLI11 would report the stray value after it instead, or take the option name as the value).
// `also` names flags that take a value here (lut's --check FILE). bad_input after `prefix`.
void refuse_missing_values(const CLI::App& app, int argc, const char* const* argv, const std::string& prefix,
                           const std::set<std::string>& also);

// After parsing: bad_input (after `prefix`) for a value that begins with "--" or is an option's
// name (a path so named can be given as ./--json), and for an empty path (--out, --junit,
// --scene, --check, --brdf), which would silently mean none.
void refuse_forgotten_values(const CLI::App& app, const std::string& prefix);

}  // namespace verify
