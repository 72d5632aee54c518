// The text of --help around the options (its head and its examples), and the two lists it and
// the parser share: the tables' old names, and a list of names in words.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace verify {

// "a, b, c"
std::string joined(const std::vector<std::string>& names);

// Old table names still accepted, and the table that replaced each.
const std::vector<std::pair<std::string, std::string>>& table_aliases();

// The head of --help: the tables, which run by default, their old names, the exit codes.
std::string help_head(const std::vector<std::string>& tables, const std::vector<std::string>& named_only);

// The foot of --help: examples, and where every option is described.
std::string help_examples(const std::string& command);

}  // namespace verify
