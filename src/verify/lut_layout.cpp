// The layout of an engine's table as a value (lut_layout.hpp): its keys read from text, checked
// against the kind, and written back in one canonical order.
#include "lut_layout.hpp"

#include <algorithm>
#include <set>
#include <tuple>

#include "args.hpp"

namespace verify {

namespace {

const std::vector<std::string> key_names = {"rows", "cols", "row0", "col0", "grid", "channels", "encoding", "size"};

const std::vector<std::string>& values_of(const std::string& key) {
    static const std::vector<std::string> axes = {"r", "alpha", "mu", "sqrt-mu"}, ends = {"low", "high"},
                                          grids = {"centres", "edges", "filament"},
                                          encodings = {"linear", "srgb", "rgbd", "half", "unorm8", "unorm10", "unorm16"},
                                          channels = {"A", "B", "A+B", "E", "E_avg", "1-E", "1-E_avg", "-"}, none = {};
    if (key == "rows" || key == "cols") return axes;
    if (key == "row0" || key == "col0") return ends;
    if (key == "grid") return grids;
    if (key == "encoding") return encodings;
    return key == "channels" ? channels : none;
}

std::string joined(const std::vector<std::string>& v, const char* sep = ", ") {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
    return s;
}

// size=WxH or WxHxD: whole numbers from 1 to 4096 (the largest table `verify lut` makes a side),
// and H x D at most 4096.
std::tuple<std::size_t, std::size_t, std::size_t> size_of(const std::string& value, const std::string& what) {
    const auto parts = split(value, 'x');
    auto side = [](const std::string& s) -> std::size_t {
        if (s.empty() || s.size() > 4 || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; })) return 0;
        const std::size_t n = std::stoul(s);
        return n <= 4096 ? n : 0;
    };
    const bool sized = parts.size() == 2 || parts.size() == 3;
    const std::size_t w = sized ? side(parts[0]) : 0, h = sized ? side(parts[1]) : 0, d = parts.size() == 3 ? side(parts[2]) : 1;
    if (!w || !h || !d)
        throw bad_input(what + ": size '" + value + "' is not WxH or WxHxD (columns x rows x slices, each 1 to 4096: size=64x64, size=32x32x32)");
    // the slices are read as one table of W x (H D) texels, whose side is at most 4096 too
    if (h * d > 4096) throw bad_input(what + ": size '" + value + "': the slices' rows, H x D, are more than 4096");
    return {w, h, d};
}

// One key's value checked; channels item by item.
void check_value(const std::string& key, const std::string& value, const std::string& what) {
    if (key == "size") {
        size_of(value, what);
        return;
    }
    const auto& allowed = values_of(key);
    for (const auto& item : key == "channels" ? split(value, ',') : std::vector<std::string>{value})
        if (std::find(allowed.begin(), allowed.end(), item) == allowed.end())
            throw bad_input(what + ": " + key + " '" + item + "' is not one of " + joined(allowed));
}

template <class E>
E index_in(const std::string& key, const std::string& value) {
    const auto& v = values_of(key);
    return E(std::find(v.begin(), v.end(), value) - v.begin());
}

}  // namespace

layout_keys parse_layout_keys(const std::string& text, const std::string& what) {
    layout_keys keys;
    for (const auto& item : split(text, ',')) {
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos) {
            // channels=B,A+B,-: the channels' items follow their key
            if (!item.empty() && !keys.empty() && keys.back().first == "channels") {
                keys.back().second += "," + item;
                continue;
            }
            throw bad_input(what + ": '" + item + "' is not KEY=VALUE (keys: " + joined(key_names) + ")");
        }
        const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
        if (std::find(key_names.begin(), key_names.end(), key) == key_names.end())
            throw bad_input(what + ": unknown key '" + key + "' (keys: " + joined(key_names) + ")");
        if (std::any_of(keys.begin(), keys.end(), [&](const auto& k) { return k.first == key; }))
            throw bad_input(what + ": key '" + key + "' is given twice");
        keys.emplace_back(key, value);
    }
    for (const auto& [key, value] : keys) check_value(key, value, what);
    return keys;
}

void apply_layout_keys(lut_layout& l, const layout_keys& keys) {
    for (const auto& [key, value] : keys) {
        if (key == "rows") l.rows = index_in<lut_axis>(key, value);
        else if (key == "cols") l.cols = index_in<lut_axis>(key, value);
        else if (key == "row0") l.row0 = index_in<lut_origin>(key, value);
        else if (key == "col0") l.col0 = index_in<lut_origin>(key, value);
        else if (key == "grid") l.grid = index_in<lut_spacing>(key, value);
        else if (key == "encoding") l.encoding = index_in<lut_encoding>(key, value);
        else if (key == "channels") l.channels = split(value, ',');
        else std::tie(l.width, l.height, l.slices) = size_of(value, "size");
    }
}

std::vector<std::string> layout_channels(const lut_layout& l, lut_kind kind) {
    if (!l.channels.empty()) return l.channels;
    return lut_channels(kind);
}

void check_layout(const lut_layout& l, lut_kind kind, const layout_keys& given, const std::string& what) {
    auto named = [&](const char* key) { return std::any_of(given.begin(), given.end(), [&](const auto& k) { return k.first == key; }); };
    if (kind == lut_kind::eavg) {
        for (const char* key : {"cols", "col0"})
            if (named(key)) throw bad_input(what + ": " + key + " is not read by --kind Eavg (one axis of roughness: rows=, row0=)");
        if (!is_roughness(l.rows)) throw bad_input(what + ": rows=" + axis_name(l.rows) + ": an E_avg table indexes r or alpha");
    } else if (is_roughness(l.rows) == is_roughness(l.cols)) {
        throw bad_input(what + ": rows=" + axis_name(l.rows) + " and cols=" + axis_name(l.cols) +
                        ": one axis is the roughness (r, alpha), the other mu (mu, sqrt-mu)");
    }
    const auto channels = layout_channels(l, kind);
    std::vector<std::string> read;
    for (const auto& c : channels)
        if (c != "-") read.push_back(c);
    const std::set<std::string> distinct(read.begin(), read.end());
    const bool dfg = distinct.size() == 2 && read.size() == 2 &&
                     std::all_of(read.begin(), read.end(), [](const std::string& c) { return c == "A" || c == "B" || c == "A+B"; });
    const std::string one = kind == lut_kind::e ? "E" : "E_avg";
    // or its complement, 1 - E (the energy a single-scattering lobe loses: openpbr-bsdf's tables)
    const bool ok = kind == lut_kind::dfg ? dfg : read == std::vector<std::string>{one} || read == std::vector<std::string>{"1-" + one};
    if (!ok)
        throw bad_input(what + ": channels '" + joined(channels, ",") + "': " +
                        (kind == lut_kind::dfg ? std::string("a split-sum table holds two of A, B, A+B (A,B or B,A+B; - skips a channel)")
                                               : "a table of --kind " + lut_kind_name(kind) + " holds one channel, " + one + " or 1-" + one + " (- skips one)"));
    if (l.encoding == lut_encoding::rgbd && channels.size() > 3)
        throw bad_input(what + ": channels '" + joined(channels, ",") + "' with encoding=rgbd: RGBD keeps its divisor in the fourth channel");
}

std::string axis_name(lut_axis a) { return values_of("rows")[std::size_t(a)]; }
std::string encoding_name(lut_encoding e) { return values_of("encoding")[std::size_t(e)]; }

std::string layout_text(const lut_layout& l, lut_kind kind) {
    const auto& ends = values_of("row0");
    std::string s = "rows=" + axis_name(l.rows);
    if (kind != lut_kind::eavg) s += ",cols=" + axis_name(l.cols);
    s += ",row0=" + ends[std::size_t(l.row0)];
    if (kind != lut_kind::eavg) s += ",col0=" + ends[std::size_t(l.col0)];
    s += ",grid=" + values_of("grid")[std::size_t(l.grid)] + ",channels=" + joined(layout_channels(l, kind), ",") +
         ",encoding=" + encoding_name(l.encoding);
    if (l.width) s += ",size=" + std::to_string(l.width) + "x" + std::to_string(l.height);
    if (l.width && l.slices > 1) s += "x" + std::to_string(l.slices);
    return s;
}

}  // namespace verify
