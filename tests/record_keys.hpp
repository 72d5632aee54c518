// The key lists that docs/records.md and docs/schema/output.schema.json give for each table,
// generated from the records a run makes (docs/records.md): each table's keys in the order its
// records hold them, and the keys every record has. test_schema compares the committed files
// with them; tools/update-schemas writes them.
#pragma once
#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace normzoo_test {

// A table's keys as its records hold them: every key in order, those every record has, and the
// JSON types each key's values took (what a new table's or key's generated entry starts from).
struct table_keys {
    std::vector<std::string> keys;
    std::vector<std::string> required;
    std::map<std::string, std::set<std::string>> types;
};

// The tables whose keys depend on the compositions and options given: listed by hand
// (docs/records.md, "Microfacet compositions, baked tables"), in records.md and the schema.
inline bool keys_by_options(const std::string& table) {
    return table == "microfacet-energy" || table == "lut" || table == "lut-check";
}

// A value's JSON type: "integer" for a whole number the writer printed as one (a double prints
// as 8.0, "number").
inline std::string json_type(const nlohmann::ordered_json& v) {
    if (v.is_number_integer()) return "integer";
    if (v.is_number()) return "number";
    if (v.is_boolean()) return "boolean";
    return v.is_null() ? "null" : v.is_string() ? "string" : v.is_array() ? "array" : "object";
}

// The types seen, in the words of records.md's type column: "number or null".
inline std::string type_words(const std::set<std::string>& seen) {
    std::string words;
    for (const char* t : {"integer", "number", "string", "boolean", "array", "object", "null"}) {
        if (!seen.count(t) || (std::string(t) == "integer" && seen.count("number"))) continue;
        words += (words.empty() ? "" : " or ") + std::string(t);
    }
    return words;
}

// The keys that stand for a family of keys: a BRDF file's parameter NAME is the key param_NAME.
inline std::string documented_key(const std::string& table, const std::string& key) {
    const bool brdf_table = table == "brdf" || table == "brdf-checks" || table == "brdf-conformance";
    return brdf_table && key.rfind("param_", 0) == 0 ? "param_NAME" : key;
}

// Each table's keys over records, in record order: a key first met in a later record goes after
// the key before it there, as the CSV writer orders its columns (src/verify/writers.cpp).
inline std::map<std::string, table_keys> keys_by_table(const std::vector<nlohmann::ordered_json>& records) {
    std::map<std::string, table_keys> out;
    std::map<std::string, std::map<std::string, std::size_t>> counts;
    std::map<std::string, std::size_t> totals;
    for (const auto& r : records) {
        const std::string table = r.at("table").get<std::string>();
        auto& keys = out[table].keys;
        ++totals[table];
        std::set<std::string> in_record;
        auto after = keys.begin();  // where this record's next new key goes
        for (auto it = r.begin(); it != r.end(); ++it) {
            const std::string key = documented_key(table, it.key());
            if (!in_record.insert(key).second) continue;
            ++counts[table][key];
            out[table].types[key].insert(json_type(it.value()));
            const auto at = std::find(keys.begin(), keys.end(), key);
            if (at == keys.end()) {
                after = keys.insert(after, key) + 1;
            } else if (at >= after) {
                after = at + 1;
            }
        }
    }
    for (auto& [table, k] : out)
        for (const auto& key : k.keys)
            if (counts[table][key] == totals[table]) k.required.push_back(key);
    return out;
}

// The first difference between a committed key list and the generated one, in words naming the
// key; empty when they are the same.
inline std::string key_list_difference(const std::vector<std::string>& committed, const std::vector<std::string>& generated) {
    for (std::size_t i = 0; i < std::max(committed.size(), generated.size()); ++i) {
        if (i < committed.size() && i < generated.size() && committed[i] == generated[i]) continue;
        if (i >= committed.size()) return "lacks key '" + generated[i] + "' (the records have it)";
        if (std::find(generated.begin(), generated.end(), committed[i]) == generated.end())
            return "has key '" + committed[i] + "', which no record has";
        if (std::find(committed.begin(), committed.end(), generated[i]) == committed.end())
            return "lacks key '" + generated[i] + "' (the records have it)";
        return "has key '" + committed[i] + "' where the records have '" + generated[i] + "'";
    }
    return {};
}

// --- docs/records.md: each table's key table between <!-- keys TABLE --> and <!-- end keys -->.
// The key column and its order are generated; each row's type and meaning are written by hand
// and kept with their key. A row may name several keys that follow each other (`a`, `b`).

struct key_row {
    std::vector<std::string> keys;  // the backquoted names of its first cell
    std::string line;
};

inline key_row parse_key_row(const std::string& line) {
    key_row row{{}, line};
    const std::size_t end = line.find('|', 1);
    const std::string cell = line.substr(1, end == std::string::npos ? std::string::npos : end - 1);
    for (std::size_t at = cell.find('`'); at != std::string::npos;) {
        const std::size_t close = cell.find('`', at + 1);
        if (close == std::string::npos) break;
        row.keys.push_back(cell.substr(at + 1, close - at - 1));
        at = cell.find('`', close + 1);
    }
    return row;
}

// The marked key tables of records.md: table name -> its rows (the head's two lines excluded).
inline std::map<std::string, std::vector<key_row>> marked_key_tables(const std::string& text) {
    std::map<std::string, std::vector<key_row>> out;
    std::istringstream in(text);
    std::string line, table;
    bool inside = false;
    while (std::getline(in, line)) {
        if (line.rfind("<!-- keys ", 0) == 0) {
            table = line.substr(10, line.find(" -->") - 10);
            inside = true;
            out[table];
        } else if (line == "<!-- end keys -->") {
            inside = false;
        } else if (inside && line.rfind("| `", 0) == 0) {
            out[table].push_back(parse_key_row(line));
        }
    }
    return out;
}

inline std::vector<std::string> keys_of_rows(const std::vector<key_row>& rows) {
    std::vector<std::string> keys;
    for (const auto& r : rows) keys.insert(keys.end(), r.keys.begin(), r.keys.end());
    return keys;
}

// A row to describe for a key no row names, typed from the values seen.
inline std::string row_to_describe(const std::string& key, const table_keys& k) {
    const auto seen = k.types.find(key);
    std::string type = seen == k.types.end() ? "" : type_words(seen->second);
    if (std::find(k.required.begin(), k.required.end(), key) == k.required.end()) type += " (optional)";
    return "| `" + key + "` | " + type + " | (to describe) |";
}

// A table's rows in the generated order ("table" left out: every record begins with it): each
// committed row where its keys come in that order, a row to describe for a key no row names.
inline std::vector<std::string> generated_rows(const std::vector<key_row>& rows, const table_keys& k) {
    std::vector<std::string> keys = k.keys;
    keys.erase(std::remove(keys.begin(), keys.end(), "table"), keys.end());
    std::vector<std::string> out;
    for (std::size_t i = 0; i < keys.size();) {
        const key_row* match = nullptr;
        for (const auto& r : rows)
            if (!r.keys.empty() && i + r.keys.size() <= keys.size() &&
                std::equal(r.keys.begin(), r.keys.end(), keys.begin() + static_cast<std::ptrdiff_t>(i)))
                match = &r;
        out.push_back(match ? match->line : row_to_describe(keys[i], k));
        i += match ? match->keys.size() : 1;
    }
    return out;
}

// The section of a table records.md lacks: its heading, a line to replace, its key table.
inline std::string new_section(const std::string& table, const table_keys& k) {
    std::string s = "### `" + table + "`\n\n(to describe: which command makes the table, and what one record is)\n\n";
    s += "<!-- keys " + table + " -->\n| key | type | meaning, unit |\n|---|---|---|\n";
    for (const auto& row : generated_rows({}, k)) s += row + "\n";
    return s + "<!-- end keys -->\n\n";
}

// records.md with every marked key table rewritten from the generated keys, everything outside
// the marked rows kept as it is; a table the records show without a section gets one after the
// last section (before the next `## ` part: the tables listed by hand).
inline std::string generated_records_md(const std::string& text, const std::map<std::string, table_keys>& keys) {
    const auto tables = marked_key_tables(text);
    std::istringstream in(text);
    std::vector<std::string> out;
    std::string line, table;
    bool inside = false;
    std::size_t sections_end = 0;  // where the new sections go
    while (std::getline(in, line)) {
        if (line.rfind("<!-- keys ", 0) == 0) {
            table = line.substr(10, line.find(" -->") - 10);
            inside = true;
        } else if (line == "<!-- end keys -->" && inside) {
            inside = false;
            const auto found = keys.find(table);
            for (const auto& row : generated_rows(tables.at(table), found == keys.end() ? table_keys{} : found->second))
                out.push_back(row + "\n");
            sections_end = 0;
        } else if (inside && line.rfind("| `", 0) == 0) {
            continue;  // a key row: written at the end of its table
        } else if (line.rfind("## ", 0) == 0 && sections_end == 0 && !tables.empty()) {
            sections_end = out.size();
        }
        out.push_back(line + "\n");
    }
    if (sections_end == 0) sections_end = out.size();
    for (const auto& [t, k] : keys)
        if (!keys_by_options(t) && !tables.count(t))
            out.insert(out.begin() + static_cast<std::ptrdiff_t>(sections_end++), new_section(t, k));
    std::string joined;
    for (const auto& l : out) joined += l;
    return joined;
}

// --- the schema's $defs: a table's `required` and the order of its `properties`, each property's
// schema kept; a key the schema lacks gets one to describe. A table whose records may carry keys
// of their own (additionalProperties: brdf's param_NAME) lists only the others.

inline nlohmann::ordered_json generated_properties(const nlohmann::ordered_json& def, const std::vector<std::string>& keys) {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    for (const auto& k : keys) {
        if (k == "param_NAME") continue;
        const auto& props = def.at("properties");
        out[k] = props.contains(k) ? props.at(k) : nlohmann::ordered_json{{"description", "(to describe)"}};
    }
    return out;
}

// The names of an object's members (a $def's properties), in order.
inline std::vector<std::string> member_names(const nlohmann::ordered_json& object) {
    std::vector<std::string> names;
    for (auto it = object.begin(); it != object.end(); ++it) names.push_back(it.key());
    return names;
}

}  // namespace normzoo_test
