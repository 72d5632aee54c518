// `verify lut ARGS` as the tests of what the command reads and writes run it: its output (stderr
// beside stdout) and exit status, or the records of its --json document. NORMZOO_VERIFY_BIN is
// the command the build made (tests/CMakeLists.txt).
#pragma once
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

#include "temp_files.hpp"

namespace normzoo_test {

inline run_result verify_lut(const std::string& args) { return run_shell(std::string(NORMZOO_VERIFY_BIN) + " lut " + args + " 2>&1"); }

// The records of a --json run (its stderr dropped).
inline nlohmann::json records(const std::string& args) {
    const auto r = run_shell(std::string(NORMZOO_VERIFY_BIN) + " lut " + args + " --json 2>/dev/null");
    CAPTURE(args, r.out);
    REQUIRE(!r.out.empty());
    return nlohmann::json::parse(r.out)["records"];
}

}  // namespace normzoo_test
