// verify: the users' command. Parses arguments (command_line), plans the tables, runs them
// (library), writes the results (writers), and exits 0 (every check holds), 1 (a check fails) or 2 (bad input).
#include <normzoo/normzoo.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <iostream>
#include <nlohmann/json.hpp>

#include "args.hpp"
#include "check.hpp"
#include "citations.hpp"
#include "command_line.hpp"
#include "brdf_examples.hpp"
#include "brdf_run.hpp"
#include "lut.hpp"
#include "microfacet_tables.hpp"
#include "plots.hpp"
#include "progress.hpp"
#include "scene.hpp"
#include "scene_run.hpp"
#include "write_guard.hpp"
#include "tables/enclosures.hpp"
#include "tables/error_audit.hpp"
#include "tables/proofs.hpp"
#include "tables/tables.hpp"
#include "writers.hpp"

namespace {

using verify::bad_input;
using verify::options;
using verify::table_output;

std::string grid_text(const options& o, const char* default_text) {
    return o.exponents.empty() ? std::string(default_text) : "n = " + o.exponents_text;
}

std::vector<std::string> all_brdf_ids() {
    std::vector<std::string> ids;
    for (auto id : normzoo::brdf_ids()) ids.emplace_back(id);
    return ids;
}

// The forms a zoo row normalizes: the punctual limit's default (its table was built for them).
std::vector<std::string> zoo_brdf_ids() {
    std::vector<std::string> ids;
    for (auto id : normzoo::zoo_brdf_ids()) ids.emplace_back(id);
    return ids;
}

std::vector<table_output> irradiance_tables(const options& o) {
    std::vector<normzoo::light_kind> lights;
    for (const auto& l : o.lights.empty() ? std::vector<std::string>{"sphere", "disk"} : o.lights)
        lights.push_back(l == "sphere" ? normzoo::light_kind::sphere : normzoo::light_kind::disk);
    const auto ratios = o.ratios.empty() ? normzoo::default_irradiance_ratios() : o.ratios;
    const auto tilts = o.tilts.empty() ? normzoo::default_irradiance_tilts() : o.tilts;
    std::string grid = o.ratios.empty() ? "ratios 1e-1 to 1e-15 by decades, 1e-30, 1e-100, 1e-300" : "ratio = " + o.ratios_text;
    grid += o.tilts.empty() ? ", tilts 0, 30, 60, 85, 89.9, 90.5, 95 degrees" : ", tilt = " + o.tilts_text;
    if (!o.lights.empty()) grid += ", lights " + o.lights.front() + (o.lights.size() > 1 ? "," + o.lights.back() : "");
    const auto models = o.models.empty() ? zoo_brdf_ids() : o.models;
    const auto infos = normzoo::irradiance_infos(normzoo::doubles_of(ratios));
    const auto points = normzoo::irradiance_points(lights, normzoo::ratio_inputs(ratios), tilts, o.jobs);
    auto rows = normzoo::irradiance_table(points);
    auto limit = normzoo::irradiance_limit_table(normzoo::irradiance_limit_summary(points));
    const std::string command = "./verify irradiance";
    std::vector<table_output> out;
    out.push_back({infos[0], std::move(rows), grid, command});
    out.push_back({infos[1], std::move(limit), grid, command});
    // irradiance-limit.svg draws from this table and the first: it keeps a copy of those rows.
    out.push_back({infos[2], normzoo::punctual_table(models, 32, o.jobs),
                   "e = 1e-1 to 1e-8, four (l_c, V) pairs, n = 32", command,
                   [irradiance = out[0].records](const table_output& punctual, verify::file_set& files) {
                       return verify::plot_limits(irradiance, punctual, files);
                   }});
    return out;
}

// The energy table's rows split for its two figures: the forms a zoo row normalizes (energy-albedo.svg)
// and the others (models-energy.svg, docs/models.md).
std::pair<table_output, table_output> split_energy_for_plots(const table_output& energy) {
    std::pair<table_output, table_output> parts{{energy.info, {}, energy.parameters, energy.command},
                                                {energy.info, {}, energy.parameters, energy.command}};
    const auto zoo = normzoo::zoo_brdf_ids();
    for (const auto& r : energy.records) {
        const auto* m = r.find("model");
        const bool of_zoo = m && std::find(zoo.begin(), zoo.end(), std::get<std::string>(*m)) != zoo.end();
        (of_zoo ? parts.first : parts.second).records.push_back(r);
    }
    return parts;
}

// Compositions named with --model D/G/F: one energy record per (model, roughness, incidence).
std::vector<table_output> composition_energy_tables(const options& o) {
    std::vector<verify::roughness_input> roughness;
    for (const auto& x : o.roughness.empty() ? normzoo::decimals({"0.01", "0.1", "0.3", "0.5", "1"}) : o.roughness)
        roughness.push_back({x, o.roughness_is_r});
    std::vector<verify::incidence_input> incidence;
    if (!o.angles.empty())
        for (const auto& t : o.angles) incidence.push_back({t, true});
    else
        for (const auto& m : o.mus.empty() ? normzoo::decimals({"1e-4", "0.01", "0.1", "0.5", "1"}) : o.mus)
            incidence.push_back({m, false});
    auto t = verify::composition_energy_table(o.models, roughness, incidence, o.parts, o.jobs);
    t.parameters = std::string(o.roughness_is_r ? "r = " : "alpha = ") +
                   (o.roughness.empty() ? "0.01, 0.1, 0.3, 0.5, 1" : o.roughness_text) +
                   (!o.angles.empty() ? ", theta = " + o.angles_text
                                      : ", mu = " + (o.mus.empty() ? std::string("1e-4, 0.01, 0.1, 0.5, 1") : o.mus_text)) +
                   (o.parts.f0 ? ", f0 = " + o.parts.f0->text() : std::string());
    for (const auto& q : verify::part_parameters())
        if (o.parts.*q.input) t.parameters += std::string(", ") + q.name + " = " + (o.parts.*q.input)->text();
    return {std::move(t)};
}

std::vector<table_output> energy_tables(const options& o) {
    if (!o.models.empty() && o.models.front().find('/') != std::string::npos) return composition_energy_tables(o);
    const auto angles = o.angles.empty() ? normzoo::default_energy_angle_inputs() : o.angles;
    const auto models = o.models.empty() ? all_brdf_ids() : o.models;
    // Each form at each value of its declared grid (--n replaces the grid of the forms swept in n).
    std::string grid = o.exponents.empty() ? "each form's declared grid (n = 1, 2, 4, ..., 2048, 1e4, 1e5; "
                                             "Ashikhmin-Shirley n = 1, 10, 100, 1000; alpha = 0.1, 0.3, 0.5, 0.7, 1; "
                                             "r = 0, 0.5, 1)"
                                           : "n = " + o.exponents_text + ", the other parameters at their grids";
    grid += o.angles.empty() ? ", angles 0, 1, ..., 89, 89.5, 89.9, 89.99 degrees" : ", theta = " + o.angles_text;
    if (!o.models.empty()) {
        grid += ", models ";
        for (const auto& m : models) grid += m + (&m == &models.back() ? "" : ",");
    }
    // The claims are about the seed's exponent forms: their grid is the exponents.
    std::string claims_grid = grid_text(o, "default exponents 1, 2, 4, ..., 2048, 1e4, 1e5");
    claims_grid += grid.substr(grid.find(", angles") != std::string::npos ? grid.find(", angles") : grid.find(", theta"));
    const std::string command = "./verify energy";
    const std::uint64_t samples = std::uint64_t(1) << 20;
    const normzoo::energy_settings es;
    const auto sweep = o.exponents.empty() ? normzoo::energy_sweep(models, angles, o.jobs, es)
                                           : normzoo::energy_sweep(models, o.exponents, angles, o.jobs, es);
    const auto summary = normzoo::energy_summary(sweep, o.jobs, es);
    auto claims = normzoo::energy_claims(sweep, summary, es);
    const auto fv = normzoo::fresnel_visibility_infos();
    std::vector<table_output> out;
    out.push_back({normzoo::energy_info(normzoo::doubles_of(angles)), normzoo::energy_records(sweep), grid, command,
                   [](const table_output& t, verify::file_set& files) {
                       // the forms a zoo row normalizes by exponent, and the others by their parameter
                       const auto [zoo_forms, other_forms] = split_energy_for_plots(t);
                       bool drawn = true;
                       if (!zoo_forms.records.empty()) drawn = verify::plot_albedo(zoo_forms, files) && drawn;
                       if (!other_forms.records.empty()) drawn = verify::plot_models_energy(other_forms, files) && drawn;
                       return drawn;
                   }});
    out.push_back({normzoo::energy_summary_info(), normzoo::energy_summary_table(summary), grid, command});
    out.push_back({normzoo::energy_claims_info(), std::move(claims), claims_grid, command});
    out.push_back({fv[0], normzoo::fresnel_visibility_table(), "k_s = 0.02, 0.05, 0.8", command,
                   verify::plot_fresnel_visibility});
    out.push_back({fv[1], normzoo::fresnel_visibility_summary(), "k_s = 0.02, 0.05, 0.8", command});
    out.push_back({fv[2], normzoo::fresnel_visibility_albedo(o.jobs), "k_s = 0.02, 0.05, 0.8; n = 16, 256", command});
    out.push_back({normzoo::monte_carlo_info(samples), normzoo::monte_carlo_table(models, samples, o.jobs),
                   "one case per form selected", command});
    return out;
}

std::vector<table_output> audit_tables(const options& o) {
    normzoo::audit_settings audit;
    if (o.seed) audit.seed = *o.seed;
    if (o.cases) audit.cases = *o.cases;
    const auto cases = normzoo::run_audit(audit, o.jobs);
    const std::string grid = "seed " + std::to_string(audit.seed) + ", " + std::to_string(cases.size()) + " cases";
    const std::string command = "./verify audit";
    std::vector<table_output> out;
    out.push_back({normzoo::error_audit_info(audit),
                   normzoo::error_audit_table(normzoo::audit_summaries(cases, audit.pessimism_limit)), grid, command});
    out.push_back({normzoo::error_audit_histogram_info(), normzoo::error_audit_histogram(normzoo::audit_histograms(cases)),
                   grid, command, verify::plot_error_audit});
    out.push_back({normzoo::error_audit_extremes_info(),
                   normzoo::error_audit_extremes(normzoo::audit_extreme_cases(cases)), grid, command});
    return out;
}

struct table_runner {
    const char* name;
    const char* help;
    std::function<std::vector<table_output>(const options&)> run;
    bool in_default_run = true;  // false: run only when named (it takes seconds)
    const char* unit = "tasks";  // what its progress line counts
};

// The tables `verify` knows, in the order a full run does them.
const std::vector<table_runner>& runners() {
    static const std::vector<table_runner> list = {
        {"zoo", "every zoo row by 1D and 2D quadrature and closed form; shader constants; 8-bit gloss",
         [](const options& o) {
             const auto n = o.exponents.empty() ? normzoo::default_zoo_exponents() : o.exponents;
             const std::string grid = grid_text(o, "default exponents 0, 0.1, 0.5, 1, 2, 4, ..., 2048, 1e4, 1e5, 1e6, 1e7");
             return std::vector<table_output>{
                 {normzoo::zoo_info(), normzoo::zoo_table(n, o.jobs), grid, "./verify zoo"},
                 {normzoo::zoo_constants_info(), normzoo::zoo_constants_table(n, o.jobs), grid, "./verify zoo"},
                 {normzoo::gloss_info(), normzoo::gloss_table(), "codes 0 to 255", "./verify zoo"}};
         }},
        {"bounds", "the Blinn-Phong bounds decided in 50 digits",
         [](const options& o) {
             const auto n = o.exponents.empty() ? normzoo::default_bounds_exponents() : o.exponents;
             return std::vector<table_output>{
                 {normzoo::bounds_info(), normzoo::bounds_table(n),
                  grid_text(o, "default exponents n = 0 and 1000 log-spaced from 1e-6 to 1e7"), "./verify bounds",
                  verify::plot_bounds}};
         }},
        {"enclosures", "every zoo row's integral enclosed rigorously (Arb), beside the quadrature and the closed form",
         [](const options& o) {
             const auto n = o.exponents.empty() ? normzoo::default_zoo_exponents() : o.exponents;
             return std::vector<table_output>{
                 {normzoo::certify::enclosures_info(), normzoo::certify::enclosures_table(n, o.jobs),
                  grid_text(o, "default exponents 0, 0.1, 0.5, 1, 2, 4, ..., 2048, 1e4, 1e5, 1e6, 1e7"),
                  "./verify enclosures", verify::plot_enclosures}};
         },
         false},  // its tables carry timings: a default run stays byte-identical without them
        {"proofs", "the Blinn-Phong bounds proved for every real n in [0, 1e7] by branch and bound (MPFI)",
         [](const options&) {  // every n in [0, 1e7]: --n does not apply
             return std::vector<table_output>{{normzoo::certify::proofs_info(), normzoo::certify::proofs_table(),
                                               "n in [0, 1e7]; controls tightened by 1e-6", "./verify proofs"}};
         },
         false},
        {"energy", "directional albedo of every BRDF form (the seed's exponent forms, Ward, Ashikhmin-Shirley, "
                   "Disney diffuse) at each value of its parameter against incident angle; the seeds' claims; the "
                   "seed's F.V comparison; Monte Carlo cross-check",
         energy_tables},
        {"microfacet", "microfacet compositions D/G/F: E(mu, alpha) of the reference compositions and the white furnace "
                       "of their multiple-scattering compensations, E_avg(alpha), and every shortcut against the exact "
                       "integrals (visibility terms, the EnvBRDFApprox fit, Monte Carlo bakers, Schlick's Fresnel)",
         [](const options& o) { return verify::microfacet_tables(o.jobs); }},
        {"irradiance", "sphere and disk lights against their closed forms and the point light as r0/r -> 0; the "
                       "punctual-light limit of every BRDF form",
         irradiance_tables},
        {"ndf", "Beckmann and GGX by roughness alpha: normalization, non-projected integral, Smith G1 and the weak "
                "white furnace; the Phong-Beckmann mapping",
         [](const options& o) {
             const std::string command = "./verify ndf";
             const std::string grid = "alpha = 1e-4, 1e-3, 1e-2, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1, 2, 5, 10";
             const auto alphas = normzoo::default_ndf_alphas();
             const auto n = o.exponents.empty() ? normzoo::default_mapping_exponents() : o.exponents;
             return std::vector<table_output>{
                 {normzoo::ndf_info(), normzoo::ndf_table(alphas, o.jobs), grid, command, verify::plot_ndf},
                 {normzoo::furnace_info(),
                  normzoo::furnace_table(alphas, normzoo::default_furnace_angles(), o.jobs),
                  grid + "; theta_v = 0, 30, 60, 80, 85, 89, 89.9 degrees", command, verify::plot_ndf_furnace},
                 {normzoo::mapping_info(), normzoo::mapping_table(n, o.jobs),
                  grid_text(o, "default exponents 1, 2, 4, ..., 128, 512, 2048, 1e4, 1e5"), command}};
         }},
        {"shader-precision", "every shader formula (zoo normalizations, (n+8)/(8 pi), gloss, Schlick and its exp2 "
                             "form, the lobe and its spherical Gaussian) in fp16 and fp32 against its exact value",
         [](const options& o) {
             // The audits once: the records summarize them, the figure draws their curves.
             auto audits = normzoo::shader_precision_audits(o.jobs);
             auto records = normzoo::shader_precision_table(audits);
             return std::vector<table_output>{
                 {normzoo::shader_precision_info(), std::move(records),
                  "n = 0, 1e-3 to 1e9; L.H in [0, 1]; gloss codes 0 to 255", "./verify shader-precision",
                  [audits = std::move(audits)](const table_output&, verify::file_set& files) {
                      return verify::plot_shader_precision(audits, files);
                  }}};
         }},
        {"brdf-code", "the BRDF Explorer files of examples/brdfs/ compiled and integrated as black boxes, against the "
                      "built-in forms they write out (docs/brdf-code.md)",
         [](const options& o) { return verify::brdf_example_tables(o.jobs); }},
        {"code-audit", "the black-box integrator of BRDFs given as code against every built-in form passed as an "
                       "opaque callable (minutes: only when named)",
         [](const options& o) { return verify::code_audit_tables(o.jobs); }, false},
        {"stability", "every integrand to the ends of its domain (n to 1e9, incidence to 90 - 1e-6 deg, r0/r to "
                      "5e-324), and where the naive formulations break; run only when named",
         [](const options& o) {
             const std::string grid = "the stress grids (fixed)";
             return std::vector<table_output>{
                 {normzoo::stability_info(), normzoo::stability_table(o.jobs), grid, "./verify stability"},
                 {normzoo::stability_naive_info(), normzoo::stability_naive_table(o.jobs), grid, "./verify stability"}};
         },
         false},
        {"audit", "every error estimate against the true error over 10,000 random cases with known answers (~10 s of "
                  "work: only when named)",
         audit_tables, false, "cases"},
    };
    return list;
}

std::vector<std::string> table_name_list() {
    std::vector<std::string> names;
    for (const auto& r : runners()) names.emplace_back(r.name);
    return names;
}

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

// The command that makes a table again, as the user types it: the table's name and the grid
// options it reads, as they were given (docs/reference.md, "The head of a table"). --jobs and
// --out change no value and are left out.
std::string table_command(const std::string& name, const options& o) {
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
    std::vector<std::string> energy_options = {"--n", "--theta", "--model", "--alpha", "--r", "--mu", "--f0"};
    for (const auto& q : verify::part_parameters()) {
        given.emplace_back(std::string("--") + q.name, o.parts.*q.input ? (o.parts.*q.input)->text() : "");
        energy_options.push_back(std::string("--") + q.name);
    }
    const std::map<std::string, std::vector<std::string>> reads = {
        {"zoo", {"--n"}},         {"bounds", {"--n"}}, {"enclosures", {"--n"}},
        {"energy", energy_options}, {"irradiance", {"--model", "--light", "--ratio", "--tilt"}},
        {"ndf", {"--n"}},         {"audit", {"--seed", "--cases"}}};
    std::string c = "./verify " + name;
    const auto it = reads.find(name);
    for (const auto& [option, value] : given)
        if (!value.empty() && it != reads.end() &&
            std::find(it->second.begin(), it->second.end(), option) != it->second.end())
            c += " " + option + " " + shell_word(value);
    return c;
}

bool same_folder(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code ea, eb;
    const auto x = std::filesystem::weakly_canonical(std::filesystem::absolute(a), ea);
    const auto y = std::filesystem::weakly_canonical(std::filesystem::absolute(b), eb);
    return !ea && !eb && x == y;
}

// Long tables show an even sample in Markdown: the run's files and --check render them alike.
std::size_t markdown_rows(const table_output& t) { return t.records.size() > 300 ? 60 : 300; }

int run(int argc, char** argv) {
    if (argc > 1 && std::string(argv[1]) == "lut") return verify::run_lut(argc - 1, argv + 1);
    for (int i = 1; i < argc; ++i)
        if (std::string(argv[i]) == "--brdf") return verify::run_brdf(argc, argv);
    std::vector<std::string> named_only;
    for (const auto& r : runners())
        if (!r.in_default_run) named_only.emplace_back(r.name);
    const auto cl = verify::parse_command_line(argc, argv, table_name_list(), named_only);
    if (cl.help) {
        std::cout << *cl.help;
        return 0;
    }
    for (const auto& note : cl.notes) std::cerr << "verify: " << note << "\n";
    // On a terminal, how far the computation is (cleared before anything else is printed).
    verify::progress shown(verify::progress::wanted(cl.json));
    const options& o = cl.opts;
    const auto& tables = cl.tables;
    const auto& scene_path = cl.scene_path;
    const auto& junit_path = cl.junit_path;
    const bool check = cl.check, json = cl.json;
    std::string out_dir = cl.out_dir;
    std::string scene_name;  // in the JUnit suites' names
    std::vector<verify::skipped_table> skipped;
    std::vector<table_output> outputs;
    if (!scene_path.empty()) {
        const auto sc = verify::load_scene(scene_path, verify::scene_model_ids());
        scene_name = sc.name;
        if (out_dir.empty()) {
            const char* env = std::getenv("NORMZOO_RESULTS_DIR");
            out_dir = (std::filesystem::path(env && *env ? env : "results") / "scenes" /
                       std::filesystem::path(scene_path).stem())
                          .string();
        }
        shown.step("scene " + std::filesystem::path(scene_path).stem().string());
        outputs = verify::scene_tables(sc, o.jobs, skipped);
    }
    std::vector<const table_runner*> plan;
    for (const auto& t : tables)  // known and each once (parse_command_line)
        plan.push_back(&*std::find_if(runners().begin(), runners().end(), [&](const auto& r) { return t == r.name; }));
    if (plan.empty() && scene_path.empty())
        for (const auto& r : runners())
            if (r.in_default_run) plan.push_back(&r);
    if (out_dir.empty()) {
        const char* env = std::getenv("NORMZOO_RESULTS_DIR");
        out_dir = env && *env ? env : "results";
    }
    // results/ and the docs that cite it hold the tables on their canonical grids only: a custom
    // grid or --json writes only to a folder named by --out (README, "Command reference").
    const std::string custom_grid = custom_grid_option(o);
    const bool writes = !check && (!cl.out_dir.empty() || (custom_grid.empty() && !json));
    const char* project_results_env = std::getenv("NORMZOO_RESULTS_DIR");
    const std::string project_results_dir = project_results_env && *project_results_env ? project_results_env : "results";
    if (writes && !custom_grid.empty() && same_folder(cl.out_dir, project_results_dir))
        throw bad_input("--out " + cl.out_dir + ": the results folder holds the tables on their canonical grids, "
                        "which the docs cite; write a run with " + custom_grid + " to another folder");
    // Paths that cannot be written are bad input, refused before the tables are computed.
    if (writes) verify::check_output_folder(out_dir, cl.out_dir.empty() ? "the output folder" : "--out");
    if (!junit_path.empty()) verify::check_output_file(junit_path, "--junit");

    // Compute everything first; only then touch the output folder.
    for (const auto* r : plan) {
        shown.step(r->name, r->unit);
        for (auto& t : r->run(o)) {
            t.command = table_command(r->name, o);
            outputs.push_back(std::move(t));
        }
    }
    shown.finish();

    bool failed = false;
    for (const auto& t : outputs)
        for (const auto& r : t.records) failed = failed || r.failed();
    // Each table's Markdown, once: written to the results, and what the docs cite.
    std::map<std::string, std::string> markdown_by_name;
    for (const auto& t : outputs) markdown_by_name[t.info.name + ".md"] = verify::markdown(t, markdown_rows(t));
    std::vector<verify::junit_case> cases;
    std::optional<verify::write_guard> guard;  // from the first file staged to the last renamed
    // What the docs' citations are compared with: what this run writes, with --check each value
    // that the comparison with the committed records accepts taken as committed.
    std::map<std::string, std::string> cited_by_name = markdown_by_name;
    if (check) {
        // Compare every file a run writes (docs/tables.md, "What --check compares"); write none.
        for (const auto& t : outputs) {
            const auto c = verify::check_committed(t, out_dir, markdown_rows(t));
            cases.push_back({"normzoo.check", t.info.name, c.diffs});
            std::ostream& os = json ? std::cerr : std::cout;
            os << t.info.name << ": " << (c.diffs.empty() ? "matches " : "DIFFERS from ");
            for (std::size_t i = 0; i < c.files.size(); ++i)
                os << (i ? ", " + c.files[i] : (std::filesystem::path(out_dir) / c.files[i]).string());
            os << (c.diffs.empty() ? " (" + std::to_string(t.records.size()) + " records)" : "") << "\n";
            for (const auto& d : c.diffs) os << "  " << d << "\n";
            for (const auto& n : c.notes) std::cerr << "verify: " << t.info.name << ": " << n << "\n";
            failed = failed || !c.diffs.empty();
            cited_by_name[t.info.name + ".md"] = c.markdown;
        }
    } else if (!writes) {
        std::cerr << "verify: nothing written: "
                  << (json ? "--json puts the records on stdout"
                           : "a run with " + custom_grid + " is not on the tables' canonical grids, which " +
                                 (std::filesystem::path(out_dir)).string() + " holds")
                  << "; to write the tables, add --out DIR\n";
    } else {
        std::filesystem::create_directories(out_dir);
        guard.emplace(out_dir);
        verify::file_set files(out_dir);
        for (const auto& t : outputs) {
            files.stage(t.info.name + ".md", markdown_by_name.at(t.info.name + ".md"));
            files.stage(t.info.name + ".csv", verify::csv(t));
            files.stage(t.info.name + ".json", verify::json_file(t));
            if (t.figure) t.figure(t, files);
        }
        if (guard->interrupted()) throw verify::interrupted();  // files removes what it staged
        files.commit();
    }
    if (!check)
        for (const auto& t : outputs)
            for (auto& c : verify::junit_test_cases(t)) cases.push_back(std::move(c));
    // The project's docs cite its results/ tables: checked with --check, else refreshed. Only
    // for the project's own results folder (the one ./verify names), never for a custom --out.
    const char* project_results = std::getenv("NORMZOO_RESULTS_DIR");
    const bool project_run = (check || writes) && scene_path.empty() && project_results && *project_results &&
                             std::filesystem::absolute(out_dir).lexically_normal() ==
                                 std::filesystem::absolute(project_results).lexically_normal();
    if (project_run) {
        const auto root = std::filesystem::absolute(out_dir).lexically_normal().parent_path();
        std::vector<std::filesystem::path> docs{root / "README.md"};
        if (std::filesystem::is_directory(root / "docs"))
            for (const auto& e : std::filesystem::directory_iterator(root / "docs"))
                if (e.path().extension() == ".md") docs.push_back(e.path());
        std::sort(docs.begin(), docs.end());
        for (const auto& d : docs) {
            if (!std::filesystem::exists(d)) continue;
            std::ifstream in(d, std::ios::binary);
            const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            std::vector<std::string> stale;
            const std::string fresh = verify::refresh_citations(text, cited_by_name, d.string(), stale);
            if (check) {
                for (const auto& s : stale) (json ? std::cerr : std::cout) << "docs: " << s << "\n";
                if (!stale.empty()) cases.push_back({"normzoo.check", "docs: " + d.filename().string(), stale});
                else if (fresh.find("normzoo:cite") != std::string::npos) cases.push_back({"normzoo.check", "docs: " + d.filename().string(), {}});
                failed = failed || !stale.empty();
            } else if (fresh != text) {
                verify::write_atomically(d, fresh);
            }
        }
    }
    if (!junit_path.empty()) verify::write_atomically(junit_path, verify::junit_document(cases, scene_name));

    if (json) {
        nlohmann::ordered_json doc;
        doc["records"] = nlohmann::ordered_json::array();
        for (const auto& t : outputs)
            for (auto& r : verify::records_json(t)) doc["records"].push_back(std::move(r));
        doc["skipped"] = nlohmann::ordered_json::array();
        for (const auto& k : skipped) doc["skipped"].push_back({{"table", k.table}, {"reason", k.reason}});
        std::cout << doc.dump() << "\n";
    } else if (!check) {
        for (const auto& t : outputs) {
            std::size_t fails = 0;
            for (const auto& r : t.records) fails += r.failed();
            std::cout << t.info.name << ": " << t.records.size() << " records, " << fails << " failing"
                      << (writes ? " -> " + (std::filesystem::path(out_dir) / (t.info.name + ".md")).string()
                                 : std::string(" (not written)"))
                      << "\n";
            verify::print_failures(std::cout, t);
        }
    }
    // Why each failing check fails, beside the JSON or the comparison (stdout is the JSON's).
    if (json || check)
        for (const auto& t : outputs) verify::print_failures(json ? std::cerr : std::cout, t);
    return failed ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const bad_input& e) {
        std::cerr << "verify: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "verify: error: " << e.what() << "\n";
        return 1;
    }
}
