// `verify lut` making a table (lut_make.hpp): the values computed (exact, or by Monte Carlo as
// engines bake them; in a layout, lut_write.hpp), the records' head, the file staged in its format
// and the console's report.
#include "lut_make.hpp"

#include <normzoo/detail/parallel.hpp>
#include <normzoo/microfacet/split_sum_shortcuts.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "args.hpp"
#include "lut_image.hpp"
#include "lut_write.hpp"
#include "writers.hpp"

namespace verify {

namespace mf = normzoo::microfacet;

namespace {

// --monte-carlo N: the split-sum pair baked as engines bake it (docs/lut.md, "As engines bake
// it"), in float, at the texel centres or a layout's points (a list, lut_write.hpp); its values
// carry no bound (HUGE_VAL). The baker divides by N.V and samples GGX of r: at an edge grid's
// r = 0 or mu = 0 it is run at 1e-4, as Cycles clamps its bake.
exact_table baked_split_sum(const lut_options& o, lut_kind kind, const lut_grid& g) {
    if (kind != lut_kind::dfg || !g.perceptual || o.model != "ggx/smith-height-correlated/one")
        throw bad_input("lut: --monte-carlo bakes the split-sum pair of ggx/smith-height-correlated by r: --kind dfg, "
                        "--map r (or a layout's rows or columns r), the default model");
    exact_table t;
    t.width = g.points ? g.roughness.size() : g.mus.size(), t.height = g.points ? 1 : g.roughness.size(), t.channels = 2;
    t.values.resize(t.width * t.height * 2);
    normzoo::detail::parallel_for(t.width * t.height, o.jobs, [&](std::size_t k) {
        const std::size_t j = g.points ? k : k / t.width, i = g.points ? k : k % t.width;
        const float r = float(std::max(g.roughness[j], 1e-4)), mu = float(std::max(g.mus[i], 1e-4));
        const auto [a, b] = normzoo::microfacet::monte_carlo_baker::eval(r, mu, o.monte_carlo);
        t.values[2 * k] = {double(a), HUGE_VAL, o.monte_carlo};
        t.values[2 * k + 1] = {double(b), HUGE_VAL, o.monte_carlo};
    });
    return t;
}

// A Monte Carlo table's head says how it was made, and its records carry no error estimate.
void head_monte_carlo(table_output& out, unsigned monte_carlo) {
    out.info.title = "A baked table as engines bake it: Monte Carlo, " + std::to_string(monte_carlo) +
                     " samples in float (docs/lut.md); not exact, no error bound";
    out.info.settings.front() = "each value by Monte Carlo as engines bake it (docs/lut.md, \"As engines bake it\"): " +
                                std::to_string(monte_carlo) + " samples; *error_estimate: none (null)";
    for (auto& r : out.records)
        for (auto& [k, v] : r.fields)
            if (k.find("error_estimate") != std::string::npos) v = nullptr;
}

// The command that makes the table again, for its head: a layout's table by its preset and
// --layout, the plain one by --map.
std::string lut_command(const lut_options& o, const part_inputs& parts, bool laid_out) {
    const std::string size = o.size ? " --size " + std::to_string(o.size) : laid_out ? std::string() : std::string(" (lists)");
    const std::string layout = !laid_out ? " --map " + o.map
                                         : (o.preset.empty() ? std::string() : " --preset " + o.preset) +
                                               (o.layout_text.empty() ? std::string() : " --layout " + o.layout_text);
    return "./verify lut --kind " + o.kind_text + " --model " + o.model + size + layout +
           (o.f0_text.empty() ? std::string() : " --f0 " + o.f0_text) + given_parts(parts) +
           (o.monte_carlo ? " --monte-carlo " + std::to_string(o.monte_carlo) : std::string());
}

// lut-KIND-N.EXT (N: the side, WxH for a table that is not square), or lut-KIND-list.EXT for
// listed values (docs/lut.md, "Formats").
std::string lut_file_name(const lut_options& o, const std::string& shape) {
    const std::string stem = "lut-" + o.kind_text + "-" + shape;
    // those that share an extension with another format's file sit beside it, not over it
    return o.format == "png16" ? stem + ".png"
           : o.format == "png8" ? stem + "-8bit.png"
           : o.format == "exr" ? stem + ".exr"
           : o.format == "exr-half" ? stem + "-half.exr"
           : o.format == "ktx2-zstd" ? stem + "-zstd.ktx2"
                                     : stem + "." + o.format;
}

// The C header's comment: the command and title, and how rows, columns and channels are laid out.
std::string c_header_comment(lut_kind kind, const lut_grid& g, const table_output& out, const lut_layout* laid_out) {
    std::string comment = "normzoo " + out.command + ": " + out.info.title + "\n";
    if (laid_out) {
        bool zero = false;
        comment += "layout " + layout_text(*laid_out, kind) + " (docs/lut.md, \"Layouts\"): rows, columns and channels in file order";
        for (const auto& n : layout_channels(*laid_out, kind)) zero = zero || n == "-";
        return comment + (zero ? "; a channel - holds 0" : "");
    }
    const std::string roughness = std::string("roughness (") + (g.perceptual ? "r, alpha = r^2" : "alpha") + ")";
    comment += (kind == lut_kind::eavg ? "one row: " + roughness : "rows: " + roughness + ", columns: mu") +
               "; texel centres (i + 0.5)/N; channels: ";
    for (const auto& n : lut_channels(kind)) comment += n + " ";
    return comment;
}

// What the file is made of: its name, the layout its texels are stored in (the plain one: the
// kind's channels, as computed), and whether a layout was asked for.
struct lut_file {
    std::string name, shape;
    lut_layout layout;
    bool laid_out = false;
};

// The table in --format, staged into the run's output folder (the output stage renames it with
// the rest: never half-written).
void stage_lut_file(const lut_options& o, lut_kind kind, const lut_grid& g, const exact_table& t, const table_output& out,
                    const lut_file& f, file_set& files) {
    if (o.format == "csv") return files.stage(f.name, csv(out));
    if (o.format == "json") return files.stage(f.name, json_file(out));
    const lut_image im = stored_image(t, f.layout, kind, o.format);
    double largest = 0;
    if (const std::size_t n = clamped_values(t, f.layout, kind, o.format, largest))  // a sheen's E above 1: docs/lut.md#sheen-tables
        std::cerr << "verify lut: " << n << " values beyond what --format " << o.format << " with encoding="
                  << encoding_name(f.layout.encoding) << " holds are clamped (the largest " << largest
                  << "); exr or exr-half holds them\n";
    if (o.format != "h") return files.stage(f.name, encode_lut_image(im, o.format, f.layout.encoding));
    const std::string name = "normzoo_" + o.kind_text + "_" + (f.laid_out ? f.shape : std::to_string(t.width));
    files.stage(f.name, encode_c_header(im, name, c_header_comment(kind, g, out, f.laid_out ? &f.layout : nullptr)));
}

// How many values are not finite (an integral that broke): their records fail.
std::size_t broken_values(const table_output& out) {
    std::size_t broken = 0;
    for (const auto& r : out.records) broken += r.failed() ? 1 : 0;
    return broken;
}

// The console's report: where the file went, or the table summed up when it is not written.
void print_lut_report(const table_output& out, const console_view& v, std::size_t texels, const std::string& file,
                      const std::string& summary) {
    const std::size_t broken = broken_values(out);
    if (broken && v.written)
        std::cerr << "verify lut: " << broken << " of " << out.records.size() << " values are not finite; nothing written to "
                  << v.out_dir << "\n";
    else if (v.written && !v.json)
        std::cerr << "verify lut: " << texels << " texels -> " << (std::filesystem::path(v.out_dir) / file).string()
                  << "\n";
    if (v.written || v.json) return;
    std::cout << summary;
    if (broken) std::cout << "FAIL: " << broken << " values are not finite\n";
}

}  // namespace

table_output make_lut(const lut_options& o, lut_kind kind, const mf::composition& c, const lut_grid& g, const lut_writing* w) {
    exact_table t = o.monte_carlo ? baked_split_sum(o, kind, g) : w ? laid_out_exact(kind, c, g, o.jobs) : exact_lut(kind, c, g, o.jobs);
    table_output out = lut_records(kind, c, g, t);
    lut_file f;
    f.shape = !o.size ? "list" : std::to_string(o.size);
    f.layout.rows = g.perceptual ? lut_axis::r : lut_axis::alpha;
    if (w) {
        // the points, row by row, are the file's texels
        t.width = w->width, t.height = w->height;
        f.layout = w->layout, f.laid_out = true;
        const std::size_t n = std::max(w->width, w->height);
        f.shape = kind == lut_kind::eavg || w->width == w->height ? std::to_string(n) : std::to_string(w->width) + "x" + std::to_string(w->height);
        out.info.settings.back() = "texels: laid out as " + layout_text(w->layout, kind) + " (docs/lut.md, \"Layouts\"): a record per " +
                                   "texel at its point, row by row in file order; the file holds the layout's channels and encoding";
    }
    f.name = lut_file_name(o, f.shape);
    if (o.monte_carlo) head_monte_carlo(out, o.monte_carlo);
    out.command = lut_command(o, g.parts, w != nullptr);
    out.parameters = w ? (kind == lut_kind::eavg ? f.shape + " texels" : std::to_string(t.width) + " x " + std::to_string(t.height) + " texels") +
                             ", " + layout_text(w->layout, kind)
                     : !o.size ? "listed points"
                     : kind == lut_kind::eavg ? std::to_string(o.size) + " texel centres"
                                              : std::to_string(o.size) + " x " + std::to_string(o.size) + " texel centres";
    // An integral that broke (a value or bound not finite) fails its record: exit 1, and no table
    // file an engine could load as if it held values.
    out.own_files = [o, kind, g, t, f](const table_output& self, file_set& files) {
        if (!broken_values(self)) stage_lut_file(o, kind, g, t, self, f, files);
    };
    double worst = 0;
    for (const auto& v : t.values) worst = std::max(worst, v.abs_error);
    std::ostringstream summary;
    summary << "lut: " << t.width * t.height << " texels of " << o.kind_text << " (" << c.id << "), largest error estimate "
            << worst << " (not written; add --out DIR or --json)\n";
    out.console = [texels = t.width * t.height, file = f.name, summary = summary.str()](const table_output& self,
                                                                                    const console_view& v) {
        print_lut_report(self, v, texels, file, summary);
    };
    return out;
}

}  // namespace verify
