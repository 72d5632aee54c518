#include "brdf_textures.hpp"

#include <algorithm>
#include <cctype>

#include "args.hpp"

namespace verify {

namespace {

// A value as a message shows it: control bytes as '?', at most 80 characters.
std::string shown(const std::string& text) {
    std::string s = text.substr(0, 80);
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    return text.size() > 80 ? s + "..." : s;
}

}  // namespace

texture_option parse_texture_option(const std::string& text) {
    const std::size_t eq = text.find('=');
    const std::string name = text.substr(0, eq);
    const bool identifier = !name.empty() && name.size() <= 256 && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                            std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
    if (eq == std::string::npos || !identifier || eq + 1 == text.size())
        throw bad_input("--texture: '" + shown(text) + "' is not NAME=FILE (the name of the code's sampler2D or Texture2D, then the "
                        "table's file: --texture dfg=dfg.png)");
    return {name, text.substr(eq + 1)};
}

std::vector<texture_option> parse_texture_options(const std::vector<std::string>& given) {
    std::vector<texture_option> out;
    for (const auto& g : given) {
        texture_option t = parse_texture_option(g);
        for (const auto& o : out)
            if (o.name == t.name) throw bad_input("--texture: " + t.name + " is bound twice (" + o.file + ", " + t.file + ")");
        out.push_back(std::move(t));
    }
    return out;
}

layout_keys parse_texture_layout(const std::string& text) {
    const layout_keys keys = parse_layout_keys(text, "--brdf: --layout");
    for (const auto& [key, value] : keys) {
        if (key == "rows" || key == "cols" || key == "grid" || key == "channels")
            throw bad_input("--brdf: --layout: " + key + " says what a table's texels mean to lut --check; a shader's sampler reads "
                            "them as stored, so only row0, col0, encoding and size apply to --texture (docs/brdf-code.md#textures)");
        if (key == "encoding" && value == "rgbd")
            throw bad_input("--brdf: --layout: encoding=rgbd is decoded by the shader's own code, after the sampler has filtered "
                            "the stored values: bind the table as stored and decode it in the shader (docs/brdf-code.md#textures)");
    }
    return keys;
}

}  // namespace verify
