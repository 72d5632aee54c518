#include "brdf_run.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include <normzoo/code/code_albedo.hpp>
#include <normzoo/code/code_checks.hpp>
#include <normzoo/decimal.hpp>
#include <normzoo/microfacet/albedo.hpp>

#include "args.hpp"
#include "brdf_file/brdf_file.hpp"
#include "brdf_file/shader_screen.hpp"
#include "brdf_file/compiled_shader.hpp"
#include "brdf_file/preprocess.hpp"

namespace verify {

namespace {


// The values each parameter takes: its default, one value, or a range in `steps` values.
struct parameter_values {
    const shader_parameter* p;
    std::vector<std::vector<double>> values;  // each one slot, or three for a color
    bool swept = false;
};

std::vector<double> numbers(const std::string& option, const std::string& text, std::size_t count) {
    std::vector<double> v;
    for (const auto& d : parse_decimal_list(option, text, "-1e300", "1e300")) v.push_back(d.to<double>());
    if (v.size() != count)
        throw bad_input(option + ": expected " + std::to_string(count) + (count == 1 ? " number" : " comma-separated numbers") +
                        ", got '" + text + "'");
    return v;
}

std::vector<parameter_values> parameter_grid(const shader_source& s, const brdf_request& o) {
    std::vector<parameter_values> grid;
    for (const auto& p : s.parameters) grid.push_back({&p, {p.default_value}, false});
    for (const auto& given : o.params) {
        const auto eq = given.find('=');
        if (eq == std::string::npos) throw bad_input("--param " + given + ": expected NAME=VALUE or NAME=LO..HI");
        const std::string name = given.substr(0, eq), text = given.substr(eq + 1);
        parameter_values* pv = nullptr;
        for (auto& g : grid)
            if (g.p->name == name) pv = &g;
        if (!pv) {
            std::string known;
            for (const auto& p : s.parameters) known += (known.empty() ? "" : ", ") + p.name;
            throw bad_input("--param " + name + ": " + s.path + " declares no parameter " + name +
                            (known.empty() ? " (it declares none)" : " (it declares " + known + ")"));
        }
        const shader_parameter& p = *pv->p;
        const std::string option = "--param " + name;
        auto in_range = [&](double x, const std::string& shown) {
            if (!(x >= p.min && x <= p.max))
                throw bad_input(option + ": " + shown + " is outside its range " + std::to_string(p.min) + " .. " + std::to_string(p.max) +
                                " (" + s.path + ":" + std::to_string(p.line) + ")");
        };
        const auto dots = text.find("..");
        if (dots != std::string::npos) {
            if (p.type != shader_parameter::kind::real) throw bad_input(option + ": only a float parameter takes a range LO..HI");
            const double lo = numbers(option, text.substr(0, dots), 1)[0], hi = numbers(option, text.substr(dots + 2), 1)[0];
            in_range(lo, text.substr(0, dots));
            in_range(hi, text.substr(dots + 2));
            if (!(lo < hi)) throw bad_input(option + ": the range " + text + " is empty");
            pv->values.clear();
            for (std::size_t k = 0; k < o.steps; ++k) pv->values.push_back({lo + (hi - lo) * static_cast<double>(k) / static_cast<double>(o.steps - 1)});
            pv->swept = true;
        } else if (p.type == shader_parameter::kind::color) {
            const auto v = numbers(option, text, 3);
            for (double x : v)
                if (x < 0) throw bad_input(option + ": a color's channels are >= 0");
            pv->values = {v};
        } else {
            const double x = numbers(option, text, 1)[0];
            if (p.type == shader_parameter::kind::boolean && x != 0 && x != 1) throw bad_input(option + ": a bool is 0 or 1, not " + text);
            in_range(x, text);
            pv->values = {{x}};
        }
    }
    return grid;
}

std::string vector_text(const normzoo::vec3<double>& v) {
    std::ostringstream o;
    o.precision(6);
    o << v.x() << "," << v.y() << "," << v.z();
    return o.str();
}

std::string numbers_text(const std::vector<double>& v) {
    std::ostringstream o;
    o.precision(17);
    for (std::size_t i = 0; i < v.size(); ++i) o << (i ? "," : "") << v[i];
    return o.str();
}

field_value parameter_field(const shader_parameter& p, const std::vector<double>& v) {
    if (p.type == shader_parameter::kind::boolean) return v[0] != 0;
    if (p.type == shader_parameter::kind::color) return numbers_text(v);
    return v[0];
}

std::string tolerance_text(double x) {
    std::ostringstream o;
    o << x;
    return o.str();
}

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

// The heads of the tables brdf and brdf-checks: what they hold, the command and the parameters.
void set_table_heads(const brdf_request& o, const std::vector<parameter_values>& grid, table_output& albedos, table_output& checks) {
    albedos.info = {"brdf", "A BRDF given as code: its albedo against incident angle, with bounds and verdicts",
                    {"the black-box integrator of docs/brdf-code.md, tolerance " + tolerance_text(o.tolerance) + " absolute",
                     "the shader compiled for the CPU over GLM, evaluated in double (albedo) and float (albedo_fp32, to 1e-6)"},
                    {"file", "theta_deg", "albedo", "error_estimate", "albedo_fp32", "conserving", "values", "pass"},
                    {"albedo"}};
    checks.info = {"brdf-checks", "A BRDF given as code: reciprocity, normalization, float against double",
                   {"reciprocity over 12 x 24 directions each way, relative tolerance 1e-9",
                    "normalization: the albedos at one incidence as a swept parameter moves, within their bounds"},
                   {"file", "check", "parameter", "theta_deg", "worst", "where", "pass"}};
    albedos.command = checks.command = o.command.empty() ? "./verify --brdf " + o.file : o.command;
    std::string shown;
    for (const auto& g : grid) shown += (shown.empty() ? "" : "; ") + g.p->name + (g.swept ? " swept" : " held") + " (" + std::to_string(g.values.size()) + " values)";
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

// A record of `table` about the file, first keyed by the scene's material where there is one.
record file_record(const brdf_request& o, const char* table) {
    record r;
    r.table = table;
    if (!o.material.empty()) r.set("material", o.material);
    r.set("file", o.shown_file.empty() ? o.file : o.shown_file);
    return r;
}

// The parameters' values at one combination, as fields param_NAME.
void set_parameters(record& r, const std::vector<parameter_values>& grid, const std::vector<std::size_t>& index) {
    for (std::size_t k = 0; k < grid.size(); ++k) r.set("param_" + grid[k].p->name, parameter_field(*grid[k].p, grid[k].values[index[k]]));
}

// A brdf record: the albedo at one incidence, in double and in float as a GPU computes it, with
// its verdicts. `reflectance` gets the largest channel's albedo where the values are a reflectance.
record albedo_record(const brdf_request& o, const std::vector<parameter_values>& grid, const std::vector<std::size_t>& index,
                     const compiled_shader::instance& f, const incidence& in,
                     std::optional<normzoo::quadrature::estimate<double>>& reflectance) {
    normzoo::albedo_settings settings;
    settings.tolerance = o.tolerance;
    normzoo::albedo_settings coarse = settings;
    coarse.tolerance = std::max(1e-6, o.tolerance);
    arm_evaluation_timer(o.file, o.eval_seconds);
    const auto e = normzoo::code::code_albedo(f, in.angle, settings);
    const auto e32 = normzoo::code::code_albedo<float>(f, in.angle, coarse);
    const normzoo::vec3<double> l(static_cast<double>(in.angle.sin_t), 0, static_cast<double>(in.angle.cos_t));
    const auto precision = normzoo::code::compare_float(f, l, e.lobe.pole);
    disarm_evaluation_timer();
    record r = file_record(o, "brdf");
    set_parameters(r, grid, index);
    r.set("theta_deg", in.theta_deg);
    const bool finite = e.finite(), non_negative = !e.found.negative;
    const auto& big = e.largest();
    const bool conserving = big.value <= 1 + big.abs_error;
    // where f returned NaN, Inf or a negative value, the record says so instead of a number
    if (finite && non_negative) {
        r.set("albedo", big.value);
        r.set("albedo_rgb", numbers_text({e.channel[0].value, e.channel[1].value, e.channel[2].value}));
        r.set("albedo_fp32", e32.finite() ? field_value(e32.largest().value) : field_value(nullptr));
        r.set("error_estimate", big.abs_error);
        reflectance = big;
    } else {
        r.set("albedo", nullptr).set("albedo_rgb", nullptr).set("albedo_fp32", nullptr).set("error_estimate", nullptr);
    }
    r.set("conserving", finite && non_negative ? field_value(conserving) : field_value(nullptr));
    r.set("values", !finite ? "non-finite" : !non_negative ? "negative" : "reflectance");
    const auto& where = !finite ? e.found.non_finite : e.found.negative;
    r.set("problem_V", where ? field_value(vector_text(*where.first)) : field_value(nullptr));
    r.set("problem_count", static_cast<std::int64_t>(where.count));
    r.set("fp32_worst_relative", precision.worst.relative);
    r.set("fp32_breakdown", precision.breaks_down());
    r.set("fp32_where_V", vector_text(precision.worst.v));
    r.set("evaluations", static_cast<std::int64_t>(e.evaluations));
    r.set("lobe_width", e.lobe.width);
    const bool pass = finite && non_negative && conserving && !precision.breaks_down();
    r.set("pass", pass);
    return r;
}

// Per swept parameter, its values and the albedos at the first incidence as it moves (the others
// at their first value): what the normalization check compares.
using albedo_sweeps = std::map<std::string, std::vector<std::pair<double, normzoo::quadrature::estimate<double>>>>;

void add_to_sweeps(const std::vector<parameter_values>& grid, const std::vector<std::size_t>& index,
                   const normzoo::quadrature::estimate<double>& albedo, albedo_sweeps& along) {
    for (std::size_t k = 0; k < grid.size(); ++k) {
        bool others_first = true;
        for (std::size_t j = 0; j < grid.size(); ++j) others_first = others_first && (j == k || index[j] == 0);
        if (grid[k].swept && others_first) along[grid[k].p->name].push_back({grid[k].values[index[k]][0], albedo});
    }
}

// A brdf-checks record: reciprocity at one combination of the parameters' values.
record reciprocity_record(const brdf_request& o, const std::vector<parameter_values>& grid, const std::vector<std::size_t>& index,
                          const compiled_shader::instance& f) {
    const auto rec = normzoo::code::check_reciprocity(f);
    record r = file_record(o, "brdf-checks");
    r.set("check", "reciprocity");
    set_parameters(r, grid, index);
    r.set("parameter", nullptr).set("theta_deg", nullptr).set("worst", rec.worst.relative);
    r.set("where", "L=" + vector_text(rec.worst.l) + " V=" + vector_text(rec.worst.v)).set("pass", rec.reciprocal());
    return r;
}

// A brdf-checks record: the albedos as the swept parameter `name` moves, within their bounds.
// Reported, not failed (no pass): a parameter may be meant to change the albedo (a base color).
record normalization_record(const brdf_request& o, const std::string& name,
                            const std::vector<std::pair<double, normzoo::quadrature::estimate<double>>>& points, double theta_deg) {
    std::vector<normzoo::quadrature::estimate<double>> es;
    for (const auto& p : points) es.push_back(p.second);
    const auto n = normzoo::code::check_normalization(es);
    record r = file_record(o, "brdf-checks");
    r.set("check", "normalization").set("parameter", name).set("theta_deg", theta_deg);
    r.set("worst", n.spread);
    std::ostringstream where;
    where.precision(12);
    where << name << "=" << points[n.lowest].first << ": " << points[n.lowest].second.value << ", " << name << "="
          << points[n.highest].first << ": " << points[n.highest].second.value << " (bounds " << n.bound << ")";
    r.set("where", where.str()).set("normalized", n.normalized());
    return r;
}

}  // namespace

std::vector<table_output> brdf_tables(const brdf_request& o, bool quiet) {
    const shader_source source = read_preprocessed(o.file, {o.defines, o.include_dirs});
    const auto grid = parameter_grid(source, o);
    const compiled_shader shader(source);
    if (!quiet)
        std::cerr << "verify: " << o.file << (shader.report().cached ? ": compiled (cached) " : ": compiled in " + std::to_string(shader.report().seconds) + " s ")
                  << shader.report().library << "\n";
    const std::vector<incidence> angles = incidences(o);
    table_output albedos, checks;
    set_table_heads(o, grid, albedos, checks);
    // Every combination of the parameters' values: the albedo at each incidence, and reciprocity.
    std::vector<std::size_t> index(grid.size(), 0);
    albedo_sweeps along;
    do {
        const std::vector<double> slots = slots_of(grid, index);
        const compiled_shader::instance f(shader, slots);
        for (std::size_t a = 0; a < angles.size(); ++a) {
            std::optional<normzoo::quadrature::estimate<double>> reflectance;
            albedos.records.push_back(albedo_record(o, grid, index, f, angles[a], reflectance));
            if (a == 0 && reflectance) add_to_sweeps(grid, index, *reflectance, along);
        }
        checks.records.push_back(reciprocity_record(o, grid, index, f));
    } while (next_combination(grid, index));
    for (const auto& [name, points] : along) checks.records.push_back(normalization_record(o, name, points, angles[0].theta_deg));
    return {std::move(albedos), std::move(checks)};
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
    for (const auto& d : q.defines) check_define(d);
    if (given(o, "--steps")) q.steps = parse_count("--steps", typed_text(o, "--steps"), 2, 1000);
    if (given(o, "--theta")) q.theta = parse_decimal_list("--theta", typed_text(o, "--theta"), "0", "90", true);
    if (given(o, "--mu")) q.mu = parse_decimal_list("--mu", typed_text(o, "--mu"), "0", "1", false, true);
    if (given(o, "--tolerance"))
        q.tolerance = parse_decimal_list("--tolerance", typed_text(o, "--tolerance"), "1e-14", "0.01").front().to<double>();
    if (given(o, "--time-limit"))
        q.eval_seconds = parse_decimal_list("--time-limit", typed_text(o, "--time-limit"), "1", "86400").front().to<double>();
    if (!q.theta.empty() && !q.mu.empty()) throw bad_input("--theta and --mu: give one of them");
    return q;
}

std::vector<table_output> brdf_file_tables(const options& o) {
    auto tables = brdf_tables(brdf_request_of(o), given(o, "--json"));
    for (auto& t : tables) t.console = print_brdf_table;
    return tables;
}

}  // namespace verify
