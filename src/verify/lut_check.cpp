// `verify lut --check FILE` (lut_check.hpp): each value of an engine's table against the exact
// one, per channel the largest error, where, how many texels are beyond their tolerance and a
// histogram by decade; and the report for the console.
#include "lut_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <vector>

#include "args.hpp"
#include "lut.hpp"
#include "lut_read.hpp"
#include "microfacet_tables.hpp"

namespace verify {

namespace mf = normzoo::microfacet;

namespace {

// One channel of an engine's table against the exact one: the largest error, at which texel,
// and the tolerance there; how many texels are beyond their tolerance, of how many; and the
// errors by decade ("<1e-8:3 1e-7:5").
struct channel_errors {
    double worst = -1, worst_tol = 0;
    std::size_t at = 0, above = 0, count = 0;
    std::string histogram;
};

channel_errors errors_of_channel(const stored_table& s, const exact_table& t, std::size_t ch, std::optional<double> tolerance) {
    channel_errors r;
    std::vector<std::size_t> histogram(9, 0);  // |error| < 1e-8, [1e-8, 1e-7), ..., >= 1e-1
    for (std::size_t k = 0; k < s.width * s.height; ++k) {
        const auto& exact = t.values[k * s.channels + ch];
        const double stored = s.values[k * s.channels + ch];
        double err = std::abs(stored - exact.value);
        // A texel that is not finite (a NaN or Inf a baker wrote) is counted and never passed:
        // its own precision, relative to it, is not finite either and would pass anything.
        const bool finite = std::isfinite(stored) && !std::isnan(err);
        if (!finite) err = std::numeric_limits<double>::infinity();
        const double tol = (tolerance ? *tolerance : s.precision[k * s.channels + ch]) + exact.abs_error;
        if (err > r.worst) r.worst = err, r.at = k, r.worst_tol = tol;
        r.above += !finite || err > tol;
        ++r.count;
        const int decade = err < 1e-8 ? 0 : err >= 0.1 ? 8 : int(std::floor(std::log10(err))) + 9;
        ++histogram[std::size_t(decade)];
    }
    const char* labels[] = {"<1e-8", "1e-8", "1e-7", "1e-6", "1e-5", "1e-4", "1e-3", "1e-2", ">=1e-1"};
    for (std::size_t b = 0; b < histogram.size(); ++b)
        if (histogram[b]) r.histogram += (r.histogram.empty() ? "" : " ") + std::string(labels[b]) + ":" + std::to_string(histogram[b]);
    return r;
}

// A texel whose looser bound passes it where the bound at 1e-10 might not (its error beyond the
// tolerance, within the tolerance plus the bound) is computed again at 1e-10: every verdict is the
// one at 1e-10 (docs/lut.md, "How a check chooses its accuracy"). An image's texels only.
void settle_undecided(const stored_table& s, exact_table& t, lut_kind kind, const mf::composition& c,
                      std::optional<double> tolerance, unsigned jobs) {
    lut_grid again = s.grid;
    again.points = true, again.mus.clear(), again.roughness.clear();
    std::vector<std::size_t> texels;
    for (std::size_t k = 0; k < s.width * s.height; ++k) {
        bool undecided = false;
        for (std::size_t ch = 0; ch < s.channels; ++ch) {
            const auto& exact = t.values[k * s.channels + ch];
            const double err = std::abs(s.values[k * s.channels + ch] - exact.value);
            const double tol = tolerance ? *tolerance : s.precision[k * s.channels + ch];
            undecided = undecided || (exact.abs_error > 1e-10 && err > tol && err <= tol + exact.abs_error);
        }
        if (!undecided) continue;
        texels.push_back(k);
        again.mus.push_back(s.grid.mus[k % s.width]);
        again.roughness.push_back(s.grid.roughness[k / s.width]);
    }
    if (texels.empty()) return;
    const exact_table settled = exact_lut(kind, c, again, jobs);
    for (std::size_t m = 0; m < texels.size(); ++m)
        for (std::size_t ch = 0; ch < s.channels; ++ch) t.values[texels[m] * s.channels + ch] = settled.values[m * s.channels + ch];
}

}  // namespace

table_output check_lut_table(const std::string& path, lut_kind kind, const mf::composition& c, bool perceptual,
                             std::optional<double> tolerance, unsigned jobs, const part_inputs& parts) {
    const std::string ext = std::filesystem::path(path).extension().string();
    const f0_value f0 = kind == lut_kind::dfg ? f0_value{} : f0_of(parts);
    stored_table s = ext == ".csv" ? read_csv_table(path, kind, {lut_kind_name(kind), &c, &parts})
                                   : read_image_table(path, kind, perceptual);
    s.grid.f0 = f0.f0, s.grid.f0_delta = f0.delta, s.grid.parts = parts;
    // dfg from an image: each value to a hundredth of its tolerance, 1e-10 at least (docs/lut.md,
    // "How a check chooses its accuracy"); a CSV's decimals, E and E_avg: 1e-10
    std::vector<double> wanted;
    if (kind == lut_kind::dfg && s.format != "csv")
        for (double p : s.precision) wanted.push_back(std::max(1e-10, (tolerance ? *tolerance : p) / 100));
    exact_table t;  // a CSV's points each at its own coordinates
    try {
        t = exact_lut(kind, c, s.grid, jobs, wanted.empty() ? nullptr : &wanted);
        if (!wanted.empty()) settle_undecided(s, t, kind, c, tolerance, jobs);
    } catch (const bad_input& e) {  // an edge (mu = 0, alpha = 0) of a model without its limits
        throw bad_input(path + ": " + e.what());
    }
    const auto names = lut_channels(kind);
    std::vector<record> rows;
    for (std::size_t ch = 0; ch < s.channels; ++ch) {
        const channel_errors e = errors_of_channel(s, t, ch, tolerance);
        const std::size_t i = s.format == "csv" || kind == lut_kind::eavg ? e.at : e.at % s.width;
        const std::size_t j = s.format == "csv" || kind == lut_kind::eavg ? e.at : e.at / s.width;
        record r{"lut-check", {}};
        r.set("file", path).set("format", s.format).set("kind", lut_kind_name(kind))
            .set("model", c.id);
        set_part_keys(r, c, parts, kind == lut_kind::dfg ? std::nullopt : std::optional<double>(f0.f0));
        r.set("channel", names[ch]).set("texels", static_cast<std::int64_t>(e.count))
            .set("max_abs_error", e.worst).set("at_index", static_cast<std::int64_t>(e.at));
        if (kind != lut_kind::eavg) r.set("at_mu", s.grid.mus[s.format == "csv" ? e.at : i]);
        r.set("at_alpha", s.grid.alpha(j)).set("tolerance_at_max", e.worst_tol)
            .set("above_tolerance", static_cast<std::int64_t>(e.above)).set("histogram", e.histogram).set("pass", e.above == 0);
        rows.push_back(std::move(r));
    }
    table_info info{"lut-check",
                             "An engine's baked table against the exact one at the same texel centres (docs/lut.md)",
                             {"exact values by microfacet/albedo.hpp at tolerance 1e-10 (dfg from an image: a hundredth of each texel's "
                              "tolerance, 1e-10 at least; split_sum_to.hpp); tolerance: what the file's format "
                              "holds (8-bit 0.5/255, 16-bit 0.5/65535, half 2^-11 relative, float 2^-24, CSV half a unit "
                              "in the last digit its column prints) or --tolerance, plus the exact value's bound (with "
                              "the rounding of the coordinates, F0 and parameters typed)",
                              "pass: no texel beyond its tolerance"},
                             {"file", "channel", "texels", "max_abs_error", "at_mu", "at_alpha", "above_tolerance", "histogram"},
                             {}};
    return {info, std::move(rows), path, ""};
}

namespace {

// One line per channel on stdout (with --json, the records are the report).
void print_lut_check(const table_output& out, const console_view& v, const std::string& path) {
    if (v.json) return;
    for (const auto& r : out.records)
        std::cout << "lut-check " << path << " (" << r.text("format") << "), " << r.text("channel") << ": max |error| "
                  << r.number("max_abs_error") << " at alpha " << r.number("at_alpha")
                  << (r.find("at_mu") ? ", mu " + detail::format_number(r.number("at_mu")) : std::string()) << "; "
                  << r.number("above_tolerance") << " of " << r.number("texels") << " above tolerance ("
                  << r.number("tolerance_at_max") << " there); |error| by decade: " << r.text("histogram")
                  << (r.failed() ? "  FAIL" : "") << "\n";
}

}  // namespace

table_output lut_check_output(const std::string& path, lut_kind kind, const mf::composition& c, bool perceptual,
                              std::optional<double> tolerance, unsigned jobs, const part_inputs& parts) {
    table_output out = check_lut_table(path, kind, c, perceptual, tolerance, jobs, parts);
    out.console = [path](const table_output& self, const console_view& v) { print_lut_check(self, v, path); };
    return out;
}

table_output check_lut_file(const std::string& path, const std::string& kind, const std::string& model, const part_inputs& parts,
                            bool perceptual, std::optional<double> tolerance, unsigned jobs) {
    const auto c = composition_of(model, parts, "");  // the caller has checked it
    return check_lut_table(path, lut_kind_of(kind), c, perceptual, tolerance, jobs, parts);
}

}  // namespace verify
