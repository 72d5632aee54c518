// irradiance: sphere and disk lights against their closed forms, the point light as r0/r -> 0,
// and the punctual-light limit of every BRDF form (docs/irradiance.md).
#include "../table_spec.hpp"

#include "../plots.hpp"
#include "../tables/grid.hpp"
#include "../tables/irradiance.hpp"

namespace verify {

namespace {

// The forms a zoo row normalizes: the punctual limit's default (its table was built for them).
std::vector<std::string> zoo_brdf_ids() {
    std::vector<std::string> ids;
    for (auto id : normzoo::zoo_brdf_ids()) ids.emplace_back(id);
    return ids;
}

std::vector<table_output> irradiance_tables(const options& o) {
    std::vector<normzoo::light_kind> lights;
    for (const auto& l : o.lights.empty() ? std::vector<std::string>{"sphere", "disk"} : o.lights)
        lights.push_back(l == "sphere" ? normzoo::light_kind::sphere : normzoo::light_kind::disk);
    const auto ratios = o.ratios.empty() ? default_irradiance_ratios() : o.ratios;
    const auto tilts = o.tilts.empty() ? default_irradiance_tilts() : o.tilts;
    std::string grid = o.ratios.empty() ? "ratios " + list_text(ratios) : "ratio = " + o.ratios_text;
    grid += o.tilts.empty() ? ", tilts " + list_text(tilts) + " degrees" : ", tilt = " + o.tilts_text;
    if (!o.lights.empty()) grid += ", lights " + o.lights.front() + (o.lights.size() > 1 ? "," + o.lights.back() : "");
    const auto models = o.models.empty() ? zoo_brdf_ids() : o.models;
    const auto infos = irradiance_infos(doubles_of(ratios));
    const auto points = irradiance_points(lights, ratio_inputs(ratios), tilts, o.jobs);
    auto rows = irradiance_table(points);
    auto limit = irradiance_limit_table(irradiance_limit_summary(points));
    const std::string command = "./verify irradiance";
    std::vector<table_output> out;
    out.push_back({infos[0], std::move(rows), grid, command});
    out.push_back({infos[1], std::move(limit), grid, command});
    // irradiance-limit.svg draws from this table and the first: it keeps a copy of those rows.
    out.push_back({infos[2], punctual_table(models, punctual_exponent, o.jobs), punctual_grid_text(), command,
                   [irradiance = out[0].records](const table_output& punctual, file_set& files) {
                       return plot_limits(irradiance, punctual, files);
                   }});
    return out;
}

}  // namespace

table_spec irradiance_spec() {
    return {"irradiance",
            "sphere and disk lights against their closed forms and the point light as r0/r -> 0; the "
            "punctual-light limit of every BRDF form",
            {"--model", "--light", "--ratio", "--tilt"}, irradiance_tables};
}

}  // namespace verify
