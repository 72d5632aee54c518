// An engine's layout by name (lut_presets.hpp).
#include "lut_presets.hpp"

#include <algorithm>

#include "args.hpp"

namespace verify {

namespace {
// num/den < 1 to 20 places by long division (cut, not rounded: within 1e-20 of the fraction),
// without trailing zeros
std::string places_of(long num, long den) {
    std::string s = "0.";
    for (int k = 0; k < 20; ++k, num %= den) s += char('0' + (num *= 10) / den);
    return s.substr(0, s.find_last_not_of('0') + 1);
}
}  // namespace

std::string openpbr_bsdf_eta_axis() {
    std::string s;
    for (int i = 0; i < 32; ++i) {
        std::string v;
        if (i == 15) v = places_of(10000, 10001);  // 1/1.0001
        else if (i == 16) v = "1.0001";
        else if (i < 16) v = places_of(10, 25 - i);
        else v = std::to_string((i - 6) / 10) + "." + std::to_string((i - 6) % 10);  // 1 + (i - 16)/10
        s += (s.empty() ? "" : ",") + v;
    }
    return s;
}

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
