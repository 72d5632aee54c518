#include "output.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <optional>
#include <nlohmann/json.hpp>

#include "check.hpp"
#include "citations.hpp"
#include "write_guard.hpp"

namespace verify {

namespace {

// Long tables show an even sample in Markdown: the run's files and --check render them alike.
std::size_t markdown_rows(const table_output& t) { return t.records.size() > 300 ? 60 : 300; }

// Compare every file a run writes (docs/tables.md, "What --check compares"); write none. What the
// docs' citations must show goes to cited_by_name: each value the comparison accepts as committed.
bool check_tables(const std::vector<table_output>& outputs, const run_plan& plan, bool json,
                  std::vector<junit_case>& cases, std::map<std::string, std::string>& cited_by_name) {
    bool failed = false;
    for (const auto& t : outputs) {
        const auto c = check_committed(t, plan.out_dir, markdown_rows(t));
        cases.push_back({"normzoo.check", t.info.name, c.diffs});
        std::ostream& os = json ? std::cerr : std::cout;
        os << t.info.name << ": " << (c.diffs.empty() ? "matches " : "DIFFERS from ");
        for (std::size_t i = 0; i < c.files.size(); ++i)
            os << (i ? ", " + c.files[i] : (std::filesystem::path(plan.out_dir) / c.files[i]).string());
        os << (c.diffs.empty() ? " (" + std::to_string(t.records.size()) + " records)" : "") << "\n";
        for (const auto& d : c.diffs) os << "  " << d << "\n";
        for (const auto& n : c.notes) std::cerr << "verify: " << t.info.name << ": " << n << "\n";
        failed = failed || !c.diffs.empty();
        cited_by_name[t.info.name + ".md"] = c.markdown;
    }
    return failed;
}

// Every table's files staged, then renamed into place together; an interrupted run leaves none.
void write_tables(const std::vector<table_output>& outputs, const std::string& out_dir,
                  const std::map<std::string, std::string>& markdown_by_name, const write_guard& guard) {
    file_set files(out_dir);
    for (const auto& t : outputs) {
        if (t.own_files) {
            t.own_files(t, files);
            continue;
        }
        files.stage(t.info.name + ".md", markdown_by_name.at(t.info.name + ".md"));
        files.stage(t.info.name + ".csv", csv(t));
        files.stage(t.info.name + ".json", json_file(t));
        if (t.figure) t.figure(t, files);
    }
    if (guard.interrupted()) throw interrupted();  // files removes what it staged
    files.commit();
}

// The README and docs/*.md beside the project's results folder: their citations refreshed, or
// with --check compared. Returns whether one is stale under --check.
bool cite_in_docs(const run_plan& plan, bool check, bool json, const std::map<std::string, std::string>& cited_by_name,
                  std::vector<junit_case>& cases) {
    const auto root = std::filesystem::absolute(plan.out_dir).lexically_normal().parent_path();
    std::vector<std::filesystem::path> docs{root / "README.md"};
    if (std::filesystem::is_directory(root / "docs"))
        for (const auto& e : std::filesystem::directory_iterator(root / "docs"))
            if (e.path().extension() == ".md") docs.push_back(e.path());
    std::sort(docs.begin(), docs.end());
    bool failed = false;
    for (const auto& d : docs) {
        if (!std::filesystem::exists(d)) continue;
        std::ifstream in(d, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::vector<std::string> stale;
        const std::string fresh = refresh_citations(text, cited_by_name, d.string(), stale);
        if (check) {
            for (const auto& s : stale) (json ? std::cerr : std::cout) << "docs: " << s << "\n";
            if (!stale.empty()) cases.push_back({"normzoo.check", "docs: " + d.filename().string(), stale});
            else if (fresh.find("normzoo:cite") != std::string::npos) cases.push_back({"normzoo.check", "docs: " + d.filename().string(), {}});
            failed = failed || !stale.empty();
        } else if (fresh != text) {
            write_atomically(d, fresh);
        }
    }
    return failed;
}

void print_json(const std::vector<table_output>& outputs, const std::vector<skipped_table>& skipped) {
    nlohmann::ordered_json doc;
    doc["records"] = nlohmann::ordered_json::array();
    for (const auto& t : outputs)
        for (auto& r : records_json(t)) doc["records"].push_back(std::move(r));
    doc["skipped"] = nlohmann::ordered_json::array();
    for (const auto& k : skipped) doc["skipped"].push_back({{"table", k.table}, {"reason", k.reason}});
    std::cout << doc.dump() << "\n";
}

void print_summary(const table_output& t, const run_plan& plan) {
    std::size_t fails = 0;
    for (const auto& r : t.records) fails += r.failed();
    std::cout << t.info.name << ": " << t.records.size() << " records, " << fails << " failing"
              << (plan.writes ? " -> " + (std::filesystem::path(plan.out_dir) / (t.info.name + ".md")).string()
                              : std::string(" (not written)"))
              << "\n";
    print_failures(std::cout, t);
}

// Each table on the console after a run that does not --check: its summary line (with --json,
// its failures on stderr), or its own report (lut, --brdf).
void print_tables(const command_line& cl, const run_plan& plan, const std::vector<table_output>& outputs) {
    for (const auto& t : outputs) {
        if (t.console) t.console(t, {cl.json, plan.writes, plan.out_dir});
        else if (cl.json) print_failures(std::cerr, t);
        else print_summary(t, plan);
    }
}

}  // namespace

bool deliver(const command_line& cl, const run_plan& plan, const std::vector<table_output>& outputs) {
    bool failed = false;
    for (const auto& t : outputs)
        for (const auto& r : t.records) failed = failed || r.failed();
    // Each table's Markdown, once: written to the results, and what the docs cite.
    std::map<std::string, std::string> markdown_by_name;
    for (const auto& t : outputs) markdown_by_name[t.info.name + ".md"] = markdown(t, markdown_rows(t));
    std::vector<junit_case> cases;
    std::optional<write_guard> guard;  // from the first file staged to the last renamed
    std::map<std::string, std::string> cited_by_name = markdown_by_name;
    if (cl.check) {
        failed = check_tables(outputs, plan, cl.json, cases, cited_by_name) || failed;
    } else if (!plan.writes && !plan.prints) {
        std::cerr << "verify: nothing written: "
                  << (cl.json ? "--json puts the records on stdout"
                              : "a run with " + plan.custom_grid + " is not on the tables' canonical grids, which " +
                                    plan.out_dir + " holds")
                  << "; to write the tables, add --out DIR\n";
    } else if (plan.writes) {
        std::filesystem::create_directories(plan.out_dir);
        guard.emplace(plan.out_dir);
        write_tables(outputs, plan.out_dir, markdown_by_name, *guard);
    }
    if (!cl.check)
        for (const auto& t : outputs)
            for (auto& c : junit_test_cases(t)) cases.push_back(std::move(c));
    if (plan.project_results) failed = cite_in_docs(plan, cl.check, cl.json, cited_by_name, cases) || failed;
    if (!cl.junit_path.empty()) write_atomically(cl.junit_path, junit_document(cases, plan.scene_name));
    if (cl.json) print_json(outputs, plan.skipped);
    // The tables on the console; after --check, why each failing check fails (stdout is the JSON's).
    if (!cl.check) print_tables(cl, plan, outputs);
    else
        for (const auto& t : outputs) print_failures(cl.json ? std::cerr : std::cout, t);
    return failed;
}

}  // namespace verify
