// The console report of `verify lut --check FILE` (lut_check_report.hpp).
#include "lut_check_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace verify {

double display_steps(double a, double b) {
    // the sRGB transfer, encoded (IEC 61966-2-1), as an 8-bit display shows a linear value
    auto encode = [](double x) {
        x = std::clamp(x, 0.0, 1.0);
        return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
    };
    return std::abs(encode(a) - encode(b)) * 255;
}

namespace {

std::string short_number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
}

// "coordinate: error" per row (or column), in file order; beyond 16, the largest error of each of
// 16 bands of consecutive rows, named by their first and last coordinates.
std::string series(const std::vector<double>& coords, const std::vector<double>& errors) {
    const std::size_t n = coords.size(), per = n <= 16 ? 1 : (n + 15) / 16;
    std::string s;
    for (std::size_t from = 0; from < n; from += per) {
        const std::size_t to = std::min(n, from + per) - 1;
        const double worst = *std::max_element(errors.begin() + long(from), errors.begin() + long(to) + 1);
        s += (s.empty() ? "" : ", ") + short_number(coords[from]) + (to > from ? ".." + short_number(coords[to]) : "") + ": " +
             short_number(worst);
    }
    return s;
}

// The keys of b that differ from a's ("grid=edges row0=high"), and b's model where it differs.
std::string differences(const layout_candidate& a, const layout_candidate& b) {
    const layout_keys ka = parse_layout_keys(layout_text(a.layout, lut_kind::dfg), "layout");
    const layout_keys kb = parse_layout_keys(layout_text(b.layout, lut_kind::dfg), "layout");
    std::string s;
    for (std::size_t i = 0; i < kb.size(); ++i)
        if (i >= ka.size() || ka[i] != kb[i]) s += (s.empty() ? "" : " ") + kb[i].first + "=" + kb[i].second;
    if (a.model != b.model) s += (s.empty() ? "" : " ") + b.model;
    return s.empty() ? "the same" : s;
}

// The detected layout and the next ones (what they change), with their largest errors on the subsample.
std::string detected_line(const lut_check_report& r) {
    const auto& ranked = r.detected->ranked;
    std::string s = "  --detect: best of " + std::to_string(ranked.size()) + " readings on " + std::to_string(r.detected->texels) +
                    " texels (max |error| " + short_number(ranked.front().max_abs_error) + ")";
    for (std::size_t i = 1; i < std::min<std::size_t>(4, ranked.size()); ++i)
        s += std::string(i == 1 ? "; next: " : ", ") + differences(ranked.front(), ranked[i]) + " " + short_number(ranked[i].max_abs_error);
    return s;
}

// "max |error| 0.0123 at alpha 0.25, mu 0.0039" of a lookup (a table of E_avg has no mu).
std::string lookup_text(const lookup_worst& w, bool with_mu, bool by_r, bool full = true) {
    if (w.error < 0) return "not measured";
    std::ostringstream s;
    const double rough = by_r ? std::sqrt(w.alpha) : w.alpha;  // in the table's own roughness
    const char* at = by_r ? " at r " : " at alpha ";
    if (full) s << "max |error| " << w.error << at << rough;
    else s << short_number(w.error) << at << short_number(rough);
    if (with_mu) s << ", mu " << (full ? detail::format_number(w.mu) : short_number(w.mu));
    s << " (between the texels " << short_number(w.between) << ")";
    return s.str();
}

}  // namespace

void print_lut_check(const table_output& out, const console_view& v, const lut_check_report& r, bool drawn) {
    const bool by_r = r.row_axis == lut_axis::r || r.col_axis == lut_axis::r;
    if (drawn && v.written)
        std::cerr << "verify lut: error map -> " << (std::filesystem::path(v.out_dir) / r.figure).string() << "\n";
    if (v.json) {  // the records are the report; the hint goes with the failures, on stderr
        if (!r.hint.empty()) std::cerr << r.hint << "\n";
        return;
    }
    for (const auto& x : out.records) {
        std::cout << "lut-check " << r.path << " (" << x.text("format") << "), " << x.text("channel") << ": max |error| "
                  << x.number("max_abs_error")  // in the table's own roughness: r where it is indexed by r
                  << (x.find("at_r") ? " at r " + detail::format_number(x.number("at_r")) : " at alpha " + detail::format_number(x.number("at_alpha")))
                  << (x.find("at_mu") ? ", mu " + detail::format_number(x.number("at_mu")) : std::string()) << "; "
                  << x.number("above_tolerance") << " of " << x.number("texels") << " above tolerance ("
                  << x.number("tolerance_at_max") << " there); |error| by decade: " << x.text("histogram")
                  << (x.failed() ? "  FAIL" : "") << "\n";
        if (r.lookup)  // a record per channel, in the channels' order
            std::cout << "  " << x.text("channel") << ", looked up "
                      << lookup_text(r.lookup->channels[std::size_t(&x - out.records.data())], !r.col_coord.empty(), by_r) << "\n";
    }
    std::cout << "  layout " << r.layout << ", model " << r.model
              << (r.not_compared ? "; " + std::to_string(r.not_compared) + " texels at r = 0 or mu = 0 not compared" : std::string())
              << (r.grid ? std::string() : "; " + std::to_string(r.rounded_points) + " of " + std::to_string(r.channels.front().count) +
                                               " points with a coordinate no double holds (its rounding measured)")
              << "\n";
    if (r.detected) std::cout << detected_line(r) << "\n";
    if (r.grid)
        for (const auto& c : r.channels) {
            std::cout << "  " << c.name << ", largest |error| by row (" << axis_name(r.row_axis) << "): " << series(r.row_coord, c.by_row) << "\n";
            if (!r.col_coord.empty())
                std::cout << "  " << c.name << ", by column (" << axis_name(r.col_axis) << "): " << series(r.col_coord, c.by_col) << "\n";
        }
    std::cout << "  in 8-bit display steps (sRGB-encoded, 1/255):";
    for (const auto& c : r.channels) std::cout << " " << c.name << " " << short_number(c.steps) << (&c == &r.channels.back() ? "" : ",");
    if (r.dielectric)
        std::cout << "; E = F0 A + B at F0 = 0.04 " << short_number(r.dielectric->steps) << " (|error| "
                  << short_number(r.dielectric->worst) << "), at F0 = 1 " << short_number(r.metal->steps) << " (|error| "
                  << short_number(r.metal->worst) << ")";
    std::cout << "\n";
    if (r.lookup && r.lookup->dielectric)
        std::cout << "  E = F0 A + B looked up, at F0 = 0.04: " << lookup_text(*r.lookup->dielectric, true, by_r, false) << "; at F0 = 1: "
                  << lookup_text(*r.lookup->metal, true, by_r, false) << "\n";
    if (r.lookup)
        std::cout << "  (bilinear between the texels, clamped to the edge, at " << r.lookup->points
                  << " points between and beyond them: docs/lut.md, \"The lookup's error\")\n";
    if (!r.hint.empty()) std::cout << r.hint << "\n";
}

void print_lut_check_slices(const table_output& out, const console_view& v, const std::vector<lut_check_report>& reports,
                            std::size_t worst, bool drawn) {
    const lut_check_report& w = reports[worst];
    const std::size_t channels = w.channels.size();
    if (!v.json) {
        std::size_t failing = 0;
        for (std::size_t k = 0; k < reports.size(); ++k)
            failing += std::any_of(out.records.begin() + std::ptrdiff_t(k * channels), out.records.begin() + std::ptrdiff_t((k + 1) * channels),
                                   [](const record& x) { return x.failed(); });
        std::cout << "lut-check " << w.path << ": " << reports.size() << " slices, " << failing << " failing; layout " << w.layout << ", model "
                  << w.model << "\n";
        for (const auto& x : out.records)
            std::cout << "  slice " << x.number("slice") << " (eta " << x.text("eta_input") << "), " << x.text("channel") << ": max |error| "
                      << short_number(x.number("max_abs_error")) << "; " << x.number("above_tolerance") << " of " << x.number("texels")
                      << " above tolerance" << (x.failed() ? "  FAIL" : "") << "\n";
        std::cout << "the slice with the largest error, " << worst << ":\n";
    }
    table_output one = out;
    one.records.assign(out.records.begin() + std::ptrdiff_t(worst * channels), out.records.begin() + std::ptrdiff_t((worst + 1) * channels));
    print_lut_check(one, v, w, drawn);
}

}  // namespace verify
