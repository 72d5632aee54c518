// Turns records into files: Markdown for people and citing, CSV and JSON for programs, each
// headed by what produced it. Files are staged under temporary names and renamed into place
// only when every one of them is complete, so a failed or interrupted run changes nothing.
#pragma once
#include "record.hpp"

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace verify {

class file_set;

// What a table's own console report knows of the run (table_output::console).
struct console_view {
    bool json = false;     // stdout carries the JSON document
    bool written = false;  // the table's files went to out_dir
    std::string out_dir;
};

struct table_output {
    table_info info;
    std::vector<record> records;
    std::string parameters;  // the grid the table was run on, for its header
    std::string command;     // the command that writes it, e.g. "./verify zoo"
    // The table's figure (plots.hpp), or none. The runner that makes the table sets it, capturing
    // by value what the figure needs beyond the records: the typed results the records only
    // summarize (the shader audits' curves), or a table run beside it (the irradiance rows). The
    // table itself comes as the argument, not captured, so a moved or copied table_output never
    // draws from a stale copy of its records.
    std::function<bool(const table_output&, file_set&)> figure = {};
    // Why a failing record fails, in one line that names it (what, where, by how much), when the
    // table says it better than its id and Markdown columns do (failure_line).
    std::function<std::string(const record&)> verdict = {};
    // A table whose files are not its Markdown, CSV and JSON (lut's one file in its --format):
    // stages them instead, among the run's other files (all renamed together, or none).
    std::function<void(const table_output&, file_set&)> own_files = {};
    // A table with a console report of its own (lut's line, --brdf's Markdown): printed instead of
    // its summary line, and with --json instead of its failures on stderr.
    std::function<void(const table_output&, const console_view&)> console = {};
};

std::string markdown(const table_output& t, std::size_t max_rows);
std::string csv(const table_output& t);
std::string json_file(const table_output& t);
nlohmann::ordered_json records_json(const table_output& t);  // the "records" array

// What names a record across runs: its id keys and inputs, never a computed value ("row = phong, n = 8").
std::string record_id(const table_output& t, const record& r);

// Why a failing check record fails, in one line: "TABLE: " and the table's verdict, or the
// record's id and the other fields its Markdown shows.
std::string failure_line(const table_output& t, const record& r);

// The failure_line of each failing record, at most max_lines, then how many more.
void print_failures(std::ostream& os, const table_output& t, std::size_t max_lines = 20);

// JUnit XML: one test case per check record (or per compared table with --check), named by
// record_id, a failure carrying its failure_line whole and every field.
struct junit_case {
    std::string suite, name;
    std::vector<std::string> failures;  // empty: passed
};
std::vector<junit_case> junit_test_cases(const table_output& t);
// The document; with a scene, its name is in every test suite's ("normzoo.NAME.zoo").
std::string junit_document(const std::vector<junit_case>& cases, const std::string& scene_name);

// A single file written to a temporary beside it and renamed into place.
void write_atomically(const std::filesystem::path& path, const std::string& content);

// Before anything is computed: the folder a run writes into is a folder, or can be made (it is
// made and removed again: a run writes only once every table is computed). Throws bad_input
// naming `option` and the path.
void check_output_folder(const std::filesystem::path& dir, const std::string& option);

// The same for the JUnit file: not a folder, and a file can be made beside it.
void check_output_file(const std::filesystem::path& file, const std::string& option);

// Files written together: stage() writes a temporary beside the target, commit() renames all.
class file_set {
public:
    explicit file_set(std::filesystem::path dir) : dir_(std::move(dir)) {}
    ~file_set();  // removes what was staged and not committed
    void stage(const std::string& name, const std::string& content);
    const std::filesystem::path& dir() const { return dir_; }
    std::filesystem::path temp_path(const std::string& name) const;  // for tools that write files (gnuplot)
    void adopt(const std::string& name, const std::filesystem::path& temp);  // a temp written by such a tool
    void commit();

private:
    std::filesystem::path dir_;
    std::vector<std::pair<std::filesystem::path, std::filesystem::path>> staged_;  // temp, target
};

}  // namespace verify
