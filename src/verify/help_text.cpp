#include "help_text.hpp"

namespace verify {

std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
}

const std::vector<std::pair<std::string, std::string>>& table_aliases() {
    static const std::vector<std::pair<std::string, std::string>> aliases = {{"models", "energy"}};
    return aliases;
}

std::string help_head(const std::vector<std::string>& tables, const std::vector<std::string>& named_only) {
    const std::string defaults =
        named_only.empty() ? "all" : "all but " + joined(named_only) + ", which run only when named";
    std::string aliases;
    for (const auto& [old_name, name] : table_aliases()) aliases += "; " + old_name + ": an old name of " + name;
    return "normzoo verify: numeric verification of shading-model normalization and energy.\n"
           "Tables: " + joined(tables) + " (default: " + defaults + aliases +
           "). --brdf FILE checks a BRDF given as shader code instead (docs/brdf-code.md; its options below say --brdf). "
           "Exit: 0 all checks hold, 1 a check fails, 2 bad input (docs/reference.md).";
}

std::string help_examples(const std::string& command) {
    return "Examples:\n"
           "  " + command + "                                  every default table, written to results/\n"
           "  " + command + " zoo --n 3,0.37                   two exponents; prints a summary, writes nothing\n"
           "  " + command + " zoo --n 3,0.37 --out /tmp/zoo    the same, tables written to /tmp/zoo\n"
           "  " + command + " energy --model ward,disney-diffuse --theta 0,60,89.9 --json\n"
           "  " + command + " energy --model ggx/smith-height-correlated/one --r 0.5 --mu 0.1,1 --json\n"
           "  " + command + " lut --kind dfg --size 32 --format png16 --out /tmp/lut   (docs/lut.md: baked tables)\n"
           "  " + command + " lut --check engine_dfg.png --kind dfg       an engine's table checked\n"
           "  " + command + " --brdf examples/brdfs/ward.brdf --param alpha=0.1..0.5   a BRDF as shader code (docs/brdf-code.md)\n"
           "  " + command + " irradiance --light disk --ratio 1e-3,1e-300 --tilt 0,95\n"
           "  " + command + " audit --cases 50000 --seed 7\n"
           "  " + command + " --scene scenes/wet-street.toml\n"
           "  " + command + " --check --junit check.xml\n"
           "Reference: docs/command-line.md (every option); docs/reference.md (scenes, records, exit codes).";
}

}  // namespace verify
