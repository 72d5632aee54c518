#include "command_line.hpp"

#include <normzoo/material/ids.hpp>
#include <normzoo/microfacet/composition.hpp>
#include <normzoo/registry.hpp>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <set>
#include <sstream>
#include <thread>

#include "args.hpp"
#include "help_text.hpp"
#include "lut_presets.hpp"
#include "option_values.hpp"

namespace verify {

namespace {

// The command as the user typed it: the ./verify wrapper exports it (it runs the build's
// binary); else the program's own file name.
std::string command_name(int argc, const char* const* argv) {
    const char* typed = std::getenv("NORMZOO_COMMAND_NAME");
    return typed && *typed ? typed
           : argc > 0 && argv[0] ? std::filesystem::path(argv[0]).filename().string()
                                 : std::string("verify");
}

// The options' text as typed: CLI11 only stores it (the App holds pointers to these, which must
// outlive the parse); the read_ functions below check it into `options`.
struct option_texts {
    std::string n, theta, model, light, ratio, tilt;
    std::string alpha, r, mu, f0;
    std::vector<std::string> parts;  // the parts' parameters, in the order of part_parameters()
    std::string seed, cases;
    std::string kind, format, tolerance, layout, preset;  // lut
    bool detect = false;
    std::size_t size = 0;
    unsigned monte_carlo = 0;
    std::string brdf, steps, time_limit, fixed, reciprocity_tolerance, against, against_tolerance;  // --brdf FILE
    std::string material;  // energy --material NAME[/COMPENSATION]
    std::vector<std::string> params, defines, include_dirs, textures, maps;  // --map: lut's (once) and --brdf's
};

// The options of the tables that read their own (table_spec::check_options): lut's (docs/lut.md)
// and --brdf's (docs/brdf-code.md). Their specs check the values.
void declare_own_options(CLI::App& app, option_texts& x) {
    app.add_option("--kind", x.kind, "lut: dfg (the split-sum pair A, B), E, Eavg, or sheen-E (E of charlie/charlie-sheen/one)");
    app.add_option("--size", x.size, "lut: N, an N x N table at texel centres (i + 0.5)/N in mu and in roughness (instead of "
                                     "--alpha or --r with --mu)")
        ->check(CLI::Range(1, 4096));
    app.add_option("--map", x.maps, "lut: what the rows of a --size table (or a checked image) index: r (alpha = r^2, default) "
                                    "or alpha; --brdf --against: SHADER_PARAM=MATERIAL_PARAM, the material's parameter the "
                                    "code's takes its values to (default: same-named ones), repeatable")
        ->allow_extra_args(false);
    app.add_option("--format", x.format, "lut: csv, json, png8 (RGBA), png16, exr (float), exr-half, h (C header of floats), "
                                         "ktx2, ktx2-zstd, dds (their format from the layout), written to --out DIR as "
                                         "lut-KIND-N.EXT");
    app.add_option("--tolerance", x.tolerance, "lut --check FILE: absolute tolerance (default: what the file's format holds); "
                                               "--brdf: the albedo's absolute tolerance (default 1e-10)");
    app.add_option("--layout", x.layout, "lut: how the table is laid out, as written or as --check FILE reads it, "
                                         "KEY=VALUE,...: rows, cols (r, alpha, mu, sqrt-mu), row0, col0 (low, high), grid "
                                         "(centres, edges, filament), channels (A,B or B,A+B; E, E_avg or their 1-E, 1-E_avg; - skips one, written as 0), "
                                         "encoding (linear, srgb, rgbd, half, unorm8, unorm10, unorm16), size (WxH; WxHxD: D slices, --check) (docs/lut.md); "
                                         "--brdf: how every --texture's file is read, of these row0, col0, encoding and size");
    std::string presets;
    for (const auto& p : lut_presets()) presets += (presets.empty() ? "" : ", ") + p.name;
    app.add_option("--preset", x.preset, "lut: an engine's layout and the model it bakes with, as written or as --check FILE reads "
                                         "it: " + presets);
    app.add_flag("--detect", x.detect, "lut --check FILE: find the layout and model (GGX as engines bake it) the table fits "
                                       "best, and check it so; --layout keys stay fixed");
    app.add_option("--monte-carlo", x.monte_carlo, "lut, dfg only: bake the table as engines do instead, N samples of GGX "
                                                   "importance sampling at Hammersley points in float, height-correlated "
                                                   "Smith (docs/lut.md); its error is not bounded")
        ->check(CLI::Range(1u, 1u << 24));
    app.add_option("--brdf", x.brdf, "A BRDF as shader code: a BRDF Explorer .brdf file, or a .glsl/.hlsl/.wgsl file with a TOML "
                                     "header (docs/brdf-code.md); printed, written only to --out");
    app.add_option("--material", x.material, "energy: a material NAME[/COMPENSATION] (NAME one of " + normzoo::material::material_ids() +
                                             "; e.g. gltf/kulla-conty): its albedo per lobe and whole with V fixed, printed "
                                             "(docs/materials.md)");
    app.add_option("--param", x.params, "--brdf and energy --material: NAME=VALUE holds a parameter (a bool true, false, 1 or 0; "
                                        "a color R,G,B; a material's choice by name), NAME=LO..HI sweeps a float one in "
                                        "--steps values, NAME=A,B,C takes a float's or a bool's list; repeatable")
        ->allow_extra_args(false);
    app.add_option("--define", x.defines, "--brdf: NAME or NAME=VALUE, a macro the file's preprocessor starts with, as -D; "
                                          "repeatable")
        ->allow_extra_args(false);
    app.add_option("--include-dir", x.include_dirs, "--brdf: a folder the file's #include directives may read from, searched "
                                                    "in the order given, as -I; repeatable (docs/brdf-code.md)")
        ->allow_extra_args(false);
    app.add_option("--texture", x.textures, "--brdf: NAME=FILE binds the code's sampler2D or Texture2D NAME to a table in any "
                                            "file lut --check reads, sampled bilinearly at texel centres, clamped to the edge; "
                                            "the albedo's bound adds what the table's storage can move; repeatable "
                                            "(docs/brdf-code.md#textures)")
        ->allow_extra_args(false);
    app.add_option("--steps", x.steps, "--brdf: values of a swept parameter, 2 to 1000 (default 5)");
    app.add_option("--time-limit", x.time_limit, "--brdf: seconds one albedo point may take before the run stops, exit 2 "
                                                 "(default 600)");
    app.add_option("--fixed", x.fixed, "--brdf: the direction the albedo holds at each incidence: light (default; the "
                                       "integral over V) or view (over L, as engines' furnace tests and split-sum tables)");
    app.add_option("--reciprocity-tolerance", x.reciprocity_tolerance, "--brdf: the relative difference f(L, V) against "
                                                                       "f(V, L) that fails reciprocity (default 1e-9)");
    app.add_option("--against", x.against, "--brdf: MATERIAL (" + normzoo::material::material_ids() + ") or a composition D/G/F, the single-scattering BRDF the code is "
                                           "compared with: f and the albedo with V held (docs/materials.md)");
    app.add_option("--against-tolerance", x.against_tolerance, "--brdf --against: the difference above which the code fails: "
                                                               "relative for f, absolute for the albedo (default 1e-6)");
}

// Every option with its help, in the order --help lists them (docs/command-line.md, "Command
// reference"). The values are checked after the parse.
void declare_options(CLI::App& app, command_line& cl, option_texts& x, const std::vector<std::string>& tables,
                     const std::vector<std::string>& forms) {
    cl.opts.jobs = std::max(1u, std::thread::hardware_concurrency());
    app.add_option("tables", cl.tables, "Tables to run, any of: " + joined(tables));
    app.add_option("--n", x.n, "Exponents, comma-separated decimals in [0, 1e9] (e.g. 0,2.5,1e6), each taken exactly as typed "
                               "(docs/conventions.md, \"Inputs are decimals\"); in energy they "
                               "replace the grid of the forms swept in n");
    app.add_option("--theta", x.theta, "Incident angles in degrees, comma-separated, in [0, 90) (energy, --brdf)");
    app.add_option("--model", x.model, "BRDF forms, comma-separated ids (energy: default all; punctual-limit: default the "
                                       "nine a zoo row normalizes): " +
                                       joined(forms) + ". Or microfacet compositions D/G/F (energy; lut: one, default "
                                       "ggx/smith-height-correlated/one; docs/microfacet.md), " +
                                       normzoo::microfacet::composition::known_parts());
    app.add_option("--alpha", x.alpha, "Roughness alpha of the compositions (Walter et al. 2007), comma-separated, in [1e-8, 100] (energy --model D/G/F, lut)");
    app.add_option("--r", x.r, "Perceptual roughness r, alpha = r^2, instead of --alpha, in [1e-4, 10]");
    app.add_option("--mu", x.mu, "Cosines of the incident angle, comma-separated, in [1e-8, 1], instead of --theta (energy --model "
                                 "D/G/F, lut; --brdf: in (0, 1])");
    app.add_option("--f0", x.f0, "F0 of the compositions' Fresnel part, in [0, 1) (default 1: F = 1 for every F part)");
    add_part_options(app, x.parts, "Compositions: ");
    app.add_option("--light", x.light, "Lights, comma-separated: sphere, disk (irradiance; default both)");
    app.add_option("--ratio", x.ratio, "r0/r, comma-separated, > 0 (< 1 for a sphere) (irradiance)");
    app.add_option("--tilt", x.tilt, "Tilts of the light's centre from N in degrees, in [0, 180] (irradiance)");
    app.add_option("--scene", cl.scene_path, "A scene file (TOML; docs/command-line.md, \"A guardrail for an engine\"): run only what it needs");
    app.add_flag("--check", cl.check, "Recompute and compare with the committed tables in --out (values within their "
                                      "error bounds); write nothing; exit 1 on a difference. lut --check FILE: an "
                                      "engine's table checked (CSV, PNG or OpenEXR; docs/lut.md)");
    app.add_option("--junit", cl.junit_path, "Also write JUnit XML to FILE (one test case per check)");
    app.add_flag("--json", cl.json, "Write one JSON document {records, skipped} to stdout");
    app.add_option("--out", cl.out_dir, "Folder for the tables (default: results/ of this checkout; lut and --brdf print, "
                                        "and write only to --out)");
    app.add_option("--jobs", cl.opts.jobs, "Threads (default: all cores)")->check(CLI::Range(1u, 256u));
    app.add_option("--seed", x.seed, "Seed of the audit's random cases, a whole number (audit; default 20240607)");
    app.add_option("--cases", x.cases, "How many random cases the audit draws at least, 1 to 10^7 (audit; default 10000)");
    declare_own_options(app, x);
}

// --model with a composition D/G/F: every id a composition, each parsed now, so that a bad one
// is exit 2 before any work.
std::vector<std::string> composition_ids(const std::string& model_text, const std::vector<std::string>& forms) {
    std::vector<std::string> models;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = model_text.find(',', start);
        const std::string id = model_text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (id.find('/') == std::string::npos) {
            if (std::find(forms.begin(), forms.end(), id) == forms.end())
                throw bad_input("--model: unknown name '" + id + "' (a BRDF form id, or a composition D/G/F)");
            throw bad_input("--model: '" + id + "' is a BRDF form and the others are compositions D/G/F: run them separately");
        }
        try {
            normzoo::microfacet::composition::parse(id);
        } catch (const std::invalid_argument& e) {
            throw bad_input(std::string("--model: ") + e.what());
        }
        models.push_back(id);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return models;
}

// The audit's --seed and --cases, and the grid of the forms: --n, --theta, --model.
void read_grid_options(const CLI::App& app, const option_texts& x, const std::vector<std::string>& forms, options& o) {
    if (app.count("--seed")) o.seed = parse_count("--seed", x.seed, 0, std::numeric_limits<std::uint64_t>::max());
    if (app.count("--cases")) o.cases = parse_count("--cases", x.cases, 1, 10000000);
    if (!x.n.empty() || app.count("--n")) {
        o.exponents = parse_decimal_list("--n", x.n, "0", "1e9");
        o.exponents_text = x.n;
    }
    if (!x.theta.empty() || app.count("--theta")) {
        o.angles = parse_decimal_list("--theta", x.theta, "0", "90", true);
        o.angles_text = x.theta;
    }
    if (!x.model.empty() || app.count("--model")) {
        if (x.model.find('/') != std::string::npos) o.models = composition_ids(x.model, forms);
        else o.models = parse_name_list("--model", x.model, forms);
    }
}

// The options only microfacet compositions take (docs/command-line.md, "Command reference").
std::vector<std::string> composition_options() {
    std::vector<std::string> names = {"--alpha", "--r", "--mu", "--f0"};
    for (const auto& q : part_parameters()) names.push_back(std::string("--") + q.name);
    return names;
}

// The compositions' --alpha or --r, --mu, --f0 and the parts' parameters, refused without a
// composition in --model.
void read_composition_options(const CLI::App& app, const option_texts& x, command_line& cl) {
    options& o = cl.opts;
    const bool compositions = !o.models.empty() && o.models.front().find('/') != std::string::npos;
    if (app.count("--alpha") && app.count("--r")) throw bad_input("--alpha and --r: give the roughness one way");
    if (app.count("--alpha")) {
        o.roughness = parse_decimal_list("--alpha", x.alpha, roughness_range_of(false).min, roughness_range_of(false).max, false, false);
        o.roughness_text = x.alpha;
    }
    if (app.count("--r")) {
        o.roughness = parse_decimal_list("--r", x.r, roughness_range_of(true).min, roughness_range_of(true).max, false, false);
        o.roughness_is_r = true;
        o.roughness_text = x.r;
    }
    if (app.count("--mu")) {
        if (app.count("--theta")) throw bad_input("--mu and --theta: give the incident direction one way");
        o.mus = parse_decimal_list("--mu", x.mu, "1e-8", "1", false, false);
        o.mus_text = x.mu;
    }
    if (app.count("--f0")) {
        const auto v = parse_decimal_list("--f0", x.f0, "0", "1", true);
        if (v.size() != 1) throw bad_input("--f0: one value, not a list ('" + x.f0 + "')");
        o.parts.f0 = v.front();
    }
    read_part_options(app, x.parts, o.parts, "");
    for (const auto& opt : composition_options())
        if (app.count(opt) && !compositions)
            throw bad_input(opt + " applies to microfacet compositions: name them with --model D/G/F");
    // with only energy named, --n would be read by nothing: a composition's roughness is alpha or r
    if (compositions && app.count("--n") && !cl.tables.empty() &&
        std::all_of(cl.tables.begin(), cl.tables.end(), [](const std::string& t) { return t == "energy" || t == "models"; }))
        throw bad_input("--n is the exponent of the BRDF forms; the compositions of --model take --alpha or --r");
}

// The lights of the irradiance tables: --light, --ratio, --tilt.
void read_light_options(const CLI::App& app, const option_texts& x, options& o) {
    if (!x.light.empty() || app.count("--light")) o.lights = parse_name_list("--light", x.light, {"sphere", "disk"});
    if (!x.ratio.empty() || app.count("--ratio")) {
        // A disk may be larger than its distance; a sphere may not (r0 < r).
        const bool sphere = o.lights.empty() || std::find(o.lights.begin(), o.lights.end(), "sphere") != o.lights.end();
        o.ratios = parse_decimal_list("--ratio", x.ratio, "0", sphere ? "1" : "1e100", sphere, true);
        o.ratios_text = x.ratio;
    }
    if (!x.tilt.empty() || app.count("--tilt")) {
        o.tilts = parse_decimal_list("--tilt", x.tilt, "0", "180");
        o.tilts_text = x.tilt;
    }
}

// With --scene the scene says what to run: no grid option and no table may be given.
void refuse_grids_with_scene(const CLI::App& app, const command_line& cl) {
    std::vector<std::string> grid_options = {"--n", "--theta", "--model", "--light", "--ratio", "--tilt"};
    const std::vector<std::string> compositions = composition_options();
    grid_options.insert(grid_options.end(), compositions.begin(), compositions.end());
    for (const auto& opt : grid_options)
        if (app.count(opt)) throw bad_input(opt + " does not go with --scene: the scene says what to run");
    if (!cl.tables.empty()) throw bad_input("tables are not named with --scene: the scene says what to run");
}

// The tables named, in order and each once: an old name runs its new table (with a note), an
// unknown one is bad input.
std::vector<std::string> table_plan(command_line& cl, const std::vector<std::string>& tables) {
    std::vector<std::string> plan;
    for (auto t : cl.tables) {
        for (const auto& [old_name, name] : table_aliases())
            if (t == old_name) {
                cl.notes.push_back("table '" + old_name + "' is now part of '" + name + "': running " + name);
                t = name;
            }
        if (std::find(tables.begin(), tables.end(), t) == tables.end())
            throw bad_input("unknown table '" + t + "' (tables: " + joined(tables) + ")");
        if (std::find(plan.begin(), plan.end(), t) == plan.end()) plan.push_back(t);
    }
    return plan;
}

// `--check FILE` (lut: an engine's table; docs/lut.md) taken out of the arguments, so that CLI11
// sees the flag --check alone: a word after --check is its FILE unless it is a table's name
// (`--check zoo` compares zoo's results) or an option. `--check=FILE` too.
std::vector<std::string> take_check_file(int argc, const char* const* argv, const std::set<std::string>& names,
                                         const std::vector<std::string>& tables, std::string& check_file) {
    std::vector<std::string> args;
    for (int i = 0; i < argc; ++i) {
        const std::string a = argv[i];
        if (i > 0 && a.rfind("--check=", 0) == 0) {
            check_file = a.substr(8);
            args.push_back("--check");
            continue;
        }
        args.push_back(a);
        if (i == 0 || a != "--check" || i + 1 == argc) continue;
        const std::string next = argv[i + 1];
        const bool table = std::find(tables.begin(), tables.end(), next) != tables.end() ||
                           std::any_of(table_aliases().begin(), table_aliases().end(), [&](const auto& p) { return p.first == next; });
        if (!table && !option_like(next, names)) check_file = next, ++i;
    }
    return args;
}

// Every option given, with its values as typed, into o.typed; and the paths of --brdf and lut's
// --check (which CLI11 saw as a flag).
void record_typed_options(const CLI::App& app, command_line& cl) {
    for (const CLI::Option* opt : app.get_options()) {
        if (opt->get_positional() || opt->get_lnames().empty() || !opt->count()) continue;
        const std::string name = "--" + opt->get_lnames().front();
        if (name != "--help") cl.opts.typed[name] = opt->results();
    }
    if (cl.opts.typed.count("--check")) cl.opts.typed["--check"].clear();
    if (!cl.check_file.empty()) cl.opts.typed["--check"] = {cl.check_file};
    if (cl.opts.typed.count("--brdf")) cl.brdf_file = cl.opts.typed["--brdf"].front();
}

// --brdf's options have always said so when they end the line (`--brdf FILE --theta`).
void refuse_last_option_without_value(const CLI::App& app, int argc, const char* const* argv) {
    if (argc < 2 || std::none_of(argv + 1, argv + argc, [](const char* a) { return std::string(a) == "--brdf"; })) return;
    const CLI::Option* last = app.get_option_no_throw(argv[argc - 1]);
    if (last && last->get_items_expected_min() > 0) throw bad_input(std::string(argv[argc - 1]) + " needs a value");
}

// lut, --brdf and --material read their own options (their specs check them): they run alone,
// never with a scene. --check FILE without lut is what it was before lut took a value: a table's name.
void plan_own_table(command_line& cl, const std::vector<std::string>& tables) {
    const bool lut = std::find(cl.tables.begin(), cl.tables.end(), "lut") != cl.tables.end();
    if (!cl.check_file.empty() && !lut) throw bad_input("unknown table '" + cl.check_file + "' (tables: " + joined(tables) + ")");
    if (cl.opts.typed.count("--material")) {  // energy --material: the table material, its options its own
        if (!cl.scene_path.empty() || !cl.brdf_file.empty()) throw bad_input("--material goes with energy alone, not --scene or --brdf");
        for (const auto& t : cl.tables) if (t != "energy") throw bad_input("--material is read by energy alone, not '" + t + "'");
        return void(cl.tables = {"material"});
    }
    if (!cl.brdf_file.empty()) {
        if (!cl.scene_path.empty()) throw bad_input("--brdf does not go with --scene: the scene names its shader files");
        if (!cl.tables.empty())
            throw bad_input("tables are not named with --brdf (" + joined(cl.tables) + "): it checks the file's BRDF alone");
        cl.tables = {"brdf-file"};
        return;
    }
    if (!cl.scene_path.empty()) throw bad_input("tables are not named with --scene: the scene says what to run");
    cl.tables = table_plan(cl, tables);  // an unknown name first
    for (const auto& t : cl.tables)
        if (t != "lut") throw bad_input("lut runs alone: name no other table beside it ('" + t + "')");
    cl.tables = {"lut"};
    if (!cl.check_file.empty()) cl.check = false;  // the flag was lut's --check FILE
}

}  // namespace

void add_part_options(CLI::App& app, std::vector<std::string>& texts, const std::string& help_prefix) {
    texts.assign(part_parameters().size(), std::string());
    for (std::size_t i = 0; i < part_parameters().size(); ++i)
        app.add_option(std::string("--") + part_parameters()[i].name, texts[i],
                       help_prefix + part_parameters()[i].meaning + "; one value, as typed" +
                           (std::string(part_parameters()[i].name) == "eta" ? " (lut --check, size=WxHxD: one per slice)" : ""));
}

std::vector<std::string> read_part_options(const CLI::App& app, const std::vector<std::string>& texts, part_inputs& p,
                                           const std::string& prefix) {
    std::vector<std::string> given;
    for (std::size_t i = 0; i < part_parameters().size(); ++i) {
        const auto& q = part_parameters()[i];
        const std::string opt = std::string("--") + q.name;
        if (!app.count(opt)) continue;
        const auto v = parse_decimal_list(opt, texts[i], q.min, q.max, false, q.min_open);
        if (v.size() != 1) throw bad_input(prefix + opt + ": one value, not a list ('" + texts[i] + "')");
        p.*q.input = v.front();
        given.push_back(opt);
    }
    return given;
}

command_line parse_command_line(int argc, const char* const* argv, const std::vector<std::string>& tables,
                                const std::vector<std::string>& named_only) {
    std::vector<std::string> forms;
    for (auto id : normzoo::brdf_ids()) forms.emplace_back(id);
    const std::string command = command_name(argc, argv);
    CLI::App app{help_head(tables, named_only), command};
    app.set_help_flag("-h,--help", "Print this help and exit");
    app.footer(help_examples(command));
    command_line cl;
    option_texts texts;
    declare_options(app, cl, texts, tables, forms);
    // `./verify lut ...` names its messages as it always has, and its --check takes a FILE
    const bool lut_first = argc > 1 && std::string(argv[1]) == "lut";
    const std::string prefix = lut_first ? "lut: " : "";
    if (lut_first) refuse_missing_values(app, argc, argv, prefix, {"--check"});
    refuse_last_option_without_value(app, argc, argv);
    const std::vector<std::string> args = take_check_file(argc, argv, option_names(app), tables, cl.check_file);
    std::vector<const char*> arg_pointers;
    for (const auto& a : args) arg_pointers.push_back(a.c_str());
    try {
        app.parse(static_cast<int>(arg_pointers.size()), arg_pointers.data());
    } catch (const CLI::CallForHelp& e) {
        std::ostringstream out, err;
        app.exit(e, out, err);
        cl.help = out.str();
        return cl;
    } catch (const CLI::ParseError& e) {
        throw bad_input(prefix + e.what());
    }

    // The values, checked in this order: the first bad one is the error.
    refuse_forgotten_values(app, prefix);
    record_typed_options(app, cl);
    if (!cl.brdf_file.empty() || !cl.check_file.empty() || cl.opts.typed.count("--material") ||
        std::find(cl.tables.begin(), cl.tables.end(), "lut") != cl.tables.end()) {
        plan_own_table(cl, tables);  // the plan checks their options (table_spec::check_options)
        return cl;
    }
    read_grid_options(app, texts, forms, cl.opts);
    read_composition_options(app, texts, cl);
    read_light_options(app, texts, cl.opts);
    if (!cl.scene_path.empty()) refuse_grids_with_scene(app, cl);
    cl.tables = table_plan(cl, tables);
    return cl;
}

}  // namespace verify
