// `verify lut` (lut.hpp): its options, as the one parser read them (command_line.cpp), checked in
// the order their messages come, then the table made (lut_make.hpp) or an engine's table
// checked (lut_check.hpp).
#include "lut.hpp"

#include <normzoo/microfacet/composition.hpp>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "args.hpp"
#include "lut_check.hpp"
#include "lut_exact.hpp"
#include "lut_layout.hpp"
#include "lut_make.hpp"
#include "lut_presets.hpp"
#include "lut_write.hpp"
#include "microfacet_tables.hpp"

namespace verify {

namespace mf = normzoo::microfacet;

namespace {

bool given(const options& o, const std::string& name) { return o.typed.count(name) > 0; }

// The value typed after `name`, or `fallback` when it was not given.
// An option given with an empty value (--tolerance "") is refused, not taken as not given.
std::string typed_text(const options& o, const std::string& name, const std::string& fallback = "") {
    const auto it = o.typed.find(name);
    if (it == o.typed.end() || it->second.empty()) return fallback;
    if (it->second.front().empty()) throw bad_input("lut: " + name + ": an empty value");
    return it->second.front();
}

// The options as typed; --size and --monte-carlo the parser has already checked as numbers.
lut_options lut_options_of(const options& t) {
    lut_options o;
    o.kind_text = typed_text(t, "--kind");
    o.model = typed_text(t, "--model", o.model);
    o.alpha_text = typed_text(t, "--alpha"), o.r_text = typed_text(t, "--r"), o.mu_text = typed_text(t, "--mu");
    if (given(t, "--map") && t.typed.at("--map").size() > 1) throw bad_input("lut: --map is given more than once");
    o.map = typed_text(t, "--map", o.map), o.format = typed_text(t, "--format", o.format);
    o.out_dir = typed_text(t, "--out"), o.check_path = typed_text(t, "--check");
    o.tolerance_text = typed_text(t, "--tolerance"), o.f0_text = typed_text(t, "--f0");
    o.layout_text = typed_text(t, "--layout"), o.preset = typed_text(t, "--preset"), o.detect = given(t, "--detect");
    if (given(t, "--size")) o.size = std::stoul(typed_text(t, "--size"));
    if (given(t, "--monte-carlo")) o.monte_carlo = static_cast<unsigned>(std::stoul(typed_text(t, "--monte-carlo")));
    o.jobs = t.jobs;
    for (const auto& q : part_parameters()) o.part_texts.push_back(typed_text(t, std::string("--") + q.name));
    return o;
}

// --kind, its message prefixed with the subcommand's.
lut_kind read_kind_option(const options& t, const std::string& text) {
    if (!given(t, "--kind")) throw bad_input("lut: --kind is required");
    try {
        return lut_kind_of(text);
    } catch (const bad_input& e) {
        throw bad_input(std::string("lut: ") + e.what());
    }
}

// The parts' parameters given, read into p: one decimal each, in its range; --eta beside --check
// may list one per slice (etas: the list; p takes the first until the slices are known).
std::vector<std::string> read_part_texts(const options& t, const lut_options& o, part_inputs& p, std::vector<normzoo::decimal>& etas) {
    std::vector<std::string> read;
    for (std::size_t i = 0; i < part_parameters().size(); ++i) {
        const auto& q = part_parameters()[i];
        const std::string opt = std::string("--") + q.name;
        if (!given(t, opt)) continue;
        const auto v = parse_decimal_list(opt, o.part_texts[i], q.min, q.max, false, q.min_open);
        if (opt == "--eta" && !o.check_path.empty()) etas = v;
        else if (v.size() != 1) throw bad_input("lut: " + opt + ": one value, not a list ('" + o.part_texts[i] + "')");
        p.*q.input = v.front();
        read.push_back(opt);
    }
    return read;
}

// Each slice's index (size=WxHxD, docs/lut.md, "Slices"): --eta's list, or the preset's; one
// --eta for one table.
std::vector<normzoo::decimal> slice_etas(const lut_options& o, lut_kind kind, const mf::composition& c, const lut_reading& r,
                                         const std::vector<normzoo::decimal>& etas, const part_inputs& parts) {
    const std::size_t n = r.layout.slices;
    const bool axis = etas.empty() && !o.preset.empty() && !preset_named(o.preset, kind).eta.empty();  // the preset's
    if (n == 1) {
        if (etas.size() > 1) throw bad_input("lut: --eta: one value, not a list, for a table of one slice (size=WxHxD has slices)");
        if (axis && !parts.eta)  // one slice cut out of a preset's table
            throw bad_input("lut: --preset " + o.preset + " checks a table of slices, each at its own index: a table of one slice "
                            "needs its --eta");
        return {};
    }
    const std::string size = "size=" + std::to_string(r.layout.width) + "x" + std::to_string(r.layout.height) + "x" + std::to_string(n);
    if (kind == lut_kind::dfg) throw bad_input("lut: " + size + ": a split-sum table's slices would differ by nothing (its pair has no index eta)");
    if (r.detect) throw bad_input("lut: --detect reads a table of one slice (size=WxH), not " + size);
    if (!c.reads("eta"))
        throw bad_input("lut: " + size + ": slices differ by their index eta, which " + c.id + " does not read (dielectric, conductor)");
    if (axis && parts.f0)
        throw bad_input("lut: --f0 and --preset " + o.preset + "'s indices: the exact Fresnel parts take their index one way");
    const std::vector<normzoo::decimal> v = axis ? parse_decimal_list("--eta", preset_named(o.preset, kind).eta, "0", "1000", false, true) : etas;
    if (v.size() != n)
        throw bad_input("lut: " + size + " holds " + std::to_string(n) + " slices, each at its own index: --eta lists one per slice, in the order "
                        "stored (" + (v.empty() ? std::string("none given") : std::to_string(v.size()) + (axis ? " in the preset's axis" : " given")) + ")");
    return v;
}

// The parts' parameters and --f0 into g, and the composition --model names (with the parameters,
// before F0 is read). dfg takes neither F0 nor an F part's parameters: the split-sum pair
// replaces the F part by Schlick's and does not depend on F0 (docs/lut.md, "Kinds").
mf::composition read_composition_options(const options& t, const lut_options& o, lut_kind kind, lut_grid& g,
                                         std::vector<normzoo::decimal>& etas) {
    for (const auto& opt : read_part_texts(t, o, g.parts, etas))
        // the split-sum pair reads the D's parameters only
        if (kind == lut_kind::dfg && mf::detail::readers_of<mf::distribution_parts>(opt.substr(2)).empty())
            throw bad_input("lut: " + opt + " is for --kind E and Eavg (the split-sum pair replaces the F part by Schlick's)");
    const mf::composition c = composition_of(o.model, g.parts, "lut: --model: ");
    if (c.transmission && (kind == lut_kind::dfg || o.monte_carlo))
        throw bad_input("lut: --model " + o.model + ": the interface's reflection plus transmission is an exact E or Eavg table (" +
                        (kind == lut_kind::dfg ? "the split-sum pair is a reflection's)" : "--monte-carlo samples a reflection)"));
    if (!o.f0_text.empty()) {
        if (kind == lut_kind::dfg) throw bad_input("lut: --f0 is for --kind E and Eavg (the split-sum pair does not depend on F0)");
        const auto v = parse_decimal_list("--f0", o.f0_text, "0", "1", true);
        if (v.size() != 1) throw bad_input("lut: --f0: one value, not a list ('" + o.f0_text + "')");
        g.parts.f0 = v.front();
        const f0_value f0 = f0_of(g.parts);
        g.f0 = f0.f0, g.f0_delta = f0.delta;
    }
    check_part_inputs({o.model}, g.parts, "lut: --");
    return c;
}

// --check FILE: the file gives the table's size and coordinates, and no table is written (--out
// takes its error map), so the options that make or write a table are refused beside it
// (docs/lut.md, "Checking an engine's table").
std::optional<double> read_check_options(const options& t, const lut_options& o) {
    for (const char* making : {"--size", "--alpha", "--r", "--mu", "--format", "--monte-carlo"})
        if (given(t, making))
            throw bad_input(std::string("lut: ") + making + " is for making a table; --check reads the table's size and "
                            "coordinates from " + o.check_path + " and writes no table");
    if (given(t, "--out") && std::filesystem::path(o.check_path).extension() == ".csv")
        throw bad_input("lut: --out takes the error map of an image checked; " + o.check_path + ", a CSV, is points, not a texture");
    if (given(t, "--map") && std::filesystem::path(o.check_path).extension() == ".csv")
        throw bad_input("lut: --map is for an image; " + o.check_path + ", a CSV, names its roughness in its header (alpha or r)");
    if (o.tolerance_text.empty()) return std::nullopt;
    return parse_decimal_list("--tolerance", o.tolerance_text, "0", "1").front().to<double>();
}

// The texels of a table to make into g: --size N texel centres (docs/lut.md, "Texel centres"),
// or the listed --alpha or --r and --mu, each with how far its double is from the decimal typed.
void read_grid_options(const lut_options& o, lut_kind kind, lut_grid& g) {
    g.perceptual = o.map == "r";
    if (o.size > 0) {
        if (!o.alpha_text.empty() || !o.r_text.empty() || !o.mu_text.empty())
            throw bad_input("lut: --size or the lists --alpha/--r and --mu, not both");
        g.roughness = texel_centres(o.size);
        if (kind != lut_kind::eavg) g.mus = texel_centres(o.size);
        return;
    }
    if (o.alpha_text.empty() == o.r_text.empty()) throw bad_input("lut: give --size N, or --alpha or --r (and --mu)");
    g.perceptual = !o.r_text.empty();
    const roughness_range range = roughness_range_of(g.perceptual);
    for (const auto& d : parse_decimal_list(g.perceptual ? "--r" : "--alpha", g.perceptual ? o.r_text : o.alpha_text, range.min,
                                            range.max, false, false)) {
        g.roughness.push_back(d.to<double>());
        g.alpha_delta.push_back(alpha_of({d, g.perceptual}).delta);
    }
    if (kind == lut_kind::eavg && !o.mu_text.empty())
        throw bad_input("lut: --mu is not read by --kind Eavg (E_avg depends on the roughness alone)");
    if (kind != lut_kind::eavg) {
        if (o.mu_text.empty()) throw bad_input("lut: --mu is needed with --alpha or --r");
        for (const auto& d : parse_decimal_list("--mu", o.mu_text, "1e-8", "1", false, false)) {
            const auto m = mu_of({d, false});
            g.mus.push_back(m.mu);
            g.mu_delta.push_back(m.delta);
        }
    }
}

// --format, before anything is computed (docs/lut.md, "Formats"): an image or header holds
// N x N texel centres (or a layout's texels), not listed points. The output folder is the plan's
// to check.
void check_format_option(const lut_options& o, bool laid_out) {
    const auto& formats = lut_formats();
    if (std::find(formats.begin(), formats.end(), o.format) == formats.end()) {
        std::string names;
        for (const auto& f : formats) names += (names.empty() ? "" : ", ") + f;
        throw bad_input("lut: --format '" + o.format + "' is not one of " + names);
    }
    if (!o.size && !laid_out && o.format != "csv" && o.format != "json")
        throw bad_input("lut: --format " + o.format + " writes an N x N table of texel centres; listed values (--alpha or --r "
                        "with --mu) are points with their own coordinates: write them as csv or json");
}

// --layout, --preset and --detect: how the checked file is laid out (docs/lut.md, "Layouts"),
// --map the rows of the plain reading. A CSV names each value's coordinates: of these it reads
// encoding= alone.
lut_reading read_reading_options(const options& t, const lut_options& o, lut_kind kind) {
    lut_reading r;
    r.detect = o.detect, r.model_given = given(t, "--model") || o.kind_text == sheen_e_kind;
    if (given(t, "--map") && (given(t, "--layout") || given(t, "--preset") || o.detect))
        throw bad_input("lut: --map is --layout rows=r or rows=alpha: give the layout in one place");
    r.layout.rows = o.map == "alpha" ? lut_axis::alpha : lut_axis::r;
    layout_keys keys;  // the preset's, then --layout's
    if (!o.preset.empty()) {
        if (o.detect) throw bad_input("lut: --preset names a layout and --detect finds one: give one of them (--layout keys stay fixed in --detect)");
        keys = parse_layout_keys(preset_named(o.preset, kind).layout, "lut: --preset " + o.preset);
    }
    if (given(t, "--layout")) r.given = parse_layout_keys(o.layout_text, "lut: --layout");
    keys.insert(keys.end(), r.given.begin(), r.given.end());
    apply_layout_keys(r.layout, keys);
    for (const auto& key : keys) r.stated.insert(key.first);
    if (std::filesystem::path(o.check_path).extension() == ".csv") {
        const std::string csv = o.check_path + ", a CSV, names each value's coordinates in its header";
        if (!o.preset.empty() || o.detect) throw bad_input(std::string("lut: ") + (o.detect ? "--detect" : "--preset") + " reads an image; " + csv);
        for (const auto& key : r.given)
            if (key.first != "encoding") throw bad_input("lut: --layout: " + key.first + " is for an image; " + csv + " (it reads encoding= alone)");
        if (r.layout.encoding == lut_encoding::srgb || r.layout.encoding == lut_encoding::rgbd)
            throw bad_input("lut: --layout: encoding=" + encoding_name(r.layout.encoding) + " decodes an image's codes; a CSV's values are "
                            "numbers (linear, half, unorm8, unorm10, unorm16)");
    }
    check_layout(r.layout, kind, keys, given(t, "--layout") ? "lut: --layout" : "lut: --preset " + o.preset);
    return r;
}

// --layout and --preset beside a table to make: the layout it is written in and its size, from
// size=WxH or --size N (docs/lut.md, "Layouts"); none without them. The table is laid out in
// W x H texels: --map (it is rows=) and listed points are refused beside them.
std::optional<lut_writing> read_writing_options(const options& t, const lut_options& o, lut_kind kind) {
    if (!given(t, "--layout") && o.preset.empty()) return std::nullopt;
    if (given(t, "--map")) throw bad_input("lut: --map is --layout rows=r or rows=alpha: give the layout in one place");
    if (!o.alpha_text.empty() || !o.r_text.empty() || !o.mu_text.empty())
        throw bad_input("lut: --layout and --preset lay out a table of texels (--size N or size=WxH); listed values (--alpha or --r "
                        "with --mu) are points with their own coordinates");
    lut_writing w;
    w.preset = o.preset;
    if (!o.preset.empty()) w.preset_keys = parse_layout_keys(preset_named(o.preset, kind).layout, "lut: --preset " + o.preset);
    if (given(t, "--layout")) w.given = parse_layout_keys(o.layout_text, "lut: --layout");
    layout_keys keys = w.preset_keys;
    keys.insert(keys.end(), w.given.begin(), w.given.end());
    apply_layout_keys(w.layout, keys);
    check_layout(w.layout, kind, keys, given(t, "--layout") ? "lut: --layout" : "lut: --preset " + o.preset);
    if (w.layout.slices > 1)
        throw bad_input("lut: " + w.named("size") + ": slices (size=WxHxD) are read by --check FILE; a table made is one of W x H texels");
    if (!w.layout.width) {
        if (!o.size) throw bad_input("lut: give --size N (or --layout size=WxH): the size of the table to lay out");
        w.width = o.size, w.height = kind == lut_kind::eavg ? 1 : o.size;
        return w;
    }
    w.width = w.layout.width, w.height = w.layout.height;
    if (kind == lut_kind::eavg && w.width != 1 && w.height != 1)
        throw bad_input("lut: " + w.named("size") + ": an E_avg table is one row or one column (size=Nx1 or 1xN)");
    const std::size_t side = kind == lut_kind::eavg ? std::max(w.width, w.height) : w.width;
    if (o.size && (o.size != side || (kind != lut_kind::eavg && w.width != w.height)))
        throw bad_input("lut: --size " + std::to_string(o.size) + " and " + w.named("size") + " give two sizes: give one");
    return w;
}

// A request read whole: what to make or check, every option checked.
struct lut_request {
    lut_options opts;
    lut_kind kind;
    mf::composition model;
    lut_grid grid;
    std::optional<double> tolerance;  // --check
    lut_reading reading;              // --check
    std::optional<lut_writing> writing;  // --layout or --preset beside a table to make
};

lut_request read_lut_request(const options& t) {
    lut_options o = lut_options_of(t);
    // --check alone is the results' comparison, which lut has none of (docs/lut.md)
    if (given(t, "--check") && o.check_path.empty())
        throw bad_input("lut: --check needs the FILE to check (an engine's table: lut --check FILE --kind KIND); lut has no "
                        "committed results to compare");
    const lut_kind kind = read_kind_option(t, o.kind_text);
    if (o.kind_text == sheen_e_kind && !given(t, "--model") && o.preset.empty()) o.model = sheen_e_model;
    if (o.map != "r" && o.map != "alpha") throw bad_input("lut: --map '" + o.map + "' is not r or alpha");
    // a preset's model, unless --model names another
    if (!o.preset.empty() && !given(t, "--model")) o.model = preset_named(o.preset, kind).model;
    lut_grid g;
    std::vector<normzoo::decimal> etas;
    const mf::composition c = read_composition_options(t, o, kind, g, etas);
    if (!o.check_path.empty()) {
        const auto tolerance = read_check_options(t, o);
        lut_reading r = read_reading_options(t, o, kind);
        r.slice_eta = slice_etas(o, kind, c, r, etas, g.parts);
        return {o, kind, c, g, tolerance, r, std::nullopt};
    }
    if (!o.tolerance_text.empty()) throw bad_input("lut: --tolerance is for --check FILE");
    if (o.detect) throw bad_input("lut: --detect is for --check FILE (how an engine's table is laid out)");
    const std::optional<lut_writing> w = read_writing_options(t, o, kind);
    if (!w) read_grid_options(o, kind, g);  // a layout's points are laid out when it is made (lut_tables)
    check_format_option(o, w.has_value());
    // a file in --format is written with --out, or asked for by --format
    if (w) check_lut_writing(*w, kind, o.format, given(t, "--format") || !o.out_dir.empty(), c);
    return {o, kind, c, g, std::nullopt, {}, w};
}

}  // namespace

void check_lut_options(const options& o) { read_lut_request(o); }

std::vector<table_output> lut_tables(const options& o) {
    const lut_request q = read_lut_request(o);
    if (!q.opts.check_path.empty())
        return {lut_check_output(q.opts.check_path, q.kind, q.model, q.reading, q.tolerance, q.opts.jobs, q.grid.parts)};
    if (!q.writing) return {make_lut(q.opts, q.kind, q.model, q.grid)};
    lut_grid laid = layout_grid(*q.writing, q.kind);  // the points; F0 and the parts' parameters as read
    laid.parts = q.grid.parts, laid.f0 = q.grid.f0, laid.f0_delta = q.grid.f0_delta;
    return {make_lut(q.opts, q.kind, q.model, laid, &*q.writing)};
}

}  // namespace verify
