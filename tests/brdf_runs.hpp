// `verify ARGS` as the end-to-end tests of shader files run it: its stdout (stderr dropped, or
// after it with `with_stderr`) and exit status, and the records of one table in a --json
// document. NORMZOO_VERIFY_BIN is the command the build made (tests/CMakeLists.txt).
#pragma once
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "temp_files.hpp"

namespace normzoo_test {

inline run_result run(const std::string& args, bool with_stderr = false) {
    return run_shell(std::string(NORMZOO_VERIFY_BIN) + " " + args + (with_stderr ? " 2>&1" : " 2>/dev/null"));
}

// The records of `table` in a --json document.
inline std::vector<nlohmann::json> records_of(const std::string& json, const std::string& table) {
    std::vector<nlohmann::json> out;
    const auto doc = nlohmann::json::parse(json);  // kept: the loop reads into it
    for (const auto& r : doc["records"])
        if (r["table"] == table) out.push_back(r);
    return out;
}

}  // namespace normzoo_test
