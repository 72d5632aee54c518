// `verify lut` making a table (lut_make.hpp): the values computed (exact, or by Monte Carlo as
// engines bake them), the records' head, the file staged in its format and the console's report.
#include "lut_make.hpp"

#include <normzoo/detail/parallel.hpp>
#include <normzoo/microfacet/split_sum_shortcuts.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "args.hpp"
#include "lut_image.hpp"
#include "writers.hpp"

namespace verify {

namespace mf = normzoo::microfacet;

namespace {

// --monte-carlo N: the split-sum pair baked as engines bake it (docs/lut.md, "As engines bake
// it"), in float; its values carry no bound (HUGE_VAL).
exact_table baked_split_sum(const lut_options& o, lut_kind kind, const lut_grid& g) {
    if (kind != lut_kind::dfg || !g.perceptual || o.model != "ggx/smith-height-correlated/one")
        throw bad_input("lut: --monte-carlo bakes the split-sum pair of ggx/smith-height-correlated by r: --kind dfg, "
                        "--map r, the default model");
    exact_table t;
    t.width = g.mus.size(), t.height = g.roughness.size(), t.channels = 2;
    t.values.resize(t.width * t.height * 2);
    normzoo::detail::parallel_for(t.width * t.height, o.jobs, [&](std::size_t k) {
        const auto [a, b] = normzoo::microfacet::monte_carlo_baker::eval(float(g.roughness[k / t.width]), float(g.mus[k % t.width]), o.monte_carlo);
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

// The command that makes the table again, for its head.
std::string lut_command(const lut_options& o, const part_inputs& parts) {
    return "./verify lut --kind " + o.kind_text + " --model " + o.model +
           (o.size ? " --size " + std::to_string(o.size) : std::string(" (lists)")) + " --map " + o.map +
           (o.f0_text.empty() ? std::string() : " --f0 " + o.f0_text) + given_parts(parts) +
           (o.monte_carlo ? " --monte-carlo " + std::to_string(o.monte_carlo) : std::string());
}

// lut-KIND-N.EXT, or lut-KIND-list.EXT for listed values (docs/lut.md, "Formats").
std::string lut_file_name(const lut_options& o) {
    const std::string stem = "lut-" + o.kind_text + "-" + (o.size ? std::to_string(o.size) : std::string("list"));
    return o.format == "png16" ? stem + ".png"
           : o.format == "exr" ? stem + ".exr"
           : o.format == "exr-half" ? stem + "-half.exr"  // beside the float one, not over it
                                    : stem + "." + o.format;
}

// The C header's comment: the command and title, and how rows, columns and channels are laid out.
std::string c_header_comment(lut_kind kind, const lut_grid& g, const table_output& out) {
    const std::string roughness = std::string("roughness (") + (g.perceptual ? "r, alpha = r^2" : "alpha") + ")";
    std::string comment = "normzoo " + out.command + ": " + out.info.title + "\n" +
                          (kind == lut_kind::eavg ? "one row: " + roughness : "rows: " + roughness + ", columns: mu") +
                          "; texel centres (i + 0.5)/N; channels: ";
    for (const auto& n : lut_channels(kind)) comment += n + " ";
    return comment;
}

// The table in --format, staged into the run's output folder (the output stage renames it with
// the rest: never half-written).
void stage_lut_file(const lut_options& o, lut_kind kind, const lut_grid& g, const exact_table& t, const table_output& out,
                    file_set& files) {
    const std::string file = lut_file_name(o);
    const lut_image im = lut_image_of(t);
    if (o.format == "csv") files.stage(file, csv(out));
    else if (o.format == "json") files.stage(file, json_file(out));
    else if (o.format == "png16") files.stage(file, encode_png16(im));
    else if (o.format == "exr" || o.format == "exr-half") files.stage(file, encode_exr(im, o.format == "exr-half"));
    else {
        std::string name = "normzoo_" + o.kind_text + "_" + std::to_string(t.width);
        files.stage(file, encode_c_header(im, name, c_header_comment(kind, g, out)));
    }
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

table_output make_lut(const lut_options& o, lut_kind kind, const mf::composition& c, const lut_grid& g) {
    const exact_table t = o.monte_carlo ? baked_split_sum(o, kind, g) : exact_lut(kind, c, g, o.jobs);
    table_output out = lut_records(kind, c, g, t);
    if (o.monte_carlo) head_monte_carlo(out, o.monte_carlo);
    out.command = lut_command(o, g.parts);
    out.parameters = !o.size ? "listed points"
                     : kind == lut_kind::eavg ? std::to_string(o.size) + " texel centres"
                                              : std::to_string(o.size) + " x " + std::to_string(o.size) + " texel centres";
    // An integral that broke (a value or bound not finite) fails its record: exit 1, and no table
    // file an engine could load as if it held values.
    out.own_files = [o, kind, g, t](const table_output& self, file_set& files) {
        if (!broken_values(self)) stage_lut_file(o, kind, g, t, self, files);
    };
    double worst = 0;
    for (const auto& v : t.values) worst = std::max(worst, v.abs_error);
    std::ostringstream summary;
    summary << "lut: " << t.width * t.height << " texels of " << o.kind_text << " (" << c.id << "), largest error estimate "
            << worst << " (not written; add --out DIR or --json)\n";
    out.console = [texels = t.width * t.height, file = lut_file_name(o), summary = summary.str()](const table_output& self,
                                                                                               const console_view& v) {
        print_lut_report(self, v, texels, file, summary);
    };
    return out;
}

}  // namespace verify
