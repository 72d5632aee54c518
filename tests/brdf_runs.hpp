// `verify --brdf ...` as the tests of shader files run it: its stdout (stderr dropped) and exit
// status, and the albedo records (table brdf) of its --json document. NORMZOO_VERIFY_BIN is the
// command the build made (tests/CMakeLists.txt).
#pragma once
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "temp_files.hpp"

namespace normzoo_test {

inline run_result run_verify_quiet(const std::string& args) {
    return run_shell(std::string(NORMZOO_VERIFY_BIN) + " " + args + " 2>/dev/null");
}

// The records of table brdf in a --json document.
inline std::vector<nlohmann::json> albedo_records(const std::string& json) {
    std::vector<nlohmann::json> out;
    const auto doc = nlohmann::json::parse(json);  // kept: the loop reads into it
    for (const auto& r : doc["records"])
        if (r["table"] == "brdf") out.push_back(r);
    return out;
}

}  // namespace normzoo_test
