// A table written as an engine loads it (lut_write.hpp): what each format holds, the texels'
// points in a layout, the exact values there with the pair's limits at the edges, and the texels
// as the file stores them.
#include "lut_write.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "args.hpp"
#include "lut_formats/dds.hpp"
#include "lut_formats/exr.hpp"
#include "lut_formats/ktx2.hpp"
#include "lut_formats/png.hpp"
#include "lut_formats/texels.hpp"

namespace verify {

namespace mf = normzoo::microfacet;

namespace {

bool is_ktx2_or_dds(const std::string& format) { return format == "ktx2" || format == "ktx2-zstd" || format == "dds"; }
bool is_records(const std::string& format) { return format == "csv" || format == "json"; }

// The encodings each format holds (docs/lut.md, "Formats"): a PNG stores 8- or 16-bit codes (what
// a sampler of them decodes: linear, sRGB, RGBD; codes of as many bits or fewer); OpenEXR and a C
// header store numbers (half, and codes their significand tells apart: a half's 11 bits hold
// 8- and 10-bit codes, not 16-bit ones); a KTX2 or DDS either, in the VkFormat or DXGI format
// chosen for it; a CSV or JSON the records, the exact values with their bounds.
std::vector<lut_encoding> held_by(const std::string& format) {
    using e = lut_encoding;
    if (format == "png8") return {e::linear, e::srgb, e::rgbd, e::unorm8};
    if (format == "png16") return {e::linear, e::srgb, e::rgbd, e::unorm8, e::unorm10, e::unorm16};
    if (format == "exr" || format == "h") return {e::linear, e::half, e::unorm8, e::unorm10, e::unorm16};
    if (format == "exr-half") return {e::linear, e::half, e::unorm8, e::unorm10};
    if (is_ktx2_or_dds(format)) return {e::linear, e::srgb, e::rgbd, e::half, e::unorm8, e::unorm10, e::unorm16};
    return {e::linear};
}

bool holds(const std::string& format, lut_encoding e) {
    const auto held = held_by(format);
    return std::find(held.begin(), held.end(), e) != held.end();
}

// Why format cannot hold e, for the refusal.
std::string why_not(const std::string& format, lut_encoding e) {
    if (is_records(format))
        return "a " + format + " holds the records, the exact values with their bounds, not values rounded to a storage";
    if (e == lut_encoding::srgb || e == lut_encoding::rgbd)
        return "encoding=" + encoding_name(e) + " stores 8- or 16-bit codes that a sampler decodes, which " + format + " does not hold";
    if (e == lut_encoding::half) return "a PNG stores 8- or 16-bit codes, not half floats";
    return format + " cannot tell " + encoding_name(e) + " codes apart";
}

// The channels the container stores for `stored` of them (docs/lut.md, "Formats").
std::size_t container_channels(const std::string& format, lut_encoding e, std::size_t stored) {
    if (format == "png8") return 4;  // RGBA, as the glTF sample viewer's table
    if (is_ktx2_or_dds(format) && (e == lut_encoding::srgb || stored == 3)) return 4;  // no RGB formats but half's (KTX2)
    return stored;
}

// How a KTX2 or DDS stores values of encoding e: float for linear, unorm16 for 10-bit codes.
value_encoding container_encoding(lut_encoding e) {
    switch (e) {
        case lut_encoding::half: return value_encoding::half;
        case lut_encoding::unorm10:
        case lut_encoding::unorm16: return value_encoding::unorm16;
        case lut_encoding::linear: return value_encoding::float32;
        default: return value_encoding::unorm8;  // unorm8, srgb, rgbd
    }
}

// Whether the texels at r = 0 and mu = 0 that w's grid=edges reaches have values: the split-sum
// pair's limits where split_sum_to derives them (Smith's G at alpha = 0, GGX with Smith's G up to
// alpha = 1 at mu = 0: the corner, (0, 1) and (1, 0) stand for every edge texel, docs/lut.md,
// "Edges"), and E and E_avg there as A + B, at F = one uncompensated. Texel centres and
// Filament's rows never reach an edge.
void check_edges(const lut_writing& w, lut_kind kind, const mf::composition& c) {
    if (w.layout.grid != lut_spacing::edges) return;
    const std::string what = "lut: " + w.named("grid") + " places texels at r = 0 and mu = 0";
    const bool f_one = c.f_part == mf::detail::index_of<mf::fresnel_parts>("one");
    if (kind != lut_kind::dfg && (!f_one || c.compensation != mf::composition::compensation_kind::none))
        throw bad_input(what + ", where " + c.id + "'s " + (kind == lut_kind::e ? "E" : "E_avg") +
                        " has no limit derived (E = A + B there needs F = one, no compensation: docs/lut.md, \"Edges\")");
    const std::vector<std::pair<double, double>> probes =  // (mu, alpha)
        kind == lut_kind::eavg ? std::vector<std::pair<double, double>>{{1, 0}} : std::vector<std::pair<double, double>>{{0, 0}, {0, 1}, {1, 0}};
    for (const auto& [mu, alpha] : probes)
        if (!pair_has_limit(c, mu, alpha))
            throw bad_input(what + ", where the split-sum pair of " + c.id + " has no limit derived (at mu = " + detail::format_number(mu) +
                            ", alpha = " + detail::format_number(alpha) + "; Smith's two G, and GGX at mu = 0: docs/lut.md, \"Edges\")");
}

// The sRGB transfer, encoded (IEC 61966-2-1), of a value clamped to [0, 1].
double srgb_encode(double v) {
    v = std::clamp(v, 0.0, 1.0);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}

double unorm(double v, double steps) { return double(std::lround(std::clamp(v, 0.0, 1.0) * steps)) / steps; }

// Babylon.js's toRGBD (packages/dev/core/src/Shaders/ShadersInclude/helperFunctions.fx): D =
// saturate(floor(max(255 / max(rgb, 1e-7), 1)) / 255), rgb = saturate((rgb D)^(1/2.2)); D in the
// fourth channel, a whole 8-bit code.
void to_rgbd(std::vector<double>& v) {
    const double most = std::max({v[0], v[1], v[2], 1e-7});
    const double d = std::clamp(std::floor(std::max(255 / most, 1.0)) / 255, 0.0, 1.0);
    for (std::size_t k = 0; k < 3; ++k) v[k] = std::clamp(std::pow(std::max(v[k] * d, 0.0), 1 / 2.2), 0.0, 1.0);
    v[3] = d;
}

// The first n values of a texel as the encoding stores them (rgbd: all four).
void encode_texel(lut_encoding e, std::vector<double>& v, std::size_t n) {
    if (e == lut_encoding::rgbd) return to_rgbd(v);
    for (std::size_t k = 0; k < n; ++k) {
        double& x = v[k];
        if (e == lut_encoding::half) x = half_to_double(double_to_half(x));
        else if (e == lut_encoding::unorm8) x = unorm(x, 255);
        else if (e == lut_encoding::unorm10) x = unorm(x, 1023);
        else if (e == lut_encoding::unorm16) x = unorm(x, 65535);
        else if (e == lut_encoding::srgb && k < 3) x = srgb_encode(x);  // alpha stays linear
    }
}

// The value of a named channel at texel k of t: A, B, A+B, E, E_avg, 1-E, 1-E_avg.
double channel_value(const exact_table& t, const std::string& name, std::size_t k) {
    if (t.channels == 1) return name.rfind("1-", 0) == 0 ? 1 - t.values[k].value : t.values[k].value;
    const double a = t.values[2 * k].value, b = t.values[2 * k + 1].value;
    return name == "A" ? a : name == "B" ? b : a + b;
}

}  // namespace

const std::vector<std::string>& lut_formats() {
    static const std::vector<std::string> formats = {"csv", "json", "png8", "png16", "exr", "exr-half", "h", "ktx2", "ktx2-zstd", "dds"};
    return formats;
}

std::string lut_writing::named(const std::string& key) const {
    for (const auto& [k, v] : given)
        if (k == key) return "--layout " + k + "=" + v;
    for (const auto& [k, v] : preset_keys)
        if (k == key) return "--preset " + preset + " (" + k + "=" + v + ")";
    return "--layout " + key + " (its default)";
}

void check_lut_writing(const lut_writing& w, lut_kind kind, const std::string& format, bool writes_file, const mf::composition& c) {
    const lut_layout& l = w.layout;
    const auto channels = layout_channels(l, kind);
    if (writes_file && !holds(format, l.encoding)) {
        std::string which;
        for (const auto& f : lut_formats())
            if (holds(f, l.encoding)) which += (which.empty() ? "" : ", ") + f;
        throw bad_input("lut: --format " + format + " cannot hold " + w.named("encoding") + ": " + why_not(format, l.encoding) +
                        " (formats that hold it: " + which + ")");
    }
    if (writes_file && is_records(format) && channels != lut_channels(kind))
        throw bad_input("lut: --format " + format + " writes the records, whose values are named (" +
                        (kind == lut_kind::dfg ? "A and B" : lut_channels(kind).front()) + "): " + w.named("channels") +
                        " lays out an image's channels");
    // the check of a CSV reads no E or E_avg at r = 0 or mu = 0 (it compares none there)
    if (writes_file && format == "csv" && kind != lut_kind::dfg && l.grid == lut_spacing::edges)
        throw bad_input("lut: --format csv with " + w.named("grid") + ": its " + lut_channels(kind).front() +
                        " at r = 0 and mu = 0 is no point that --check reads back from a CSV; write json or an image");
    const std::size_t stored = l.encoding == lut_encoding::rgbd ? 4 : channels.size();
    if (writes_file && !is_records(format) && stored > 4)
        throw bad_input("lut: " + w.named("channels") + ": " + std::to_string(stored) + " channels; an image holds at most 4");
    const std::size_t rows = kind == lut_kind::eavg ? std::max(w.width, w.height) : w.height;
    if (l.grid == lut_spacing::edges && (rows < 2 || (kind != lut_kind::eavg && w.width < 2)))
        throw bad_input("lut: " + w.named("grid") + " places texel t of n at t/(n - 1): it needs two texels along each axis (the table is " +
                        std::to_string(w.width) + " x " + std::to_string(w.height) + ")");
    check_edges(w, kind, c);
}

lut_grid layout_grid(const lut_writing& w, lut_kind kind) {
    const lut_layout& l = w.layout;
    lut_grid g;
    if (kind == lut_kind::eavg) {  // one axis, rows, however the image holds it
        const std::size_t n = std::max(w.width, w.height);
        g.perceptual = l.rows == lut_axis::r;
        for (std::size_t j = 0; j < n; ++j) g.roughness.push_back(axis_coordinate(l.grid, true, l.row0, j, n));
        return g;
    }
    const bool rough_rows = is_roughness(l.rows);
    g.perceptual = (rough_rows ? l.rows : l.cols) == lut_axis::r;
    g.points = true;
    for (std::size_t j = 0; j < w.height; ++j)
        for (std::size_t i = 0; i < w.width; ++i) {
            const double ur = axis_coordinate(l.grid, rough_rows, l.row0, j, w.height);
            const double uc = axis_coordinate(l.grid, !rough_rows, l.col0, i, w.width);
            g.roughness.push_back(rough_rows ? ur : uc);
            g.mus.push_back(mu_of_coordinate(rough_rows ? l.cols : l.rows, rough_rows ? uc : ur));
        }
    return g;
}

exact_table laid_out_exact(lut_kind kind, const mf::composition& c, const lut_grid& g, unsigned jobs) {
    if (kind == lut_kind::dfg) return exact_lut(kind, c, g, jobs);  // split_sum_to takes the edges itself
    // E and E_avg where they are defined; at the edges A + B, the split-sum pair's limits there (at
    // alpha = 0, A + B = 1 at every mu: E_avg(0) is that)
    lut_grid inner = g, edges = g;
    inner.mus.clear(), inner.roughness.clear(), edges.mus.clear(), edges.roughness.clear();
    edges.points = true;
    std::vector<bool> at_edge;
    for (std::size_t k = 0; k < g.roughness.size(); ++k) {
        const double mu = kind == lut_kind::eavg ? 1 : g.mus[k];
        at_edge.push_back(!comparable_point(mu, g.alpha(k)));
        lut_grid& to = at_edge.back() ? edges : inner;
        to.roughness.push_back(g.roughness[k]);
        if (kind == lut_kind::e || at_edge.back()) to.mus.push_back(mu);
    }
    const exact_table in = inner.roughness.empty() ? exact_table{} : exact_lut(kind, c, inner, jobs);
    const exact_table pair = edges.roughness.empty() ? exact_table{} : exact_lut(lut_kind::dfg, c, edges, jobs);
    exact_table t;
    t.width = g.roughness.size(), t.height = 1, t.channels = 1;
    std::size_t next_in = 0, next_edge = 0;
    for (const bool edge : at_edge) {
        if (!edge) {
            t.values.push_back(in.values[next_in++]);
            continue;
        }
        const auto& a = pair.values[2 * next_edge], & b = pair.values[2 * next_edge + 1];
        t.values.push_back({a.value + b.value, a.abs_error + b.abs_error, a.evaluations + b.evaluations});
        ++next_edge;
    }
    return t;
}

lut_image stored_image(const exact_table& t, const lut_layout& l, lut_kind kind, const std::string& format) {
    const auto names = layout_channels(l, kind);
    const std::size_t stored = l.encoding == lut_encoding::rgbd ? 4 : names.size();
    lut_image im{t.width, t.height, container_channels(format, l.encoding, stored), {}};
    im.data.reserve(t.width * t.height * im.channels);
    std::vector<double> v(std::max<std::size_t>(im.channels, 4));
    for (std::size_t k = 0; k < t.width * t.height; ++k) {
        // what the layout does not name ("-", or a channel the container adds): 0, and an alpha 1
        // (opaque, as Godot writes its table's)
        std::fill(v.begin(), v.end(), 0.0);
        v[3] = 1;
        for (std::size_t c = 0; c < names.size(); ++c)
            if (names[c] != "-") v[c] = channel_value(t, names[c], k);
        encode_texel(l.encoding, v, names.size());
        im.data.insert(im.data.end(), v.begin(), v.begin() + std::ptrdiff_t(im.channels));
    }
    return im;
}

std::size_t clamped_values(const exact_table& t, const lut_layout& l, lut_kind kind, const std::string& format, double& largest) {
    const lut_encoding e = l.encoding;
    const bool rgbd = e == lut_encoding::rgbd;
    const bool unit = format == "png8" || format == "png16" || e == lut_encoding::unorm8 || e == lut_encoding::unorm10 ||
                      e == lut_encoding::unorm16 || e == lut_encoding::srgb;
    std::size_t n = 0;
    largest = 0;
    if (!rgbd && !unit) return 0;
    const auto names = layout_channels(l, kind);
    for (std::size_t k = 0; k < t.width * t.height; ++k)
        for (const auto& name : names) {
            if (name == "-") continue;
            const double v = channel_value(t, name, k);
            if (v < 0 || v > (rgbd ? 255.0 : 1.0)) ++n, largest = std::max(largest, v);
        }
    return n;
}

std::string encode_lut_image(const lut_image& im, const std::string& format, lut_encoding e) {
    if (format == "png8") return encode_png8(im);
    if (format == "png16") return encode_png16(im);
    if (format == "exr" || format == "exr-half") return encode_exr(im, format == "exr-half");
    const bool srgb = e == lut_encoding::srgb;
    if (format == "dds") return encode_dds(im, dds_format_with(im.channels, container_encoding(e), srgb)->dxgi);
    return encode_ktx2(im, ktx2_format_with(im.channels, container_encoding(e), srgb)->vk, format == "ktx2-zstd");
}

}  // namespace verify
