// libFuzzer harness of --brdf's --param values (src/verify/brdf_parameters.cpp; docs/brdf-code.md,
// "Parameters"): bytes -> the first picks --steps (2 to 257), the rest, one --param text a line
// -> parameter_grid over a file that declares a float, a bool, a color and a float of the whole
// range. It must return or throw bad_input naming the option; anything else is a finding, and so
// is an accepted grid that breaks the contract: every value in its parameter's range, a bool 0 or
// 1 shown as true or false, a color three channels >= 0, each value's text reading back as it, a
// range's values in order from the double nearest LO to the double nearest HI.
// A line that starts with "texture " is a --texture value instead (brdf_textures.hpp), and one
// that starts with "layout " a --layout text as --texture reads it: each must be accepted or
// throw bad_input naming its option; an accepted --texture splits at its first '=' into a name
// of letters, digits and '_' and a file that is not empty, no name twice.
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "args.hpp"
#include "brdf_parameters.hpp"
#include "brdf_textures.hpp"
#include "layout_names.hpp"

namespace {

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "param_fuzzer: %s\n", what.c_str());
    std::abort();
}

verify::shader_source declared() {
    using kind = verify::shader_parameter::kind;
    verify::shader_source s;
    s.path = "fuzz.glsl";
    s.parameters = {{kind::real, "k", -1, 1, {0.5}, 2},
                    {kind::boolean, "flag", 0, 1, {0}, 3},
                    {kind::color, "tint", 0, HUGE_VAL, {1, 0.5, 0.25}, 4},
                    {kind::real, "wide", -1e300, 1e300, {0}, 5}};
    return s;
}

void check_values(const verify::parameter_values& g, const std::string& given) {
    using kind = verify::shader_parameter::kind;
    const auto& p = *g.p;
    if (g.values.empty() || g.values.size() != g.texts.size()) finding("values and their texts differ in number");
    for (std::size_t i = 0; i < g.values.size(); ++i) {
        const auto& v = g.values[i];
        if (v.size() != p.slots()) finding("a value with the wrong number of slots");
        if (p.type == kind::boolean) {
            if (!(v[0] == 0 || v[0] == 1) || g.texts[i] != (v[0] != 0 ? "true" : "false")) finding("a bool that is not 0 or 1 as shown");
        } else if (p.type == kind::color) {
            for (double c : v)
                if (!(c >= 0) || !std::isfinite(c)) finding("a color channel below 0 or not finite");
        } else {
            if (!(v[0] >= p.min && v[0] <= p.max)) finding("a value outside its range: " + given);
            if (std::strtod(g.texts[i].c_str(), nullptr) != v[0]) finding("a text that does not read back as its value: " + g.texts[i]);
            if (i > 0 && given.find("..") != std::string::npos && !(g.values[i - 1][0] <= v[0])) finding("a range out of order: " + given);
        }
    }
}

// The --texture and --layout lines, through their parsers.
void check_texture_lines(const std::vector<std::string>& textures, const std::vector<std::string>& layouts) {
    try {
        const auto bound = verify::parse_texture_options(textures);
        if (bound.size() != textures.size()) finding("a --texture value lost or added");
        for (std::size_t i = 0; i < bound.size(); ++i) {
            const auto& b = bound[i];
            if (textures[i] != b.name + "=" + b.file) finding("a --texture value not split at its first '=': " + textures[i]);
            if (b.name.empty() || b.file.empty()) finding("an empty name or file accepted");
            for (char c : b.name)
                if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') finding("a name that is no identifier: " + b.name);
            for (std::size_t j = 0; j < i; ++j)
                if (bound[j].name == b.name) finding("a name bound twice: " + b.name);
        }
    } catch (const verify::bad_input& e) {
        if (std::string(e.what()).rfind("--texture", 0) != 0) finding(std::string("a message that does not name --texture: ") + e.what());
    }
    for (const auto& l : layouts) {
        try {
            for (const auto& [key, value] : verify::parse_texture_layout(l))
                if (key == "rows" || key == "cols" || key == "grid" || key == "channels" || (key == "encoding" && value == "rgbd"))
                    finding("a layout key a sampler does not read, accepted: " + key);
        } catch (const verify::bad_input& e) {
            if (std::string(e.what()).rfind("--brdf: --layout", 0) != 0) finding(std::string("a message that does not name --layout: ") + e.what());
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::size_t steps = 2 + data[0];
    std::vector<std::string> params;
    std::string line;
    for (std::size_t i = 1; i < size; ++i) {
        const char c = static_cast<char>(data[i]);
        if (c == '\n') params.push_back(line), line.clear();
        else line += c;
    }
    params.push_back(line);
    std::vector<std::string> textures, layouts;
    for (auto p = params.begin(); p != params.end();) {
        if (p->rfind("texture ", 0) == 0) textures.push_back(p->substr(8)), p = params.erase(p);
        else if (p->rfind("layout ", 0) == 0) layouts.push_back(p->substr(7)), p = params.erase(p);
        else ++p;
    }
    try {
        check_texture_lines(textures, layouts);
    } catch (const std::exception& e) {
        finding(std::string("an exception that is not bad_input: ") + e.what());
    }
    static const verify::shader_source s = declared();
    try {
        const auto grid = verify::parameter_grid(s, params, steps);
        if (grid.size() != s.parameters.size()) finding("a grid without every parameter");
        for (const auto& g : grid) {
            std::string given;
            for (const auto& p : params)
                if (p.rfind(g.p->name + "=", 0) == 0) given = p.substr(g.p->name.size() + 1);
            check_values(g, given);
            const std::size_t dots = given.find("..");
            if (dots == std::string::npos) continue;
            if (g.values.size() != steps) finding("a range not in --steps values");
            if (g.values.front()[0] != std::strtod(given.substr(0, dots).c_str(), nullptr) ||
                g.values.back()[0] != std::strtod(given.substr(dots + 2).c_str(), nullptr))
                finding("a range that does not run from the double nearest LO to the double nearest HI: " + given);
        }
    } catch (const verify::bad_input& e) {
        if (std::string(e.what()).rfind("--param ", 0) != 0) finding(std::string("a message that does not name --param: ") + e.what());
    } catch (const std::exception& e) {
        finding(std::string("an exception that is not bad_input: ") + e.what());
    }
    return 0;
}
