// `verify --check`: the tables recomputed against their committed copies, values within their
// error bounds and everything else exactly, in every file a run writes (docs/tables.md, "What
// --check compares"); and JUnit XML for CI servers.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "writers.hpp"

namespace verify {

// The differences between a recomputed table's records and those of `dir/NAME.json` (empty: they agree).
std::vector<std::string> compare_with_committed(const table_output& t, const std::filesystem::path& dir);

// What --check found for one table in its folder.
struct table_check {
    std::vector<std::string> files;  // compared, in order: NAME.json, NAME.md, NAME.csv, the figures
    std::vector<std::string> diffs;  // empty: every one agrees
    std::vector<std::string> notes;  // what could not be compared (a figure gnuplot did not draw)
    std::string markdown;            // NAME.md as compared: what the docs' citations must show
};

// Every file a run writes for `t` against its committed copy in `dir`: the JSON's records within
// their error bounds (compare_with_committed), and its head and layout as the writer makes them;
// NAME.md (`md_rows` as the run gives markdown()) and NAME.csv byte for byte against what a run
// writes, each value the record comparison accepts taken as committed; the table's figures,
// drawn again, byte for byte where one is committed.
table_check check_committed(const table_output& t, const std::filesystem::path& dir, std::size_t md_rows);


}  // namespace verify
