// A scene's energy, energy-summary and shader-normalization tables (scene_tables.hpp).
#include "scene_tables.hpp"

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include <normzoo/check.hpp>
#include <normzoo/registry.hpp>

#include "tables/energy.hpp"
#include "tables/grid.hpp"
#include "tables/shader_normalization.hpp"

namespace verify::scene_parts {

namespace {

bool is_brdf(const std::string& model) {
    return normzoo::with_brdf(model, [](auto) {});
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

// The records of the energy tables, gathered over the materials that are BRDF forms.
struct energy_rows {
    std::vector<record> sweep, summary, shader;
};

// A material's energy sweep over its range at its specular, and its summary.
void add_material_energy(const scene_run& run, const scene_material& m, const std::vector<normzoo::decimal>& angles,
                         energy_rows& e) {
    energy_settings es;
    es.tolerance = run.s->albedo;
    es.specular = m.specular;
    // The forms swept in n over the material's exponent range; the others over their own grids.
    const auto points = energy_sweep({m.model}, angles, run.jobs, es, [&](const normzoo::brdf::parameter& p) {
        return p.name == "n" ? normzoo::exponents_in_range(declared_grid(p), m.n_lo, m.n_hi)
                             : declared_grid(p);
    });
    auto groups = energy_summary(points, run.jobs, es);
    // In a scene a gain fails the run unless the scene allows it.
    if (!run.s->allow_energy_gain)
        for (auto& g : groups) g.trusted = g.trusted && !g.gains;
    auto rows_m = energy_records(points);
    auto sum_m = energy_summary_table(groups);
    for (auto& r : sum_m) r.fields.insert(r.fields.begin(), {"material", m.name});
    for (auto& r : rows_m) r.fields.insert(r.fields.begin(), {"material", m.name});
    e.sweep.insert(e.sweep.end(), rows_m.begin(), rows_m.end());
    e.summary.insert(e.summary.end(), sum_m.begin(), sum_m.end());
}

// A material's normalization expression against the exact factor over its range, with the
// largest albedo it gives (docs/reference.md, "[[materials]]").
record shader_normalization_record(const scene_run& run, const scene_material& m, const std::vector<normzoo::decimal>& angles) {
    normzoo::shader_normalization_verdict v{};
    normzoo::albedo_settings as{run.s->albedo, normzoo::albedo_settings{}.max_panels};
    check_shader_normalization(m.model, m.shader, m.n_min, m.n_max, m.specular, doubles_of(angles), as, v);
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
        .set("pass", v.trusted && std::abs(v.max_rel_error) <= run.s->normalization &&
                         (v.conserving || run.s->allow_energy_gain));
    return r;
}

// The energy tables of the materials swept (each with its shader-normalization record or not),
// in the scene's order: energy and energy-summary, then shader-normalization if any.
std::vector<table_output> energy_tables(const scene_run& run, const std::vector<std::pair<std::size_t, bool>>& swept) {
    const scene& s = *run.s;
    energy_rows e;
    const auto angles = default_energy_angle_inputs();
    for (const auto& [index, with_shader] : swept) {
        add_material_energy(run, s.materials[index], angles, e);
        if (with_shader) e.shader.push_back(shader_normalization_record(run, s.materials[index], angles));
    }
    std::vector<table_output> out;
    out.push_back({energy_info(doubles_of(angles), energy_settings{s.albedo, 1}), std::move(e.sweep),
                   run.head + ", each material over its range", run.command});
    auto info = energy_summary_info();
    info.settings.push_back(s.allow_energy_gain ? "the scene allows energy gain: a gain is reported, not failed"
                                                : "in a scene a form that gains energy fails (pass = false); "
                                                  "[tolerance] allow_energy_gain = true makes it a finding only");
    info.md_columns.insert(info.md_columns.begin(), "material");
    out.push_back({info, std::move(e.summary), run.head, run.command});
    out.back().verdict = [allow = s.allow_energy_gain](const record& r) { return energy_summary_verdict(r, allow); };
    if (!e.shader.empty()) {
        out.push_back({shader_normalization_info(), std::move(e.shader), run.head, run.command});
        out.back().verdict = [tolerance = s.normalization, allow = s.allow_energy_gain](const record& r) {
            return shader_normalization_verdict(r, tolerance, allow);
        };
    }
    return out;
}

}  // namespace

// energy, energy-summary and shader-normalization: each material that is a BRDF form, computed
// in one job (a material's sweep, then its expression, as the tables list them).
void plan_energy_tables(const scene_run& run, run_plan& p) {
    std::vector<std::pair<std::size_t, bool>> swept;  // a material's index, and whether its expression is checked
    bool any_shader = false;
    for (std::size_t i = 0; i < run.s->materials.size(); ++i) {
        const auto& m = run.s->materials[i];
        if (m.composition || m.code()) continue;  // the compositions' and the code's own tables
        if (!is_brdf(m.model)) {
            p.skipped.push_back({"energy: " + m.name, "model " + m.model + " is a distribution, not a BRDF form"});
            continue;
        }
        const bool zoo_constant = normzoo::with_zoo_brdf(m.model, [](auto) {});
        if (m.normalization && !zoo_constant)
            p.skipped.push_back({"shader-normalization: " + m.name,
                                 "model " + m.model + " has no zoo constant for a shader expression to replace"});
        swept.emplace_back(i, m.normalization && zoo_constant);
        any_shader = any_shader || swept.back().second;
    }
    if (swept.empty()) p.skipped.push_back({"energy", "no material is a BRDF form"});
    if (!any_shader) p.skipped.push_back({"shader-normalization", "no material gives a normalization expression"});
    if (!swept.empty())
        p.jobs.push_back(scene_job(run, "energy", [run, swept = std::move(swept)] { return energy_tables(run, swept); }));
}

}  // namespace verify::scene_parts
