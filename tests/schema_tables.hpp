// The tables docs/schema/output.schema.json describes, beyond their key lists (tests/record_keys.hpp):
// a $defs entry per table, the record's oneOf over them and the enum of the records' `table`.
// Generated where the records show a table the schema lacks, so that adding a table needs no hand
// edit of the schema; test_schema compares them, tools/update-schemas writes them (docs/records.md).
#pragma once
#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "record_keys.hpp"

namespace normzoo_test {

const std::string table_enum_pointer = "/$defs/record/properties/table/enum";
const std::string one_of_pointer = "/$defs/record/oneOf";

// The table a $defs entry describes: its `table` const (energy has two entries, the forms' and
// the compositions'), or "" for an entry that is no table's (record).
inline std::string def_table(const nlohmann::ordered_json& def) {
    const nlohmann::ordered_json::json_pointer at("/properties/table/const");
    return def.contains(at) && def.at(at).is_string() ? def.at(at).get<std::string>() : "";
}

// A key's schema type from the values seen: a double may be null in another run (the writer
// prints a value that is not finite as null), and an integer key with doubles is a number.
inline nlohmann::ordered_json schema_type(const std::set<std::string>& seen) {
    std::vector<std::string> types;
    for (const char* t : {"integer", "number", "string", "boolean", "array", "object"})
        if (seen.count(t) && !(std::string(t) == "integer" && seen.count("number"))) types.push_back(t);
    if (seen.count("null") || seen.count("number")) types.push_back("null");
    if (types.size() == 1) return types.front();
    return types;
}

// The $defs entry of a table the schema lacks: its keys, required and typed, each to describe.
inline nlohmann::ordered_json new_table_def(const std::string& table, const table_keys& k) {
    nlohmann::ordered_json properties = nlohmann::ordered_json::object();
    for (const auto& key : k.keys)
        properties[key] = key == "table" ? nlohmann::ordered_json{{"const", table}}
                                         : nlohmann::ordered_json{{"type", schema_type(k.types.at(key))},
                                                                  {"description", "(to describe)"}};
    return {{"type", "object"},
            {"description", "(to describe)"},
            {"required", k.required},
            {"additionalProperties", false},
            {"properties", properties}};
}

// The generated parts as {JSON pointer: value}: a $defs entry for each table the records show
// and no entry describes; the oneOf, the committed references to existing entries in their order
// and then one to each entry not referenced; the `table` enum, every table the oneOf takes and
// the records show, sorted (lut and lut-check, which no generating run makes, kept by their entries).
inline nlohmann::ordered_json generated_table_parts(const nlohmann::ordered_json& schema,
                                                    const std::map<std::string, table_keys>& keys) {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    nlohmann::ordered_json defs = schema.at("$defs");
    std::set<std::string> described;
    for (const auto& def : defs) described.insert(def_table(def));
    for (const auto& [table, k] : keys)
        if (!described.count(table)) {
            defs[table] = new_table_def(table, k);
            out["/$defs/" + table] = defs[table];
        }
    nlohmann::ordered_json one_of = nlohmann::ordered_json::array();
    std::set<std::string> referenced;
    for (const auto& ref : schema.at(nlohmann::ordered_json::json_pointer(one_of_pointer))) {
        const std::string name = ref.at("$ref").get<std::string>().substr(8);  // after "#/$defs/"
        if (defs.contains(name) && referenced.insert(name).second) one_of.push_back(ref);
    }
    std::set<std::string> tables;
    for (auto it = defs.begin(); it != defs.end(); ++it) {
        if (def_table(*it).empty()) continue;
        tables.insert(def_table(*it));
        if (!referenced.count(it.key())) one_of.push_back({{"$ref", "#/$defs/" + it.key()}});
    }
    for (const auto& [table, k] : keys) tables.insert(table);
    out[one_of_pointer] = one_of;
    out[table_enum_pointer] = std::vector<std::string>(tables.begin(), tables.end());
    return out;
}

// The schema with the generated parts in place (the key lists are generated from it).
inline nlohmann::ordered_json with_table_parts(nlohmann::ordered_json schema, const nlohmann::ordered_json& parts) {
    for (const auto& [pointer, value] : parts.items()) schema[nlohmann::ordered_json::json_pointer(pointer)] = value;
    return schema;
}

}  // namespace normzoo_test
