#include "plan.hpp"

#include <algorithm>
#include <cstdlib>
#include <utility>

#include "args.hpp"
#include "writers.hpp"

namespace verify {

namespace {

// The first grid option given ("--n", ...), or empty: the run is on the tables' canonical grids.
std::string custom_grid_option(const options& o) {
    const std::pair<bool, const char*> given[] = {
        {!o.exponents.empty(), "--n"},  {!o.angles.empty(), "--theta"}, {!o.models.empty(), "--model"},
        {!o.lights.empty(), "--light"}, {!o.ratios.empty(), "--ratio"}, {!o.tilts.empty(), "--tilt"},
        {o.seed.has_value(), "--seed"}, {o.cases.has_value(), "--cases"}, {!o.roughness.empty(), o.roughness_is_r ? "--r" : "--alpha"},
        {!o.mus.empty(), "--mu"},       {o.parts.f0.has_value(), "--f0"}};
    for (const auto& [set, name] : given)
        if (set) return name;
    return {};
}

// A value as a shell takes it back: quoted when it holds anything but a list's characters.
std::string shell_word(const std::string& v) {
    const bool plain = !v.empty() && v.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                                                         ".,+-_") == std::string::npos;
    if (plain) return v;
    std::string q = "'";
    for (char c : v) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string comma_list(const std::vector<std::string>& items) {
    std::string s;
    for (const auto& i : items) s += (s.empty() ? "" : ",") + i;
    return s;
}

bool same_folder(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code ea, eb;
    const auto x = std::filesystem::weakly_canonical(std::filesystem::absolute(a), ea);
    const auto y = std::filesystem::weakly_canonical(std::filesystem::absolute(b), eb);
    return !ea && !eb && x == y;
}

// The results folder ./verify names (NORMZOO_RESULTS_DIR), or empty when run otherwise.
std::string project_results_env() {
    const char* env = std::getenv("NORMZOO_RESULTS_DIR");
    return env && *env ? env : "";
}

}  // namespace

std::vector<std::string> table_names() {
    std::vector<std::string> names;
    for (const auto& s : table_specs()) names.emplace_back(s.name);
    return names;
}

std::vector<std::string> named_only_tables() {
    std::vector<std::string> names;
    for (const auto& s : table_specs())
        if (!s.in_default_run) names.emplace_back(s.name);
    return names;
}

std::string table_command(const table_spec& spec, const options& o) {
    std::vector<std::pair<std::string, std::string>> given = {
        {"--n", o.exponents.empty() ? "" : o.exponents_text},
        {"--theta", o.angles.empty() ? "" : o.angles_text},
        {"--model", comma_list(o.models)},
        {"--light", comma_list(o.lights)},
        {"--ratio", o.ratios.empty() ? "" : o.ratios_text},
        {"--tilt", o.tilts.empty() ? "" : o.tilts_text},
        {"--seed", o.seed ? std::to_string(*o.seed) : ""},
        {"--cases", o.cases ? std::to_string(*o.cases) : ""},
        {o.roughness_is_r ? "--r" : "--alpha", o.roughness.empty() ? "" : o.roughness_text},
        {"--mu", o.mus.empty() ? "" : o.mus_text},
        {"--f0", o.parts.f0 ? o.parts.f0->text() : ""}};
    for (const auto& q : part_parameters())
        given.emplace_back(std::string("--") + q.name, o.parts.*q.input ? (o.parts.*q.input)->text() : "");
    std::string c = std::string("./verify ") + spec.name;
    for (const auto& [option, value] : given)
        if (!value.empty() && std::find(spec.reads.begin(), spec.reads.end(), option) != spec.reads.end())
            c += " " + option + " " + shell_word(value);
    return c;
}

run_plan make_plan(const command_line& cl) {
    run_plan p;
    for (const auto& t : cl.tables) p.tables.push_back(find_table_spec(t));  // known and each once (the parser)
    if (p.tables.empty() && cl.scene_path.empty())
        for (const auto& s : table_specs())
            if (s.in_default_run) p.tables.push_back(&s);
    const std::string results = project_results_env();
    const std::string results_dir = results.empty() ? "results" : results;  // where tables go by default
    p.out_dir = cl.out_dir;
    if (p.out_dir.empty() && !cl.scene_path.empty())
        p.out_dir = (std::filesystem::path(results_dir) / "scenes" / std::filesystem::path(cl.scene_path).stem()).string();
    if (p.out_dir.empty()) p.out_dir = results_dir;
    // results/ and the docs that cite it hold the tables on their canonical grids only: a custom
    // grid or --json writes only to a folder named by --out (docs/tables.md, "Where a run writes").
    p.custom_grid = custom_grid_option(cl.opts);
    p.writes = !cl.check && (!cl.out_dir.empty() || (p.custom_grid.empty() && !cl.json));
    if (p.writes && !p.custom_grid.empty() && same_folder(cl.out_dir, results_dir))
        throw bad_input("--out " + cl.out_dir + ": the results folder holds the tables on their canonical grids, "
                        "which the docs cite; write a run with " + p.custom_grid + " to another folder");
    // Paths that cannot be written are bad input, refused before the tables are computed.
    if (p.writes) check_output_folder(p.out_dir, cl.out_dir.empty() ? "the output folder" : "--out");
    if (!cl.junit_path.empty()) check_output_file(cl.junit_path, "--junit");
    // The project's docs cite its results/ tables: checked with --check, else refreshed. Only for
    // the project's own results folder (the one ./verify names), never for a custom --out.
    p.project_results = (cl.check || p.writes) && cl.scene_path.empty() && !results.empty() &&
                        std::filesystem::absolute(p.out_dir).lexically_normal() ==
                            std::filesystem::absolute(results).lexically_normal();
    return p;
}

}  // namespace verify
