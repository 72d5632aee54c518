#include "writers.hpp"

#include <normzoo/version.hpp>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>

namespace verify {

namespace {

using nlohmann::ordered_json;

ordered_json to_json(const normzoo::field_value& v) {
    return std::visit(
        [](const auto& x) -> ordered_json {
            using X = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<X, std::nullptr_t>) return nullptr;
            else if constexpr (std::is_same_v<X, double>) return std::isfinite(x) ? ordered_json(x) : ordered_json(nullptr);
            else return x;
        },
        v);
}

std::string to_text(const normzoo::field_value& v) {
    if (std::holds_alternative<std::string>(v)) return std::get<std::string>(v);
    if (std::holds_alternative<std::nullptr_t>(v)) return "";
    if (std::holds_alternative<double>(v) && !std::isfinite(std::get<double>(v))) {
        const double d = std::get<double>(v);
        return std::isnan(d) ? "nan" : (d > 0 ? "inf" : "-inf");
    }
    return to_json(v).dump();
}

// Markdown is for reading: doubles to 4 significant digits (CSV and JSON keep them all).
std::string to_short_text(const normzoo::field_value& v) {
    if (!std::holds_alternative<double>(v) || !std::isfinite(std::get<double>(v))) return to_text(v);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", std::get<double>(v));
    return buf;
}

std::string csv_cell(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

// Keys in order of first appearance over all records.
std::vector<std::string> all_keys(const table_output& t) {
    std::vector<std::string> keys;
    std::set<std::string> seen;
    for (const auto& r : t.records)
        for (const auto& [k, v] : r.fields)
            if (seen.insert(k).second) keys.push_back(k);
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
    out << "\n|";
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
        // Long tables show an even sample (first and last included) and every failure.
        const bool sampled = n <= max_rows || i == n - 1 || (i * (max_rows - 1)) % (n - 1) < max_rows - 1;
        if (!sampled && !r.failed()) continue;
        ++shown;
        out << "|";
        for (const auto& c : t.info.md_columns) {
            const auto* v = r.find(c);
            out << " " << (v ? to_short_text(*v) : std::string()) << " |";
        }
        out << "\n";
    }
    out << "\n" << n << " records";
    if (checks) out << ", " << checks - failed << " of " << checks << " checks pass";
    out << ".";
    if (shown < n)
        out << " Showing " << shown << " of them (an even sample and every failure); all are in `" << t.info.name
            << ".csv` and `" << t.info.name << ".json`.";
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

std::string json_file(const table_output& t) {
    ordered_json doc;
    doc["normzoo"] = NORMZOO_VERSION;
    doc["table"] = t.info.name;
    doc["title"] = t.info.title;
    doc["command"] = t.command;
    doc["parameters"] = t.parameters;
    doc["settings"] = t.info.settings;
    doc["records"] = records_json(t);
    return doc.dump(1) + "\n";
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

std::filesystem::path file_set::temp_path(const std::string& name) const {
    return dir_ / ("." + name + ".tmp." + std::to_string(::getpid()));
}

void file_set::stage(const std::string& name, const std::string& content) {
    const auto temp = temp_path(name);
    {
        std::ofstream f(temp, std::ios::binary | std::ios::trunc);
        f << content;
        f.flush();
        if (!f) throw std::runtime_error("cannot write " + temp.string());
    }
    staged_.emplace_back(temp, dir_ / name);
}

void file_set::adopt(const std::string& name, const std::filesystem::path& temp) {
    staged_.emplace_back(temp, dir_ / name);
}

void file_set::commit() {
    for (const auto& [temp, target] : staged_) std::filesystem::rename(temp, target);
    staged_.clear();
}

file_set::~file_set() {
    std::error_code ignored;
    for (const auto& [temp, target] : staged_) std::filesystem::remove(temp, ignored);
}

}  // namespace verify
