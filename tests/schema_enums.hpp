// The enums of docs/schema/ that the registry determines, generated from it: the BRDF forms, the
// zoo rows, the NDFs, the models a scene may name and the composition ids D/G/F[/compensation]
// (JSON Schema has no grammar for them). test_schema compares each with the committed schema;
// tools/update-schemas writes them (docs/records.md).
#pragma once
#include <algorithm>
#include <string>
#include <tuple>
#include <stdexcept>
#include <vector>

#include <normzoo/microfacet/composition.hpp>
#include <normzoo/registry.hpp>

namespace normzoo_test {

struct schema_enum {
    std::string file;     // under docs/schema/
    std::string pointer;  // JSON pointer to the enum's array
    std::vector<std::string> ids;
};

template <class Ids>
std::vector<std::string> strings_of(const Ids& ids) {
    return {ids.begin(), ids.end()};
}

// Every composition the part lists make, in the parts' order, with each compensation.
inline std::vector<std::string> composition_ids() {
    namespace mf = normzoo::microfacet;
    auto names = [](auto parts) {
        std::vector<std::string> v;
        std::apply([&](auto... p) { (v.emplace_back(decltype(p)::id), ...); }, parts);
        return v;
    };
    std::vector<std::string> ids;
    for (const auto& d : names(mf::distribution_parts{}))
        for (const auto& g : names(mf::masking_parts{}))
            for (const auto& f : names(mf::fresnel_parts{}))
                for (const char* compensation : {"", "/kulla-conty", "/turquin", "/fdez-aguera"}) {
                    const std::string id = d + "/" + g + "/" + f + compensation;
                    try {
                        (void)mf::composition::parse(id);
                        ids.push_back(id);
                    } catch (const std::invalid_argument&) {
                        // a Smith G over a D without a closed-form Lambda
                    }
                }
    return ids;
}

inline std::vector<schema_enum> registry_enums() {
    const auto forms = strings_of(normzoo::brdf_ids());
    const auto rows = strings_of(normzoo::zoo_row_ids());
    std::vector<std::string> ndfs;
    normzoo::for_each_ndf([&](auto ndf) { ndfs.emplace_back(decltype(ndf)::id); });
    // What a scene's material or a shader normalization names: every form, then the zoo rows that are not forms.
    std::vector<std::string> models = forms;
    for (const auto& r : rows)
        if (std::find(models.begin(), models.end(), r) == models.end()) models.push_back(r);
    const std::string scene_model = "/properties/materials/items/properties/model/anyOf";
    std::vector<schema_enum> out = {{"scene.schema.json", scene_model + "/0/enum", models},
                                    {"scene.schema.json", scene_model + "/1/enum", composition_ids()},
                                    {"output.schema.json", "/$defs/shader-normalization/properties/model/enum", models}};
    for (const char* table : {"energy", "energy-montecarlo", "energy-summary", "punctual-limit"})
        out.push_back({"output.schema.json", std::string("/$defs/") + table + "/properties/model/enum", forms});
    for (const char* table : {"bounds", "enclosures", "zoo"})
        out.push_back({"output.schema.json", std::string("/$defs/") + table + "/properties/row/enum", rows});
    for (const char* table : {"ndf", "ndf-furnace"})
        out.push_back({"output.schema.json", std::string("/$defs/") + table + "/properties/ndf/enum", ndfs});
    return out;
}

}  // namespace normzoo_test
