// An engine's layout by name (lut_presets.hpp).
#include "lut_presets.hpp"

#include <algorithm>

#include "args.hpp"

namespace verify {

const lut_preset& preset_named(const std::string& name, lut_kind kind) {
    const auto& all = lut_presets();
    const auto it = std::find_if(all.begin(), all.end(), [&](const lut_preset& p) { return p.name == name; });
    if (it == all.end()) {
        std::string names;
        for (const auto& p : all) names += (names.empty() ? "" : ", ") + p.name;
        const std::string why = name == "eevee" ? "; EEVEE indexes its table by sqrt(1 - N.V), which no layout key expresses" : "";
        throw bad_input("lut: --preset: unknown engine '" + name + "' (presets: " + names + ")" + why);
    }
    if (it->kind != kind)
        throw bad_input("lut: --preset " + name + " is a table of --kind " + lut_kind_name(it->kind) + ", not " + lut_kind_name(kind));
    return *it;
}

}  // namespace verify
