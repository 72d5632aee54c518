// --texture's table read (brdf_textures.hpp): the file through lut's readers under the layout's
// keys, its texels as a sampler sees them, each with its storage's two ends.
#include <algorithm>
#include <filesystem>

#include "args.hpp"
#include "brdf_textures.hpp"

namespace verify {

namespace {

// The file as lut's reader gives it, with size=WxH applied (the same texels, row by row).
decoded_lut read_file(const texture_option& t, const lut_reading& reading) {
    const std::string ext = std::filesystem::path(t.file).extension().string();
    if (ext == ".csv" || ext == ".json" || ext == ".CSV" || ext == ".JSON")
        throw bad_input(t.file + ": a " + ext.substr(1) + " table holds points, which lut --check compares, not the image a sampler "
                        "reads: bind a PNG, OpenEXR, KTX2, DDS or Radiance HDR file, or a source file's array");
    // A sampler decodes a KTX2 or DDS sRGB format itself: lut's reader lets one through when the
    // layout names no encoding (as for --detect), and read_texture decodes it. --detect would
    // also let a file of another orientation through, which a GPU's upload does not turn over.
    lut_reading r = reading;
    r.detect = reading.stated.count("encoding") == 0;
    decoded_lut d = read_laid_out(t.file, r, lut_kind::dfg);
    const std::string& o = d.orientation;
    if (o.size() == 2 && ((o[1] == 'u' && !reading.stated.count("row0")) || (o[0] == 'l' && !reading.stated.count("col0"))))
        throw bad_input(t.file + ": KTXorientation '" + o + "': a GPU's sampler takes the first stored row as v = 0 and the first "
                        "column as u = 0 (rd), and a loader that honours the orientation turns it over: --layout row0= and col0= "
                        "say where v = 0 and u = 0 are");
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
    if (reading.layout.slices > 1)
        throw bad_input("--texture " + t.name + ": size=" + std::to_string(reading.layout.width) + "x" + std::to_string(reading.layout.height) +
                        "x" + std::to_string(reading.layout.slices) + ": a texture is one table of W x H texels (size=WxH)");
    reading.given = layout;
    for (const auto& k : layout) reading.stated.insert(k.first);
    lut_layout l = reading.layout;
    decoded_lut d;
    try {
        d = read_file(t, reading);
    } catch (const bad_input& e) {
        throw bad_input("--texture " + t.name + ": " + e.what());
    }
    if (!reading.stated.count("encoding") && sampled_as_srgb(d)) l.encoding = lut_encoding::srgb;  // as its sampler decodes it
    // Each texel is held nine times (the three tables here; each program's three bound copies in
    // double and float): a million texels cost about 250 MB, lut's largest (4096^2) 4 GB.
    if (d.image.width * d.image.height > max_texture_texels)
        throw bad_input("--texture " + t.name + ": " + t.file + " is " + std::to_string(d.image.width) + " x " +
                        std::to_string(d.image.height) + " texels; --texture binds at most " + std::to_string(max_texture_texels) +
                        " (1024 x 1024), as it holds the table several times over (docs/brdf-code.md#textures)");
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
