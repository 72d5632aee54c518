// `verify lut` (lut.hpp): its command line read and checked, in the order its messages come,
// then the table made (lut_make.hpp) or an engine's table checked (lut_check.hpp).
#include "lut.hpp"

#include <normzoo/microfacet/composition.hpp>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "args.hpp"
#include "command_line.hpp"
#include "lut_check.hpp"
#include "lut_exact.hpp"
#include "lut_make.hpp"
#include "microfacet_tables.hpp"

namespace verify {

namespace mf = normzoo::microfacet;

namespace {

// The options, in the order --help lists them.
void add_lut_options(CLI::App& app, lut_options& o) {
    app.add_option("--kind", o.kind_text, "dfg (the split-sum pair A, B), E, or Eavg")->required();
    app.add_option("--model", o.model, "A composition D/G/F[/kulla-conty|turquin] (default ggx/smith-height-correlated/one); "
                                       "dfg replaces its F by Schlick's");
    app.add_option("--size", o.size, "N: an N x N table at texel centres (i + 0.5)/N in mu and in roughness")->check(CLI::Range(1, 4096));
    app.add_option("--alpha", o.alpha_text, "Roughness values alpha, comma-separated, instead of --size");
    app.add_option("--r", o.r_text, "Perceptual roughness values r (alpha = r^2), instead of --size");
    app.add_option("--mu", o.mu_text, "Cosines of the incident angle, comma-separated, with --alpha or --r");
    app.add_option("--f0", o.f0_text, "E and Eavg: F0 of the composition's Fresnel part, in [0, 1) (default 1: F = 1 for "
                                      "every F part); dfg's A and B do not depend on it");
    add_part_options(app, o.part_texts, "");
    app.add_option("--map", o.map, "What the rows of a --size table (or a checked image) index: r (alpha = r^2, default) or alpha");
    app.add_option("--format", o.format, "csv, json, png16, exr (float), exr-half, h (C header of floats) (with --out)");
    app.add_option("--out", o.out_dir, "Folder to write the table to (lut-KIND-N.EXT); without it nothing is written");
    app.add_option("--check", o.check_path, "An engine's table to check: CSV (columns mu, alpha or r, and A, B / E / E_avg), "
                                            "PNG (8 or 16 bit) or OpenEXR; an image is N x N texel centres");
    app.add_option("--tolerance", o.tolerance_text, "Absolute tolerance of --check (default: what the file's format holds)");
    app.add_option("--monte-carlo", o.monte_carlo, "dfg only: bake the table as engines do instead, N samples of GGX "
                                                   "importance sampling at Hammersley points in float, height-correlated "
                                                   "Smith (docs/lut.md); its error is not bounded")
        ->check(CLI::Range(1u, 1u << 24));
    app.add_flag("--json", o.json, "Write one JSON document {records, skipped} to stdout");
    app.add_option("--jobs", o.jobs, "Threads (default: all cores)")->check(CLI::Range(1u, 256u));
}

// --kind, its message prefixed with the subcommand's.
lut_kind read_kind_option(const std::string& text) {
    try {
        return lut_kind_of(text);
    } catch (const bad_input& e) {
        throw bad_input(std::string("lut: ") + e.what());
    }
}

// The parts' parameters and --f0 into g, and the composition --model names (with the parameters,
// before F0 is read). dfg takes neither F0 nor an F part's parameters: the split-sum pair
// replaces the F part by Schlick's and does not depend on F0 (docs/lut.md, "Kinds").
mf::composition read_composition_options(const CLI::App& app, const lut_options& o, lut_kind kind, lut_grid& g) {
    for (const auto& opt : read_part_options(app, o.part_texts, g.parts, "lut: "))
        // the split-sum pair reads the D's parameters only
        if (kind == lut_kind::dfg && mf::detail::readers_of<mf::distribution_parts>(opt.substr(2)).empty())
            throw bad_input("lut: " + opt + " is for --kind E and Eavg (the split-sum pair replaces the F part by Schlick's)");
    const mf::composition c = composition_of(o.model, g.parts, "lut: --model: ");
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

// --check FILE: the file gives the table's size and coordinates; nothing is written, so the
// options that make or write a table are refused beside it (docs/lut.md, "Checking an engine's
// table").
int check_engine_table(const CLI::App& app, const lut_options& o, lut_kind kind, const mf::composition& c, const part_inputs& parts) {
    for (const char* making : {"--size", "--alpha", "--r", "--mu", "--format", "--out", "--monte-carlo"})
        if (app.count(making))
            throw bad_input(std::string("lut: ") + making + " is for making a table; --check reads the table's size and "
                            "coordinates from " + o.check_path + " and writes nothing");
    if (app.count("--map") && std::filesystem::path(o.check_path).extension() == ".csv")
        throw bad_input("lut: --map is for an image; " + o.check_path + ", a CSV, names its roughness in its header (alpha or r)");
    std::optional<double> tolerance;
    if (!o.tolerance_text.empty()) {
        const auto t = parse_decimal_list("--tolerance", o.tolerance_text, "0", "1");
        tolerance = t.front().to<double>();
    }
    return run_lut_check(o.check_path, kind, c, o.map == "r", tolerance, o.json, o.jobs, parts);
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

// --format and --out, before anything is computed (docs/lut.md, "Formats"): an image or header
// holds N x N texel centres, not listed points.
void check_output_options(const lut_options& o) {
    const std::vector<std::string> formats = {"csv", "json", "png16", "exr", "exr-half", "h"};
    if (std::find(formats.begin(), formats.end(), o.format) == formats.end())
        throw bad_input("lut: --format '" + o.format + "' is not one of csv, json, png16, exr, exr-half, h");
    if (!o.size && o.format != "csv" && o.format != "json")
        throw bad_input("lut: --format " + o.format + " writes an N x N table of texel centres; listed values (--alpha or --r "
                        "with --mu) are points with their own coordinates: write them as csv or json");
    if (!o.out_dir.empty()) check_output_folder(o.out_dir, "--out");
}

}  // namespace

int run_lut(int argc, char** argv) {
    CLI::App app{"normzoo verify lut: the tables engines bake (split-sum pair, E(mu, alpha), E_avg(alpha)), exact, "
                 "and an engine's own table checked against them (docs/lut.md). Exit 0, 1 (a checked table is off), 2 "
                 "(bad input).",
                 "verify lut"};
    lut_options o;
    add_lut_options(app, o);
    refuse_missing_values(app, argc, argv, "lut: ");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        throw bad_input("lut: " + std::string(e.what()));
    }
    refuse_forgotten_values(app, "lut: ");
    const lut_kind kind = read_kind_option(o.kind_text);
    if (o.map != "r" && o.map != "alpha") throw bad_input("lut: --map '" + o.map + "' is not r or alpha");
    lut_grid g;
    const mf::composition c = read_composition_options(app, o, kind, g);
    if (!o.check_path.empty()) return check_engine_table(app, o, kind, c, g.parts);
    if (!o.tolerance_text.empty()) throw bad_input("lut: --tolerance is for --check FILE");
    read_grid_options(o, kind, g);
    check_output_options(o);
    return make_lut(o, kind, c, g);
}

}  // namespace verify
