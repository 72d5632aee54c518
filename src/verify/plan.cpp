#include "plan.hpp"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <utility>

#include "args.hpp"
#include "scene.hpp"
#include "scene_run.hpp"
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

std::string listed(const std::vector<std::string>& items) {
    std::string s;
    for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
    return s;
}

bool same_folder(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code ea, eb;
    const auto x = std::filesystem::weakly_canonical(std::filesystem::absolute(a), ea);
    const auto y = std::filesystem::weakly_canonical(std::filesystem::absolute(b), eb);
    return !ea && !eb && x == y;
}

// A table as the user asks for it: its name, or the option that plans it ("--brdf").
std::string shown_name(const table_spec& s) { return s.planned_by ? s.planned_by : s.name; }

bool reads(const table_spec& s, const std::string& option) {
    return std::find(s.reads.begin(), s.reads.end(), option) != s.reads.end();
}

// An option given that no planned table reads is bad input when a planned table reads options of
// its own (it runs alone), or when only such tables read it (--kind without lut); the options of
// the run itself (--out, --json, ...) go with every table (docs/command-line.md, "Options a
// table does not read"). Then those tables check their own options.
void refuse_unread_options(const command_line& cl, const std::vector<const table_spec*>& planned) {
    const std::vector<std::string> of_the_run = {"--out", "--json", "--junit", "--jobs", "--check", "--scene"};
    const bool own_planned = std::any_of(planned.begin(), planned.end(), [](const table_spec* s) { return bool(s->check_options); });
    for (const auto& [option, values] : cl.opts.typed) {
        if (std::find(of_the_run.begin(), of_the_run.end(), option) != of_the_run.end()) continue;
        if (std::any_of(planned.begin(), planned.end(), [&](const table_spec* s) { return reads(*s, option); })) continue;
        std::vector<std::string> readers;
        bool own_only = true;
        for (const auto& s : table_specs())
            if (reads(s, option)) readers.push_back(shown_name(s)), own_only = own_only && bool(s.check_options);
        if (!own_planned && (readers.empty() || !own_only)) continue;
        std::vector<std::string> names;
        for (const auto* s : planned) names.push_back(shown_name(*s));
        throw bad_input((own_planned && names.front() == "lut" ? "lut: " : "") + option + " is not read by " +
                        (names.empty() ? std::string("the default tables") : listed(names)) +
                        (readers.empty() ? std::string() : " (" + listed(readers) + " read" + (readers.size() == 1 ? "s" : "") + " it)"));
    }
    for (const auto* s : planned)
        if (s->check_options) s->check_options(cl.opts);
}

// The results folder ./verify names (NORMZOO_RESULTS_DIR), or empty when run otherwise.
std::string project_results_env() {
    const char* env = std::getenv("NORMZOO_RESULTS_DIR");
    return env && *env ? env : "";
}

// A job for each spec planned, in order: its tables as it computes them, each head with the
// command that makes it again (a table with options of its own heads its records itself).
std::vector<table_job> spec_jobs(const std::vector<const table_spec*>& specs, const options& given) {
    const auto o = std::make_shared<const options>(given);  // the jobs' own, shared
    std::vector<table_job> jobs;
    for (const auto* spec : specs)
        jobs.push_back({spec->name, spec->unit, [spec, o, command = table_command(*spec, given)] {
                            auto tables = spec->run(*o);
                            if (!spec->check_options)
                                for (auto& t : tables) t.command = command;
                            return tables;
                        }});
    return jobs;
}

}  // namespace

std::vector<std::string> table_names() {
    std::vector<std::string> names;
    for (const auto& s : table_specs())
        if (!s.planned_by) names.emplace_back(s.name);
    return names;
}

std::vector<std::string> named_only_tables() {
    std::vector<std::string> names;
    for (const auto& s : table_specs())
        if (!s.in_default_run && !s.planned_by) names.emplace_back(s.name);
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

run_plan make_plan(const command_line& cl, std::shared_ptr<const scene> sc) {
    run_plan p;
    std::vector<const table_spec*> specs;
    for (const auto& t : cl.tables) specs.push_back(find_table_spec(t));  // known and each once (the parser)
    if (specs.empty() && cl.scene_path.empty())
        for (const auto& s : table_specs())
            if (s.in_default_run) specs.push_back(&s);
    refuse_unread_options(cl, specs);
    p.prints = std::any_of(specs.begin(), specs.end(), [](const table_spec* s) { return !s->writes_by_default; });
    if (p.prints && cl.check && cl.out_dir.empty())
        throw bad_input("--check with " + shown_name(*specs.front()) + " compares the tables it wrote to a folder: name it "
                        "with --out DIR (it writes nothing to results/)");
    p.scene_name = cl.brdf_file;  // the JUnit suites of a shader file are named by it
    if (sc) {
        p.scene_name = sc->name;
        plan_scene_tables(sc, cl.opts.jobs, p);
    }
    for (auto& job : spec_jobs(specs, cl.opts)) p.jobs.push_back(std::move(job));
    const std::string results = project_results_env();
    const std::string results_dir = results.empty() ? "results" : results;  // where tables go by default
    p.out_dir = cl.out_dir;
    if (p.out_dir.empty() && !cl.scene_path.empty())
        p.out_dir = (std::filesystem::path(results_dir) / "scenes" / std::filesystem::path(cl.scene_path).stem()).string();
    if (p.out_dir.empty()) p.out_dir = results_dir;
    // results/ and the docs that cite it hold the tables on their canonical grids only: a custom
    // grid or --json writes only to a folder named by --out (docs/tables.md, "Where a run writes").
    p.custom_grid = custom_grid_option(cl.opts);
    p.writes = !cl.check && (!cl.out_dir.empty() || (!p.prints && p.custom_grid.empty() && !cl.json));
    if (p.writes && !p.custom_grid.empty() && same_folder(cl.out_dir, results_dir))
        throw bad_input("--out " + cl.out_dir + ": the results folder holds the tables on their canonical grids, "
                        "which the docs cite; write a run with " + p.custom_grid + " to another folder");
    // Paths that cannot be written are bad input, refused before the tables are computed.
    if (p.writes) check_output_folder(p.out_dir, cl.out_dir.empty() ? "the output folder" : "--out");
    if (!cl.junit_path.empty()) check_output_file(cl.junit_path, "--junit");
    // The project's docs cite its results/ tables: checked with --check, else refreshed. Only for
    // the project's own results folder (the one ./verify names), never for a custom --out.
    p.project_results = (cl.check || p.writes) && cl.scene_path.empty() && !p.prints && !results.empty() &&
                        std::filesystem::absolute(p.out_dir).lexically_normal() ==
                            std::filesystem::absolute(results).lexically_normal();
    return p;
}

}  // namespace verify
