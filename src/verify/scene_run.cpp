#include "scene_run.hpp"

#include "brdf_run.hpp"

#include "lut.hpp"
#include "microfacet_tables.hpp"

#include <normzoo/normzoo.hpp>

#include "tables/tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>

namespace verify {

namespace {

using normzoo::record;

std::string zoo_row_of(const std::string& model) {
    std::string row = model;  // a zoo row id names itself
    normzoo::with_zoo_brdf(model, [&](auto form) { row = decltype(form)::zoo_row; });
    return row;
}

// Five roughness values over [lo, hi]: the ends as written and three between them (log-spaced
// when the range spans a decade or more), each a shortest decimal.
std::vector<normzoo::decimal> roughness_samples(const normzoo::decimal& lo, const normzoo::decimal& hi) {
    if (lo == hi) return {lo};
    const double a = lo.to<double>(), b = hi.to<double>();
    std::vector<normzoo::decimal> out{lo};
    for (int k = 1; k < 4; ++k) {
        const double x = b / a >= 10 ? a * std::pow(b / a, k / 4.0) : a + (b - a) * k / 4.0;
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.3g", x);
        out.emplace_back(buf);
    }
    out.push_back(hi);
    return out;
}

bool is_brdf(const std::string& model) {
    return normzoo::with_brdf(model, [](auto) {});
}

std::vector<normzoo::decimal> tilts_for(const scene_light& l) {
    if (!l.tilt_input) return {normzoo::decimal("0")};
    return normzoo::exponents_in_range(normzoo::default_irradiance_tilts(), l.tilt_input->first, l.tilt_input->second);
}

// r0/r of a scene's light: radius / distance in 50 digits, rounded to binary128 (within its epsilon).
normzoo::ratio_input ratio_of(const scene_light& l) {
    const normzoo::wide r = l.radius_input.to<normzoo::wide>() / l.distance_input.to<normzoo::wide>();
    const normzoo::quad q = static_cast<normzoo::quad>(r);
    const bool exact = normzoo::wide(q) * l.distance_input.to<normzoo::wide>() == l.radius_input.to<normzoo::wide>() &&
                       l.radius_input.exact_in<normzoo::wide>() && l.distance_input.exact_in<normzoo::wide>();
    return {q, exact ? 0.0 : static_cast<double>(std::numeric_limits<normzoo::quad>::epsilon()),
            l.radius_input.text() + "/" + l.distance_input.text()};
}

// A number in a verdict: three significant digits, as a person reads it.
std::string short_number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
}

// "largest albedo 1.07 +- 1e-11 at n = 1, 0 deg: gains energy" and whether the scene allows it.
std::string energy_words(double albedo, double error, const std::string& where, bool conserving, bool allow_gain) {
    std::string s = "largest albedo " + short_number(albedo) + " +- " + short_number(error) + " at " + where + ": ";
    if (conserving) return s + "conserves energy";
    return s + (allow_gain ? "gains energy, which the scene allows" : "gains energy, which the scene does not allow");
}

// The scene's verdicts, one line each: the material, its model and range, and what fails by how much.
std::string shader_normalization_verdict(const record& r, double tolerance, bool allow_gain) {
    const double rel = r.number("max_rel_error");
    const bool conserving = std::get<bool>(*r.find("conserving"));
    std::string s = "material \"" + r.text("material") + "\" (" + r.text("model") + ", n in [" +
                    short_number(r.number("n_min")) + ", " + short_number(r.number("n_max")) + "], " +
                    r.text("expression") + "): relative error " + short_number(100 * rel) + "% at n = " +
                    short_number(r.number("at_n")) + (std::abs(rel) <= tolerance ? ", within" : ", above") +
                    " the tolerance " + short_number(tolerance) + "; " +
                    energy_words(r.number("max_albedo"), r.number("max_albedo_error"),
                                 "n = " + short_number(r.number("at_n_albedo")) + ", " +
                                     short_number(r.number("at_theta_deg")) + " deg",
                                 conserving, allow_gain);
    if (std::abs(rel) <= tolerance && (conserving || allow_gain))
        s += "; an albedo was not computed to the scene's tolerance.albedo";
    return s;
}

std::string energy_summary_verdict(const record& r, bool allow_gain) {
    const bool conserving = std::get<bool>(*r.find("conserving"));
    const std::string parameter = r.text("parameter");
    std::string s = "material \"" + r.text("material") + "\" (" + r.text("model") +
                    (parameter == "none" ? "" : ", " + parameter + " = " + short_number(r.number("value"))) + "): " +
                    energy_words(r.number("max_albedo"), r.number("max_albedo_error"),
                                 short_number(r.number("argmax_theta_deg")) + " deg", conserving, allow_gain);
    if (conserving || allow_gain) s += "; an albedo was not computed to the scene's tolerance.albedo";
    return s;
}

// What every table of a scene's run shares: the scene, the threads, the command and head its
// tables show, and where the tables and the skipped ones go, in the order they are added.
struct scene_run {
    const scene& s;
    unsigned jobs;
    std::string command, head;
    std::vector<table_output>& out;
    std::vector<skipped_table>& skipped;
};

// zoo: the rows the materials use, each over the union of their exponent ranges.
void add_zoo_table(const scene_run& run) {
    std::map<std::string, std::set<normzoo::decimal>> rows;
    for (const auto& m : run.s.materials)
        if (!m.composition && !m.code())
            for (const auto& n : normzoo::exponents_in_range(normzoo::default_zoo_exponents(), m.n_lo, m.n_hi))
                rows[zoo_row_of(m.model)].insert(n);
    normzoo::zoo_settings zs;
    zs.digits_1d = run.s.digits;
    std::vector<record> zoo;
    normzoo::for_each_zoo_row([&](auto row) {
        using Row = decltype(row);
        auto it = rows.find(Row::id);
        if (it == rows.end()) {
            run.skipped.push_back({std::string("zoo: ") + Row::id, "no material uses this row"});
            return;
        }
        for (const auto& n : it->second) {
            if (!Row::has_exponent && n != *it->second.begin()) continue;
            zoo.push_back(normzoo::zoo_record<Row>(Row::has_exponent ? n : normzoo::decimal(), zs));
        }
    });
    if (!zoo.empty()) run.out.push_back({normzoo::zoo_info(zs), std::move(zoo), run.head + ", the rows its materials use", run.command});
}

// bounds: the Blinn-Phong rows the materials use, each row over its own materials' exponents.
void add_bounds_table(const scene_run& run) {
    std::map<std::string, std::set<normzoo::decimal>> bound_n{{"blinn-phong", {}}, {"blinn-phong-modified", {}}};
    for (const auto& m : run.s.materials) {
        if (m.composition || m.code()) continue;
        const auto row = bound_n.find(zoo_row_of(m.model));
        if (row != bound_n.end())
            for (const auto& n : normzoo::exponents_in_range(normzoo::default_bounds_exponents(), m.n_lo, m.n_hi))
                row->second.insert(n);
    }
    const auto& bp = bound_n["blinn-phong"];
    const auto& bpm = bound_n["blinn-phong-modified"];
    if (bp.empty() && bpm.empty()) {
        run.skipped.push_back({"bounds", "no material uses a Blinn-Phong row"});
    } else {
        for (const auto& [row, n] : bound_n)
            if (n.empty()) run.skipped.push_back({"bounds: " + row, "no material uses this row"});
        run.out.push_back({normzoo::bounds_info(),
                           normzoo::bounds_table({bp.begin(), bp.end()}, {bpm.begin(), bpm.end()}),
                           run.head + ", exponents of its Blinn-Phong materials", run.command});
    }
}

// The records of the energy tables, gathered over the materials that are BRDF forms.
struct energy_rows {
    std::vector<record> sweep, summary, shader;
};

// A material's energy sweep over its range at its specular, and its summary.
void add_material_energy(const scene_run& run, const scene_material& m, const std::vector<normzoo::decimal>& angles,
                         energy_rows& e) {
    normzoo::energy_settings es;
    es.tolerance = run.s.albedo;
    es.specular = m.specular;
    // The forms swept in n over the material's exponent range; the others over their own grids.
    const auto points = normzoo::energy_sweep({m.model}, angles, run.jobs, es, [&](const normzoo::brdf::parameter& p) {
        return p.name == "n" ? normzoo::exponents_in_range(normzoo::declared_grid(p), m.n_lo, m.n_hi)
                             : normzoo::declared_grid(p);
    });
    auto groups = normzoo::energy_summary(points, run.jobs, es);
    // In a scene a gain fails the run unless the scene allows it.
    if (!run.s.allow_energy_gain)
        for (auto& g : groups) g.trusted = g.trusted && !g.gains;
    auto rows_m = normzoo::energy_records(points);
    auto sum_m = normzoo::energy_summary_table(groups);
    for (auto& r : sum_m) r.fields.insert(r.fields.begin(), {"material", m.name});
    for (auto& r : rows_m) r.fields.insert(r.fields.begin(), {"material", m.name});
    e.sweep.insert(e.sweep.end(), rows_m.begin(), rows_m.end());
    e.summary.insert(e.summary.end(), sum_m.begin(), sum_m.end());
}

// A material's normalization expression against the exact factor over its range, with the
// largest albedo it gives (docs/reference.md, "[[materials]]").
record shader_normalization_record(const scene_run& run, const scene_material& m, const std::vector<normzoo::decimal>& angles) {
    normzoo::shader_normalization_verdict v{};
    normzoo::albedo_settings as{run.s.albedo, normzoo::albedo_settings{}.max_panels};
    normzoo::check_shader_normalization(m.model, m.shader, m.n_min, m.n_max, m.specular, normzoo::doubles_of(angles), as, v);
    record r{"shader-normalization", {}};
    r.set("material", m.name)
        .set("model", m.model)
        .set("expression", *m.normalization)
        .set("n_min", m.n_min)
        .set("n_max", m.n_max)
        .set("max_rel_error", v.max_rel_error)
        .set("at_n", v.at_n)
        .set("max_albedo", v.max_albedo)
        .set("max_albedo_error", v.albedo_error)
        .set("at_n_albedo", v.at_n_albedo)
        .set("at_theta_deg", v.at_theta_deg)
        .set("conserving", v.conserving)
        .set("verdict", v.describe())
        .set("pass", v.trusted && std::abs(v.max_rel_error) <= run.s.normalization &&
                         (v.conserving || run.s.allow_energy_gain));
    return r;
}

// energy, energy-summary and shader-normalization: each material that is a BRDF form.
void add_energy_tables(const scene_run& run) {
    const scene& s = run.s;
    energy_rows e;
    const auto angles = normzoo::default_energy_angle_inputs();
    for (const auto& m : s.materials) {
        if (m.composition || m.code()) continue;  // below: the compositions' and the code's own tables
        if (!is_brdf(m.model)) {
            run.skipped.push_back({"energy: " + m.name, "model " + m.model + " is a distribution, not a BRDF form"});
            continue;
        }
        add_material_energy(run, m, angles, e);
        if (m.normalization && !normzoo::with_zoo_brdf(m.model, [](auto) {})) {
            run.skipped.push_back({"shader-normalization: " + m.name,
                                   "model " + m.model + " has no zoo constant for a shader expression to replace"});
        } else if (m.normalization) {
            e.shader.push_back(shader_normalization_record(run, m, angles));
        }
    }
    if (!e.sweep.empty()) {
        run.out.push_back({normzoo::energy_info(normzoo::doubles_of(angles), normzoo::energy_settings{s.albedo, 1}), std::move(e.sweep),
                           run.head + ", each material over its range", run.command});
        auto info = normzoo::energy_summary_info();
        info.settings.push_back(s.allow_energy_gain ? "the scene allows energy gain: a gain is reported, not failed"
                                                    : "in a scene a form that gains energy fails (pass = false); "
                                                      "[tolerance] allow_energy_gain = true makes it a finding only");
        info.md_columns.insert(info.md_columns.begin(), "material");
        run.out.push_back({info, std::move(e.summary), run.head, run.command});
        run.out.back().verdict = [allow = s.allow_energy_gain](const record& r) { return energy_summary_verdict(r, allow); };
    } else {
        run.skipped.push_back({"energy", "no material is a BRDF form"});
    }
    if (!e.shader.empty()) {
        run.out.push_back({normzoo::shader_normalization_info(), std::move(e.shader), run.head, run.command});
        run.out.back().verdict = [tolerance = s.normalization, allow = s.allow_energy_gain](const record& r) {
            return shader_normalization_verdict(r, tolerance, allow);
        };
    } else {
        run.skipped.push_back({"shader-normalization", "no material gives a normalization expression"});
    }
}

// A composition's E(mu, alpha) over its roughness range at its F0 (the compensations' white
// furnace with it); one that gains energy fails unless the scene allows it.
table_output composition_energy_of(const scene_run& run, const scene_material& m) {
    std::vector<roughness_input> rough;
    for (const auto& x : roughness_samples(m.rough_lo, m.rough_hi)) rough.push_back({x, m.rough_is_r});
    std::vector<incidence_input> mus;
    for (const char* mu : {"1e-4", "0.01", "0.1", "0.3", "0.5", "0.7", "0.9", "1"}) mus.push_back({normzoo::decimal(mu), false});
    auto t = composition_energy_table({m.model}, rough, mus, m.parts, run.jobs);
    for (auto& r : t.records) {
        r.table = "microfacet-energy";
        r.fields.insert(r.fields.begin(), {"material", m.name});
        // a composition that gains energy fails, unless the scene allows it
        const normzoo::field_value* conserving = r.find("conserving");
        if (!r.find("pass")) r.set("pass", (conserving && std::get<bool>(*conserving)) || run.s.allow_energy_gain);
    }
    return t;
}

// The baked table a composition names, checked as `verify lut --check` does (docs/lut.md).
table_output lut_check_of(const scene_run& run, const scene_material& m) {
    table_output check;
    try {
        check = check_lut_file(m.lut_path, m.lut_kind, m.model, m.parts, m.lut_map_r, std::nullopt, run.jobs);
    } catch (const bad_input& e) {  // the table's own message, at the scene's line that names it
        throw bad_input(m.lut_place + ": " + e.what());
    }
    for (auto& r : check.records) r.fields.insert(r.fields.begin(), {"material", m.name});
    check.parameters = run.head + ", material " + m.name;
    check.command = run.command;
    return check;
}

// microfacet-energy and lut-check: the microfacet compositions and the baked tables they name.
void add_composition_tables(const scene_run& run) {
    std::vector<record> comp;
    std::optional<normzoo::table_info> comp_info;
    std::vector<table_output> lut_checks;
    for (const auto& m : run.s.materials) {
        if (!m.composition) continue;
        auto t = composition_energy_of(run, m);
        if (!comp_info) comp_info = t.info;
        comp.insert(comp.end(), t.records.begin(), t.records.end());
        if (!m.lut_path.empty()) lut_checks.push_back(lut_check_of(run, m));
    }
    if (comp_info) {
        comp_info->name = "microfacet-energy";
        comp_info->md_columns.insert(comp_info->md_columns.begin(), "material");
        run.out.push_back({*comp_info, std::move(comp), run.head + ", each composition over its roughness range", run.command});
        for (auto& c : lut_checks) run.out.push_back(std::move(c));
    } else {
        run.skipped.push_back({"microfacet-energy", "no material is a microfacet composition"});
    }
}

// A material given as code: its file's tables over its parameters (docs/brdf-code.md).
std::vector<table_output> code_tables_of(const scene_run& run, const scene_material& m) {
    brdf_request q;
    q.file = m.brdf_path;
    q.shown_file = m.brdf_written;
    q.material = m.name;
    q.command = run.command;
    q.params = m.brdf_params;
    auto tables = brdf_tables(q, true);
    for (auto& t : tables)
        for (auto& r : t.records) {
            // a gain is a finding only where the scene allows it
            const normzoo::field_value* conserving = r.find("conserving");
            if (run.s.allow_energy_gain && conserving && std::holds_alternative<bool>(*conserving) && !std::get<bool>(*conserving))
                for (auto& [key, value] : r.fields)
                    if (key == "pass")
                        value = r.text("values") == "reflectance" && !std::get<bool>(*r.find("fp32_breakdown"));
        }
    return tables;
}

// brdf and brdf-checks: each material given as code, its records gathered table by table.
void add_code_tables(const scene_run& run) {
    std::vector<table_output> code_tables;
    for (const auto& m : run.s.materials) {
        if (!m.code()) continue;
        auto tables = code_tables_of(run, m);
        for (std::size_t k = 0; k < tables.size(); ++k) {
            if (code_tables.size() <= k) {
                tables[k].info.md_columns.insert(tables[k].info.md_columns.begin(), "material");
                tables[k].parameters = run.head + ", each material given as code over its parameters";
                code_tables.push_back(std::move(tables[k]));
            } else {
                for (auto& r : tables[k].records) code_tables[k].records.push_back(std::move(r));
            }
        }
    }
    if (code_tables.empty()) run.skipped.push_back({"brdf, brdf-checks", "no material is given as code (brdf = \"file\")"});
    for (auto& t : code_tables) run.out.push_back(std::move(t));
}

// irradiance: each light at its size, over its tilt range.
void add_irradiance_table(const scene_run& run) {
    std::vector<record> irr;
    for (const auto& l : run.s.lights) {
        const auto kind = l.type == "sphere" ? normzoo::light_kind::sphere : normzoo::light_kind::disk;
        auto rows_l = normzoo::irradiance_table({kind}, {ratio_of(l)}, tilts_for(l), run.jobs);
        for (auto& r : rows_l) r.fields.insert(r.fields.begin(), {"light_name", l.name});
        irr.insert(irr.end(), rows_l.begin(), rows_l.end());
    }
    if (!irr.empty()) {
        auto info = normzoo::irradiance_infos({})[0];
        info.md_pivot.reset();
        info.md_columns.insert(info.md_columns.begin(), "light_name");
        run.out.push_back({info, std::move(irr), run.head + ", each light at its r0/r", run.command});
    } else {
        run.skipped.push_back({"irradiance", "the scene has no lights"});
    }
}

// The tables a scene never asks for, and why.
void skip_tables_without_a_scene(std::vector<skipped_table>& skipped) {
    skipped.push_back({"irradiance-limit", "the limit r0/r -> 0 is the default table's; a scene's light has one size"});
    skipped.push_back({"punctual-limit", "the punctual-light limit does not depend on a scene"});
    skipped.push_back({"zoo-constants, gloss-8bit", "the scene's own expressions are checked in shader-normalization"});
    skipped.push_back({"energy-claims, fresnel-visibility, energy-montecarlo", "the seeds' claims and the method's "
                                                                               "cross-checks do not depend on a scene"});
    skipped.push_back({"shader-precision", "the fp16 / fp32 audit of shader formulas does not depend on a scene"});
}

}  // namespace

// Each kind of table the scene asks for, in the order of the results (docs/command-line.md, "A
// guardrail for an engine"); what it does not need goes to `skipped` with the reason.
std::vector<table_output> scene_tables(const scene& s, unsigned jobs, std::vector<skipped_table>& skipped) {
    std::vector<table_output> out;
    const scene_run run{s, jobs, "./verify --scene " + s.path, "scene '" + s.name + "'", out, skipped};
    add_zoo_table(run);
    add_bounds_table(run);
    add_energy_tables(run);
    add_composition_tables(run);
    add_code_tables(run);
    add_irradiance_table(run);
    skip_tables_without_a_scene(skipped);
    return out;
}

}  // namespace verify
