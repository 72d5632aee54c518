// `verify --check`: the tables recomputed against their committed copies, values within their
// error bounds and everything else exactly; and JUnit XML for CI servers.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "writers.hpp"

namespace verify {

// The differences between a recomputed table and `dir/NAME.json` (empty: they agree).
std::vector<std::string> compare_with_committed(const table_output& t, const std::filesystem::path& dir);

// One test case per check record (or per compared table with --check), failures with the numbers.
struct junit_case {
    std::string suite, name;
    std::vector<std::string> failures;  // empty: passed
};
std::vector<junit_case> junit_cases(const table_output& t);
std::string junit_xml(const std::vector<junit_case>& cases);

}  // namespace verify
