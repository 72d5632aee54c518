// The writers of writers.hpp: a table's Markdown, CSV and JSON with their heads, the ids and
// failure lines that name its records, and JUnit XML. Staging and writing the files themselves
// is file_set.cpp's.
#include "writers.hpp"

#include <normzoo/version.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>
#include <set>
#include <sstream>

#include "check.hpp"
#include "formulas.hpp"

namespace verify {

namespace {

using nlohmann::ordered_json;

ordered_json to_json(const field_value& v) {
    return std::visit(
        [](const auto& x) -> ordered_json {
            using X = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<X, std::nullptr_t>) return nullptr;
            else if constexpr (std::is_same_v<X, double>) return std::isfinite(x) ? ordered_json(x) : ordered_json(nullptr);
            else if constexpr (std::is_same_v<X, json_text>) return ordered_json::parse(x.text);
            else return x;
        },
        v);
}

std::string to_text(const field_value& v) {
    if (std::holds_alternative<std::string>(v)) return std::get<std::string>(v);
    if (std::holds_alternative<json_text>(v)) return std::get<json_text>(v).text;
    if (std::holds_alternative<std::nullptr_t>(v)) return "";
    if (std::holds_alternative<double>(v) && !std::isfinite(std::get<double>(v))) {
        const double d = std::get<double>(v);
        return std::isnan(d) ? "nan" : (d > 0 ? "inf" : "-inf");
    }
    return to_json(v).dump();
}

// Markdown is for reading: doubles to 4 significant digits, or 12 where a table asks (CSV and
// JSON keep them all).
std::string to_short_text(const field_value& v, bool precise = false) {
    if (!std::holds_alternative<double>(v) || !std::isfinite(std::get<double>(v))) return to_text(v);
    char buf[32];
    std::snprintf(buf, sizeof buf, precise ? "%.12g" : "%.4g", std::get<double>(v));
    return buf;
}

bool is_precise(const table_info& info, const std::string& key) {
    return std::find(info.md_precise.begin(), info.md_precise.end(), key) != info.md_precise.end();
}

// The pivot view: rows in order of first appearance, cells blank where no record has them.
void pivot_markdown(std::ostringstream& out, const table_output& t) {
    const pivot_view& p = *t.info.md_pivot;
    out << "|";
    for (const auto& k : p.row_keys) out << " " << k << " |";
    // Column values are inputs (angles such as 89.9999): written in full, never rounded together.
    for (double c : p.columns) out << " " << p.column_key << " = " << to_short_text(c, true) << " |";
    out << "\n|";
    for (std::size_t i = 0; i < p.row_keys.size() + p.columns.size(); ++i) out << "---|";
    out << "\n";
    std::vector<std::string> order;
    std::map<std::string, std::vector<std::string>> lines;
    for (const auto& r : t.records) {
        std::string key;
        for (const auto& k : p.row_keys) key += "| " + (r.find(k) ? to_short_text(*r.find(k)) : std::string()) + " ";
        auto [it, fresh] = lines.try_emplace(key, p.columns.size());
        if (fresh) order.push_back(key);
        const double c = r.number(p.column_key, std::nan(""));
        for (std::size_t j = 0; j < p.columns.size(); ++j)
            if (c == p.columns[j] && r.find(p.value_key))
                it->second[j] = to_short_text(*r.find(p.value_key), is_precise(t.info, p.value_key)) +
                                (r.failed() ? " (fails)" : "");
    }
    for (const auto& key : order) {
        out << key << "|";
        for (const auto& cell : lines[key]) out << " " << cell << " |";
        out << "\n";
    }
}

std::string csv_cell(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

// Keys in the records' order: a key first met in a later record goes after the key before it
// there, so that a column some records lack (f0 in a sweep that mixes F parts) stays among its
// neighbours rather than after the results.
std::vector<std::string> all_keys(const table_output& t) {
    std::vector<std::string> keys;
    std::set<std::string> seen;
    for (const auto& r : t.records) {
        auto after = keys.begin();  // where this record's next new key goes
        for (const auto& [k, v] : r.fields) {
            if (seen.insert(k).second) {
                after = keys.insert(after, k) + 1;
            } else {
                const auto at = std::find(keys.begin(), keys.end(), k);
                if (at >= after) after = at + 1;
            }
        }
    }
    return keys;
}

std::string provenance(const table_output& t) {
    return std::string("normzoo ") + NORMZOO_VERSION + ", `" + t.command + "`, " + t.parameters;
}

}  // namespace

std::string markdown(const table_output& t, std::size_t max_rows) {
    std::ostringstream out;
    out << "# " << t.info.name << ": " << t.info.title << "\n\n";
    out << "Produced by " << provenance(t) << ".\n\n";
    for (const auto& s : t.info.settings) out << "- " << s << "\n";
    out << "\n";
    // What each row or form of the table is (docs/conventions.md has the notation).
    if (const auto formulas = formula_lines(t.records); !formulas.empty()) {
        out << "Formulas:\n\n";
        for (const auto& f : formulas) out << "- " << f << "\n";
        out << "\n";
    }
    if (t.info.md_pivot) {
        pivot_markdown(out, t);
        std::size_t failed = 0, checks = 0;
        for (const auto& r : t.records) checks += r.find("pass") != nullptr, failed += r.failed();
        out << "\n" << t.records.size() << " records";
        if (checks) out << ", " << checks - failed << " of " << checks << " checks pass";
        out << ". The grid shows " << t.info.md_pivot->value_key << " at " << t.info.md_pivot->columns.size()
            << " values of " << t.info.md_pivot->column_key << "; every record is in `" << t.info.name << ".csv` and `"
            << t.info.name << ".json`.\n";
        return out.str();
    }
    out << "|";
    for (const auto& c : t.info.md_columns) out << " " << c << " |";
    out << "\n|";
    for (std::size_t i = 0; i < t.info.md_columns.size(); ++i) out << "---|";
    out << "\n";
    const std::size_t n = t.records.size();
    std::size_t shown = 0, failed = 0, checks = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto& r = t.records[i];
        if (r.find("pass")) ++checks;
        if (r.failed()) ++failed;
        // Long tables show an even sample (first and last included), every failure and the rows
        // the table asks for (md_always).
        const bool sampled = n <= max_rows || i == n - 1 || (i * (max_rows - 1)) % (n - 1) < max_rows - 1;
        const auto* marked = t.info.md_always ? r.find(t.info.md_always->first) : nullptr;
        const bool always = marked && std::holds_alternative<std::string>(*marked) &&
                            std::get<std::string>(*marked) == t.info.md_always->second;
        if (!sampled && !r.failed() && !always) continue;
        ++shown;
        out << "|";
        for (const auto& c : t.info.md_columns) {
            const auto* v = r.find(c);
            out << " " << (v ? to_short_text(*v, is_precise(t.info, c)) : std::string()) << " |";
        }
        out << "\n";
    }
    out << "\n" << n << " records";
    if (checks) out << ", " << checks - failed << " of " << checks << " checks pass";
    out << ".";
    if (shown < n) {
        const std::string also = t.info.md_always ? ", every failure and every " + t.info.md_always->first + " " +
                                                        t.info.md_always->second
                                                  : " and every failure";
        out << " Showing " << shown << " of them (an even sample" << also << "); all are in `" << t.info.name
            << ".csv` and `" << t.info.name << ".json`.";
    }
    out << "\n";
    return out.str();
}

std::string csv(const table_output& t) {
    std::ostringstream out;
    out << "# " << provenance(t) << "\n";
    for (const auto& s : t.info.settings) out << "# " << s << "\n";
    const auto keys = all_keys(t);
    out << "table";
    for (const auto& k : keys) out << "," << csv_cell(k);
    out << "\n";
    for (const auto& r : t.records) {
        out << csv_cell(r.table);
        for (const auto& k : keys) {
            const auto* v = r.find(k);
            out << "," << (v ? csv_cell(to_text(*v)) : std::string());
        }
        out << "\n";
    }
    return out.str();
}

// One record per line: long tables stay small and their diffs readable.
std::string json_file(const table_output& t) {
    ordered_json head;
    head["normzoo"] = NORMZOO_VERSION;
    head["table"] = t.info.name;
    head["title"] = t.info.title;
    head["command"] = t.command;
    head["parameters"] = t.parameters;
    head["settings"] = t.info.settings;
    std::string text = head.dump(1);
    text.pop_back();  // the closing brace
    text += ",\n \"records\": [";
    const auto records = records_json(t);
    for (std::size_t i = 0; i < records.size(); ++i) text += (i ? ",\n  " : "\n  ") + records[i].dump();
    text += records.empty() ? "]\n}\n" : "\n ]\n}\n";
    return text;
}

nlohmann::ordered_json records_json(const table_output& t) {
    ordered_json records = ordered_json::array();
    for (const auto& r : t.records) {
        ordered_json o;
        o["table"] = r.table;
        for (const auto& [k, v] : r.fields) o[k] = to_json(v);
        records.push_back(std::move(o));
    }
    return records;
}

namespace {

// An input as it was given: the shortest text that reads back as the same double ("8", "0.1").
std::string id_text(const field_value& v) {
    std::string s = to_text(v);
    if (std::holds_alternative<double>(v) && s.size() > 2 && s.compare(s.size() - 2, 2, ".0") == 0) s.resize(s.size() - 2);
    return s;
}

// The keys that name record r: those its table declares (table_info::id_keys) that r has, not null, so that
// a JUnit test case keeps its name from run to run (docs/command-line.md).
std::vector<std::string> id_keys_of(const table_output& t, const record& r) {
    std::vector<std::string> keys;
    if (!t.info.id_keys.empty()) {
        const bool typed_incidence = r.find("mu_input") || r.find("theta_input");
        for (const auto& k : t.info.id_keys) {
            const field_value* v = r.find(k);
            // a null is absent for this record (docs/records.md); theta_deg from mu is computed
            if (v && !std::holds_alternative<std::nullptr_t>(*v) && !(k == "theta_deg" && typed_incidence)) keys.push_back(k);
        }
        return keys;
    }
    // A table that declares none: its leading text fields that are not numbers (names, not values).
    for (const auto& [k, v] : r.fields) {
        if (!std::holds_alternative<std::string>(v)) break;
        const std::string& text = std::get<std::string>(v);
        char* end = nullptr;
        std::strtod(text.c_str(), &end);
        if (!text.empty() && end == text.c_str() + text.size()) break;
        keys.push_back(k);
    }
    if (keys.empty() && !r.fields.empty()) keys.push_back(r.fields.front().first);
    return keys;
}

// The JUnit message attribute: the line whole when short, else cut at a word and marked.
std::string short_message(const std::string& line, std::size_t max = 200) {
    if (line.size() <= max) return line;
    const std::size_t cut = line.rfind(' ', max - 4);
    return line.substr(0, cut == std::string::npos ? max - 4 : cut) + " ...";
}

std::string xml_escaped(const std::string& s) {
    std::string o;
    for (char ch : s) {
        switch (ch) {
            case '&': o += "&amp;"; break;
            case '<': o += "&lt;"; break;
            case '>': o += "&gt;"; break;
            case '"': o += "&quot;"; break;
            default: o += ch;
        }
    }
    return o;
}

}  // namespace

std::string record_id(const table_output& t, const record& r) {
    std::string s;
    for (const auto& k : id_keys_of(t, r)) s += (s.empty() ? "" : ", ") + k + " = " + id_text(*r.find(k));
    return s;
}

std::string failure_line(const table_output& t, const record& r) {
    if (t.verdict) return t.info.name + ": " + t.verdict(r);
    const auto ids = id_keys_of(t, r);
    std::string why;
    for (const auto& c : t.info.md_columns) {
        const auto* v = r.find(c);
        if (c == "pass" || !v || std::holds_alternative<std::nullptr_t>(*v) ||
            std::find(ids.begin(), ids.end(), c) != ids.end())
            continue;
        why += (why.empty() ? "" : ", ") + c + " = " + to_short_text(*v, is_precise(t.info, c));
    }
    const std::string id = record_id(t, r);
    return t.info.name + ": " + id + (id.empty() || why.empty() ? "" : ": ") + why;
}

void print_failures(std::ostream& os, const table_output& t, std::size_t max_lines) {
    std::size_t failing = 0;
    for (const auto& r : t.records)
        if (r.failed() && ++failing <= max_lines) os << "  " << failure_line(t, r) << "\n";
    if (failing > max_lines)
        os << "  ... and " << failing - max_lines << " more failing " << t.info.name << " records (every one is in "
           << t.info.name << ".md)\n";
}

std::vector<junit_case> junit_test_cases(const table_output& t) {
    std::vector<junit_case> cases;
    for (const auto& r : t.records) {
        if (!r.find("pass")) continue;
        junit_case c{"normzoo." + t.info.name, record_id(t, r), {}};
        if (r.failed()) {
            std::string all;
            for (const auto& [k, v] : r.fields) all += (all.empty() ? "" : "; ") + k + " = " + to_text(v);
            c.failures = {failure_line(t, r), all};
        }
        cases.push_back(std::move(c));
    }
    return cases;
}

std::string junit_document(const std::vector<junit_case>& cases, const std::string& scene_name) {
    // "normzoo.zoo" -> "normzoo.NAME.zoo": a CI server keeps each scene's cases apart.
    auto suite_name = [&](const std::string& s) {
        if (scene_name.empty()) return s;
        return s.rfind("normzoo.", 0) == 0 ? "normzoo." + scene_name + s.substr(7) : scene_name + "." + s;
    };
    std::vector<std::string> suites;
    std::map<std::string, std::vector<const junit_case*>> by_suite;
    for (const auto& c : cases) {
        if (!by_suite.count(c.suite)) suites.push_back(c.suite);
        by_suite[c.suite].push_back(&c);
    }
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\""
      << xml_escaped(scene_name.empty() ? "normzoo" : "normzoo." + scene_name) << "\">\n";
    for (const auto& s : suites) {
        std::size_t failures = 0;
        for (const auto* c : by_suite[s]) failures += !c->failures.empty();
        const std::string name = xml_escaped(suite_name(s));
        x << "  <testsuite name=\"" << name << "\" tests=\"" << by_suite[s].size() << "\" failures=\"" << failures
          << "\">\n";
        for (const auto* c : by_suite[s]) {
            x << "    <testcase classname=\"" << name << "\" name=\"" << xml_escaped(c->name) << "\"";
            if (c->failures.empty()) {
                x << "/>\n";
                continue;
            }
            // The message is what a CI server lists; the body keeps every line whole.
            x << ">\n      <failure message=\"" << xml_escaped(short_message(c->failures.front())) << "\">";
            for (const auto& f : c->failures) x << xml_escaped(f) << "\n";
            x << "</failure>\n    </testcase>\n";
        }
        x << "  </testsuite>\n";
    }
    x << "</testsuites>\n";
    return x.str();
}

}  // namespace verify
