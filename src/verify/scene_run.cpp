// The plan of a scene's run: each kind of table it asks for, in the order of the results; the
// compositions', the baked tables' and the code's here, the others in scene_zoo.cpp and
// scene_energy.cpp (scene_tables.hpp).
#include "scene_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "brdf_run.hpp"
#include "lut.hpp"
#include "microfacet_tables.hpp"
#include "scene_tables.hpp"

namespace verify {

namespace {

using scene_parts::scene_run;

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
        const field_value* conserving = r.find("conserving");
        if (!r.find("pass")) r.set("pass", (conserving && std::get<bool>(*conserving)) || run.s->allow_energy_gain);
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

// microfacet-energy and lut-check: the microfacet compositions and the baked tables they name,
// computed in one job (a composition's sweep, then its table's check, material by material).
void plan_composition_tables(const scene_run& run, run_plan& p) {
    const auto& materials = run.s->materials;
    if (std::none_of(materials.begin(), materials.end(), [](const scene_material& m) { return m.composition; })) {
        p.skipped.push_back({"microfacet-energy", "no material is a microfacet composition"});
        return;
    }
    p.jobs.push_back(scene_parts::scene_job(run, "microfacet-energy", [run] {
        std::vector<record> comp;
        std::vector<table_output> lut_checks;
        for (const auto& m : run.s->materials) {
            if (!m.composition) continue;
            auto t = composition_energy_of(run, m);
            comp.insert(comp.end(), t.records.begin(), t.records.end());
            if (!m.lut_path.empty()) lut_checks.push_back(lut_check_of(run, m));
        }
        auto info = microfacet_energy_info();
        info.md_columns.insert(info.md_columns.begin(), "material");
        std::vector<table_output> out;
        out.push_back({info, std::move(comp), run.head + ", each composition over its roughness range", run.command});
        for (auto& c : lut_checks) out.push_back(std::move(c));
        return out;
    }));
}

// A material given as code: its file's tables over its parameters (docs/brdf-code.md).
std::vector<table_output> code_tables_of(const scene_run& run, const scene_material& m) {
    brdf_request q;
    q.file = m.brdf_path;
    q.shown_file = m.brdf_written;
    q.material = m.name;
    q.command = run.command;
    q.params = m.brdf_params;
    q.defines = m.brdf_defines;
    q.include_dirs = m.brdf_include_dirs;
    q.textures = m.brdf_textures;
    q.layout = m.brdf_layout;
    if (m.brdf_fixed_view) q.fixed = normzoo::code::fixed_direction::view;
    q.allow_energy_gain = run.s->allow_energy_gain;  // a gain is then a finding only
    return brdf_tables(q, true);
}

// brdf and brdf-checks: each material given as code, its records gathered table by table.
void plan_code_tables(const scene_run& run, run_plan& p) {
    const auto& materials = run.s->materials;
    if (std::none_of(materials.begin(), materials.end(), [](const scene_material& m) { return m.code(); })) {
        p.skipped.push_back({"brdf, brdf-checks", "no material is given as code (brdf = \"file\")"});
        return;
    }
    p.jobs.push_back(scene_parts::scene_job(run, "brdf", [run] {
        std::vector<table_output> code_tables;
        for (const auto& m : run.s->materials) {
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
        return code_tables;
    }));
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
// guardrail for an engine"); what it does not need goes to p.skipped with the reason.
void plan_scene_tables(const std::shared_ptr<const scene>& s, unsigned threads, run_plan& p) {
    const scene_run run{s, threads, "./verify --scene " + s->path, "scene '" + s->name + "'",
                        "scene " + std::filesystem::path(s->path).stem().string()};
    scene_parts::plan_zoo_table(run, p);
    scene_parts::plan_bounds_table(run, p);
    scene_parts::plan_energy_tables(run, p);
    plan_composition_tables(run, p);
    plan_code_tables(run, p);
    scene_parts::plan_irradiance_table(run, p);
    skip_tables_without_a_scene(p.skipped);
}

}  // namespace verify
