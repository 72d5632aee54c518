// An engine's table read back for `verify lut --check` (lut_read.hpp): a CSV's header, its rows'
// coordinates and values, and what the digits printed hold.
#include "lut_read.hpp"

#include <normzoo/decimal.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include "args.hpp"
#include "lut_formats/printed.hpp"
#include "microfacet_tables.hpp"

namespace verify {

namespace mf = normzoo::microfacet;

namespace {

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

// The columns a CSV's header names: mu, the roughness (alpha, else r), r beside alpha (-1
// without both) and the kind's value columns, in lut_channels' order; -1 where absent.
struct csv_columns {
    std::vector<std::string> header;
    int mu = -1, rough = -1, r_beside = -1;
    std::vector<int> values;
    int at(const std::string& n) const {
        const auto it = std::find(header.begin(), header.end(), n);
        return it == header.end() ? -1 : int(it - header.begin());
    }
};

// The first line that is not a comment: bad_input for an image named as a CSV, a column named
// twice, or a column the kind needs missing.
csv_columns read_header(const std::string& line, const std::vector<std::string>& cells, const std::string& path,
                        std::size_t line_no, lut_kind kind) {
    if (line.rfind("\x89PNG", 0) == 0 || line.rfind("\x76\x2f\x31\x01", 0) == 0)
        throw bad_input(path + ": holds a PNG or OpenEXR image, not a CSV table: name it .png or .exr");
    csv_columns cols;
    const auto& header = cols.header = cells;
    for (std::size_t a = 0; a < header.size(); ++a)
        if (std::find(header.begin() + std::ptrdiff_t(a) + 1, header.end(), header[a]) != header.end())
            throw bad_input(path + ":" + std::to_string(line_no) + ": the header names '" + header[a] + "' twice");
    cols.mu = cols.at("mu");
    cols.rough = cols.at("alpha") >= 0 ? cols.at("alpha") : cols.at("r");
    cols.r_beside = cols.at("alpha") >= 0 ? cols.at("r") : -1;
    const auto names = lut_channels(kind);
    for (const auto& n : names) cols.values.push_back(cols.at(n));
    std::string missing;
    if (kind != lut_kind::eavg && cols.mu < 0) missing += " mu";
    if (cols.rough < 0) missing += " alpha (or r)";
    for (std::size_t c = 0; c < names.size(); ++c)
        if (cols.values[c] < 0) missing += " " + names[c];
    if (!missing.empty()) throw bad_input(path + ":" + std::to_string(line_no) + ": the header lacks the columns" + missing);
    return cols;
}

// A row of the table, as many cells as the header; where: "PATH:LINE: ", for its messages.
struct csv_row {
    const std::vector<std::string>& cells;
    const csv_columns& columns;
    std::string where;

    // The cell of a column the header names, or null.
    const std::string* named(const char* key) const {
        const int at = columns.at(key);
        return at < 0 ? nullptr : &cells[std::size_t(at)];
    }
    const std::string& cell(int at) const { return cells[std::size_t(at)]; }
    // a decimal number: strtod alone would take a hex float (0x1p-1), whose printed digits say
    // nothing of what it holds, and leading white space
    double parsed(const std::string& t, const char* what) const {
        if (t.find_first_not_of("0123456789+-.eE") != std::string::npos)
            throw bad_input(where + what + " '" + t + "' is not a decimal number");
        char* end = nullptr;
        const double v = std::strtod(t.c_str(), &end);
        if (t.empty() || *end != '\0' || !std::isfinite(v)) throw bad_input(where + what + " '" + t + "' is not a finite number");
        return v;
    }
    double number(int at, const char* what) const { return parsed(cell(at), what); }
    // a coordinate is the decimal printed: its rounding to double enters the exact value's bound;
    // zero: 0 itself is taken too (a corner-aligned split-sum table's edge, split_sum_to.hpp)
    normzoo::decimal coordinate(int at, const char* what, const char* lo, const char* hi, bool zero = false) const {
        const std::string& t = cell(at);
        std::optional<normzoo::decimal> d;
        try {
            d.emplace(t);
            (void)d->to<double>();
        } catch (const std::invalid_argument& e) {
            throw bad_input(where + what + " " + e.what());
        }
        if (zero && d->is_zero()) return *d;
        if (!(*d > normzoo::decimal(lo)) || *d > normzoo::decimal(hi))
            throw bad_input(where + what + " " + t + " is not in (" + lo + ", " + hi + "]");
        return *d;
    }
};

// A row that `verify lut` wrote: bad_input, naming the line, where it was made with other
// options than the check's (own_rows). An empty cell (or no column) is a key the row's record
// did not have.
void check_own_row(const csv_row& row, lut_kind kind, const own_rows& own) {
    auto differ = [&](const char* key, const std::string& here) {
        const std::string* made = row.named(key);
        throw bad_input(row.where + "the row was made with " + key + (made && !made->empty() ? " = " + *made : " not given") +
                        ", the check is of " + here + ": give the options the table was made with");
    };
    if (const auto* k = row.named("kind"); k && *k != own.kind) differ("kind", "kind = " + own.kind);
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
    if (const auto* m = row.named("model"); m && !same_model(*m)) differ("model", "model = " + own.c->id);
    auto same = [&](const char* key, std::optional<double> value, const std::string& shown) {
        const std::string* made = row.named(key);
        const bool written = made && !made->empty();
        if (written != value.has_value() || (written && !(row.parsed(*made, key) == *value))) differ(key, shown);
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

// A coordinate read and how far the double is from the decimal printed.
struct coordinate {
    double value, delta;
};

// The row's roughness (alpha, or r; where both are given they must agree), with how far the
// double is from the decimal printed.
coordinate read_roughness(const csv_row& row, lut_kind kind, bool perceptual) {
    const csv_columns& cols = row.columns;
    const bool edges = kind == lut_kind::dfg;  // the split-sum pair has its limits at 0 (docs/lut.md, "Edges")
    const auto rough = row.coordinate(cols.rough, perceptual ? "r" : "alpha", "0", perceptual ? "10" : "100", edges);
    coordinate out{rough.to<double>(), rough.is_zero() ? 0.0 : alpha_of({rough, perceptual}).delta};
    if (cols.r_beside >= 0) {  // alpha and r both given: they must agree
        const auto r = row.coordinate(cols.r_beside, "r", "0", "10", edges);
        const double rd = r.to<double>(), ad = rough.to<double>();
        // each as printed, and alpha = r^2 formed in float (2^-23 relative) or in double
        const double pa = printed_precision(ad, digits_of(row.cell(cols.rough)));
        const double pr = printed_precision(rd, digits_of(row.cell(cols.r_beside)));
        const double slack = pa + (2 * rd + pr) * pr + 0x1p-23 * ad;
        if (!(std::abs(rd * rd - ad) <= slack))
            throw bad_input(row.where + "alpha " + rough.text() + " and r " + r.text() + " disagree (alpha = r^2)");
        // r's square a double where alpha's digits are not (a table made by r prints r^2 rounded):
        // the point is r's, and nothing rounds (docs/lut.md, "How a check chooses its accuracy")
        if (out.delta > 0 && rd > 0 && squares_exactly(r)) out = {rd * rd, 0};
    }
    return out;
}

// The row's mu, with how far the double is from the decimal printed.
coordinate read_mu(const csv_row& row, lut_kind kind) {
    const auto mu_text = row.coordinate(row.columns.mu, "mu", "0", "1", kind == lut_kind::dfg);
    if (mu_text.is_zero()) return {0.0, 0.0};
    try {
        const auto m = mu_of({mu_text, false});
        return {m.mu, m.delta};
    } catch (const bad_input& e) {
        throw bad_input(row.where + e.what());
    }
}

// The row's point, added to grid. A table's rows share few coordinates (a 256 x 256 list has 256
// of each), so each text is read once: reading a decimal exactly is most of a row's cost.
struct coordinate_reader {
    std::unordered_map<std::string, coordinate> roughness, mu;

    void read(const csv_row& row, lut_kind kind, lut_grid& grid) {
        const csv_columns& cols = row.columns;
        std::string key = row.cell(cols.rough);
        if (cols.r_beside >= 0) key += "," + row.cell(cols.r_beside);
        auto r = roughness.find(key);
        if (r == roughness.end()) r = roughness.emplace(key, read_roughness(row, kind, grid.perceptual)).first;
        grid.roughness.push_back(r->second.value);
        grid.alpha_delta.push_back(r->second.delta);
        if (kind == lut_kind::eavg) return;
        auto m = mu.find(row.cell(cols.mu));
        if (m == mu.end()) m = mu.emplace(row.cell(cols.mu), read_mu(row, kind)).first;
        grid.mus.push_back(m->second.value);
        grid.mu_delta.push_back(m->second.delta);
    }
};

// The cells check_own_row reads (all but the coordinates and values): rows of one table share
// them, so a row like the one before needs no second check.
std::string own_cells(const csv_row& row) {
    const csv_columns& cols = row.columns;
    std::string key;
    for (int c = 0; c < int(row.cells.size()); ++c)
        if (c != cols.mu && c != cols.rough && c != cols.r_beside &&
            std::find(cols.values.begin(), cols.values.end(), c) == cols.values.end())
            key += row.cells[std::size_t(c)] + ",";
    return key;
}

}  // namespace

stored_table read_csv_table(const std::string& path, lut_kind kind, const own_rows& own) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw bad_input(path + ": cannot be read");
    stored_table s;
    s.format = "csv";
    std::string line;
    csv_columns cols;
    std::size_t line_no = 0;
    const auto names = lut_channels(kind);
    // per value column, the most decimals and significant digits printed
    std::vector<printed_digits> finest(names.size(), printed_digits{std::numeric_limits<long>::min() / 2, 0});
    coordinate_reader coordinates;
    std::string own_checked;  // own_cells of the last row check_own_row passed
    while (std::getline(in, line)) {
        ++line_no;
        if (line_no == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a UTF-8 byte order mark
        if (line.empty() || line[0] == '#' || line == "\r") continue;
        const auto cells = split_csv(line);
        if (cols.header.empty()) {
            cols = read_header(line, cells, path, line_no, kind);
            s.grid.perceptual = cols.at("alpha") < 0;
            continue;
        }
        const csv_row row{cells, cols, path + ":" + std::to_string(line_no) + ": "};
        if (cells.size() != cols.header.size())  // a row cut short or run on: its cells may not be the header's
            throw bad_input(row.where + std::to_string(cells.size()) + " cells, the header has " + std::to_string(cols.header.size()));
        if (const std::string* table = row.named("table"); table && *table == "lut") {
            std::string cells_now = own_cells(row);
            if (cells_now != own_checked) check_own_row(row, kind, own), own_checked = std::move(cells_now);
        }
        coordinates.read(row, kind, s.grid);
        for (std::size_t c = 0; c < cols.values.size(); ++c) {
            s.values.push_back(row.number(cols.values[c], "a value"));
            const printed_digits d = digits_of(row.cell(cols.values[c]));
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

}  // namespace verify
