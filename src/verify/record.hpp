// A table row as the command hands it to the writers, built at its edge from the library's typed
// results: ordered (key, value) pairs. Values that need more digits than a double holds travel as
// decimal strings.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "library_names.hpp"

namespace verify {

// JSON a record carries as it is (a list of objects: lut-check's candidates): a JSON value in the
// JSON output, its text in CSV and Markdown.
struct json_text {
    std::string text;
};
inline bool operator==(const json_text& a, const json_text& b) { return a.text == b.text; }

using field_value = std::variant<std::nullptr_t, bool, std::int64_t, double, std::string, json_text>;

struct record {
    std::string table;
    std::vector<std::pair<std::string, field_value>> fields;

    record& set(std::string key, field_value value) {
        fields.emplace_back(std::move(key), std::move(value));
        return *this;
    }
    const field_value* find(const std::string& key) const {
        for (const auto& [k, v] : fields)
            if (k == key) return &v;
        return nullptr;
    }
    // Typed reads, for what draws a table from its records: a number from a double, an integer or
    // a decimal string (the values wider than a double travel as text); `otherwise` when the key
    // is missing, null or a bool.
    double number(const std::string& key, double otherwise = 0) const {
        const field_value* v = find(key);
        if (v && std::holds_alternative<double>(*v)) return std::get<double>(*v);
        if (v && std::holds_alternative<std::int64_t>(*v)) return static_cast<double>(std::get<std::int64_t>(*v));
        if (v && std::holds_alternative<std::string>(*v)) return std::strtod(std::get<std::string>(*v).c_str(), nullptr);
        return otherwise;
    }
    // A string field's text; empty when the key is missing or not a string.
    std::string text(const std::string& key) const {
        const field_value* v = find(key);
        return v && std::holds_alternative<std::string>(*v) ? std::get<std::string>(*v) : std::string();
    }
    // Every check record has "pass"; records that only report (findings) have none.
    bool failed() const {
        const field_value* p = find("pass");
        return p && std::holds_alternative<bool>(*p) && !std::get<bool>(*p);
    }
};

// A number that may be absent: null in the record when it is.
inline field_value optional_field(const std::optional<double>& x) { return x ? field_value(*x) : field_value(nullptr); }

namespace detail {
// A number in a table's text: six significant digits.
inline std::string format_number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
}
}  // namespace detail

// A Markdown view of a long table as a grid: one line per distinct row_keys, one column per
// value of column_key listed (e.g. albedo by model and n against a few angles).
struct pivot_view {
    std::vector<std::string> row_keys;
    std::string column_key;
    std::vector<double> columns;
    std::string value_key;
};

// How --check compares a table's records with the committed ones (docs/tables.md, "What --check
// compares"): the values that carry an error bound may differ by the sum of both records' bounds;
// the ignored fields (the bounds, and what moves with them) are not compared; every other field
// must match exactly.
struct bounded_value {
    std::string value;  // the field compared within the bounds
    std::string error;  // the field holding its bound
    bool relative;      // the bound is relative to the value
};
struct check_rule {
    std::vector<bounded_value> bounded;
    std::set<std::string> ignored;
};

// What produced a table, for the head of every results file, and what names and compares its records.
struct table_info {
    std::string name;                     // "zoo"
    std::string title;                    // one line for people
    std::vector<std::string> settings;    // number types, integrators, tolerances
    std::vector<std::string> md_columns;  // the keys the Markdown view shows (CSV/JSON show all)
    std::vector<std::string> md_precise = {};  // of those, the ones shown to 12 digits, not 4
    std::optional<pivot_view> md_pivot = {};    // shown instead of the rows when set
    std::optional<std::pair<std::string, std::string>> md_always = {};  // (key, text): rows a long table always shows
    // The fields that name a record across runs (record_id, JUnit names, failure lines): its ids and
    // inputs, never a computed value; a key a record lacks is left out. Empty: the record's leading
    // text fields (src/verify/writers.cpp).
    std::vector<std::string> id_keys = {};
    check_rule check = {};  // none: every field must match exactly
};

}  // namespace verify
