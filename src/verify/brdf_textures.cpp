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

namespace {

// The file as lut's reader gives it, with size=WxH applied (the same texels, row by row).
decoded_lut read_file(const texture_option& t, const lut_reading& reading) {
    decoded_lut d = read_laid_out(t.file, reading, lut_kind::dfg);
    const lut_layout& l = reading.layout;
    if (l.width) {
        if (l.width * l.height != d.image.width * d.image.height)
            throw bad_input(t.file + ": size=" + std::to_string(l.width) + "x" + std::to_string(l.height) + " is " +
                            std::to_string(l.width * l.height) + " texels; the file holds " +
                            std::to_string(d.image.width * d.image.height));
        d.image.width = l.width, d.image.height = l.height;
    }
    return d;
}

}  // namespace

texture_table read_texture(const texture_option& t, const layout_keys& layout) {
    lut_reading reading;
    apply_layout_keys(reading.layout, layout);
    reading.given = layout;
    for (const auto& k : layout) reading.stated.insert(k.first);
    const lut_layout& l = reading.layout;
    decoded_lut d;
    try {
        d = read_file(t, reading);
    } catch (const bad_input& e) {
        throw bad_input("--texture " + t.name + ": " + e.what());
    }
    texture_table out;
    out.name = t.name, out.file = t.file, out.format = d.format;
    out.width = d.image.width, out.height = d.image.height;
    const std::size_t n = out.width * out.height;
    out.rgba.assign(4 * n, 0.0), out.low.assign(4 * n, 0.0), out.high.assign(4 * n, 0.0);
    for (std::size_t j = 0; j < out.height; ++j)
        for (std::size_t i = 0; i < out.width; ++i) {
            // v = 0 at the row the layout calls the low end: the first stored row unless row0=high
            const std::size_t row = l.row0 == lut_origin::low ? j : out.height - 1 - j;
            const std::size_t col = l.col0 == lut_origin::low ? i : out.width - 1 - i;
            const std::size_t texel = row * d.image.width + col, at = 4 * (j * out.width + i);
            for (std::size_t c = 0; c < 4; ++c) {
                stored_value s{c == 3 ? 1.0 : 0.0, 0.0};  // a channel the file lacks, as a GPU fills it
                if (c < d.image.channels) s = decode_texel(d, l.encoding, texel, c);
                out.rgba[at + c] = s.value, out.low[at + c] = s.value - s.tolerance, out.high[at + c] = s.value + s.tolerance;
                out.largest_step = std::max(out.largest_step, s.tolerance);
            }
        }
    return out;
}

}  // namespace verify
