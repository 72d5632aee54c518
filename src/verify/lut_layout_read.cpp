// An engine's table read under its layout (lut_layout.hpp): the file read with what neither it
// nor the layout says refused, where each texel sits, what its stored values decode to, and how
// far each can be from what was stored before its rounding.
#include "lut_layout.hpp"

#include <normzoo/microfacet/albedo.hpp>
#include <normzoo/microfacet/split_sum_to.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "args.hpp"
#include "lut_formats/read.hpp"

namespace verify {

namespace mf = normzoo::microfacet;

double axis_coordinate(lut_spacing grid, bool roughness, lut_origin origin, std::size_t i, std::size_t n) {
    const double t = double(origin == lut_origin::low ? i : n - 1 - i);
    if (grid == lut_spacing::edges) return t / double(n - 1);
    // Filament's generator (cmgen's iblLutDfg) bakes image row y at r = saturate((h - y + 0.5)/h)
    // and writes its table bottom row first ("GL order"): row t from the low end holds
    // r = (t + 1.5)/h, one texel rougher than its centre, the last one clamped to 1.
    if (grid == lut_spacing::filament && roughness) return std::min(1.0, (t + 1.5) / double(n));
    return (t + 0.5) / double(n);
}

bool comparable_point(double mu, double alpha) {
    return mu >= normzoo::microfacet::smallest_mu && alpha >= normzoo::microfacet::smallest_alpha;
}

bool pair_has_limit(const mf::composition& c, double mu, double alpha) {
    try {
        (void)mf::split_sum_to(c, mu, alpha, {1e-3, 1e-3});  // the limit, cheaply: refused or not
        return true;
    } catch (const std::invalid_argument&) {
        return false;
    }
}

bool sampled_as_srgb(const decoded_lut& d) {
    return d.colour.declared == colour_declaration::kind::srgb && d.format.find("png") == std::string::npos;
}

decoded_lut read_laid_out(const std::string& path, const lut_reading& reading, lut_kind kind) {
    const lut_layout& l = reading.layout;
    decoded_lut d;
    try {
        d = read_lut_file(path, {"", l.width, l.height * l.slices});  // slices: one below another
    } catch (const bad_input& e) {
        if (l.slices == 1) throw;
        throw bad_input(std::string(e.what()) + " (size=" + std::to_string(l.width) + "x" + std::to_string(l.height) + "x" +
                        std::to_string(l.slices) + ": " + std::to_string(l.slices) + " slices of " + std::to_string(l.width) + " x " +
                        std::to_string(l.height) + ", read as one table of " + std::to_string(l.width) + " x " +
                        std::to_string(l.height * l.slices) + ")");
    }
    if (!d.shaped)
        throw bad_input(path + ": the array '" + d.array_name + "' holds " + std::to_string(d.image.data.size()) +
                        " numbers and the file gives no size (declared [H][W][C], a size constant): not a table to check "
                        "(--layout size=WxH gives it)");
    // integers written in decimal are codes where the layout says unorm8 or unorm16 (openpbr-bsdf's
    // tables: unorm16 codes in decimal), read as hex ones are
    const bool unorm = l.encoding == lut_encoding::unorm8 || l.encoding == lut_encoding::unorm16;
    if (d.encoding == value_encoding::decimal_text && unorm && d.format == "array-decimal" &&
        std::all_of(d.image.data.begin(), d.image.data.end(), [](double v) { return v >= 0 && v == std::floor(v); }))
        d.encoding = value_encoding::hex_integer;
    if (d.encoding == value_encoding::hex_integer) {
        if (l.encoding != lut_encoding::half && l.encoding != lut_encoding::unorm8 && l.encoding != lut_encoding::unorm16)
            throw bad_input(path + ": the array '" + d.array_name + "' holds hex integers, which may be binary16 bits, unorm8 or unorm16: "
                            "the check reads arrays of decimals, or these as --layout encoding=half, unorm8 or unorm16 says "
                            "(--detect tries each)");
        interpret_hex(path, d, l.encoding == lut_encoding::half     ? hex_meaning::binary16
                               : l.encoding == lut_encoding::unorm8 ? hex_meaning::unorm8
                                                                    : hex_meaning::unorm16);
    }
    // Rows and columns are read as stored, which is how a sampler addresses them: a layout that
    // names where they begin (row0, col0), or --detect, reads a file that declares another
    // orientation; the default would take its bottom row for the first roughness unasked.
    if (d.orientation.size() == 2 && d.orientation != "rd") {
        auto named = [&](const char* key) { return reading.detect || reading.stated.count(key) > 0; };
        if ((d.orientation[1] == 'u' && !named("row0")) || (d.orientation[0] == 'l' && !named(kind == lut_kind::eavg ? "row0" : "col0")))
            throw bad_input(path + ": KTXorientation '" + d.orientation + "': the check reads the first row stored as the first "
                            "roughness (rd); --layout row0= and col0= say where the rows and columns as stored begin");
    }
    if (d.exposure != 1)
        throw bad_input(path + ": EXPOSURE= " + std::to_string(d.exposure) + " scaled the pixels: the check reads the values as stored");
    if (sampled_as_srgb(d) && l.encoding != lut_encoding::srgb && !(reading.detect && !reading.stated.count("encoding")))
        throw bad_input(path + ": " + d.format + " holds sRGB-encoded values, which a sampler decodes: the check reads the values as "
                        "stored (--layout encoding=srgb decodes them)");
    return d;
}

namespace {

// The sRGB transfer, decoded (IEC 61966-2-1): what a sampler of an sRGB texture returns.
double srgb_decode(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// Half an ulp of half at v (11 significant bits; 2^-25 below its normal range), as an OpenEXR
// half image holds it.
double half_step(double v) { return std::ldexp(1.0, -11) * std::abs(v) + std::ldexp(1.0, -25); }

// A monotone decode f at the stored raw, and how far it moves over raw +- p.
template <class F>
stored_value spread(F f, double raw, double p) {
    const double v = f(raw);
    return {v, std::max(f(raw + p) - v, v - f(raw - p))};
}

}  // namespace

double encoding_step(lut_encoding e, double v) {
    switch (e) {
        case lut_encoding::half: return half_step(v);
        case lut_encoding::unorm8: return 0.5 / 255;
        case lut_encoding::unorm10: return 0.5 / 1023;
        case lut_encoding::unorm16: return 0.5 / 65535;
        default: return 0;
    }
}

stored_value decode_texel(const decoded_lut& d, lut_encoding e, std::size_t texel, std::size_t channel) {
    const std::size_t at = texel * d.image.channels + channel;
    const double raw = d.image.data[at], p = d.tolerance(at);
    if (e == lut_encoding::srgb)  // alpha is linear in an sRGB image
        return channel == 3 ? stored_value{raw, p} : spread(srgb_decode, raw, p);
    if (e == lut_encoding::rgbd) {
        // Babylon's fromRGBD: rgb = c^2.2 / D, D in the fourth channel. Its encoder stores
        // D = floor(255 / max(rgb)) / 255, a whole 8-bit code: D carries no rounding.
        const double divisor = d.image.data[texel * d.image.channels + 3];
        return spread([divisor](double c) { return std::pow(std::max(c, 0.0), 2.2) / divisor; }, raw, p);
    }
    // A value rounded to half, to 8, 10 or 16 bits and then stored: both roundings, the file's
    // left out where the file stores exactly that.
    const bool same = (e == lut_encoding::half && d.encoding == value_encoding::half) ||
                      (e == lut_encoding::unorm8 && d.encoding == value_encoding::unorm8) ||
                      (e == lut_encoding::unorm16 && d.encoding == value_encoding::unorm16);
    return {raw, encoding_step(e, raw) + (same ? 0 : p)};
}

decoded_lut slices_of(decoded_lut d, const lut_layout& l, const std::string& path) {
    auto& im = d.image;
    const std::size_t n = l.width * l.height * l.slices;
    if (n != im.width * im.height)
        throw bad_input(path + ": size=" + std::to_string(l.width) + "x" + std::to_string(l.height) + "x" + std::to_string(l.slices) +
                        " is " + std::to_string(n) + " texels; the file holds " + std::to_string(im.width * im.height) + " (" +
                        std::to_string(im.width) + " x " + std::to_string(im.height) + ")");
    im.width = l.width, im.height = l.height * l.slices;  // the same texels, row by row
    return d;
}

decoded_lut shaped_lut(decoded_lut d, const lut_layout& l, lut_kind kind, const std::string& path) {
    auto& im = d.image;
    if (l.width) {
        if (l.width * l.height != im.width * im.height)
            throw bad_input(path + ": size=" + std::to_string(l.width) + "x" + std::to_string(l.height) + " is " +
                            std::to_string(l.width * l.height) + " texels; the file holds " + std::to_string(im.width * im.height) +
                            " (" + std::to_string(im.width) + " x " + std::to_string(im.height) + ")");
        im.width = l.width, im.height = l.height;  // the same texels, row by row
    }
    if (kind == lut_kind::eavg) {
        if (im.height != 1 && im.width != 1)
            throw bad_input(path + ": " + std::to_string(im.width) + " x " + std::to_string(im.height) +
                            " is not an E_avg table (one row or one column)");
        im.height = std::max(im.width, im.height), im.width = 1;  // one column of roughness
    }
    const auto channels = layout_channels(l, kind);
    const std::size_t need = l.encoding == lut_encoding::rgbd ? 4 : channels.size();
    if (im.channels < need) {
        std::string why = kind == lut_kind::dfg ? "a split-sum table needs 2 (A, B)" : "a table needs 1";
        if (!l.channels.empty() || l.encoding == lut_encoding::rgbd) {
            std::string named;
            for (const auto& c : channels) named += (named.empty() ? "" : ",") + c;
            why = "the layout reads " + std::to_string(need) + " (channels=" + named +
                  (l.encoding == lut_encoding::rgbd ? ", then RGBD's divisor" : "") + ")";
        }
        throw bad_input(path + ": " + std::to_string(im.channels) + " channel(s); " + why);
    }
    if (l.grid == lut_spacing::edges && (im.height < 2 || (kind != lut_kind::eavg && im.width < 2)))
        throw bad_input(path + ": " + std::to_string(im.width) + " x " + std::to_string(im.height) +
                        " texels: grid=edges (t/(n - 1)) needs two texels along each axis");
    return d;
}

read_table lay_out(const decoded_lut& d, const lut_layout& l, lut_kind kind, const mf::composition* edges) {
    read_table t;
    const std::size_t w = d.image.width, h = d.image.height;
    t.format = d.format, t.width = w, t.height = h, t.grid = true;
    t.row_axis = l.rows, t.col_axis = l.cols;
    // the roughness as the table gives it, r or alpha (the records' at_r)
    t.points.perceptual = (is_roughness(l.rows) || kind == lut_kind::eavg ? l.rows : l.cols) == lut_axis::r;
    for (std::size_t j = 0; j < h; ++j) t.row_coord.push_back(axis_coordinate(l.grid, is_roughness(l.rows), l.row0, j, h));
    if (kind != lut_kind::eavg)
        for (std::size_t i = 0; i < w; ++i) t.col_coord.push_back(axis_coordinate(l.grid, is_roughness(l.cols), l.col0, i, w));
    const auto channels = layout_channels(l, kind);
    for (const auto& c : channels)
        if (c != "-") t.channels.push_back(c);
    t.points.points = true;
    for (std::size_t k = 0; k < w * h; ++k) {
        const double ur = t.row_coord[k / w];
        const double uc = kind == lut_kind::eavg ? 0 : t.col_coord[k % w];
        const bool rough_rows = is_roughness(l.rows) || kind == lut_kind::eavg;
        const double mu = kind == lut_kind::eavg ? 1 : mu_of_coordinate(rough_rows ? l.cols : l.rows, rough_rows ? uc : ur);
        const double rough = rough_rows ? ur : uc, alpha = alpha_of_coordinate(rough_rows ? l.rows : l.cols, rough);
        for (std::size_t c = 0; c < channels.size(); ++c) {
            if (channels[c] == "-") continue;
            const stored_value v = decode_texel(d, l.encoding, k, c);
            t.values.push_back(v.value);
            t.tolerance.push_back(v.tolerance);
        }
        // r = 0 or mu = 0: the pair's limit where the model has one, else not compared
        if (!comparable_point(mu, alpha) && !(edges && kind == lut_kind::dfg && pair_has_limit(*edges, mu, alpha))) continue;
        t.points.roughness.push_back(t.points.perceptual ? rough : alpha);
        if (kind != lut_kind::eavg) t.points.mus.push_back(mu);
        t.texel.push_back(k);
    }
    return t;
}

normzoo::quadrature::estimate<double> exact_channel(const exact_table& t, const std::string& name, std::size_t p) {
    if (t.channels == 1) {
        const auto& e = t.values[p];
        // a complement, 1 - E: its bound with the subtraction's rounding
        if (name.rfind("1-", 0) == 0) return {1 - e.value, e.abs_error + 0x1p-53, e.evaluations};
        return e;
    }
    const auto& a = t.values[2 * p];
    const auto& b = t.values[2 * p + 1];
    if (name == "A") return a;
    if (name == "B") return b;
    return {a.value + b.value, a.abs_error + b.abs_error, a.evaluations};
}

}  // namespace verify
