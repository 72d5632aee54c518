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

}  // namespace

std::vector<table_output> scene_tables(const scene& s, unsigned jobs, std::vector<skipped_table>& skipped) {
    const std::string command = "./verify --scene " + s.path;
    const std::string head = "scene '" + s.name + "'";
    std::vector<table_output> out;

    // The zoo rows the materials use, each over the union of their exponent ranges.
    std::map<std::string, std::set<normzoo::decimal>> rows;
    for (const auto& m : s.materials)
        if (!m.composition && !m.code())
        for (const auto& n : normzoo::exponents_in_range(normzoo::default_zoo_exponents(), m.n_lo, m.n_hi))
            rows[zoo_row_of(m.model)].insert(n);
    normzoo::zoo_settings zs;
    zs.digits_1d = s.digits;
    std::vector<record> zoo;
    normzoo::for_each_zoo_row([&](auto row) {
        using Row = decltype(row);
        auto it = rows.find(Row::id);
        if (it == rows.end()) {
            skipped.push_back({std::string("zoo: ") + Row::id, "no material uses this row"});
            return;
        }
        for (const auto& n : it->second) {
            if (!Row::has_exponent && n != *it->second.begin()) continue;
            zoo.push_back(normzoo::zoo_record<Row>(Row::has_exponent ? n : normzoo::decimal(), zs));
        }
    });
    if (!zoo.empty()) out.push_back({normzoo::zoo_info(zs), std::move(zoo), head + ", the rows its materials use", command});

    // The bounds of the Blinn-Phong rows the materials use, each row over its own materials' exponents.
    std::map<std::string, std::set<normzoo::decimal>> bound_n{{"blinn-phong", {}}, {"blinn-phong-modified", {}}};
    for (const auto& m : s.materials) {
        if (m.composition || m.code()) continue;
        const auto row = bound_n.find(zoo_row_of(m.model));
        if (row != bound_n.end())
            for (const auto& n : normzoo::exponents_in_range(normzoo::default_bounds_exponents(), m.n_lo, m.n_hi))
                row->second.insert(n);
    }
    const auto& bp = bound_n["blinn-phong"];
    const auto& bpm = bound_n["blinn-phong-modified"];
    if (bp.empty() && bpm.empty()) {
        skipped.push_back({"bounds", "no material uses a Blinn-Phong row"});
    } else {
        for (const auto& [row, n] : bound_n)
            if (n.empty()) skipped.push_back({"bounds: " + row, "no material uses this row"});
        out.push_back({normzoo::bounds_info(),
                       normzoo::bounds_table({bp.begin(), bp.end()}, {bpm.begin(), bpm.end()}),
                       head + ", exponents of its Blinn-Phong materials", command});
    }

    // Energy: each material that is a BRDF form, over its range, at its specular.
    std::vector<record> sweep, summary, shader;
    const auto angles = normzoo::default_energy_angle_inputs();
    for (const auto& m : s.materials) {
        if (m.composition || m.code()) continue;  // below: the compositions' and the code's own tables
        if (!is_brdf(m.model)) {
            skipped.push_back({"energy: " + m.name, "model " + m.model + " is a distribution, not a BRDF form"});
            continue;
        }
        normzoo::energy_settings es;
        es.tolerance = s.albedo;
        es.specular = m.specular;
        // The forms swept in n over the material's exponent range; the others over their own grids.
        const auto points = normzoo::energy_sweep({m.model}, angles, jobs, es, [&](const normzoo::brdf::parameter& p) {
            return p.name == "n" ? normzoo::exponents_in_range(normzoo::declared_grid(p), m.n_lo, m.n_hi)
                                 : normzoo::declared_grid(p);
        });
        auto groups = normzoo::energy_summary(points, jobs, es);
        // In a scene a gain fails the run unless the scene allows it.
        if (!s.allow_energy_gain)
            for (auto& g : groups) g.trusted = g.trusted && !g.gains;
        auto rows_m = normzoo::energy_records(points);
        auto sum_m = normzoo::energy_summary_table(groups);
        for (auto& r : sum_m) r.fields.insert(r.fields.begin(), {"material", m.name});
        for (auto& r : rows_m) r.fields.insert(r.fields.begin(), {"material", m.name});
        sweep.insert(sweep.end(), rows_m.begin(), rows_m.end());
        summary.insert(summary.end(), sum_m.begin(), sum_m.end());
        if (m.normalization && !normzoo::with_zoo_brdf(m.model, [](auto) {})) {
            skipped.push_back({"shader-normalization: " + m.name,
                               "model " + m.model + " has no zoo constant for a shader expression to replace"});
        } else if (m.normalization) {
            normzoo::shader_normalization_verdict v{};
            normzoo::albedo_settings as{s.albedo, normzoo::albedo_settings{}.max_panels};
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
                .set("pass", v.trusted && std::abs(v.max_rel_error) <= s.normalization &&
                                 (v.conserving || s.allow_energy_gain));
            shader.push_back(std::move(r));
        }
    }
    if (!sweep.empty()) {
        out.push_back({normzoo::energy_info(normzoo::doubles_of(angles), normzoo::energy_settings{s.albedo, 1}), std::move(sweep),
                       head + ", each material over its range", command});
        auto info = normzoo::energy_summary_info();
        info.settings.push_back(s.allow_energy_gain ? "the scene allows energy gain: a gain is reported, not failed"
                                                    : "in a scene a form that gains energy fails (pass = false); "
                                                      "[tolerance] allow_energy_gain = true makes it a finding only");
        info.md_columns.insert(info.md_columns.begin(), "material");
        out.push_back({info, std::move(summary), head, command});
        out.back().verdict = [allow = s.allow_energy_gain](const record& r) { return energy_summary_verdict(r, allow); };
    } else {
        skipped.push_back({"energy", "no material is a BRDF form"});
    }
    if (!shader.empty()) {
        out.push_back({normzoo::shader_normalization_info(), std::move(shader), head, command});
        out.back().verdict = [tolerance = s.normalization, allow = s.allow_energy_gain](const record& r) {
            return shader_normalization_verdict(r, tolerance, allow);
        };
    } else {
        skipped.push_back({"shader-normalization", "no material gives a normalization expression"});
    }

    // Microfacet compositions: E(mu, alpha) over each material's roughness range at its F0 (the
    // compensations' white furnace with it), and the baked table it names, checked.
    std::vector<record> comp;
    std::optional<normzoo::table_info> comp_info;
    std::vector<table_output> lut_checks;
    for (const auto& m : s.materials) {
        if (!m.composition) continue;
        std::vector<roughness_input> rough;
        for (const auto& x : roughness_samples(m.rough_lo, m.rough_hi)) rough.push_back({x, m.rough_is_r});
        std::vector<incidence_input> mus;
        for (const char* mu : {"1e-4", "0.01", "0.1", "0.3", "0.5", "0.7", "0.9", "1"}) mus.push_back({normzoo::decimal(mu), false});
        auto t = composition_energy_table({m.model}, rough, mus, m.parts, jobs);
        for (auto& r : t.records) {
            r.table = "microfacet-energy";
            r.fields.insert(r.fields.begin(), {"material", m.name});
            // a composition that gains energy fails, unless the scene allows it
            const normzoo::field_value* conserving = r.find("conserving");
            if (!r.find("pass")) r.set("pass", (conserving && std::get<bool>(*conserving)) || s.allow_energy_gain);
        }
        if (!comp_info) comp_info = t.info;
        comp.insert(comp.end(), t.records.begin(), t.records.end());
        if (!m.lut_path.empty()) {
            table_output check;
            try {
                check = check_lut_file(m.lut_path, m.lut_kind, m.model, m.parts, m.lut_map_r, std::nullopt, jobs);
            } catch (const bad_input& e) {  // the table's own message, at the scene's line that names it
                throw bad_input(m.lut_place + ": " + e.what());
            }
            for (auto& r : check.records) r.fields.insert(r.fields.begin(), {"material", m.name});
            check.parameters = head + ", material " + m.name;
            check.command = command;
            lut_checks.push_back(std::move(check));
        }
    }
    if (comp_info) {
        comp_info->name = "microfacet-energy";
        comp_info->md_columns.insert(comp_info->md_columns.begin(), "material");
        out.push_back({*comp_info, std::move(comp), head + ", each composition over its roughness range", command});
        for (auto& c : lut_checks) out.push_back(std::move(c));
    } else {
        skipped.push_back({"microfacet-energy", "no material is a microfacet composition"});
    }

    // BRDFs given as code: each material's file over its parameters (docs/brdf-code.md).
    std::vector<table_output> code_tables;
    for (const auto& m : s.materials) {
        if (!m.code()) continue;
        brdf_request q;
        q.file = m.brdf_path;
        q.shown_file = m.brdf_written;
        q.material = m.name;
        q.command = command;
        q.params = m.brdf_params;
        auto tables = brdf_tables(q, true);
        for (std::size_t k = 0; k < tables.size(); ++k) {
            for (auto& r : tables[k].records) {
                // a gain is a finding only where the scene allows it
                const normzoo::field_value* conserving = r.find("conserving");
                if (s.allow_energy_gain && conserving && std::holds_alternative<bool>(*conserving) && !std::get<bool>(*conserving))
                    for (auto& [key, value] : r.fields)
                        if (key == "pass")
                            value = r.text("values") == "reflectance" && !std::get<bool>(*r.find("fp32_breakdown"));
            }
            if (code_tables.size() <= k) {
                tables[k].info.md_columns.insert(tables[k].info.md_columns.begin(), "material");
                tables[k].parameters = head + ", each material given as code over its parameters";
                code_tables.push_back(std::move(tables[k]));
            } else {
                for (auto& r : tables[k].records) code_tables[k].records.push_back(std::move(r));
            }
        }
    }
    if (code_tables.empty()) skipped.push_back({"brdf, brdf-checks", "no material is given as code (brdf = \"file\")"});
    for (auto& t : code_tables) out.push_back(std::move(t));

    // Irradiance: each light at its size, over its tilt range.
    std::vector<record> irr;
    for (const auto& l : s.lights) {
        const auto kind = l.type == "sphere" ? normzoo::light_kind::sphere : normzoo::light_kind::disk;
        auto rows_l = normzoo::irradiance_table({kind}, {ratio_of(l)}, tilts_for(l), jobs);
        for (auto& r : rows_l) r.fields.insert(r.fields.begin(), {"light_name", l.name});
        irr.insert(irr.end(), rows_l.begin(), rows_l.end());
    }
    if (!irr.empty()) {
        auto info = normzoo::irradiance_infos({})[0];
        info.md_pivot.reset();
        info.md_columns.insert(info.md_columns.begin(), "light_name");
        out.push_back({info, std::move(irr), head + ", each light at its r0/r", command});
    } else {
        skipped.push_back({"irradiance", "the scene has no lights"});
    }
    skipped.push_back({"irradiance-limit", "the limit r0/r -> 0 is the default table's; a scene's light has one size"});
    skipped.push_back({"punctual-limit", "the punctual-light limit does not depend on a scene"});
    skipped.push_back({"zoo-constants, gloss-8bit", "the scene's own expressions are checked in shader-normalization"});
    skipped.push_back({"energy-claims, fresnel-visibility, energy-montecarlo", "the seeds' claims and the method's "
                                                                               "cross-checks do not depend on a scene"});
    skipped.push_back({"shader-precision", "the fp16 / fp32 audit of shader formulas does not depend on a scene"});
    return out;
}

}  // namespace verify
