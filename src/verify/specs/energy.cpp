// energy: the directional albedo of every BRDF form at each value of its parameter, the seeds'
// claims, the F.V comparison, the Monte Carlo cross-check (docs/energy.md); with --model D/G/F,
// the energy of the compositions named (docs/microfacet.md).
#include "../table_spec.hpp"

#include <algorithm>

#include "../microfacet_tables.hpp"
#include "../plots.hpp"
#include "../tables/energy.hpp"
#include "../tables/energy_claims.hpp"
#include "../tables/fresnel_visibility.hpp"
#include "../tables/grid.hpp"
#include "../tables/montecarlo.hpp"

namespace verify {

namespace {

std::vector<std::string> all_brdf_ids() {
    std::vector<std::string> ids;
    for (auto id : normzoo::brdf_ids()) ids.emplace_back(id);
    return ids;
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

bool plot_energy(const table_output& t, file_set& files) {
    // the forms a zoo row normalizes by exponent, and the others by their parameter
    const auto [zoo_forms, other_forms] = split_energy_for_plots(t);
    bool drawn = true;
    if (!zoo_forms.records.empty()) drawn = plot_albedo(zoo_forms, files) && drawn;
    if (!other_forms.records.empty()) drawn = plot_models_energy(other_forms, files) && drawn;
    return drawn;
}

// The grid of compositions named with --model D/G/F where --alpha (or --r) and --mu are not given.
std::vector<decimal> default_composition_roughness() { return decimals({"0.01", "0.1", "0.3", "0.5", "1"}); }
std::vector<decimal> default_composition_mus() { return decimals({"1e-4", "0.01", "0.1", "0.5", "1"}); }

// Compositions named with --model D/G/F: one energy record per (model, roughness, incidence).
std::vector<table_output> composition_energy_tables(const options& o) {
    std::vector<roughness_input> roughness;
    for (const auto& x : o.roughness.empty() ? default_composition_roughness() : o.roughness)
        roughness.push_back({x, o.roughness_is_r});
    std::vector<incidence_input> incidence;
    if (!o.angles.empty())
        for (const auto& t : o.angles) incidence.push_back({t, true});
    else
        for (const auto& m : o.mus.empty() ? default_composition_mus() : o.mus) incidence.push_back({m, false});
    auto t = composition_energy_table(o.models, roughness, incidence, o.parts, o.jobs);
    t.parameters = std::string(o.roughness_is_r ? "r = " : "alpha = ") +
                   (o.roughness.empty() ? list_text(default_composition_roughness()) : o.roughness_text) +
                   (!o.angles.empty() ? ", theta = " + o.angles_text
                                      : ", mu = " + (o.mus.empty() ? list_text(default_composition_mus()) : o.mus_text)) +
                   (o.parts.f0 ? ", f0 = " + o.parts.f0->text() : std::string());
    for (const auto& q : part_parameters())
        if (o.parts.*q.input) t.parameters += std::string(", ") + q.name + " = " + (o.parts.*q.input)->text();
    return {std::move(t)};
}

// The grid in the head of the energy tables: each form's declared grid or the options given.
std::string energy_grid(const options& o, const std::vector<std::string>& models) {
    std::string grid = o.exponents.empty() ? "each form's declared grid (" + declared_grids_text() + ")"
                                           : "n = " + o.exponents_text + ", the other parameters at their grids";
    grid += o.angles.empty() ? ", angles " + list_text(default_energy_angle_inputs()) + " degrees"
                             : ", theta = " + o.angles_text;
    if (!o.models.empty()) {
        grid += ", models ";
        for (const auto& m : models) grid += m + (&m == &models.back() ? "" : ",");
    }
    return grid;
}

std::vector<table_output> energy_tables(const options& o) {
    if (!o.models.empty() && o.models.front().find('/') != std::string::npos) return composition_energy_tables(o);
    const auto angles = o.angles.empty() ? default_energy_angle_inputs() : o.angles;
    const auto models = o.models.empty() ? all_brdf_ids() : o.models;
    // Each form at each value of its declared grid (--n replaces the grid of the forms swept in n).
    const std::string grid = energy_grid(o, models);
    // The claims are about the seed's exponent forms: their grid is the exponents.
    std::string claims_grid = grid_text(o, "default exponents " + list_text(default_energy_exponents()));
    claims_grid += grid.substr(grid.find(", angles") != std::string::npos ? grid.find(", angles") : grid.find(", theta"));
    const std::string command = "./verify energy";
    const std::uint64_t samples = std::uint64_t(1) << 20;
    const energy_settings es;
    const auto sweep = o.exponents.empty() ? energy_sweep(models, angles, o.jobs, es)
                                           : energy_sweep(models, o.exponents, angles, o.jobs, es);
    const auto summary = energy_summary(sweep, o.jobs, es);
    auto claims = energy_claims(sweep, summary, es);
    const auto fv = fresnel_visibility_infos();
    std::vector<table_output> out;
    out.push_back({energy_info(doubles_of(angles)), energy_records(sweep), grid, command,
                   plot_energy});
    out.push_back({energy_summary_info(), energy_summary_table(summary), grid, command});
    out.push_back({energy_claims_info(), std::move(claims), claims_grid, command});
    const std::string fv_grid = compared_reflectances_text();
    out.push_back({fv[0], fresnel_visibility_table(), fv_grid, command,
                   plot_fresnel_visibility});
    out.push_back({fv[1], fresnel_visibility_summary(), fv_grid, command});
    out.push_back({fv[2], fresnel_visibility_albedo(o.jobs), fv_grid + "; n = " + list_text(compared_exponents()), command});
    out.push_back({monte_carlo_info(samples), monte_carlo_table(models, samples, o.jobs),
                   "one case per form selected", command});
    return out;
}

// The options the energy table reads: the zoo's and forms' grids, and a composition's inputs.
std::vector<std::string> energy_options() {
    std::vector<std::string> reads = {"--n", "--theta", "--model", "--alpha", "--r", "--mu", "--f0"};
    for (const auto& q : part_parameters()) reads.push_back(std::string("--") + q.name);
    return reads;
}

}  // namespace

table_spec energy_spec() {
    return {"energy",
            "directional albedo of every BRDF form (the seed's exponent forms, Ward, Ashikhmin-Shirley, "
            "Disney diffuse) at each value of its parameter against incident angle; the seeds' claims; the "
            "seed's F.V comparison; Monte Carlo cross-check",
            energy_options(), energy_tables};
}

}  // namespace verify
