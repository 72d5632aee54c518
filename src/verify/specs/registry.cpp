// The command's tables in the order a full run takes them: a table is its spec, the file of its
// name beside this one, and its two lines here.
#include "../table_spec.hpp"

namespace verify {

// Each defined in the file of its name.
table_spec zoo_spec();
table_spec bounds_spec();
table_spec enclosures_spec();
table_spec proofs_spec();
table_spec energy_spec();
table_spec microfacet_spec();
table_spec material_blend_spec();
table_spec material_furnace_spec();
table_spec irradiance_spec();
table_spec ndf_spec();
table_spec shader_precision_spec();
table_spec brdf_code_spec();
table_spec code_audit_spec();
table_spec stability_spec();
table_spec audit_spec();
table_spec lut_spec();
table_spec brdf_file_spec();
table_spec material_spec();

const std::vector<table_spec>& table_specs() {
    static const std::vector<table_spec> list = {
        zoo_spec(),         bounds_spec(),     enclosures_spec(), proofs_spec(),     energy_spec(),
        microfacet_spec(),  material_blend_spec(), material_furnace_spec(), irradiance_spec(), ndf_spec(),        shader_precision_spec(),
        brdf_code_spec(),   code_audit_spec(), stability_spec(),  audit_spec(),
        lut_spec(),         brdf_file_spec(),    material_spec(),
    };
    return list;
}

const table_spec* find_table_spec(const std::string& name) {
    for (const auto& s : table_specs())
        if (name == s.name) return &s;
    return nullptr;
}

std::string grid_text(const options& o, const std::string& default_text) {
    return o.exponents.empty() ? default_text : "n = " + o.exponents_text;
}

}  // namespace verify
