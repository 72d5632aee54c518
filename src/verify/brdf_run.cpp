#include "brdf_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include <normzoo/decimal.hpp>
#include <normzoo/microfacet/albedo.hpp>

#include "args.hpp"
#include "brdf_file/brdf_file.hpp"
#include "brdf_file/shader_screen.hpp"
#include "brdf_file/compiled_shader.hpp"
#include "brdf_file/preprocess.hpp"
#include "brdf_parameters.hpp"
#include "brdf_records.hpp"
#include "brdf_textures.hpp"
#include "brdf_conformance.hpp"

namespace verify {

namespace {

using normzoo::code::fixed_direction;

// An incident direction: its angle, from the decimal as typed, and theta in degrees for the records.
struct incidence {
    normzoo::degrees_angle<normzoo::quad> angle;
    double theta_deg;
};

// The incident angles, each from its decimal as typed (docs/conventions.md#inputs-are-decimals):
// --theta (default 0, 15, ..., 75, 85, 89 degrees) or --mu.
std::vector<incidence> incidences(const brdf_request& o) {
    std::vector<normzoo::decimal> theta = o.theta;
    if (theta.empty() && o.mu.empty()) theta = parse_decimal_list("--theta", "0,15,30,45,60,75,85,89", "0", "90", true);
    std::vector<incidence> angles;
    for (const auto& t : theta) angles.push_back({normzoo::degrees_of<normzoo::quad>(t), t.to<double>()});
    for (const auto& m : o.mu) {
        const auto a = normzoo::microfacet::angle_of_cosine(m.to<double>());
        angles.push_back({a, static_cast<double>(a.radians * 180 / boost::math::constants::pi<normzoo::quad>())});
    }
    return angles;
}

// The columns of a table's Markdown: `before`, the swept parameters (the others are in its head),
// then `after`; and the keys that name a record (JUnit, failure lines): every parameter.
std::vector<std::string> columns(const std::vector<parameter_values>& grid, std::vector<std::string> before,
                                 const std::vector<std::string>& after, bool swept_only) {
    for (const auto& g : grid)
        if (g.swept() || !swept_only) before.push_back("param_" + g.p->name);
    before.insert(before.end(), after.begin(), after.end());
    return before;
}

// --brdf FILE with the options that build and sample it, so that the head's command runs again
// (the parameters have a line of their own).
std::string command_of(const brdf_request& o) {
    std::string c = "./verify --brdf " + o.file;
    for (const auto& d : o.include_dirs) c += " --include-dir " + d;
    for (const auto& d : o.defines) c += " --define " + d;
    for (const auto& t : o.textures) c += " --texture " + t;
    if (!o.layout.empty()) c += " --layout " + o.layout;
    return c;
}

// The heads of the tables brdf and brdf-checks: what they hold, the command and the parameters.
void set_table_heads(const brdf_request& o, const std::vector<parameter_values>& grid, table_output& albedos, table_output& checks,
                     bool binary16) {
    const std::string held = o.fixed == fixed_direction::light
                                 ? "L held at theta_deg: the albedo is the integral over V of f(L, V) N.V (fixed = light)"
                                 : "V held at theta_deg: the albedo is the integral over L of f(L, V) N.L, as engines' furnace "
                                   "tests and split-sum tables take it (fixed = view)";
    albedos.info = {"brdf", "A BRDF given as code: its albedo against incident angle, with bounds and verdicts",
                    {"the black-box integrator of docs/brdf-code.md, tolerance " + tolerance_text(o.tolerance) + " absolute", held,
                     "the shader compiled for the CPU over GLM, evaluated in double (albedo) and float (albedo_fp32, to 1e-6)"},
                    columns(grid, {"file"}, {"theta_deg", "albedo", "error_estimate", "albedo_fp32", "conserving", "values", "pass", "reason"}, true),
                    columns(grid, {"albedo"}, {}, true)};
    if (binary16) {  // the code declares reduced precision (docs/brdf-code.md#precision)
        albedos.info.settings.push_back("the values it declares mediump, lowp, half or min16float rounded to binary16 (albedo_fp16, to 1e-3)");
        auto& c = albedos.info.md_columns;
        c.insert(std::find(c.begin(), c.end(), "albedo_fp32") + 1, "albedo_fp16");
    }
    albedos.info.id_keys = columns(grid, {"material", "file"}, {"theta_deg", "fixed"}, false);
    checks.info = {"brdf-checks", "A BRDF given as code: reciprocity, normalization, float against double",
                   {"reciprocity over 12 x 24 directions each way, relative tolerance " + tolerance_text(o.reciprocity_tolerance),
                    "normalization: the albedos at one incidence as a swept parameter moves, within their bounds"},
                   columns(grid, {"file", "check"}, {"parameter", "theta_deg", "worst", "where", "pass", "reason"}, true),
                   columns(grid, {}, {}, true)};
    checks.info.id_keys = columns(grid, {"material", "file", "check"}, {"parameter", "theta_deg"}, false);
    albedos.command = checks.command = o.command.empty() ? command_of(o) : o.command;
    std::string shown;
    for (const auto& g : grid) shown += (shown.empty() ? "" : "; ") + g.p->name + " = " + g.given;
    albedos.parameters = checks.parameters = shown.empty() ? "no parameters" : shown;
}

// The shader's parameter slots at one combination of the values: index[k] picks grid[k]'s.
std::vector<double> slots_of(const std::vector<parameter_values>& grid, const std::vector<std::size_t>& index) {
    std::vector<double> slots;
    for (std::size_t k = 0; k < grid.size(); ++k)
        for (double x : grid[k].values[index[k]]) slots.push_back(x);
    return slots;
}

// The next combination, the last parameter moving fastest; false after the last one.
bool next_combination(const std::vector<parameter_values>& grid, std::vector<std::size_t>& index) {
    for (std::size_t k = grid.size(); k-- > 0;) {
        if (++index[k] < grid[k].values.size()) return true;
        index[k] = 0;
    }
    return false;
}

// The albedo with the values the code declares in reduced precision in binary16
// (docs/brdf-code.md#precision), and binary16 against double about the lobe, with binary16's own
// tolerance and floor (normzoo::code::binary16_tolerance).
template <class H>
void add_binary16(const brdf_request& o, const H& h, const incidence& in, albedo_results& r) {
    normzoo::albedo_settings coarse;
    coarse.tolerance = std::max(normzoo::code::binary16_albedo_tolerance, o.tolerance);
    coarse.max_panels = normzoo::code::binary16_albedo_panels;
    r.albedo_fp16 = normzoo::code::code_albedo<float>(h, in.angle, coarse, o.fixed);
    const normzoo::vec3<double> held(static_cast<double>(in.angle.sin_t), 0, static_cast<double>(in.angle.cos_t));
    const auto& pole = r.albedo.lobe.pole;
    using normzoo::code::binary16_tolerance, normzoo::code::binary16_floor;
    r.precision_fp16 = o.fixed == fixed_direction::light
                           ? normzoo::code::compare_float(h, held, pole, 32, 64, binary16_tolerance, binary16_floor)
                           : normzoo::code::compare_float(normzoo::code::view_held<H>{h}, held, pole, 32, 64, binary16_tolerance, binary16_floor);
}

// Per channel, how far f moves when every texel of its textures sits at the low or the high end
// of what its storage holds: the larger of |f_low - f| and |f_high - f| (docs/brdf-code.md#textures).
struct storage_deviation {
    const compiled_shader::instance &f, &low, &high;
    template <class T>
    std::array<T, 3> operator()(const normzoo::vec3<T>& l, const normzoo::vec3<T>& v, const normzoo::vec3<T>& n, const normzoo::vec3<T>& x,
                                const normzoo::vec3<T>& y) const {
        const auto a = f(l, v, n, x, y), b = low(l, v, n, x, y), c = high(l, v, n, x, y);
        std::array<T, 3> d;
        for (int k = 0; k < 3; ++k) d[k] = std::max(std::abs(b[k] - a[k]), std::abs(c[k] - a[k]));
        return d;
    }
};

// The albedo at one incidence, with the direction held that o says, in double and in float as a
// GPU computes it, and float against double about its lobe; with textures, what their storage
// can move it by (the deviation's albedo and its own bound, in the largest channel).
template <class F>
albedo_results albedo_at(const brdf_request& o, const F& f, const incidence& in, bool binary16,
                          const storage_deviation* storage = nullptr) {
    normzoo::albedo_settings settings;
    settings.tolerance = o.tolerance;
    normzoo::albedo_settings coarse = settings;
    coarse.tolerance = std::max(1e-6, o.tolerance);
    arm_evaluation_timer(o.file, o.eval_seconds);
    std::size_t before = 0, undefined_evaluations = 0;
    f.take_undefined(before);  // the reciprocity check's, not this albedo's
    auto e = normzoo::code::code_albedo(f, in.angle, settings, o.fixed);
    const auto undefined = f.take_undefined(undefined_evaluations);
    auto e32 = normzoo::code::code_albedo<float>(f, in.angle, coarse, o.fixed);
    const normzoo::vec3<double> held(static_cast<double>(in.angle.sin_t), 0, static_cast<double>(in.angle.cos_t));
    const auto precision = o.fixed == fixed_direction::light
                               ? normzoo::code::compare_float(f, held, e.lobe.pole)
                               : normzoo::code::compare_float(normzoo::code::view_held<F>{f}, held, e.lobe.pole);
    std::optional<double> bound;
    if (storage) {
        const auto d = normzoo::code::code_albedo(*storage, in.angle, settings, o.fixed);
        double worst = 0;
        for (const auto& c : d.channel) worst = std::max(worst, c.value + c.abs_error);
        bound = d.usable() ? worst : std::numeric_limits<double>::quiet_NaN();
    }
    albedo_results r{std::move(e), std::move(e32), precision, {}, {}, undefined, undefined_evaluations, bound};
    if (binary16) add_binary16(o, compiled_shader::binary16_view{f}, in, r);
    disarm_evaluation_timer();
    return r;
}

// Each --texture's table, read before anything is compiled.
std::vector<texture_table> texture_tables(const brdf_request& o) {
    const layout_keys layout = o.layout.empty() ? layout_keys{} : parse_texture_layout(o.layout);
    std::vector<texture_table> tables;
    for (const auto& t : parse_texture_options(o.textures)) tables.push_back(read_texture(t, layout));
    return tables;
}

// The tables bound to an instance: their values, or their storage's low or high ends.
void bind_textures(compiled_shader::instance& f, const std::vector<texture_table>& tables, std::vector<double> texture_table::*which) {
    for (std::size_t k = 0; k < tables.size(); ++k) f.bind(k, tables[k].width, tables[k].height, (tables[k].*which).data());
}

// Per swept parameter, its values as shown and the albedos at the first incidence as it moves (the
// others at their first value): what the normalization check compares.
using albedo_sweeps = std::map<std::string, std::vector<std::pair<std::string, normzoo::quadrature::estimate<double>>>>;

void add_to_sweeps(const parameter_point& at, const normzoo::quadrature::estimate<double>& albedo, albedo_sweeps& along) {
    for (std::size_t k = 0; k < at.grid.size(); ++k) {
        bool others_first = true;
        for (std::size_t j = 0; j < at.grid.size(); ++j) others_first = others_first && (j == k || at.index[j] == 0);
        if (at.grid[k].swept() && others_first) along[at.grid[k].p->name].push_back({at.grid[k].texts[at.index[k]], albedo});
    }
}

// The brdf-conformance record at one combination: the code's albedo with V held at each incidence
// (the black-box integrator's, as the brdf table's), then f and the albedos against the material.
template <class F>
record conformance_at(const brdf_request& o, const F& f, const std::vector<incidence>& angles, const parameter_point& at,
                      const reference_material& m, const std::vector<conformance_binding>& bindings) {
    normzoo::albedo_settings settings;
    settings.tolerance = o.tolerance;
    std::vector<normzoo::code::code_albedo_result> held(angles.size());
    std::vector<conformance_incidence> in;
    for (std::size_t a = 0; a < angles.size(); ++a) {
        arm_evaluation_timer(o.file, o.eval_seconds);
        held[a] = normzoo::code::code_albedo(f, angles[a].angle, settings, fixed_direction::view);
        disarm_evaluation_timer();
        in.push_back({angles[a].theta_deg, static_cast<double>(angles[a].angle.cos_t), &held[a]});
    }
    const code_sample sample = [&](const normzoo::vec3<double>& l, const normzoo::vec3<double>& v) {
        return normzoo::code::call<double>(f, l, v).value;
    };
    return conformance_record(o, at, compare_to_material(sample, m, material_values(at, m, bindings), in, o.tolerance));
}

}  // namespace

std::vector<table_output> brdf_tables(const brdf_request& o, bool quiet) {
    const std::vector<texture_table> textures = texture_tables(o);
    shader_source source = read_preprocessed(o.file, {o.defines, o.include_dirs});
    for (const auto& t : textures) source.textures.push_back(t.name);
    const auto grid = parameter_grid(source, o.params, o.steps);
    const compiled_shader shader(source);
    if (!quiet)
        std::cerr << "verify: " << o.file << (shader.report().cached ? ": compiled (cached) " : ": compiled in " + std::to_string(shader.report().seconds) + " s ")
                  << shader.report().library << "\n";
    const std::vector<incidence> angles = incidences(o);
    table_output albedos, checks;
    set_table_heads(o, grid, albedos, checks, shader.report().binary16);
    for (const auto& t : textures) {
        char step[32];
        std::snprintf(step, sizeof step, "%.3g", t.largest_step);
        albedos.info.settings.push_back("texture " + t.name + " = " + t.file + " (" + t.format + ", " + std::to_string(t.width) + " x " +
                                        std::to_string(t.height) + ", each texel known to " + step +
                                        "): bilinear at texel centres, clamped to the edge; error_estimate adds texture_storage_bound");
    }
    // --against: the material and how the code's parameters bind to its (brdf_conformance.hpp)
    std::optional<reference_material> material;
    std::vector<conformance_binding> bindings;
    table_output conformance;
    if (!o.against.empty()) {
        material = reference_material_named(o.against, "--against");
        bindings = bind_conformance(grid, *material, o.maps);
        conformance.info = conformance_info(o, grid, bindings, *material);
        conformance.command = albedos.command + " --against " + o.against;
        for (const auto& m : o.maps) conformance.command += " --map " + m;
        conformance.parameters = albedos.parameters;
    }
    // Every combination of the parameters' values: the albedo at each incidence, and reciprocity.
    std::vector<std::size_t> index(grid.size(), 0);
    const parameter_point at{grid, index};
    albedo_sweeps along;
    do {
        compiled_shader::instance f(shader, slots_of(grid, index));
        std::unique_ptr<compiled_shader::instance> low, high;
        std::optional<storage_deviation> storage;
        if (!textures.empty()) {
            low = std::make_unique<compiled_shader::instance>(shader, slots_of(grid, index));
            high = std::make_unique<compiled_shader::instance>(shader, slots_of(grid, index));
            bind_textures(f, textures, &texture_table::rgba);
            bind_textures(*low, textures, &texture_table::low);
            bind_textures(*high, textures, &texture_table::high);
            storage.emplace(storage_deviation{f, *low, *high});
        }
        for (std::size_t a = 0; a < angles.size(); ++a) {
            const albedo_results results = albedo_at(o, f, angles[a], shader.report().binary16, storage ? &*storage : nullptr);
            albedos.records.push_back(albedo_record(o, at, angles[a].theta_deg, results));
            if (a == 0 && results.albedo.usable() && !results.albedo.found.negative)
                add_to_sweeps(at, results.albedo.largest(), along);
        }
        checks.records.push_back(reciprocity_record(o, at, normzoo::code::check_reciprocity(f, 12, 24, o.reciprocity_tolerance)));
        if (material) conformance.records.push_back(conformance_at(o, f, angles, at, *material, bindings));
    } while (next_combination(grid, index));
    for (const auto& [name, points] : along) checks.records.push_back(normalization_record(o, name, points, angles[0].theta_deg));
    std::vector<table_output> out{std::move(albedos), std::move(checks)};
    if (material) out.push_back(std::move(conformance));
    return out;
}

namespace {

bool given(const options& o, const std::string& name) { return o.typed.count(name) > 0; }

std::string typed_text(const options& o, const std::string& name) {
    const auto it = o.typed.find(name);
    return it == o.typed.end() || it->second.empty() ? std::string() : it->second.front();
}

// On the console: each table's Markdown (stdout) and its failures (stderr) when it is not
// written; written (--out), its summary line as every table's.
void print_brdf_table(const table_output& t, const console_view& v) {
    if (v.written) {
        std::size_t fails = 0;
        for (const auto& r : t.records) fails += r.failed();
        std::cout << t.info.name << ": " << t.records.size() << " records, " << fails << " failing -> "
                  << (std::filesystem::path(v.out_dir) / (t.info.name + ".md")).string() << "\n";
        print_failures(std::cout, t);
        return;
    }
    if (!v.json) std::cout << markdown(t, 300) << "\n";
    print_failures(std::cerr, t);
}

}  // namespace

brdf_request brdf_request_of(const options& o) {
    brdf_request q;
    q.file = typed_text(o, "--brdf");
    if (given(o, "--param")) q.params = o.typed.at("--param");
    if (given(o, "--define")) q.defines = o.typed.at("--define");
    if (given(o, "--include-dir")) q.include_dirs = o.typed.at("--include-dir");
    if (given(o, "--texture")) q.textures = o.typed.at("--texture");
    q.layout = typed_text(o, "--layout");
    (void)parse_texture_options(q.textures);
    if (given(o, "--layout") && q.textures.empty()) throw bad_input("--brdf: --layout says how a --texture's file is read; no --texture is given");
    if (given(o, "--layout")) (void)parse_texture_layout(q.layout);
    for (const auto& d : q.defines) check_define(d);
    if (given(o, "--steps")) q.steps = parse_count("--steps", typed_text(o, "--steps"), 2, 1000);
    if (given(o, "--theta")) q.theta = parse_decimal_list("--theta", typed_text(o, "--theta"), "0", "90", true);
    if (given(o, "--mu")) q.mu = parse_decimal_list("--mu", typed_text(o, "--mu"), "0", "1", false, true);
    if (given(o, "--tolerance"))
        q.tolerance = parse_decimal_list("--tolerance", typed_text(o, "--tolerance"), "1e-14", "0.01").front().to<double>();
    if (given(o, "--time-limit"))
        q.eval_seconds = parse_decimal_list("--time-limit", typed_text(o, "--time-limit"), "1", "86400").front().to<double>();
    if (given(o, "--fixed")) {
        const std::string d = typed_text(o, "--fixed");
        if (d != "light" && d != "view") throw bad_input("--fixed: '" + d + "' is not light or view (the direction the albedo holds)");
        q.fixed = d == "light" ? fixed_direction::light : fixed_direction::view;
    }
    if (given(o, "--reciprocity-tolerance"))
        q.reciprocity_tolerance =
            parse_decimal_list("--reciprocity-tolerance", typed_text(o, "--reciprocity-tolerance"), "0", "1e6").front().to<double>();
    if (!q.theta.empty() && !q.mu.empty()) throw bad_input("--theta and --mu: give one of them");
    q.against = typed_text(o, "--against");
    if (given(o, "--map")) q.maps = o.typed.at("--map");
    if (given(o, "--against-tolerance"))
        q.against_tolerance =
            parse_decimal_list("--against-tolerance", typed_text(o, "--against-tolerance"), "0", "1e6").front().to<double>();
    if (q.against.empty() && (given(o, "--map") || given(o, "--against-tolerance")))
        throw bad_input(std::string("--brdf: ") + (given(o, "--map") ? "--map" : "--against-tolerance") +
                        " is read with --against MATERIAL; none is given");
    if (!q.against.empty()) (void)reference_material_named(q.against, "--against");
    return q;
}

std::vector<table_output> brdf_file_tables(const options& o) {
    auto tables = brdf_tables(brdf_request_of(o), given(o, "--json"));
    for (auto& t : tables) t.console = print_brdf_table;
    return tables;
}

}  // namespace verify
