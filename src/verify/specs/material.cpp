// material: a material's albedo with V fixed, per lobe and whole (docs/materials.md). Planned by
// `energy --material NAME[/COMPENSATION]`, never named; its options are its own (--param, --steps,
// --mu or --theta), checked before anything is computed; printed, or written only to --out.
#include "../table_spec.hpp"

#include <normzoo/albedo_input.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/material/registry.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <filesystem>
#include <type_traits>

#include "../args.hpp"
#include "../brdf_parameters.hpp"
#include "../tables/material.hpp"

namespace verify {

namespace {

namespace mat = normzoo::material;
using normzoo::decimal;

// One value of a parameter: its number(s) (one, or three for a colour), each with a bound on its
// relative rounding to double (a decimal's as typed; a sweep's point, rounded once: 2^-53), or a
// choice.
struct param_value {
    std::vector<double> x, rounding;
    int choice = 0;  // a choice parameter's index among its choices
};

param_value typed_value(const std::vector<decimal>& d) {
    param_value v;
    for (const auto& x : d) v.x.push_back(x.to<double>()), v.rounding.push_back(x.rounding<double>());
    return v;
}

struct material_request {
    std::string name;  // as typed
    std::string id;    // the material's (material/registry.hpp)
    mat::compensation_kind compensation = mat::compensation_kind::none;
    std::vector<std::vector<param_value>> values;  // per declared parameter, in declaration order
    std::vector<decimal> mus, thetas;
};

std::string typed_text(const options& o, const std::string& name) {
    const auto it = o.typed.find(name);
    return it == o.typed.end() || it->second.empty() ? std::string() : it->second.front();
}

// The values of `p` from the text after NAME=: a choice's id; a colour's R,G,B or one grey
// number; a number's value, list A,B,C or range LO..HI in `steps` values.
std::vector<param_value> read_values(const normzoo::parameter& p, const std::string& text, std::size_t steps) {
    const std::string option = "--param " + std::string(p.name);
    if (text.empty()) throw bad_input(option + ": no value (NAME=VALUE or NAME=LO..HI)");
    if (!p.choices.empty()) {
        const auto ids = split(std::string(p.choices), ',');
        const auto it = std::find(ids.begin(), ids.end(), text);
        if (it == ids.end()) throw bad_input(option + ": '" + text + "' is not one of " + std::string(p.choices));
        return {{{}, {}, int(it - ids.begin())}};
    }
    const std::string lo = normzoo::decimal::shortest(p.min).text(), hi = normzoo::decimal::shortest(p.max).text();
    const auto dots = text.find("..");
    if (dots != std::string::npos) {
        if (p.components != 1) throw bad_input(option + ": a colour takes R,G,B or one number, not a range");
        const auto a = parse_decimal_list(option, text.substr(0, dots), lo, hi), b = parse_decimal_list(option, text.substr(dots + 2), lo, hi);
        if (a.size() != 1 || b.size() != 1) throw bad_input(option + ": a range LO..HI has one number at each end, not '" + text + "'");
        if (!(a.front() < b.front())) throw bad_input(option + ": the range " + text + " is empty");
        std::vector<param_value> out;
        for (double x : sweep_values(a.front(), b.front(), steps)) out.push_back({{x}, {0x1p-53}});
        return out;
    }
    const auto v = parse_decimal_list(option, text, lo, hi);
    if (p.components == 3) {
        if (v.size() == 1) return {typed_value({v[0], v[0], v[0]})};  // grey
        if (v.size() != 3) throw bad_input(option + ": a colour is three numbers R,G,B (or one, grey), not " + std::to_string(v.size()));
        return {typed_value(v)};
    }
    std::vector<param_value> out;
    for (const auto& d : v) out.push_back(typed_value({d}));
    return out;
}

// The material's name split: its id (a registry's) and the compensation suffix, checked.
material_request named_request(const options& o) {
    material_request q;
    q.name = typed_text(o, "--material");
    const auto parts = split(q.name, '/');
    q.id = parts[0];
    if (!mat::visit_material(q.id, [](auto) {}))
        throw bad_input("--material: unknown material '" + q.id + "' (known: " + mat::material_ids() + ")");
    if (parts.size() > 2) throw bad_input("--material: '" + q.name + "' is NAME or NAME/COMPENSATION");
    try {
        if (parts.size() == 2) q.compensation = mat::parse_compensation(parts[1]);
    } catch (const std::invalid_argument& e) {
        throw bad_input(std::string("--material: ") + e.what());
    }
    return q;
}

// Every combination of the parameters' values (the first parameter varying slowest).
std::vector<std::vector<std::size_t>> combinations(const material_request& q) {
    std::vector<std::vector<std::size_t>> all{{}};
    for (const auto& v : q.values) {
        std::vector<std::vector<std::size_t>> next;
        for (const auto& c : all)
            for (std::size_t k = 0; k < v.size(); ++k) {
                next.push_back(c);
                next.back().push_back(k);
            }
        all = std::move(next);
    }
    return all;
}

// The material at one combination of values (`index` into each parameter's list, in order).
template <class M>
M material_at(const material_request& q, const std::vector<std::size_t>& index) {
    M m;
    for (std::size_t i = 0; i < q.values.size(); ++i) {
        const param_value& v = q.values[i][index[i]];
        if (!M::parameters[i].choices.empty()) m.choose(i, std::size_t(v.choice));
        for (std::size_t j = 0; j < v.x.size(); ++j) m.set(i, j, v.x[j]);
    }
    return m;
}

// The values of M's parameters from --param (the declared defaults where not given), checked:
// a name M declares, once each, in range; every combination M's input_error lets through.
template <class M>
void read_params(const options& o, material_request& q) {
    const std::size_t steps = o.typed.count("--steps") ? parse_count("--steps", typed_text(o, "--steps"), 2, 1000) : 5;
    const auto& declared = M::parameters;
    for (const auto& p : declared)
        q.values.push_back({p.choices.empty() ? param_value{std::vector<double>(std::size_t(p.components), p.held),
                                                            std::vector<double>(std::size_t(p.components), 0.0)}
                                              : param_value{}});  // the defaults are exact in double
    std::vector<bool> given(declared.size(), false);
    if (o.typed.count("--param"))
        for (const auto& text : o.typed.at("--param")) {
            const auto eq = text.find('=');
            const std::string name = text.substr(0, eq);
            const auto it = std::find_if(declared.begin(), declared.end(), [&](const normzoo::parameter& p) { return p.name == name; });
            if (eq == std::string::npos || it == declared.end()) {
                std::string known;
                for (const auto& p : declared) known += (known.empty() ? "" : ", ") + std::string(p.name);
                throw bad_input("--param " + text + ": " + std::string(M::id) + " has no parameter '" + name + "' (its parameters: " + known + ")");
            }
            const std::size_t i = std::size_t(it - declared.begin());
            if (given[i]) throw bad_input("--param " + name + ": given twice");
            given[i] = true;
            q.values[i] = read_values(*it, text.substr(eq + 1), steps);
        }
    std::size_t points = 1;
    for (const auto& v : q.values) points *= v.size();
    if (points > 10000) throw bad_input("--param: " + std::to_string(points) + " combinations of values, more than 10000");
    for (const auto& c : combinations(q))
        if (const char* why = M::input_error(material_at<M>(q, c).in)) {
            std::string at;
            for (std::size_t i = 0; i < c.size(); ++i)
                if (given[i] && declared[i].components == 1 && declared[i].choices.empty())
                    at += (at.empty() ? "" : ", ") + std::string(declared[i].name) + "=" + shortest_text(q.values[i][c[i]].x[0]);
            throw bad_input("--param " + (at.empty() ? std::string("(the defaults)") : at) + ": " + why);
        }
}

template <class M>
material_request material_request_of(const options& o) {
    material_request q = named_request(o);
    read_params<M>(o, q);
    for (const auto& c : combinations(q))
        if (const char* why = mat::compensation_error(material_at<M>(q, c), q.compensation))
            throw bad_input("--material: " + q.name + ": " + why);
    if (o.typed.count("--mu") && o.typed.count("--theta")) throw bad_input("--mu and --theta: give the incident direction one way");
    if (o.typed.count("--mu")) q.mus = parse_decimal_list("--mu", typed_text(o, "--mu"), "1e-8", "1", false, false);
    if (o.typed.count("--theta")) q.thetas = parse_decimal_list("--theta", typed_text(o, "--theta"), "0", "90", true);
    if (q.mus.empty() && q.thetas.empty()) q.mus = parse_decimal_list("--mu", "1e-4,0.01,0.1,0.5,1", "0", "1");
    return q;
}

struct incidence_value {
    double mu, delta;  // the double taken and a bound on its distance to the input's cosine
};

std::vector<incidence_value> incidences(const material_request& q) {
    std::vector<incidence_value> out;
    for (const auto& m : q.mus) out.push_back({m.to<double>(), m.rounding<double>() * m.to<double>()});
    for (const auto& t : q.thetas) {
        const auto angle = normzoo::degrees_of<normzoo::quad>(t);  // the cosine from the decimal, in binary128
        const double mu = static_cast<double>(angle.cos_t);
        if (!(mu >= 1e-8)) throw bad_input("--theta: " + t.text() + " degrees is within 5.7e-7 degrees of grazing (mu < 1e-8)");
        out.push_back({mu, static_cast<double>(abs(angle.cos_t - normzoo::quad(mu))) + 1e-33});
    }
    return out;
}

// Whether parameter p is squared into an alpha inside the material (its rounding enters once more):
// the roughnesses, by the specifications' names (glTF's roughness, OpenPBR's specular_roughness).
bool squared(const normzoo::parameter& p) {
    const std::string_view n = p.name;
    return n.size() >= 9 && (n.substr(n.size() - 9) == "roughness" || n.substr(n.size() - 9) == "Roughness");
}

// What the inputs' rounding to double can move each channel (normzoo::albedo_input_rounding, a
// slope over a relative step, per input that rounds): mu, each number parameter's components,
// and a roughness squared into alpha rounded once more (as if it rounded by 2^-54 more).
template <class M>
mat::rgb input_rounding(const material_request& q, const std::vector<std::size_t>& index, const incidence_value& in,
                        const mat::material_albedo<M::lobe_count>& at) {
    const M m = material_at<M>(q, index);
    mat::rgb moved_by{};
    auto add = [&](double xd, double delta, double upper, auto set) {
        if (!(delta > 0) || xd == 0) return;
        const double moved_x = normzoo::input_rounding_step(xd, upper);
        M mm = m;
        double mu = in.mu;
        set(mm, mu, moved_x);
        const auto moved = mat::albedo(mm, mu, q.compensation);
        for (std::size_t k = 0; k < 3; ++k)
            moved_by[k] += normzoo::albedo_input_rounding(
                [&](double) { return normzoo::quadrature::estimate<double>{moved.whole.value[k], moved.whole.abs_error[k], 0}; },
                xd, delta, {at.whole.value[k], at.whole.abs_error[k], 0}, upper);
    };
    add(in.mu, in.delta, 1.0, [](M&, double& mu, double x) { mu = x; });
    for (std::size_t i = 0; i < q.values.size(); ++i) {
        const param_value& v = q.values[i][index[i]];
        for (std::size_t j = 0; j < v.x.size(); ++j) {
            double relative = v.rounding[j];
            if (squared(M::parameters[i]) && std::fma(v.x[j], v.x[j], -(v.x[j] * v.x[j])) != 0) relative += 0x1p-54;
            const double upper = M::parameters[i].max;
            add(v.x[j], relative * std::abs(v.x[j]), upper, [&](M& g, double&, double x) { g.set(i, j, x); });
        }
    }
    return moved_by;
}

template <class M>
std::vector<std::pair<std::string, field_value>> recorded_params(const material_request& q, const std::vector<std::size_t>& index) {
    std::vector<std::pair<std::string, field_value>> out;
    for (std::size_t i = 0; i < q.values.size(); ++i) {
        const auto& p = M::parameters[i];
        const param_value& v = q.values[i][index[i]];
        const std::string key = "param_" + std::string(p.name);
        if (!p.choices.empty()) out.emplace_back(key, split(std::string(p.choices), ',')[std::size_t(v.choice)]);
        else if (p.components == 3)
            out.emplace_back(key, json_text{"[" + shortest_text(v.x[0]) + ", " + shortest_text(v.x[1]) + ", " + shortest_text(v.x[2]) + "]"});
        else out.emplace_back(key, v.x[0]);
    }
    return out;
}

template <class M>
material_point point_at(const material_request& q, const std::vector<std::size_t>& index, const incidence_value& in,
                        double reciprocity) {
    const M m = material_at<M>(q, index);
    const auto a = mat::albedo(m, in.mu, q.compensation);
    material_point p{q.name, recorded_params<M>(q, index), in.mu, a.whole, {}, {}, reciprocity};
    const mat::rgb moved = input_rounding<M>(q, index, in, a);
    for (std::size_t k = 0; k < 3; ++k) p.whole.abs_error[k] += moved[k];
    for (std::size_t i = 0; i < M::lobe_count; ++i) p.lobes.emplace_back(std::string(M::lobe_ids[i]), a.lobes[i].largest());
    if (mat::claims_preservation(m, q.compensation)) p.preserving = mat::preserving(p.whole);
    return p;
}

// A material may word its table's notes on how its albedo is computed and what it claims
// (settings 1 and 3 of material_info, which word glTF's); the others keep those.
template <class M, class = void>
struct has_own_notes : std::false_type {};
template <class M>
struct has_own_notes<M, std::void_t<decltype(M::albedo_method), decltype(M::preservation_claim)>> : std::true_type {};

template <class M>
table_info material_info_of(const std::vector<std::string>& params) {
    table_info t = material_info(params);
    if constexpr (has_own_notes<M>::value) {
        t.settings[1] = M::albedo_method;
        t.settings[3] = M::preservation_claim;
    }
    return t;
}

template <class M>
std::vector<std::string> param_keys() {
    std::vector<std::string> keys;
    for (const auto& p : M::parameters) keys.push_back("param_" + std::string(p.name));
    return keys;
}

// On the console: the Markdown (stdout) unless --json or written (then its summary line).
void print_material_table(const table_output& t, const console_view& v) {
    if (v.written) {
        std::cout << t.info.name << ": " << t.records.size() << " records -> "
                  << (std::filesystem::path(v.out_dir) / (t.info.name + ".md")).string() << "\n";
        return;
    }
    if (!v.json) std::cout << markdown(t, 300) << "\n";
}

template <class M>
std::vector<table_output> material_tables_of(const options& o) {
    const material_request q = material_request_of<M>(o);
    const auto combos = combinations(q);
    const auto in = incidences(q);
    std::vector<double> reciprocity(combos.size());
    std::vector<material_point> points(combos.size() * in.size());
    normzoo::detail::parallel_for(combos.size(), o.jobs, [&](std::size_t c) {
        reciprocity[c] = mat::reciprocity_difference(material_at<M>(q, combos[c]), q.compensation);  // of the directions only
    });
    normzoo::detail::parallel_for(points.size(), o.jobs, [&](std::size_t i) {
        points[i] = point_at<M>(q, combos[i / in.size()], in[i % in.size()], reciprocity[i / in.size()]);
    });
    std::vector<record> records;
    for (const auto& p : points) records.push_back(material_record(p));
    std::string command = "./verify energy --material " + q.name;
    if (o.typed.count("--param"))
        for (const auto& p : o.typed.at("--param")) command += " --param " + p;
    for (const char* opt : {"--steps", "--mu", "--theta"})
        if (o.typed.count(opt)) command += std::string(" ") + opt + " " + typed_text(o, opt);
    table_output t{material_info_of<M>(param_keys<M>()), std::move(records), "the values of --param and the incidences given", command};
    t.console = print_material_table;
    return {std::move(t)};
}

// The material named by --material, from the registry (material/registry.hpp).
std::vector<table_output> material_tables(const options& o) {
    std::vector<table_output> out;
    mat::visit_material(named_request(o).id, [&](auto m) { out = material_tables_of<decltype(m)>(o); });
    return out;
}

void check_material_options(const options& o) {
    mat::visit_material(named_request(o).id, [&](auto m) { material_request_of<decltype(m)>(o); });
}

}  // namespace

table_spec material_spec() {
    table_spec s{"material",
                 "a material's albedo with V fixed, per lobe and whole, per channel (energy --material NAME; docs/materials.md)",
                 {"--material", "--param", "--steps", "--mu", "--theta"},
                 material_tables,
                 false,
                 "points"};
    s.check_options = check_material_options;
    s.writes_by_default = false;
    s.planned_by = "--material";
    return s;
}

}  // namespace verify
