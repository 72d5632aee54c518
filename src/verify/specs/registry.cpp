// The command's tables in the order a full run takes them: one line per table, its spec in the
// file of the same name beside this one.
#include "specs.hpp"

namespace verify {

const std::vector<table_spec>& table_specs() {
    static const std::vector<table_spec> list = {
        zoo_spec(),         bounds_spec(),     enclosures_spec(), proofs_spec(),     energy_spec(),
        microfacet_spec(),  irradiance_spec(), ndf_spec(),        shader_precision_spec(),
        brdf_code_spec(),   code_audit_spec(), stability_spec(),  audit_spec(),
    };
    return list;
}

const table_spec* find_table_spec(const std::string& name) {
    for (const auto& s : table_specs())
        if (name == s.name) return &s;
    return nullptr;
}

std::string grid_text(const options& o, const char* default_text) {
    return o.exponents.empty() ? std::string(default_text) : "n = " + o.exponents_text;
}

}  // namespace verify
