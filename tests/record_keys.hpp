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

// A table's keys as its records hold them: every key in order, and those every record has.
struct table_keys {
    std::vector<std::string> keys;
    std::vector<std::string> required;
};

// The keys that stand for a family of keys: a BRDF file's parameter NAME is the key param_NAME.
inline std::string documented_key(const std::string& table, const std::string& key) {
    const bool brdf_table = table == "brdf" || table == "brdf-checks";
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

// A table's rows in the generated order: each committed row where its keys come in that order,
// a row to describe for a key no row names.
inline std::vector<std::string> generated_rows(const std::vector<key_row>& rows, const std::vector<std::string>& keys) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < keys.size();) {
        const key_row* match = nullptr;
        for (const auto& r : rows)
            if (!r.keys.empty() && i + r.keys.size() <= keys.size() &&
                std::equal(r.keys.begin(), r.keys.end(), keys.begin() + static_cast<std::ptrdiff_t>(i)))
                match = &r;
        out.push_back(match ? match->line : "| `" + keys[i] + "` | | (to describe) |");
        i += match ? match->keys.size() : 1;
    }
    return out;
}

// records.md with every marked key table rewritten from the generated keys ("table" left out:
// every record begins with it); everything outside the marked rows kept as it is.
inline std::string generated_records_md(const std::string& text, const std::map<std::string, table_keys>& keys) {
    const auto tables = marked_key_tables(text);
    std::istringstream in(text);
    std::ostringstream out;
    std::string line, table;
    bool inside = false;
    while (std::getline(in, line)) {
        if (line.rfind("<!-- keys ", 0) == 0) {
            table = line.substr(10, line.find(" -->") - 10);
            inside = true;
        } else if (line == "<!-- end keys -->" && inside) {
            inside = false;
            const auto found = keys.find(table);
            std::vector<std::string> listed = found == keys.end() ? std::vector<std::string>{} : found->second.keys;
            listed.erase(std::remove(listed.begin(), listed.end(), "table"), listed.end());
            for (const auto& row : generated_rows(tables.at(table), listed)) out << row << "\n";
        } else if (inside && line.rfind("| `", 0) == 0) {
            continue;  // a key row: written at the end of its table
        }
        out << line << "\n";
    }
    return out.str();
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
