#include "check.hpp"

#include <normzoo/real.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace verify {

namespace {

using nlohmann::ordered_json;

struct checked_value {
    const char* value;
    const char* error;
    bool relative;
};
struct check_rule {
    std::vector<checked_value> values;  // within the sum of both bounds
    std::set<std::string> ignore;       // bounds and diagnostics that may move with them
};

// Per table: which values carry an error bound, and which fields are the bounds themselves or
// derived from them. Everything else (ids, grids, verdicts, closed forms) must match exactly.
const std::map<std::string, check_rule>& rules() {
    static const std::map<std::string, check_rule> r = {
        {"zoo",
         {{{"norm_quadrature", "error_estimate", true}, {"norm_quadrature_2d", "error_estimate_2d", true}},
          {"rel_error", "error_estimate", "digits", "rel_error_2d", "error_estimate_2d", "digits_2d", "evaluations",
           "evaluations_2d"}}},
        {"energy",
         {{{"albedo", "error_estimate", false}},
          {"error_estimate", "tolerance", "evaluations", "closed_form_difference"}}},
        {"energy-summary",
         {{{"max_albedo", "max_albedo_error", false}, {"gain", "max_albedo_error", false},
           {"albedo_at_normal", "max_albedo_error", false}},
          {"max_albedo_error"}}},
        {"energy-claims", {{{"value", "error_estimate", false}}, {"error_estimate"}}},
        {"fresnel-visibility-albedo",
         {{{"albedo_minimalist", "error_minimalist", false}, {"albedo_schlick_ksk", "error_schlick_ksk", false}},
          {"error_minimalist", "error_schlick_ksk", "ratio"}}},
        {"energy-montecarlo",
         {{{"quadrature_albedo", "quadrature_error", false}},
          {"quadrature_error", "quadrature_evaluations", "deviation_in_standard_errors",
           "mc_samples_for_quadrature_error"}}},
        {"irradiance",
         {{{"E_quadrature", "error_estimate", true}},
          {"rel_error", "error_estimate", "digits", "normalized", "deviation", "observed_order"}}},
        {"irradiance-limit",
         {{}, {"fewest_digits", "deviation_at_smallest_ratio", "mean_observed_order", "orders_observed"}}},
        {"punctual-limit",
         {{{"cone_integral", "error_estimate", true}}, {"deviation", "error_estimate", "observed_order"}}},
        {"enclosures",
         {{{"enclosure_mid", "enclosure_rel_radius", true}, {"norm_quadrature", "quadrature_error_estimate", true}},
          {"enclosure_radius", "enclosure_rel_radius", "quadrature_error_estimate", "quadrature_error_certified",
           "seconds"}}},
        {"proofs", {{}, {"seconds"}}},
        {"shader-normalization", {{{"max_albedo", "max_albedo_error", false}}, {"max_albedo_error", "verdict"}}},
    };
    return r;
}

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

}  // namespace

std::vector<std::string> compare_with_committed(const table_output& t, const std::filesystem::path& dir) {
    std::vector<std::string> diffs;
    const auto path = dir / (t.info.name + ".json");
    std::ifstream f(path);
    if (!f) return {"no committed copy at " + path.string()};
    std::vector<ordered_json> old;
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
    static const check_rule none;
    const auto it = rules().find(t.info.name);
    const check_rule& rule = it == rules().end() ? none : it->second;
    const std::size_t n = std::min(committed.size(), fresh.size());
    for (std::size_t i = 0; i < n && diffs.size() < 50; ++i) {
        const auto& a = committed[i];
        const auto& b = fresh[i];
        std::set<std::string> keys;
        for (auto k = a.begin(); k != a.end(); ++k) keys.insert(k.key());
        for (auto k = b.begin(); k != b.end(); ++k) keys.insert(k.key());
        for (const auto& key : keys) {
            if (rule.ignore.count(key)) continue;
            if (!a.contains(key) || !b.contains(key)) {
                diffs.push_back("record " + std::to_string(i + 1) + " (" + identity(b) + "): field " + key +
                                (a.contains(key) ? " is gone" : " is new"));
                continue;
            }
            const checked_value* cv = nullptr;
            for (const auto& v : rule.values)
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
                    m << "record " << i + 1 << " (" << identity(b) << "): " << key << " " << a[key].dump() << " -> "
                      << b[key].dump() << ", difference " << normzoo::to_decimal(abs(x - y), 3) << " > bound "
                      << normzoo::to_decimal(bound, 3);
                    diffs.push_back(m.str());
                }
            } else if (a[key] != b[key]) {
                diffs.push_back("record " + std::to_string(i + 1) + " (" + identity(b) + "): " + key + " " +
                                a[key].dump() + " -> " + b[key].dump());
            }
        }
    }
    if (diffs.size() >= 50) diffs.push_back("(further differences not listed)");
    return diffs;
}

std::vector<junit_case> junit_cases(const table_output& t) {
    std::vector<junit_case> cases;
    const auto recs = records_json(t);
    for (std::size_t i = 0; i < t.records.size(); ++i) {
        if (!t.records[i].find("pass")) continue;
        junit_case c{"normzoo." + t.info.name, identity(recs[i]), {}};
        if (t.records[i].failed()) {
            std::string all;
            for (auto k = recs[i].begin(); k != recs[i].end(); ++k)
                all += (all.empty() ? "" : "; ") + k.key() + " = " + (k->is_string() ? k->get<std::string>() : k->dump());
            c.failures.push_back(all);
        }
        cases.push_back(std::move(c));
    }
    return cases;
}

std::string junit_xml(const std::vector<junit_case>& cases) {
    auto esc = [](const std::string& s) {
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
    };
    std::vector<std::string> suites;
    std::map<std::string, std::vector<const junit_case*>> by_suite;
    for (const auto& c : cases) {
        if (!by_suite.count(c.suite)) suites.push_back(c.suite);
        by_suite[c.suite].push_back(&c);
    }
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"normzoo\">\n";
    for (const auto& s : suites) {
        std::size_t failures = 0;
        for (const auto* c : by_suite[s]) failures += !c->failures.empty();
        x << "  <testsuite name=\"" << esc(s) << "\" tests=\"" << by_suite[s].size() << "\" failures=\"" << failures
          << "\">\n";
        for (const auto* c : by_suite[s]) {
            x << "    <testcase classname=\"" << esc(s) << "\" name=\"" << esc(c->name) << "\"";
            if (c->failures.empty()) {
                x << "/>\n";
                continue;
            }
            x << ">\n      <failure message=\"" << esc(c->failures.front().substr(0, 200)) << "\">";
            for (const auto& f : c->failures) x << esc(f) << "\n";
            x << "</failure>\n    </testcase>\n";
        }
        x << "  </testsuite>\n";
    }
    x << "</testsuites>\n";
    return x.str();
}

}  // namespace verify
