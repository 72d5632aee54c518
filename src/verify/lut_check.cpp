// `verify lut --check FILE` (lut_check.hpp): the table read (a CSV's points, or an image under
// its layout, found by --detect where asked), each value against the exact one, per channel the
// largest error, where, how many texels are beyond their tolerance and a histogram by decade.
#include "lut_check.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <vector>

#include "args.hpp"
#include "lut.hpp"
#include "lut_check_report.hpp"
#include "lut_formats/texels.hpp"
#include "lut_lookup.hpp"
#include "lut_read.hpp"
#include "microfacet_tables.hpp"

namespace verify {

namespace mf = normzoo::microfacet;

namespace {

// A CSV's points as the check reads them: the values as printed, each holding what its digits
// hold and, with encoding=half or unorm, the step of that storage as well.
read_table table_of_csv(const std::string& path, lut_kind kind, const mf::composition& c, const part_inputs& parts, lut_encoding e) {
    const stored_table s = read_csv_table(path, kind, {lut_kind_name(kind), &c, &parts});
    read_table t;
    t.format = s.format, t.width = s.width, t.height = s.height, t.points = s.grid;
    t.channels = lut_channels(kind);
    t.values = s.values;
    for (std::size_t k = 0; k < s.values.size(); ++k) t.tolerance.push_back(s.precision[k] + encoding_step(e, s.values[k]));
    for (std::size_t p = 0; p < s.width; ++p) t.texel.push_back(p);
    return t;
}

layout_search search_of(const lut_reading& reading, lut_kind kind, const std::string& model, const part_inputs& parts, unsigned jobs) {
    layout_search s;
    s.kind = kind, s.start = reading.layout, s.parts = parts, s.jobs = jobs;
    for (const auto& k : reading.given) s.fixed.insert(k.first);
    s.models = reading.model_given ? std::vector<std::string>{model} : baked_models();
    return s;
}

channel_errors errors_of_channel(const read_table& t, const exact_table& exact, std::size_t ch, std::optional<double> tolerance) {
    channel_errors r;
    r.name = t.channels[ch];
    if (t.grid) r.by_row.assign(t.height, 0), r.by_col.assign(t.width, 0);
    std::vector<std::size_t> histogram(9, 0);  // |error| < 1e-8, [1e-8, 1e-7), ..., >= 1e-1
    const std::size_t n = t.channels.size();
    for (std::size_t p = 0; p < t.texel.size(); ++p) {
        const std::size_t k = t.texel[p];
        const auto truth = exact_channel(exact, r.name, p);
        const double stored = t.values[k * n + ch];
        double err = std::abs(stored - truth.value);
        // A texel that is not finite (a NaN or Inf a baker wrote) is counted and never passed:
        // its own precision, relative to it, is not finite either and would pass anything.
        const bool finite = std::isfinite(stored) && !std::isnan(err);
        if (!finite) err = std::numeric_limits<double>::infinity();
        const double tol = (tolerance ? *tolerance : t.tolerance[k * n + ch]) + truth.abs_error;
        if (err > r.worst) r.worst = err, r.at = p, r.worst_tol = tol;
        r.above += !finite || err > tol;
        ++r.count;
        if (t.grid) r.by_row[k / t.width] = std::max(r.by_row[k / t.width], err), r.by_col[k % t.width] = std::max(r.by_col[k % t.width], err);
        // steps <= 255 x 12.92 |error| (the transfer's steepest slope): most texels need no pow
        if (!finite || 13 * 255 * err > r.steps) r.steps = std::max(r.steps, finite ? display_steps(stored, truth.value) : err);
        const int decade = err < 1e-8 ? 0 : err >= 0.1 ? 8 : int(std::floor(std::log10(err))) + 9;
        ++histogram[std::size_t(decade)];
    }
    const char* labels[] = {"<1e-8", "1e-8", "1e-7", "1e-6", "1e-5", "1e-4", "1e-3", "1e-2", ">=1e-1"};
    for (std::size_t b = 0; b < histogram.size(); ++b)
        if (histogram[b]) r.histogram += (r.histogram.empty() ? "" : " ") + std::string(labels[b]) + ":" + std::to_string(histogram[b]);
    return r;
}

// E = F0 A + B from a split-sum table's stored channels (A, B, or either beside A+B), against
// the exact pair.
e_errors errors_of_e(const read_table& t, const exact_table& exact, double f0) {
    e_errors r;
    const std::size_t n = t.channels.size();
    auto at = [&](const std::string& name) { return std::size_t(std::find(t.channels.begin(), t.channels.end(), name) - t.channels.begin()); };
    const std::size_t ia = at("A"), ib = at("B"), is = at("A+B");
    for (std::size_t p = 0; p < t.texel.size(); ++p) {
        const double* v = &t.values[t.texel[p] * n];
        const double a = ia < n ? v[ia] : v[is] - v[ib], b = ib < n ? v[ib] : v[is] - v[ia];
        const double truth = f0 * exact.values[2 * p].value + exact.values[2 * p + 1].value, stored = f0 * a + b;
        const double err = std::abs(stored - truth);
        if (std::isnan(err) || !std::isfinite(err)) return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
        r.worst = std::max(r.worst, err);
        if (13 * 255 * err > r.steps) r.steps = std::max(r.steps, display_steps(stored, truth));  // as above
    }
    return r;
}

// A texel whose verdict a looser bound could flip (its error within that bound of its tolerance,
// either side: the looser exact value can as well put a texel beyond its tolerance inside it) is
// computed again at 1e-10: every verdict is the one at 1e-10 (docs/lut.md, "How a check chooses
// its accuracy"). The texels of an image or a CSV, any kind: a split-sum texel is undecided where
// a stored channel that reads a looser A or B is.
void settle_undecided(const read_table& t, lut_kind kind, exact_table& exact, const mf::composition& c,
                      std::optional<double> tolerance, unsigned jobs) {
    lut_grid again = t.points;
    again.mus.clear(), again.roughness.clear(), again.mu_delta.clear(), again.alpha_delta.clear();
    const std::size_t n = t.channels.size(), per = exact.channels;
    std::vector<char> reads_a(n), reads_b(n);  // per channel, once: not a text per texel
    for (std::size_t ch = 0; ch < n; ++ch) reads_a[ch] = t.channels[ch] != "B", reads_b[ch] = per == 2 && t.channels[ch] != "A";
    std::vector<std::size_t> points;
    for (std::size_t p = 0; p < t.texel.size(); ++p) {
        bool undecided = false;
        for (std::size_t ch = 0; ch < n; ++ch) {
            const auto truth = exact_channel(exact, t.channels[ch], p);
            // computed looser than 1e-10: A's bound (or E's), B's, or either for A+B
            const bool looser = (reads_a[ch] && exact.values[per * p].abs_error > 1e-10) ||
                                (reads_b[ch] && exact.values[per * p + 1].abs_error > 1e-10);
            const double err = std::abs(t.values[t.texel[p] * n + ch] - truth.value);
            const double tol = tolerance ? *tolerance : t.tolerance[t.texel[p] * n + ch];
            // 2e-10 more: where the bound at 1e-10 itself, on either side, could still move it
            undecided = undecided || (looser && std::abs(err - tol) <= truth.abs_error + 2e-10);
        }
        if (!undecided) continue;
        points.push_back(p);
        if (!t.points.mus.empty()) again.mus.push_back(t.points.mus[p]);  // E_avg reads none
        again.roughness.push_back(t.points.roughness[p]);
        if (!t.points.mu_delta.empty()) again.mu_delta.push_back(t.points.mu_delta[p]);  // a list's decimals
        if (!t.points.alpha_delta.empty()) again.alpha_delta.push_back(t.points.alpha_delta[p]);
    }
    if (points.empty()) return;
    const exact_table settled = exact_lut(kind, c, again, jobs);
    for (std::size_t m = 0; m < points.size(); ++m)
        for (std::size_t ch = 0; ch < per; ++ch) exact.values[points[m] * per + ch] = settled.values[m * per + ch];
}

// A lookup's largest error and where, as `prefix` names it (lookup_at_mu, lookup_dielectric_at_mu).
void set_lookup_worst(record& r, const char* error_key, const std::string& prefix, const lookup_worst& w, lut_kind kind, bool perceptual) {
    r.set(error_key, w.error);
    if (kind != lut_kind::eavg) r.set(prefix + "_at_mu", w.mu);
    if (perceptual) r.set(prefix + "_at_r", w.roughness);
    r.set(prefix + "_at_alpha", w.alpha);
}

// The lookup's error beside the storage's (docs/lut.md, "The lookup's error"): channel ch's, and
// for a split-sum table that of E at F0 = 0.04 and 1.
void set_lookup_keys(record& r, const lookup_errors& l, std::size_t ch, lut_kind kind, bool perceptual) {
    r.set("lookup_points", static_cast<std::int64_t>(l.points));
    set_lookup_worst(r, "max_lookup_error", "lookup", l.channels[ch], kind, perceptual);
    r.set("max_interpolation_error", l.channels[ch].between);
    if (!l.dielectric) return;
    set_lookup_worst(r, "max_lookup_error_dielectric", "lookup_dielectric", *l.dielectric, kind, perceptual);
    set_lookup_worst(r, "max_lookup_error_metal", "lookup_metal", *l.metal, kind, perceptual);
}

// One lut-check record per channel.
std::vector<record> check_records(const std::string& path, const read_table& t, lut_kind kind, const mf::composition& c,
                                  const part_inputs& parts, const lut_check_report& rep) {
    const f0_value f0 = kind == lut_kind::dfg ? f0_value{} : f0_of(parts);
    std::vector<record> rows;
    for (const auto& e : rep.channels) {
        record r{"lut-check", {}};
        r.set("file", path).set("format", t.format).set("kind", lut_kind_name(kind)).set("model", c.id);
        set_part_keys(r, c, parts, kind == lut_kind::dfg ? std::nullopt : std::optional<double>(f0.f0));
        r.set("channel", e.name).set("texels", static_cast<std::int64_t>(e.count)).set("layout", rep.layout);
        if (rep.not_compared) r.set("not_compared", static_cast<std::int64_t>(rep.not_compared));
        r.set("max_abs_error", e.worst).set("at_index", static_cast<std::int64_t>(t.texel[e.at]));
        if (kind != lut_kind::eavg) r.set("at_mu", t.points.mus[e.at]);
        const double alpha = t.points.alpha(e.at);
        if (t.points.perceptual) r.set("at_r", t.points.roughness[e.at]);
        r.set("at_alpha", alpha).set("tolerance_at_max", e.worst_tol);
        if (rep.dielectric) r.set("max_error_dielectric", rep.dielectric->worst).set("max_error_metal", rep.metal->worst);
        if (rep.lookup) set_lookup_keys(r, *rep.lookup, std::size_t(&e - rep.channels.data()), kind, t.points.perceptual);
        r.set("above_tolerance", static_cast<std::int64_t>(e.above)).set("histogram", e.histogram);
        if (rep.detected) {
            nlohmann::ordered_json list = nlohmann::ordered_json::array();
            for (std::size_t i = 0; i < std::min<std::size_t>(10, rep.detected->ranked.size()); ++i) {
                const auto& d = rep.detected->ranked[i];
                const double err = d.max_abs_error;
                list.push_back({{"layout", layout_text(d.layout, kind)}, {"model", d.model},
                                {"max_abs_error", std::isfinite(err) ? nlohmann::ordered_json(err) : nlohmann::ordered_json(nullptr)}});
            }
            r.set("candidates", json_text{list.dump()});
        }
        r.set("pass", e.above == 0);
        rows.push_back(std::move(r));
    }
    return rows;
}

table_info check_info() {
    return {"lut-check",
            "An engine's baked table against the exact one at the coordinates its layout gives its texels (docs/lut.md)",
            {"exact values by microfacet/albedo.hpp at tolerance 1e-10 (dfg: a hundredth of each texel's "
             "tolerance, 1e-10 at least; split_sum_to.hpp); tolerance: what the file's storage holds (8-bit "
             "0.5/255, 16-bit 0.5/65535, half 2^-11 relative, float 2^-24, CSV half a unit in the last digit its column "
             "prints; with encoding=half or unorm that step as well, through the decode for srgb and rgbd) or --tolerance, "
             "plus the exact value's bound (with the rounding of the coordinates, F0 and parameters typed)",
             "pass: no texel beyond its tolerance"},
            {"file", "channel", "texels", "max_abs_error", "at_mu", "at_alpha", "above_tolerance", "histogram"},
            {},
            std::nullopt,
            std::nullopt,
            // a JUnit case per file, model, slice and channel (a table of slices: one per slice)
            {"file", "kind", "model", "f0_input", "eta_input", "slice", "channel"}};
}

// The table read (a CSV, or an image under its layout or the one --detect finds), checked.
struct checked {
    table_output out;
    lut_check_report report;
    std::optional<decoded_lut> image;  // for the hint
    std::optional<lut_error_map> map;  // an image's: the figure --out draws
};

// slice: one slice of a table of slices (size=WxHxD), read already and shaped under `reading`,
// whose lookup is not measured (its table is looked up between slices too); whole: that table's
// layout, which the report and records name.
checked check(const std::string& path, lut_kind kind, const mf::composition& c, const lut_reading& reading,
              std::optional<double> tolerance, unsigned jobs, const part_inputs& parts, const decoded_lut* slice = nullptr,
              const lut_layout* whole = nullptr) {
    checked r;
    r.report.path = path;
    std::string model = c.id;
    mf::composition used = c;
    read_table t;
    if (std::filesystem::path(path).extension() == ".csv") {
        t = table_of_csv(path, kind, c, parts, reading.layout.encoding);
        r.report.layout = "encoding=" + encoding_name(reading.layout.encoding);
        for (std::size_t p = 0; p < t.texel.size(); ++p)  // a coordinate no double holds: its rounding is measured
            r.report.rounded_points += t.points.alpha_delta[p] > 0 || (!t.points.mu_delta.empty() && t.points.mu_delta[p] > 0);
    } else {
        lut_layout layout = reading.layout;
        if (reading.detect) {
            detected_table found = detect_table(path, reading, kind, search_of(reading, kind, c.id, parts, jobs));
            r.image = std::move(found.image), r.report.detected = std::move(found.ranking);
            if (r.report.detected->ranked.empty()) throw bad_input(path + ": --detect has no layout to try with the keys given");
            layout = r.report.detected->ranked.front().layout, model = r.report.detected->ranked.front().model;
        } else {
            r.image = slice ? *slice : shaped_lut(read_laid_out(path, reading, kind), reading.layout, kind, path);
        }
        used = model == c.id ? c : composition_of(model, parts, "lut: --model: ");
        t = lay_out(*r.image, layout, kind, &used);  // a split-sum table's edges at the model's limits
        r.report.layout = layout_text(whole ? *whole : layout, kind);
        r.report.not_compared = t.width * t.height - t.texel.size();
        if (t.texel.empty()) throw bad_input(path + ": no texel to compare (every one at r = 0 or mu = 0)");
    }
    r.report.model = used.id;
    r.report.grid = t.grid, r.report.row_coord = t.row_coord, r.report.col_coord = t.col_coord;
    r.report.row_axis = t.row_axis, r.report.col_axis = t.col_axis;
    const f0_value f0 = kind == lut_kind::dfg ? f0_value{} : f0_of(parts);  // the split-sum pair takes none
    t.points.f0 = f0.f0, t.points.f0_delta = f0.delta, t.points.parts = parts;
    // each value to a hundredth of its tolerance, 1e-10 at least (docs/lut.md, "How a check chooses
    // its accuracy")
    const std::vector<double> wanted = wanted_tolerances(t, kind, tolerance, t.texel);
    exact_table exact;  // each compared texel at its own coordinates
    try {
        exact = exact_lut(kind, used, t.points, jobs, &wanted);
        settle_undecided(t, kind, exact, used, tolerance, jobs);
    } catch (const bad_input& e) {  // a CSV's edge (mu = 0, alpha = 0) of a model without its limits
        throw bad_input(path + ": " + e.what());
    }
    for (std::size_t ch = 0; ch < t.channels.size(); ++ch) r.report.channels.push_back(errors_of_channel(t, exact, ch, tolerance));
    if (kind == lut_kind::dfg) r.report.dielectric = errors_of_e(t, exact, 0.04), r.report.metal = errors_of_e(t, exact, 1);
    if (t.grid) {  // an image, as a shader samples it; a CSV's points are no texture
        if (!slice) r.report.lookup = measure_lookup(t, kind, used, tolerance, jobs);
        r.map = error_map_of(t, exact, kind, tolerance);
    }
    r.out = {check_info(), check_records(path, t, kind, used, parts, r.report), path, ""};
    return r;
}

// A table of slices (size=WxHxD, docs/lut.md, "Slices"): the file read once, each slice shaped
// as a table of its own and checked at its index eta (reading.slice_eta), its records with its
// place, `slice`; the report of each, and of the worst slice's error map.
struct checked_slices {
    table_output out;
    std::vector<lut_check_report> reports;
    std::size_t worst = 0;  // the slice whose largest error is the largest
    std::optional<lut_error_map> map;
};

checked_slices check_slices(const std::string& path, lut_kind kind, const mf::composition& c, const lut_reading& reading,
                            std::optional<double> tolerance, unsigned jobs, const part_inputs& parts) {
    const lut_layout& l = reading.layout;
    const decoded_lut all = slices_of(read_laid_out(path, reading, kind), l, path);
    lut_reading one = reading;
    one.layout.slices = 1, one.slice_eta.clear();
    checked_slices r;
    double worst = -1;
    for (std::size_t k = 0; k < l.slices; ++k) {
        part_inputs at = parts;
        at.eta = reading.slice_eta[k];
        const mf::composition ck = composition_of(c.id, at, "lut: --model: ");
        const decoded_lut image = shaped_lut(decoded_slice(all, l.width, l.height, k), one.layout, kind, path);
        checked x = check(path, kind, ck, one, tolerance, jobs, at, &image, &l);
        for (auto& rec : x.out.records) {
            rec.set("slice", static_cast<std::int64_t>(k));
            if (rec.number("max_abs_error") > worst) worst = rec.number("max_abs_error"), r.worst = k, r.map = x.map;
        }
        if (k == 0) r.out = std::move(x.out);
        else r.out.records.insert(r.out.records.end(), x.out.records.begin(), x.out.records.end());
        r.reports.push_back(std::move(x.report));
    }
    return r;
}

// Where a failing image reads far better (a tenth of the error or less on the subsample) under
// another layout or model than the one checked, any key free: that reading, for the console, and
// the --layout keys and --model that --detect would have to drop to find it.
std::string wrong_layout_hint(const decoded_lut& d, lut_kind kind, const lut_reading& reading, const lut_check_report& rep,
                              const part_inputs& parts, unsigned jobs) {
    layout_search any = search_of(lut_reading{}, kind, rep.model, parts, jobs);
    any.start.width = reading.layout.width, any.start.height = reading.layout.height;
    const layout_ranking all = rank_layouts(d, any);
    layout_search as_checked = any;
    apply_layout_keys(as_checked.start, parse_layout_keys(rep.layout, "layout"));
    as_checked.fixed = {"rows", "cols", "row0", "col0", "grid", "channels", "encoding", "size"};
    as_checked.models = {rep.model};
    const layout_ranking now = rank_layouts(d, as_checked);
    if (all.ranked.empty() || now.ranked.empty()) return "";
    const auto& best = all.ranked.front();
    const double before = now.ranked.front().max_abs_error;
    if (!(best.max_abs_error * 10 <= before)) return "";
    std::string drop;  // what the user fixed that the better reading changes
    const layout_keys found = parse_layout_keys(layout_text(best.layout, kind), "layout");
    for (const auto& key : reading.given)
        if (key.first != "size" && key.first != "encoding" && std::find(found.begin(), found.end(), key) == found.end())
            drop += " --layout " + key.first + "=" + key.second;
    if (reading.model_given && best.model != rep.model) drop += " --model " + rep.model;
    return "lut-check: " + rep.path + " reads far better as " + layout_text(best.layout, kind) + " with " + best.model +
           " (max |error| " + detail::format_number(best.max_abs_error) + " against " + detail::format_number(before) +
           " as checked, on " + std::to_string(all.texels) + " texels): try --detect" + (drop.empty() ? "" : " without" + drop);
}

// lut-check-STEM.svg, the stem of the file checked with what is not a letter, digit, '.', '-' or
// '_' replaced by '_': a name that stays in the output folder and needs no quoting.
std::string figure_name(const std::string& path) {
    std::string stem = std::filesystem::path(path).stem().string();
    for (char& ch : stem)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '-' && ch != '_') ch = '_';
    return "lut-check-" + stem + ".svg";
}

}  // namespace

table_output check_lut_table(const std::string& path, lut_kind kind, const mf::composition& c, const lut_reading& reading,
                             std::optional<double> tolerance, unsigned jobs, const part_inputs& parts) {
    if (reading.layout.slices > 1) return check_slices(path, kind, c, reading, tolerance, jobs, parts).out;
    return check(path, kind, c, reading, tolerance, jobs, parts).out;
}

namespace {

table_output sliced_output(const std::string& path, lut_kind kind, const mf::composition& c, const lut_reading& reading,
                           std::optional<double> tolerance, unsigned jobs, const part_inputs& parts) {
    checked_slices r = check_slices(path, kind, c, reading, tolerance, jobs, parts);
    auto drawn = std::make_shared<bool>(false);
    lut_check_report& worst = r.reports[r.worst];
    if (r.map) {
        worst.figure = figure_name(path);
        const std::string title = std::filesystem::path(path).filename().string() + ", slice " + std::to_string(r.worst) + " (eta " +
                                  r.out.records[r.worst * worst.channels.size()].text("eta_input") + "): " + worst.model;
        r.out.own_files = [map = std::move(*r.map), name = worst.figure, title, drawn](const table_output&, file_set& files) {
            *drawn = plot_lut_check(map, name, title, files);
        };
    }
    r.out.console = [reports = std::move(r.reports), at = r.worst, drawn](const table_output& self, const console_view& v) {
        print_lut_check_slices(self, v, reports, at, *drawn);
    };
    return std::move(r.out);
}

}  // namespace

table_output lut_check_output(const std::string& path, lut_kind kind, const mf::composition& c, const lut_reading& reading,
                              std::optional<double> tolerance, unsigned jobs, const part_inputs& parts) {
    if (reading.layout.slices > 1) return sliced_output(path, kind, c, reading, tolerance, jobs, parts);
    checked r = check(path, kind, c, reading, tolerance, jobs, parts);
    const bool failed = std::any_of(r.out.records.begin(), r.out.records.end(), [](const record& x) { return x.failed(); });
    if (failed && r.image && !reading.detect) r.report.hint = wrong_layout_hint(*r.image, kind, reading, r.report, parts, jobs);
    // With --out: the error map, staged with the run's files (docs/lut.md, "The error map")
    auto drawn = std::make_shared<bool>(false);
    if (r.map) {
        r.report.figure = figure_name(path);
        const std::string title = std::filesystem::path(path).filename().string() + ": " + r.report.layout + ", " + r.report.model;
        r.out.own_files = [map = std::move(*r.map), name = r.report.figure, title, drawn](const table_output&, file_set& files) {
            *drawn = plot_lut_check(map, name, title, files);
        };
    }
    r.out.console = [rep = std::move(r.report), drawn](const table_output& self, const console_view& v) {
        print_lut_check(self, v, rep, *drawn);
    };
    return std::move(r.out);
}

table_output check_lut_file(const std::string& path, const std::string& kind, const std::string& model, const part_inputs& parts,
                            bool perceptual, std::optional<double> tolerance, unsigned jobs) {
    const auto c = composition_of(model, parts, "");  // the caller has checked it
    lut_reading reading;
    reading.layout.rows = perceptual ? lut_axis::r : lut_axis::alpha;
    return check_lut_table(path, lut_kind_of(kind), c, reading, tolerance, jobs, parts);
}

}  // namespace verify
