#include "lut.hpp"

#include <normzoo/albedo_input.hpp>
#include <normzoo/detail/parallel.hpp>
#include <normzoo/microfacet/multiple_scattering.hpp>
#include <normzoo/microfacet/split_sum.hpp>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "args.hpp"
#include "command_line.hpp"
#include "lut_image.hpp"
#include "microfacet_shortcuts.hpp"
#include "microfacet_tables.hpp"
#include "writers.hpp"

namespace verify {

namespace mf = normzoo::microfacet;
using normzoo::record;

namespace {

enum class lut_kind { dfg, e, eavg };

struct lut_grid {
    std::vector<double> mus;        // columns (empty for Eavg)
    std::vector<double> roughness;  // rows: r or alpha as given
    bool perceptual = true;         // roughness is r, alpha = r^2
    // Listed decimals: how far each mu and each alpha computed at can be from the one typed
    // (microfacet_tables.hpp, mu_of and alpha_of); empty at texel centres, which doubles hold.
    std::vector<double> mu_delta, alpha_delta;
    double f0 = 1, f0_delta = 0;  // E and Eavg: the F0 of the composition's F part (--f0), as typed
    part_inputs parts;            // the parts' parameters as typed (set in the composition too)
    bool points = false;          // a list of points (a CSV's rows): roughness[j] goes with mus[j]
    double alpha(std::size_t j) const { return perceptual ? roughness[j] * roughness[j] : roughness[j]; }
};

// Texel centres of an n-texel axis: (i + 0.5) / n (docs/lut.md, "Texel centres").
std::vector<double> centres(std::size_t n) {
    std::vector<double> c(n);
    for (std::size_t i = 0; i < n; ++i) c[i] = (double(i) + 0.5) / double(n);
    return c;
}

std::string kind_name(lut_kind k) { return k == lut_kind::dfg ? "dfg" : k == lut_kind::e ? "E" : "Eavg"; }

std::vector<std::string> channels_of(lut_kind k) {
    if (k == lut_kind::dfg) return {"A", "B"};
    return {k == lut_kind::e ? "E" : "E_avg"};
}

// The exact table: values[(j * width + i) * channels + c] with their bounds.
struct exact_table {
    std::size_t width = 0, height = 0, channels = 0;
    std::vector<normzoo::quadrature::estimate<double>> values;
};

using estimate = normzoo::quadrature::estimate<double>;

// The exact channels of one texel or point (one for E and Eavg, A and B for dfg); mu is not read
// for Eavg; terms: Kulla-Conty's at this alpha and f0, or null.
std::array<estimate, 2> exact_texel(lut_kind kind, const mf::composition& c, double mu, double alpha, double f0,
                                    const std::vector<mf::kulla_conty_terms>* terms) {
    if (kind == lut_kind::eavg) return {mf::average_albedo(c, alpha, f0), estimate{}};
    if (kind == lut_kind::e)
        return {mf::compensated_albedo(c, mu, alpha, f0, {}, terms ? terms->data() : nullptr, terms ? terms->size() : 0), estimate{}};
    const auto s = mf::split_sum(c, mu, alpha);
    return {s.a, s.b};
}

exact_table compute(lut_kind kind, const mf::composition& c, const lut_grid& g, unsigned jobs) {
    exact_table t;
    const bool one_row = kind == lut_kind::eavg || g.points;  // texel k has roughness k
    t.width = one_row ? g.roughness.size() : g.mus.size();
    t.height = one_row ? 1 : g.roughness.size();
    t.channels = kind == lut_kind::dfg ? 2 : 1;
    t.values.resize(t.width * t.height * t.channels);
    // Kulla-Conty's terms of alpha alone, once per row of an E table (and at its rounded inputs'
    // steps); a list's points share those of their roughness
    std::vector<std::vector<mf::kulla_conty_terms>> terms;
    std::vector<std::size_t> terms_of(g.roughness.size());  // roughness j -> its terms
    if (kind == lut_kind::e && c.compensation == mf::composition::compensation_kind::kulla_conty) {
        auto delta = [&](std::size_t j) { return g.alpha_delta.empty() ? 0.0 : g.alpha_delta[j]; };
        std::vector<std::size_t> first;  // a roughness of each set of terms
        std::map<std::pair<double, double>, std::size_t> set_of;  // (alpha, its delta) -> set
        for (std::size_t j = 0; j < g.roughness.size(); ++j) {
            const auto [at, added] = set_of.emplace(std::make_pair(g.alpha(j), delta(j)), first.size());
            if (added) first.push_back(j);
            terms_of[j] = at->second;
        }
        terms.resize(first.size());
        normzoo::detail::parallel_for(terms.size(), jobs, [&](std::size_t m) {
            terms[m] = kulla_conty_row(c, g.alpha(first[m]), delta(first[m]), g.f0, g.f0_delta, g.parts);
        });
    }
    auto terms_at = [&](std::size_t j) { return terms.empty() ? nullptr : &terms[terms_of[j]]; };
    // channel ch of the texel at (mu, alpha, f0) of row j
    auto texel = [&](double mu, double alpha, double f0, std::size_t j, std::size_t ch) {
        return exact_texel(kind, c, mu, alpha, f0, terms_at(j))[ch];
    };
    normzoo::detail::parallel_for(t.width * t.height, jobs, [&](std::size_t k) {
        const std::size_t i = kind == lut_kind::eavg ? 0 : g.points ? k : k % t.width, j = one_row ? k : k / t.width;
        const double mu = kind == lut_kind::eavg ? 1.0 : g.mus[i], alpha = g.alpha(j);
        const auto v = exact_texel(kind, c, mu, alpha, g.f0, terms_at(j));
        for (std::size_t ch = 0; ch < t.channels; ++ch) t.values[k * t.channels + ch] = v[ch];
        // listed decimals: what their rounding to double can move, channel by channel
        for (std::size_t ch = 0; ch < t.channels; ++ch) {
            auto& e = t.values[k * t.channels + ch];
            double moved = 0;
            if (!g.alpha_delta.empty())
                moved += normzoo::albedo_input_rounding([&](double a) { return texel(mu, a, g.f0, j, ch); }, alpha, g.alpha_delta[j], e);
            if (!g.mu_delta.empty() && kind != lut_kind::eavg)
                moved += normzoo::albedo_input_rounding([&](double m) { return texel(m, alpha, g.f0, j, ch); }, mu, g.mu_delta[i], e, 1.0);
            if (g.f0_delta > 0)
                moved += normzoo::albedo_input_rounding([&](double f) { return texel(mu, alpha, f, j, ch); }, g.f0, g.f0_delta, e, 1.0);
            moved += part_inputs_rounding(c, g.parts, e, [&](const mf::composition& m) {  // Kulla-Conty's terms move too
                return exact_texel(kind, m, mu, alpha, g.f0, terms_at(j))[ch];
            });
            e.abs_error += moved;
        }
    });
    return t;
}

table_output records_of(lut_kind kind, const mf::composition& c, const lut_grid& g, const exact_table& t) {
    std::vector<record> rows;
    const auto names = channels_of(kind);
    for (std::size_t j = 0; j < t.height; ++j)
        for (std::size_t i = 0; i < t.width; ++i) {
            const std::size_t row = kind == lut_kind::eavg ? i : j;
            record r{"lut", {}};
            r.set("kind", kind_name(kind)).set("model", c.id);
            r.set("alpha", g.alpha(row));
            if (g.perceptual) r.set("r", g.roughness[row]);
            if (kind != lut_kind::eavg) r.set("mu", g.mus[i]);
            set_part_keys(r, c, g.parts, kind == lut_kind::dfg ? std::nullopt : std::optional<double>(g.f0));
            bool finite = true;
            for (std::size_t ch = 0; ch < t.channels; ++ch) {
                const auto& v = t.values[(j * t.width + i) * t.channels + ch];
                r.set(names[ch], v.value).set(t.channels > 1 ? names[ch] + "_error_estimate" : "error_estimate", v.abs_error);
                finite = finite && std::isfinite(v.value) && !std::isnan(v.abs_error);
            }
            if (!finite) r.set("pass", false);  // an integral that broke is a failure, never a value
            rows.push_back(std::move(r));
        }
    normzoo::table_info info{"lut",
                             "A baked table, exact: the split-sum pair (A, B), E(mu, alpha) or E_avg(alpha) of a "
                             "composition (docs/lut.md)",
                             {"each value by microfacet/albedo.hpp (split_sum.hpp, multiple_scattering.hpp) at tolerance "
                              "1e-10 absolute; *error_estimate: its bound",
                              "texels: rows are roughness (r, alpha = r^2, or alpha), columns mu; texel centres (i + 0.5)/N"},
                             {"alpha", "mu", names[0], names.size() > 1 ? names[1] : "error_estimate"},
                             {names[0]}};
    return {info, std::move(rows), "", ""};
}

lut_image image_of(const exact_table& t) {
    lut_image im{t.width, t.height, t.channels, {}};
    for (const auto& v : t.values) im.data.push_back(v.value);
    return im;
}

// The digits a decimal was printed with: after the point (less the exponent: 1.5e-3 has 4) and
// significant ones (from the first nonzero digit).
struct printed_digits {
    long decimals = 0, significant = 0;
};
printed_digits digits_of(const std::string& cell) {
    const auto e = cell.find_first_of("eE");
    const std::string mantissa = cell.substr(0, e);
    const long exponent = e == std::string::npos ? 0 : std::strtol(cell.c_str() + e + 1, nullptr, 10);
    const auto dot = mantissa.find('.');
    printed_digits d;
    d.decimals = (dot == std::string::npos ? 0 : long(mantissa.size() - dot - 1)) - exponent;
    bool leading = true;
    for (char ch : mantissa)
        if (ch >= '0' && ch <= '9') {
            leading = leading && ch == '0';
            d.significant += !leading;
        }
    return d;
}

// What a CSV cell holds of the value printed: half a unit in the last digit the column prints,
// as fixed decimals or as significant digits, whichever is coarser at this value. The column's
// finest cell shows its format: a value printed "0.5" beside others of 17 digits is exact
// (shortest round-trip printing of doubles); beside "0.123457" it is 0.5 to 6 digits. A column
// of at most 9 significant digits may be floats printed shortest (0.33333334 reads back as the
// float, not as the double): it holds what a float holds as well, 2^-24 relative.
double printed_precision(double v, const printed_digits& column) {
    const double fixed = 0.5 * std::pow(10.0, double(-column.decimals));
    if (v == 0) return fixed;
    const double magnitude = std::floor(std::log10(std::abs(v)));
    const double digits = std::max(fixed, 0.5 * std::pow(10.0, magnitude - double(column.significant) + 1));
    return column.significant <= 9 ? std::max(digits, 0x1p-24 * std::abs(v)) : digits;
}

// An engine's table read back: values, and per value what its format can hold.
struct stored_table {
    std::size_t width = 0, height = 0, channels = 0;
    std::vector<double> values, precision;
    lut_grid grid;
    std::string format;
};

std::vector<std::string> split_csv(const std::string& line) {
    std::vector<std::string> cells;
    std::size_t from = 0;
    while (true) {  // every comma ends a cell, a last one too (an empty last cell is a cell)
        const std::size_t comma = line.find(',', from);
        std::string cell = line.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
        while (!cell.empty() && (cell.back() == '\r' || cell.back() == ' ')) cell.pop_back();
        while (!cell.empty() && cell.front() == ' ') cell.erase(cell.begin());
        cells.push_back(cell);
        if (comma == std::string::npos) break;
        from = comma + 1;
    }
    return cells;
}

// What a row that `verify lut` wrote (its `table` cell is "lut") must name for the check to be of
// the same table: its kind, model, F0 (E, Eavg) and the parameters the model reads. Another is
// refused, naming the line: comparing it would only fail, without saying why.
struct own_rows {
    std::string kind;
    const mf::composition* c = nullptr;
    const part_inputs* parts = nullptr;  // F0 as well
};

// A CSV with a header naming mu, alpha or r, and the kind's value columns (the lut records' CSV
// is one); '#' lines are comments. Each row is a texel at the coordinates it gives.
stored_table read_csv(const std::string& path, lut_kind kind, const own_rows& own) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw bad_input(path + ": cannot be read");
    stored_table s;
    s.format = "csv";
    std::string line;
    std::vector<std::string> header;
    std::size_t line_no = 0;
    const auto names = channels_of(kind);
    int mu_col = -1, rough_col = -1, r_beside_col = -1;
    std::vector<int> value_cols;
    // per value column, the most decimals and significant digits printed
    std::vector<printed_digits> finest(names.size(), printed_digits{std::numeric_limits<long>::min() / 2, 0});
    while (std::getline(in, line)) {
        ++line_no;
        if (line_no == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a UTF-8 byte order mark
        if (line.empty() || line[0] == '#' || line == "\r") continue;
        const auto cells = split_csv(line);
        auto col = [&](const std::string& n) {
            const auto it = std::find(header.begin(), header.end(), n);
            return it == header.end() ? -1 : int(it - header.begin());
        };
        if (header.empty()) {
            if (line.rfind("\x89PNG", 0) == 0 || line.rfind("\x76\x2f\x31\x01", 0) == 0)
                throw bad_input(path + ": holds a PNG or OpenEXR image, not a CSV table: name it .png or .exr");
            header = cells;
            for (std::size_t a = 0; a < header.size(); ++a)
                if (std::find(header.begin() + std::ptrdiff_t(a) + 1, header.end(), header[a]) != header.end())
                    throw bad_input(path + ":" + std::to_string(line_no) + ": the header names '" + header[a] + "' twice");
            mu_col = col("mu");
            rough_col = col("alpha") >= 0 ? col("alpha") : col("r");
            r_beside_col = col("alpha") >= 0 ? col("r") : -1;
            s.grid.perceptual = col("alpha") < 0;
            for (const auto& n : names) value_cols.push_back(col(n));
            std::string missing;
            if (kind != lut_kind::eavg && mu_col < 0) missing += " mu";
            if (rough_col < 0) missing += " alpha (or r)";
            for (std::size_t c = 0; c < names.size(); ++c)
                if (value_cols[c] < 0) missing += " " + names[c];
            if (!missing.empty()) throw bad_input(path + ":" + std::to_string(line_no) + ": the header lacks the columns" + missing);
            continue;
        }
        const std::string where = path + ":" + std::to_string(line_no) + ": ";
        if (cells.size() != header.size())  // a row cut short or run on: its cells may not be the header's
            throw bad_input(where + std::to_string(cells.size()) + " cells, the header has " + std::to_string(header.size()));
        auto named = [&](const char* key) -> const std::string* {
            const int at = col(key);
            return at < 0 ? nullptr : &cells[std::size_t(at)];
        };
        auto cell = [&](int at) -> const std::string& { return cells[std::size_t(at)]; };
        auto parsed = [&](const std::string& t, const char* what) {
            char* end = nullptr;
            const double v = std::strtod(t.c_str(), &end);
            if (t.empty() || *end != '\0' || !std::isfinite(v)) throw bad_input(where + what + " '" + t + "' is not a finite number");
            return v;
        };
        auto number = [&](int at, const char* what) { return parsed(cell(at), what); };
        if (const std::string* table = named("table"); table && *table == "lut") {
            // an empty cell (or no column) is a key the row's record did not have
            auto differ = [&](const char* key, const std::string& here) {
                const std::string* made = named(key);
                throw bad_input(where + "the row was made with " + key + (made && !made->empty() ? " = " + *made : " not given") +
                                ", the check is of " + here + ": give the options the table was made with");
            };
            if (const auto* k = named("kind"); k && *k != own.kind) differ("kind", "kind = " + own.kind);
            // the compensation (a fourth part) changes E, not E_avg nor the split-sum pair (docs/lut.md):
            // for those, the same D, G and F parts as the composition's parser reads them
            auto same_model = [&](const std::string& made) {
                if (made == own.c->id || kind == lut_kind::e) return made == own.c->id;
                try {
                    const mf::composition m = mf::composition::parse(made);
                    return m.d_part == own.c->d_part && m.g_part == own.c->g_part && m.f_part == own.c->f_part;
                } catch (const std::invalid_argument&) {
                    return false;
                }
            };
            if (const auto* m = named("model"); m && !same_model(*m)) differ("model", "model = " + own.c->id);
            auto same = [&](const char* key, std::optional<double> value, const std::string& shown) {
                const std::string* made = named(key);
                const bool written = made && !made->empty();
                if (written != value.has_value() || (written && !(parsed(*made, key) == *value))) differ(key, shown);
            };
            for (const auto& q : part_parameters()) {
                const bool given = own.parts->*q.input && own.c->reads(q.name);
                same(q.name, given ? std::optional<double>(own.c->*q.member) : std::nullopt,
                     given ? std::string(q.name) + " = " + (own.parts->*q.input)->text() : std::string(q.name) + " not given");
            }
            // then F0, where the check's albedo depends on it (an older row may carry an F0 it ignores);
            // after the parameters, as a row made with eta has no F0 and the difference is eta
            if (kind != lut_kind::dfg && uses_f0(*own.c, *own.parts))
                same("f0", f0_of(*own.parts).f0, own.parts->f0 ? "f0 = " + own.parts->f0->text() : "f0 = 1 (not given)");
        }
        // a coordinate is the decimal printed: its rounding to double enters the exact value's bound
        auto coordinate = [&](int at, const char* what, const char* lo, const char* hi) {
            const std::string& t = cell(at);
            std::optional<normzoo::decimal> d;
            try {
                d.emplace(t);
                (void)d->to<double>();
            } catch (const std::invalid_argument& e) {
                throw bad_input(where + what + " " + e.what());
            }
            if (!(*d > normzoo::decimal(lo)) || *d > normzoo::decimal(hi))
                throw bad_input(where + what + " " + t + " is not in (" + lo + ", " + hi + "]");
            return *d;
        };
        const auto rough = coordinate(rough_col, s.grid.perceptual ? "r" : "alpha", "0", s.grid.perceptual ? "10" : "100");
        s.grid.roughness.push_back(rough.to<double>());
        s.grid.alpha_delta.push_back(alpha_of({rough, s.grid.perceptual}).delta);
        if (r_beside_col >= 0) {  // alpha and r both given: they must agree
            const auto r = coordinate(r_beside_col, "r", "0", "10");
            const double rd = r.to<double>(), ad = rough.to<double>();
            // each as printed, and alpha = r^2 formed in float (2^-23 relative) or in double
            const double pa = printed_precision(ad, digits_of(cell(rough_col)));
            const double pr = printed_precision(rd, digits_of(cell(r_beside_col)));
            const double slack = pa + (2 * rd + pr) * pr + 0x1p-23 * ad;
            if (!(std::abs(rd * rd - ad) <= slack))
                throw bad_input(where + "alpha " + rough.text() + " and r " + r.text() + " disagree (alpha = r^2)");
        }
        if (kind != lut_kind::eavg) {
            const auto mu_text = coordinate(mu_col, "mu", "0", "1");
            try {
                const auto m = mu_of({mu_text, false});
                s.grid.mus.push_back(m.mu);
                s.grid.mu_delta.push_back(m.delta);
            } catch (const bad_input& e) {
                throw bad_input(where + e.what());
            }
        }
        for (std::size_t c = 0; c < value_cols.size(); ++c) {
            s.values.push_back(number(value_cols[c], "a value"));
            const printed_digits d = digits_of(cell(value_cols[c]));
            finest[c].decimals = std::max(finest[c].decimals, d.decimals);
            finest[c].significant = std::max(finest[c].significant, d.significant);
        }
    }
    for (std::size_t k = 0; k < s.values.size(); ++k) s.precision.push_back(printed_precision(s.values[k], finest[k % finest.size()]));
    if (s.grid.roughness.empty()) throw bad_input(path + ": no table rows");
    s.channels = names.size();
    s.width = s.grid.roughness.size();  // one texel per row: a list of points
    s.height = 1;
    s.grid.points = true;
    return s;
}

stored_table read_image(const std::string& path, lut_kind kind, bool perceptual) {
    const decoded_lut d = read_lut_image(path);
    const auto& im = d.image;
    stored_table s;
    s.format = d.format;
    const std::size_t need = kind == lut_kind::dfg ? 2 : 1;
    if (im.channels < need)
        throw bad_input(path + ": " + std::to_string(im.channels) + " channel(s); a " +
                        (kind == lut_kind::dfg ? "split-sum table needs 2 (A, B)" : "table needs 1"));
    if (kind == lut_kind::eavg) {
        if (im.height != 1 && im.width != 1)
            throw bad_input(path + ": " + std::to_string(im.width) + " x " + std::to_string(im.height) +
                            " is not an E_avg table (one row or one column)");
    } else if (im.width != im.height) {
        throw bad_input(path + ": " + std::to_string(im.width) + " x " + std::to_string(im.height) +
                        " is not a table of mu and roughness (square, N x N)");
    }
    s.grid.perceptual = perceptual;
    const std::size_t n = kind == lut_kind::eavg ? std::max(im.width, im.height) : im.width;
    s.grid.roughness = centres(n);
    if (kind != lut_kind::eavg) s.grid.mus = centres(n);
    s.channels = need;
    s.width = kind == lut_kind::eavg ? n : im.width;
    s.height = kind == lut_kind::eavg ? 1 : im.height;
    for (std::size_t k = 0; k < s.width * s.height; ++k)
        for (std::size_t c = 0; c < need; ++c) {
            const double v = im.data[k * im.channels + c];
            s.values.push_back(v);
            s.precision.push_back(d.absolute + d.relative * std::abs(v));
        }
    return s;
}

// parts: F0 (read for E and Eavg) and the parts' parameters as typed
table_output check_table(const std::string& path, lut_kind kind, const mf::composition& c, bool perceptual,
                         std::optional<double> tolerance, unsigned jobs, const part_inputs& parts) {
    const std::string ext = std::filesystem::path(path).extension().string();
    const f0_value f0 = kind == lut_kind::dfg ? f0_value{} : f0_of(parts);
    stored_table s = ext == ".csv" ? read_csv(path, kind, {kind_name(kind), &c, &parts}) : read_image(path, kind, perceptual);
    s.grid.f0 = f0.f0, s.grid.f0_delta = f0.delta, s.grid.parts = parts;
    const exact_table t = compute(kind, c, s.grid, jobs);  // a CSV's points each at its own coordinates
    const auto names = channels_of(kind);
    std::vector<record> rows;
    for (std::size_t ch = 0; ch < s.channels; ++ch) {
        double worst = -1, worst_tol = 0;
        std::size_t at = 0, above = 0, count = 0;
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
            if (err > worst) worst = err, at = k, worst_tol = tol;
            above += !finite || err > tol;
            ++count;
            const int decade = err < 1e-8 ? 0 : err >= 0.1 ? 8 : int(std::floor(std::log10(err))) + 9;
            ++histogram[std::size_t(decade)];
        }
        std::string hist;
        const char* labels[] = {"<1e-8", "1e-8", "1e-7", "1e-6", "1e-5", "1e-4", "1e-3", "1e-2", ">=1e-1"};
        for (std::size_t b = 0; b < histogram.size(); ++b)
            if (histogram[b]) hist += (hist.empty() ? "" : " ") + std::string(labels[b]) + ":" + std::to_string(histogram[b]);
        const std::size_t i = s.format == "csv" || kind == lut_kind::eavg ? at : at % s.width;
        const std::size_t j = s.format == "csv" || kind == lut_kind::eavg ? at : at / s.width;
        record r{"lut-check", {}};
        r.set("file", path).set("format", s.format).set("kind", kind_name(kind))
            .set("model", c.id);
        set_part_keys(r, c, parts, kind == lut_kind::dfg ? std::nullopt : std::optional<double>(f0.f0));
        r.set("channel", names[ch]).set("texels", static_cast<std::int64_t>(count))
            .set("max_abs_error", worst).set("at_index", static_cast<std::int64_t>(at));
        if (kind != lut_kind::eavg) r.set("at_mu", s.grid.mus[s.format == "csv" ? at : i]);
        r.set("at_alpha", s.grid.alpha(j)).set("tolerance_at_max", worst_tol)
            .set("above_tolerance", static_cast<std::int64_t>(above)).set("histogram", hist).set("pass", above == 0);
        rows.push_back(std::move(r));
    }
    normzoo::table_info info{"lut-check",
                             "An engine's baked table against the exact one at the same texel centres (docs/lut.md)",
                             {"exact values by microfacet/albedo.hpp at tolerance 1e-10; tolerance: what the file's format "
                              "holds (8-bit 0.5/255, 16-bit 0.5/65535, half 2^-11 relative, float 2^-24, CSV half a unit "
                              "in the last digit its column prints) or --tolerance, plus the exact value's bound (with "
                              "the rounding of the coordinates, F0 and parameters typed)",
                              "pass: no texel beyond its tolerance"},
                             {"file", "channel", "texels", "max_abs_error", "at_mu", "at_alpha", "above_tolerance", "histogram"},
                             {}};
    return {info, std::move(rows), path, ""};
}

int check_lut(const std::string& path, lut_kind kind, const mf::composition& c, bool perceptual,
              std::optional<double> tolerance, bool json, unsigned jobs, const part_inputs& parts) {
    const table_output out = check_table(path, kind, c, perceptual, tolerance, jobs, parts);
    const auto& rows = out.records;
    bool failed = false;
    for (const auto& r : rows) failed = failed || r.failed();
    if (json) {
        nlohmann::ordered_json doc;
        doc["records"] = records_json(out);
        doc["skipped"] = nlohmann::ordered_json::array();
        std::cout << doc.dump() << "\n";
    } else {
        for (const auto& r : rows)
            std::cout << "lut-check " << path << " (" << r.text("format") << "), " << r.text("channel") << ": max |error| "
                      << r.number("max_abs_error") << " at alpha " << r.number("at_alpha")
                      << (r.find("at_mu") ? ", mu " + normzoo::detail::format_number(r.number("at_mu")) : std::string()) << "; "
                      << r.number("above_tolerance") << " of " << r.number("texels") << " above tolerance ("
                      << r.number("tolerance_at_max") << " there); |error| by decade: " << r.text("histogram")
                      << (r.failed() ? "  FAIL" : "") << "\n";
    }
    return failed ? 1 : 0;
}

lut_kind kind_of(const std::string& text) {
    if (text == "dfg") return lut_kind::dfg;
    if (text == "E") return lut_kind::e;
    if (text == "Eavg") return lut_kind::eavg;
    throw bad_input("--kind '" + text + "' is not dfg, E or Eavg");
}

}  // namespace

table_output check_lut_file(const std::string& path, const std::string& kind, const std::string& model, const part_inputs& parts,
                            bool perceptual, std::optional<double> tolerance, unsigned jobs) {
    const auto c = composition_of(model, parts, "");  // the caller has checked it
    return check_table(path, kind_of(kind), c, perceptual, tolerance, jobs, parts);
}

int run_lut(int argc, char** argv) {
    CLI::App app{"normzoo verify lut: the tables engines bake (split-sum pair, E(mu, alpha), E_avg(alpha)), exact, "
                 "and an engine's own table checked against them (docs/lut.md). Exit 0, 1 (a checked table is off), 2 "
                 "(bad input).",
                 "verify lut"};
    std::string kind_text, model = "ggx/smith-height-correlated/one", alpha_text, r_text, mu_text, map = "r",
                             format = "csv", out_dir, check_path, tolerance_text, f0_text;
    std::size_t size = 0;
    unsigned monte_carlo = 0;
    bool json = false;
    unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
    app.add_option("--kind", kind_text, "dfg (the split-sum pair A, B), E, or Eavg")->required();
    app.add_option("--model", model, "A composition D/G/F[/kulla-conty|turquin] (default ggx/smith-height-correlated/one); "
                                     "dfg replaces its F by Schlick's");
    app.add_option("--size", size, "N: an N x N table at texel centres (i + 0.5)/N in mu and in roughness")->check(CLI::Range(1, 4096));
    app.add_option("--alpha", alpha_text, "Roughness values alpha, comma-separated, instead of --size");
    app.add_option("--r", r_text, "Perceptual roughness values r (alpha = r^2), instead of --size");
    app.add_option("--mu", mu_text, "Cosines of the incident angle, comma-separated, with --alpha or --r");
    app.add_option("--f0", f0_text, "E and Eavg: F0 of the composition's Fresnel part, in [0, 1) (default 1: F = 1 for "
                                    "every F part); dfg's A and B do not depend on it");
    std::vector<std::string> part_texts;
    add_part_options(app, part_texts, "");
    app.add_option("--map", map, "What the rows of a --size table (or a checked image) index: r (alpha = r^2, default) or alpha");
    app.add_option("--format", format, "csv, json, png16, exr (float), exr-half, h (C header of floats) (with --out)");
    app.add_option("--out", out_dir, "Folder to write the table to (lut-KIND-N.EXT); without it nothing is written");
    app.add_option("--check", check_path, "An engine's table to check: CSV (columns mu, alpha or r, and A, B / E / E_avg), "
                                          "PNG (8 or 16 bit) or OpenEXR; an image is N x N texel centres");
    app.add_option("--tolerance", tolerance_text, "Absolute tolerance of --check (default: what the file's format holds)");
    app.add_option("--monte-carlo", monte_carlo, "dfg only: bake the table as engines do instead, N samples of GGX "
                                                 "importance sampling at Hammersley points in float, height-correlated "
                                                 "Smith (docs/lut.md); its error is not bounded")
        ->check(CLI::Range(1u, 1u << 24));
    app.add_flag("--json", json, "Write one JSON document {records, skipped} to stdout");
    app.add_option("--jobs", jobs, "Threads (default: all cores)")->check(CLI::Range(1u, 256u));
    refuse_missing_values(app, argc, argv, "lut: ");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        throw bad_input("lut: " + std::string(e.what()));
    }
    refuse_forgotten_values(app, "lut: ");
    lut_kind kind;
    try {
        kind = kind_of(kind_text);
    } catch (const bad_input& e) {
        throw bad_input(std::string("lut: ") + e.what());
    }
    if (map != "r" && map != "alpha") throw bad_input("lut: --map '" + map + "' is not r or alpha");
    lut_grid g;
    for (const auto& opt : read_part_options(app, part_texts, g.parts, "lut: "))
        // the split-sum pair reads the D's parameters only
        if (kind == lut_kind::dfg && mf::detail::readers_of<mf::distribution_parts>(opt.substr(2)).empty())
            throw bad_input("lut: " + opt + " is for --kind E and Eavg (the split-sum pair replaces the F part by Schlick's)");
    const mf::composition c = composition_of(model, g.parts, "lut: --model: ");
    if (!f0_text.empty()) {
        if (kind == lut_kind::dfg) throw bad_input("lut: --f0 is for --kind E and Eavg (the split-sum pair does not depend on F0)");
        const auto v = parse_decimal_list("--f0", f0_text, "0", "1", true);
        if (v.size() != 1) throw bad_input("lut: --f0: one value, not a list ('" + f0_text + "')");
        g.parts.f0 = v.front();
        const f0_value f0 = f0_of(g.parts);
        g.f0 = f0.f0, g.f0_delta = f0.delta;
    }
    check_part_inputs({model}, g.parts, "lut: --");
    if (!check_path.empty()) {
        // the file gives the table's size and coordinates; nothing is written
        for (const char* making : {"--size", "--alpha", "--r", "--mu", "--format", "--out", "--monte-carlo"})
            if (app.count(making))
                throw bad_input(std::string("lut: ") + making + " is for making a table; --check reads the table's size and "
                                "coordinates from " + check_path + " and writes nothing");
        if (app.count("--map") && std::filesystem::path(check_path).extension() == ".csv")
            throw bad_input("lut: --map is for an image; " + check_path + ", a CSV, names its roughness in its header (alpha or r)");
        std::optional<double> tolerance;
        if (!tolerance_text.empty()) {
            const auto t = parse_decimal_list("--tolerance", tolerance_text, "0", "1");
            tolerance = t.front().to<double>();
        }
        return check_lut(check_path, kind, c, map == "r", tolerance, json, jobs, g.parts);
    }
    if (!tolerance_text.empty()) throw bad_input("lut: --tolerance is for --check FILE");
    g.perceptual = map == "r";
    if (size > 0) {
        if (!alpha_text.empty() || !r_text.empty() || !mu_text.empty())
            throw bad_input("lut: --size or the lists --alpha/--r and --mu, not both");
        g.roughness = centres(size);
        if (kind != lut_kind::eavg) g.mus = centres(size);
    } else {
        if (alpha_text.empty() == r_text.empty()) throw bad_input("lut: give --size N, or --alpha or --r (and --mu)");
        g.perceptual = !r_text.empty();
        const roughness_range range = roughness_range_of(g.perceptual);
        for (const auto& d : parse_decimal_list(g.perceptual ? "--r" : "--alpha", g.perceptual ? r_text : alpha_text, range.min,
                                                range.max, false, false)) {
            g.roughness.push_back(d.to<double>());
            g.alpha_delta.push_back(alpha_of({d, g.perceptual}).delta);
        }
        if (kind == lut_kind::eavg && !mu_text.empty())
            throw bad_input("lut: --mu is not read by --kind Eavg (E_avg depends on the roughness alone)");
        if (kind != lut_kind::eavg) {
            if (mu_text.empty()) throw bad_input("lut: --mu is needed with --alpha or --r");
            for (const auto& d : parse_decimal_list("--mu", mu_text, "1e-8", "1", false, false)) {
                const auto m = mu_of({d, false});
                g.mus.push_back(m.mu);
                g.mu_delta.push_back(m.delta);
            }
        }
    }
    const std::vector<std::string> formats = {"csv", "json", "png16", "exr", "exr-half", "h"};
    if (std::find(formats.begin(), formats.end(), format) == formats.end())
        throw bad_input("lut: --format '" + format + "' is not one of csv, json, png16, exr, exr-half, h");
    if (!size && format != "csv" && format != "json")
        throw bad_input("lut: --format " + format + " writes an N x N table of texel centres; listed values (--alpha or --r "
                        "with --mu) are points with their own coordinates: write them as csv or json");
    if (!out_dir.empty()) check_output_folder(out_dir, "--out");

    exact_table t;
    if (monte_carlo) {
        if (kind != lut_kind::dfg || !g.perceptual || model != "ggx/smith-height-correlated/one")
            throw bad_input("lut: --monte-carlo bakes the split-sum pair of ggx/smith-height-correlated by r: --kind dfg, "
                            "--map r, the default model");
        t.width = g.mus.size(), t.height = g.roughness.size(), t.channels = 2;
        t.values.resize(t.width * t.height * 2);
        normzoo::detail::parallel_for(t.width * t.height, jobs, [&](std::size_t k) {
            const auto [a, b] = monte_carlo_split_sum(float(g.roughness[k / t.width]), float(g.mus[k % t.width]), monte_carlo);
            t.values[2 * k] = {double(a), HUGE_VAL, monte_carlo};
            t.values[2 * k + 1] = {double(b), HUGE_VAL, monte_carlo};
        });
    } else {
        t = compute(kind, c, g, jobs);
    }
    table_output out = records_of(kind, c, g, t);
    if (monte_carlo) {
        out.info.title = "A baked table as engines bake it: Monte Carlo, " + std::to_string(monte_carlo) +
                         " samples in float (docs/lut.md); not exact, no error bound";
        out.info.settings.front() = "each value by Monte Carlo as engines bake it (docs/lut.md, \"As engines bake it\"): " +
                                    std::to_string(monte_carlo) + " samples; *error_estimate: none (null)";
        for (auto& r : out.records)
            for (auto& [k, v] : r.fields)
                if (k.find("error_estimate") != std::string::npos) v = nullptr;
    }
    out.command = "./verify lut --kind " + kind_text + " --model " + model +
                  (size ? " --size " + std::to_string(size) : std::string(" (lists)")) + " --map " + map +
                  (f0_text.empty() ? std::string() : " --f0 " + f0_text) + given_parts(g.parts) +
                  (monte_carlo ? " --monte-carlo " + std::to_string(monte_carlo) : std::string());
    out.parameters = !size ? "listed points"
                     : kind == lut_kind::eavg ? std::to_string(size) + " texel centres"
                                              : std::to_string(size) + " x " + std::to_string(size) + " texel centres";
    // An integral that broke (a value or bound not finite) fails its record: exit 1, and no table
    // file an engine could load as if it held values.
    std::size_t broken = 0;
    for (const auto& r : out.records) broken += r.failed() ? 1 : 0;
    if (broken && !out_dir.empty())
        std::cerr << "verify lut: " << broken << " of " << out.records.size()
                  << " values are not finite; nothing written to " << out_dir << "\n";
    if (!out_dir.empty() && !broken) {
        std::filesystem::create_directories(out_dir);
        file_set files(out_dir);
        const std::string stem = "lut-" + kind_text + "-" + (size ? std::to_string(size) : std::string("list"));
        const std::string file = format == "png16" ? stem + ".png"
                                 : format == "exr" ? stem + ".exr"
                                 : format == "exr-half" ? stem + "-half.exr"  // beside the float one, not over it
                                                        : stem + "." + format;
        const lut_image im = image_of(t);
        if (format == "csv") files.stage(file, csv(out));
        else if (format == "json") files.stage(file, json_file(out));
        else if (format == "png16") files.stage(file, encode_png16(im));
        else if (format == "exr" || format == "exr-half") files.stage(file, encode_exr(im, format == "exr-half"));
        else {
            std::string name = "normzoo_" + kind_text + "_" + std::to_string(t.width);
            const std::string roughness = std::string("roughness (") + (g.perceptual ? "r, alpha = r^2" : "alpha") + ")";
            std::string comment = "normzoo " + out.command + ": " + out.info.title + "\n" +
                                  (kind == lut_kind::eavg ? "one row: " + roughness : "rows: " + roughness + ", columns: mu") +
                                  "; texel centres (i + 0.5)/N; channels: ";
            for (const auto& n : channels_of(kind)) comment += n + " ";
            files.stage(file, encode_c_header(im, name, comment));
        }
        files.commit();
        if (!json) std::cerr << "verify lut: " << t.width * t.height << " texels -> " << (std::filesystem::path(out_dir) / file).string() << "\n";
    }
    if (json) {
        nlohmann::ordered_json doc;
        doc["records"] = records_json(out);
        doc["skipped"] = nlohmann::ordered_json::array();
        std::cout << doc.dump() << "\n";
    } else if (out_dir.empty()) {
        double worst = 0;
        for (const auto& v : t.values) worst = std::max(worst, v.abs_error);
        std::cout << "lut: " << t.width * t.height << " texels of " << kind_text << " (" << c.id
                  << "), largest error estimate " << worst << " (not written; add --out DIR or --json)\n";
        if (broken) std::cout << "FAIL: " << broken << " values are not finite\n";
    }
    return broken ? 1 : 0;
}

}  // namespace verify
