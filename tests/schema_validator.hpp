// A validator for the part of JSON Schema (draft 2020-12) that docs/schema/ uses: type, enum,
// const, required, properties, additionalProperties, items, minItems, maxItems, minimum,
// maximum, exclusiveMinimum, exclusiveMaximum, oneOf, anyOf and $ref to "#/$defs/NAME". Debian
// packages no C++ validator. A keyword outside this set is an error, so a schema never
// silently asks for more than is checked; annotations ($schema, $id, title, description,
// $comment, $defs) are read as such.
#pragma once
#include <nlohmann/json.hpp>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace normzoo_test {

class schema_validator {
public:
    explicit schema_validator(nlohmann::json root) : root_(std::move(root)) {}

    // Every place where `doc` breaks the schema, as "PATH: what"; empty when it conforms.
    std::vector<std::string> errors(const nlohmann::json& doc) const {
        std::vector<std::string> out;
        check(root_, doc, "$", out);
        return out;
    }

private:
    static bool is_type(const nlohmann::json& v, const std::string& type) {
        if (type == "null") return v.is_null();
        if (type == "boolean") return v.is_boolean();
        if (type == "object") return v.is_object();
        if (type == "array") return v.is_array();
        if (type == "string") return v.is_string();
        if (type == "number") return v.is_number();
        // JSON Schema: a number with no fractional part is an integer (8.0 too).
        if (type == "integer")
            return v.is_number_integer() || (v.is_number_float() && std::floor(v.get<double>()) == v.get<double>());
        throw std::invalid_argument("schema: unknown type '" + type + "'");
    }

    const nlohmann::json& resolve(const std::string& ref) const {
        const std::string prefix = "#/$defs/";
        if (ref.rfind(prefix, 0) != 0) throw std::invalid_argument("schema: $ref '" + ref + "' is not #/$defs/NAME");
        return root_.at("$defs").at(ref.substr(prefix.size()));
    }

    void check(const nlohmann::json& s, const nlohmann::json& v, const std::string& at,
               std::vector<std::string>& out) const {
        static const std::set<std::string> annotations = {"$schema", "$id", "title", "description", "$comment", "$defs"};
        static const std::set<std::string> known = {"type",     "enum",     "const",    "required",      "properties",
                                                    "additionalProperties", "items",    "minItems",      "maxItems",
                                                    "minimum",  "maximum",  "exclusiveMinimum", "exclusiveMaximum",
                                                    "oneOf",    "anyOf",    "$ref"};
        if (s.is_boolean()) {
            if (!s.get<bool>()) out.push_back(at + ": not allowed here");
            return;
        }
        for (auto it = s.begin(); it != s.end(); ++it)
            if (!known.count(it.key()) && !annotations.count(it.key()))
                throw std::invalid_argument("schema: keyword '" + it.key() + "' is not supported (at " + at + ")");
        if (s.contains("$ref")) check(resolve(s["$ref"].get<std::string>()), v, at, out);
        if (s.contains("type")) {
            bool ok = false;
            if (s["type"].is_array()) {
                for (const auto& t : s["type"]) ok = ok || is_type(v, t.get<std::string>());
            } else {
                ok = is_type(v, s["type"].get<std::string>());
            }
            if (!ok) {
                out.push_back(at + ": " + v.dump() + " is not of type " + s["type"].dump());
                return;  // the other keywords would only repeat it
            }
        }
        if (s.contains("const") && v != s["const"]) out.push_back(at + ": " + v.dump() + " is not " + s["const"].dump());
        if (s.contains("enum")) {
            bool found = false;
            for (const auto& e : s["enum"]) found = found || e == v;
            if (!found) out.push_back(at + ": " + v.dump() + " is not one of " + s["enum"].dump());
        }
        if (v.is_number()) {
            const double x = v.get<double>();
            if (s.contains("minimum") && x < s["minimum"].get<double>()) out.push_back(at + ": " + v.dump() + " < minimum " + s["minimum"].dump());
            if (s.contains("maximum") && x > s["maximum"].get<double>()) out.push_back(at + ": " + v.dump() + " > maximum " + s["maximum"].dump());
            if (s.contains("exclusiveMinimum") && !(x > s["exclusiveMinimum"].get<double>()))
                out.push_back(at + ": " + v.dump() + " is not > " + s["exclusiveMinimum"].dump());
            if (s.contains("exclusiveMaximum") && !(x < s["exclusiveMaximum"].get<double>()))
                out.push_back(at + ": " + v.dump() + " is not < " + s["exclusiveMaximum"].dump());
        }
        if (v.is_object()) {
            if (s.contains("required"))
                for (const auto& k : s["required"])
                    if (!v.contains(k.get<std::string>())) out.push_back(at + ": the key '" + k.get<std::string>() + "' is missing");
            const nlohmann::json none = nlohmann::json::object();
            const auto& props = s.contains("properties") ? s["properties"] : none;
            for (auto it = v.begin(); it != v.end(); ++it) {
                const std::string where = at + "." + it.key();
                if (props.contains(it.key())) check(props[it.key()], it.value(), where, out);
                else if (s.contains("additionalProperties")) check(s["additionalProperties"], it.value(), where, out);
            }
        }
        if (v.is_array()) {
            if (s.contains("minItems") && v.size() < s["minItems"].get<std::size_t>())
                out.push_back(at + ": fewer than " + s["minItems"].dump() + " items");
            if (s.contains("maxItems") && v.size() > s["maxItems"].get<std::size_t>())
                out.push_back(at + ": more than " + s["maxItems"].dump() + " items");
            if (s.contains("items"))
                for (std::size_t i = 0; i < v.size(); ++i) check(s["items"], v[i], at + "[" + std::to_string(i) + "]", out);
        }
        if (s.contains("oneOf") || s.contains("anyOf")) {
            const bool one = s.contains("oneOf");
            std::size_t matching = 0;
            std::vector<std::string> closest;  // the errors of the branch with the fewest, to say why none matches
            for (const auto& branch : s[one ? "oneOf" : "anyOf"]) {
                std::vector<std::string> e;
                check(branch, v, at, e);
                if (e.empty()) ++matching;
                else if (closest.empty() || e.size() < closest.size()) closest = e;
            }
            if (matching == 0) {
                out.push_back(at + ": matches no schema of " + (one ? "oneOf" : "anyOf") + ", e.g.:");
                for (const auto& e : closest) out.push_back("  " + e);
            } else if (one && matching > 1) {
                out.push_back(at + ": matches " + std::to_string(matching) + " schemas of oneOf, not one");
            }
        }
    }

    nlohmann::json root_;
};

}  // namespace normzoo_test
