// A scene's zoo, bounds and irradiance tables (scene_tables.hpp).
#include "scene_tables.hpp"

#include <limits>
#include <map>
#include <set>

#include <normzoo/registry.hpp>
#include <normzoo/wide.hpp>

#include "tables/bounds.hpp"
#include "tables/grid.hpp"
#include "tables/irradiance.hpp"
#include "tables/zoo.hpp"

namespace verify::scene_parts {

namespace {

std::string zoo_row_of(const std::string& model) {
    std::string row = model;  // a zoo row id names itself
    normzoo::with_zoo_brdf(model, [&](auto form) { row = decltype(form)::zoo_row; });
    return row;
}

std::vector<normzoo::decimal> tilts_for(const scene_light& l) {
    if (!l.tilt_input) return {normzoo::decimal("0")};
    return normzoo::exponents_in_range(default_irradiance_tilts(), l.tilt_input->first, l.tilt_input->second);
}

// r0/r of a scene's light: radius / distance in 50 digits, rounded to binary128 (within its epsilon).
ratio_input ratio_of(const scene_light& l) {
    const normzoo::wide r = l.radius_input.to<normzoo::wide>() / l.distance_input.to<normzoo::wide>();
    const normzoo::quad q = static_cast<normzoo::quad>(r);
    const bool exact = normzoo::wide(q) * l.distance_input.to<normzoo::wide>() == l.radius_input.to<normzoo::wide>() &&
                       l.radius_input.exact_in<normzoo::wide>() && l.distance_input.exact_in<normzoo::wide>();
    return {q, exact ? 0.0 : static_cast<double>(std::numeric_limits<normzoo::quad>::epsilon()),
            l.radius_input.text() + "/" + l.distance_input.text()};
}

}  // namespace

// zoo: the rows the materials use, each over the union of their exponent ranges.
void plan_zoo_table(const scene_run& run, run_plan& p) {
    using row_exponents = std::map<std::string, std::set<normzoo::decimal>>;
    row_exponents rows;
    for (const auto& m : run.s->materials)
        if (!m.composition && !m.code())
            for (const auto& n : normzoo::exponents_in_range(default_zoo_exponents(), m.n_lo, m.n_hi))
                rows[zoo_row_of(m.model)].insert(n);
    bool any_row = false;  // a model that is not a zoo row, nor normalized by one, names none
    normzoo::for_each_zoo_row([&](auto row) {
        using Row = decltype(row);
        if (rows.count(Row::id)) any_row = true;
        else p.skipped.push_back({std::string("zoo: ") + Row::id, "no material uses this row"});
    });
    if (!any_row) return;
    p.jobs.push_back(scene_job(run, "zoo", [run, rows = std::move(rows)] {
        zoo_settings zs;
        zs.digits_1d = run.s->digits;
        std::vector<record> zoo;
        normzoo::for_each_zoo_row([&](auto row) {
            using Row = decltype(row);
            const auto it = rows.find(Row::id);
            if (it == rows.end()) return;
            for (const auto& n : it->second) {
                if (!Row::has_exponent && n != *it->second.begin()) continue;
                zoo.push_back(zoo_record<Row>(Row::has_exponent ? n : normzoo::decimal(), zs));
            }
        });
        return std::vector<table_output>{{zoo_info(zs), std::move(zoo), run.head + ", the rows its materials use", run.command}};
    }));
}

// bounds: the Blinn-Phong rows the materials use, each row over its own materials' exponents.
void plan_bounds_table(const scene_run& run, run_plan& p) {
    std::map<std::string, std::set<normzoo::decimal>> bound_n{{"blinn-phong", {}}, {"blinn-phong-modified", {}}};
    for (const auto& m : run.s->materials) {
        if (m.composition || m.code()) continue;
        const auto row = bound_n.find(zoo_row_of(m.model));
        if (row != bound_n.end())
            for (const auto& n : normzoo::exponents_in_range(default_bounds_exponents(), m.n_lo, m.n_hi))
                row->second.insert(n);
    }
    const auto& bp = bound_n["blinn-phong"];
    const auto& bpm = bound_n["blinn-phong-modified"];
    if (bp.empty() && bpm.empty()) {
        p.skipped.push_back({"bounds", "no material uses a Blinn-Phong row"});
        return;
    }
    for (const auto& [row, n] : bound_n)
        if (n.empty()) p.skipped.push_back({"bounds: " + row, "no material uses this row"});
    p.jobs.push_back(scene_job(run, "bounds", [run, bp = std::vector<normzoo::decimal>(bp.begin(), bp.end()),
                                               bpm = std::vector<normzoo::decimal>(bpm.begin(), bpm.end())] {
        return std::vector<table_output>{
            {bounds_info(), bounds_table(bp, bpm), run.head + ", exponents of its Blinn-Phong materials", run.command}};
    }));
}

// irradiance: each light at its size, over its tilt range.
void plan_irradiance_table(const scene_run& run, run_plan& p) {
    if (run.s->lights.empty()) {
        p.skipped.push_back({"irradiance", "the scene has no lights"});
        return;
    }
    p.jobs.push_back(scene_job(run, "irradiance", [run] {
        std::vector<record> irr;
        for (const auto& l : run.s->lights) {
            const auto kind = l.type == "sphere" ? normzoo::light_kind::sphere : normzoo::light_kind::disk;
            auto rows_l = irradiance_table({kind}, {ratio_of(l)}, tilts_for(l), run.jobs);
            for (auto& r : rows_l) r.fields.insert(r.fields.begin(), {"light_name", l.name});
            irr.insert(irr.end(), rows_l.begin(), rows_l.end());
        }
        auto info = irradiance_infos({})[0];
        info.md_pivot.reset();
        info.md_columns.insert(info.md_columns.begin(), "light_name");
        return std::vector<table_output>{{info, std::move(irr), run.head + ", each light at its r0/r", run.command}};
    }));
}

}  // namespace verify::scene_parts
