#include "check.hpp"

#include <normzoo/real.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace verify {

namespace {

using nlohmann::ordered_json;

// Decimal strings carry up to 34 digits: read them in binary128.
normzoo::quad as_number(const ordered_json& v) {
    if (v.is_number()) return v.get<double>();
    if (v.is_string()) {
        try {
            return normzoo::quad(v.get<std::string>());
        } catch (const std::exception&) {
            return std::numeric_limits<normzoo::quad>::quiet_NaN();
        }
    }
    return std::numeric_limits<normzoo::quad>::quiet_NaN();
}

// "row = phong, n = 8": the record's leading fields, to say which one differs.
std::string identity(const ordered_json& rec) {
    std::string s;
    int k = 0;
    for (auto it = rec.begin(); it != rec.end() && k < 4; ++it) {
        if (it.key() == "table") continue;
        s += (s.empty() ? "" : ", ") + it.key() + " = " + (it->is_string() ? it->get<std::string>() : it->dump());
        ++k;
    }
    return s;
}

// A field of a committed record against the computed one (both hold `key`) under the table's
// rule (its table_info's): the difference, or empty when they agree (equal, within both bounds,
// or not compared).
std::string field_difference(const check_rule& rule, const std::string& key, const ordered_json& a,
                             const ordered_json& b) {
    if (rule.ignored.count(key)) return {};
    const bounded_value* cv = nullptr;
    for (const auto& v : rule.bounded)
        if (key == v.value) cv = &v;
    if (cv && !a[key].is_null() && !b[key].is_null()) {
        using boost::multiprecision::abs;
        using boost::multiprecision::isnan;
        const normzoo::quad x = as_number(a[key]), y = as_number(b[key]);
        const normzoo::quad zero = 0;
        normzoo::quad bound = (a.contains(cv->error) ? abs(as_number(a[cv->error])) : zero) +
                              (b.contains(cv->error) ? abs(as_number(b[cv->error])) : zero);
        if (cv->relative) bound *= abs(x);
        // plus the last printed digit: 34 digits for decimal strings, a double's 17 for numbers
        bound += (a[key].is_string() ? normzoo::quad(1e-33) : normzoo::quad(4e-16)) * abs(x);
        if (abs(x - y) > bound || isnan(x) != isnan(y)) {
            std::ostringstream m;
            m.precision(17);
            m << key << " " << a[key].dump() << " -> " << b[key].dump() << ", difference "
              << normzoo::to_decimal(abs(x - y), 3) << " > bound " << normzoo::to_decimal(bound, 3);
            return m.str();
        }
        return {};
    }
    return a[key] != b[key] ? key + " " + a[key].dump() + " -> " + b[key].dump() : std::string();
}

std::string slurp(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

// A committed JSON value back to a record's field. Numbers take the type the run gives that field
// (8.0 written as 8 must differ); a null where the run has a non-finite double stands for it, as
// JSON has no nan or inf (writers.cpp).
field_value field_from_json(const ordered_json& v, const field_value* computed) {
    const bool computed_double = computed && std::holds_alternative<double>(*computed);
    if (v.is_null())
        return computed_double && !std::isfinite(std::get<double>(*computed)) ? *computed : field_value(nullptr);
    if (v.is_boolean()) return v.get<bool>();
    if (v.is_number_float() || (v.is_number() && computed_double)) return v.get<double>();
    if (v.is_number()) return v.get<std::int64_t>();
    if (v.is_string()) return v.get<std::string>();
    return json_text{v.dump()};  // a list or object as the writers make them
}

// The records of a committed JSON file, for the writers: what a run that computed them would
// have written beside it.
std::vector<record> records_from_json(const ordered_json& records, const std::vector<record>& computed) {
    std::vector<record> out;
    if (!records.is_array()) return out;
    for (std::size_t i = 0; i < records.size(); ++i) {
        record r;
        if (records[i].is_object())
            for (auto k = records[i].begin(); k != records[i].end(); ++k) {
                if (k.key() == "table" && k->is_string()) {
                    r.table = k->get<std::string>();
                    continue;
                }
                r.set(k.key(), field_from_json(*k, i < computed.size() ? computed[i].find(k.key()) : nullptr));
            }
        out.push_back(std::move(r));
    }
    return out;
}

// What a run writes, with every value the record comparison accepts taken from the committed
// records: the computed records' fields in their order, each replaced by the committed one where
// they agree (equal, within both bounds, or not compared, such as timings).
std::vector<record> accepted_records(const table_output& t, const ordered_json& committed) {
    const check_rule& rule = t.info.check;
    const auto fresh = records_json(t);
    std::vector<record> out = t.records;
    for (std::size_t i = 0; i < out.size() && committed.is_array() && i < committed.size(); ++i) {
        const auto& a = committed[i];
        if (!a.is_object()) continue;
        for (auto& [key, value] : out[i].fields)
            if (a.contains(key) && field_difference(rule, key, a, fresh[i]).empty()) value = field_from_json(a[key], &value);
    }
    return out;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        lines.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return lines;
}

// The word or number of `line` around byte `at`: between separators of Markdown, CSV and SVG,
// else a few characters either side; shortened when long (a path of an SVG).
std::string token_at(const std::string& line, std::size_t at) {
    static const std::string separators = " |,\"'\t<>=;:()[]{}";
    std::string token;
    if (at >= line.size()) return "(the line ends)";
    if (separators.find(line[at]) != std::string::npos) {
        const std::size_t from = at < 10 ? 0 : at - 10;
        token = line.substr(from, 21);
    } else {
        std::size_t b = at, e = at;
        while (b > 0 && separators.find(line[b - 1]) == std::string::npos) --b;
        while (e < line.size() && separators.find(line[e]) == std::string::npos) ++e;
        token = line.substr(b, e - b);
    }
    return token.size() > 60 ? token.substr(0, 57) + "..." : token;
}

// The first lines where a committed file differs from what a run writes: FILE:LINE:COLUMN and
// the word or number there on each side.
std::vector<std::string> text_differences(const std::filesystem::path& file, const std::string& committed,
                                          const std::string& expected) {
    if (committed == expected) return {};
    const auto a = lines_of(committed), b = lines_of(expected);
    std::vector<std::string> diffs;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
        const std::string* x = i < a.size() ? &a[i] : nullptr;
        const std::string* y = i < b.size() ? &b[i] : nullptr;
        if (x && y && *x == *y) continue;
        if (++differing > 5) continue;
        std::size_t col = 0;
        if (x && y)
            while (col < x->size() && col < y->size() && (*x)[col] == (*y)[col]) ++col;
        diffs.push_back(file.string() + ":" + std::to_string(i + 1) + ":" + std::to_string(col + 1) + ": has '" +
                        (x ? token_at(*x, col) : std::string("(the file ends)")) + "' where a run writes '" +
                        (y ? token_at(*y, col) : std::string("(the file ends)")) + "'");
    }
    if (differing > 5) diffs.push_back(file.string() + ": " + std::to_string(differing - 5) + " more lines differ");
    if (a.size() != b.size())
        diffs.push_back(file.string() + ": " + std::to_string(a.size()) + " lines, a run writes " + std::to_string(b.size()));
    if (diffs.empty()) diffs.push_back(file.string() + ": differs from what a run writes (line ends)");
    return diffs;
}

// A folder of its own for figures drawn to be compared, removed with everything in it.
struct scratch_dir {
    std::filesystem::path path;
    explicit scratch_dir(const std::string& name)
        : path(std::filesystem::temp_directory_path() /
               ("normzoo-check-" + std::to_string(::getpid()) + "-" + name)) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~scratch_dir() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
    scratch_dir(const scratch_dir&) = delete;
    scratch_dir& operator=(const scratch_dir&) = delete;
};

}  // namespace

std::vector<std::string> compare_with_committed(const table_output& t, const std::filesystem::path& dir) {
    std::vector<std::string> diffs;
    const auto path = dir / (t.info.name + ".json");
    std::ifstream f(path);
    if (!f) return {"no committed copy at " + path.string()};
    ordered_json head;
    try {
        head = ordered_json::parse(f);
    } catch (const std::exception& e) {
        return {path.string() + " is not JSON: " + e.what()};
    }
    const auto fresh = records_json(t);
    const auto& committed = head["records"];
    if (head.value("settings", ordered_json::array()) != ordered_json(t.info.settings))
        diffs.push_back("the method described in the head changed");
    if (head.value("parameters", std::string()) != t.parameters)
        diffs.push_back("the grid changed: '" + head.value("parameters", std::string()) + "' -> '" + t.parameters + "'");
    if (committed.size() != fresh.size())
        diffs.push_back(std::to_string(committed.size()) + " committed records, " + std::to_string(fresh.size()) +
                        " computed");
    const check_rule& rule = t.info.check;
    const std::size_t n = std::min(committed.size(), fresh.size());
    for (std::size_t i = 0; i < n && diffs.size() < 50; ++i) {
        const auto& a = committed[i];
        const auto& b = fresh[i];
        std::set<std::string> keys;
        for (auto k = a.begin(); k != a.end(); ++k) keys.insert(k.key());
        for (auto k = b.begin(); k != b.end(); ++k) keys.insert(k.key());
        for (const auto& key : keys) {
            if (rule.ignored.count(key)) continue;
            if (!a.contains(key) || !b.contains(key)) {
                diffs.push_back("record " + std::to_string(i + 1) + " (" + identity(b) + "): field " + key +
                                (a.contains(key) ? " is gone" : " is new"));
                continue;
            }
            const std::string d = field_difference(rule, key, a, b);
            if (!d.empty()) diffs.push_back("record " + std::to_string(i + 1) + " (" + identity(b) + "): " + d);
        }
    }
    if (diffs.size() >= 50) diffs.push_back("(further differences not listed)");
    return diffs;
}

table_check check_committed(const table_output& t, const std::filesystem::path& dir, std::size_t md_rows) {
    table_check c;
    const std::string name = t.info.name;
    c.files.push_back(name + ".json");
    for (const auto& d : compare_with_committed(t, dir)) c.diffs.push_back(name + ".json: " + d);
    const std::string json_text = slurp(dir / (name + ".json"));
    ordered_json doc;
    try {
        doc = ordered_json::parse(json_text);
    } catch (const std::exception&) {
        doc = nullptr;  // compare_with_committed said so
    }
    const ordered_json committed_records = doc.is_object() ? doc.value("records", ordered_json::array()) : ordered_json();
    if (doc.is_object()) {
        // The JSON as the writer makes it of its own records: its head (version, title, command)
        // and layout, which the record comparison does not read.
        const table_output committed{t.info, records_from_json(committed_records, t.records), t.parameters, t.command};
        for (auto& d : text_differences(dir / (name + ".json"), json_text, json_file(committed)))
            c.diffs.push_back(std::move(d));
    }
    // The Markdown and CSV as a run writes them, each value the record comparison accepts taken
    // as committed: so every number in every file is held to the JSON comparison's bounds,
    // timings stay free, and a platform's differences within the bounds fail nothing.
    table_output written{t.info, accepted_records(t, committed_records), t.parameters, t.command};
    const std::pair<std::string, std::string> texts[] = {{name + ".md", markdown(written, md_rows)},
                                                         {name + ".csv", csv(written)}};
    c.markdown = texts[0].second;
    for (const auto& [file, expected] : texts) {
        c.files.push_back(file);
        if (!std::filesystem::exists(dir / file)) {
            c.diffs.push_back("no committed copy at " + (dir / file).string());
            continue;
        }
        for (auto& d : text_differences(dir / file, slurp(dir / file), expected)) c.diffs.push_back(std::move(d));
    }
    if (!t.figure) return c;
    // The figures are drawn from the computed records, as a run draws them: gnuplot's SVG is the
    // same bytes for the same data, so they compare exactly.
    const scratch_dir scratch(name);
    bool drawn = false;
    {
        file_set figures(scratch.path);
        drawn = t.figure(t, figures);
        figures.commit();
    }
    std::vector<std::filesystem::path> made;
    for (const auto& e : std::filesystem::directory_iterator(scratch.path)) made.push_back(e.path());
    std::sort(made.begin(), made.end());
    for (const auto& p : made) {
        const std::string file = p.filename().string();
        if (!std::filesystem::exists(dir / file)) {
            c.notes.push_back(file + " is not in " + dir.string() + ": not compared");
            continue;
        }
        c.files.push_back(file);
        for (auto& d : text_differences(dir / file, slurp(dir / file), slurp(p))) c.diffs.push_back(std::move(d));
    }
    if (!drawn) c.notes.push_back(name + "'s figure could not be drawn (gnuplot): not compared");
    return c;
}

}  // namespace verify
