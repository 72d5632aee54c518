// The command end to end, shared by the test_cli*.cpp files: running it, and reading what it
// prints and writes.
#pragma once
#include <catch2/catch.hpp>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <normzoo/version.hpp>
#include <normzoo/wide.hpp>

#include <boost/math/constants/constants.hpp>

#include "args.hpp"
#include "lut_fixtures.hpp"
#include "lut_formats/dds.hpp"
#include "lut_formats/ktx2.hpp"
#include "lut_image.hpp"
#include "temp_files.hpp"

namespace cli_test {

namespace fs = std::filesystem;
using normzoo_test::run_result;
using normzoo_test::run_shell;

inline run_result run(const std::string& args) {
    return run_shell(std::string(NORMZOO_VERIFY_BIN) + " " + args + " 2>/dev/null");
}

// The command with `args` exits 2, and its message names `named`.
inline void check_refused(const std::string& args, const std::string& named) {
    const auto b = run_shell(std::string(NORMZOO_VERIFY_BIN) + " " + args + " 2>&1");
    CAPTURE(args, b.out);
    CHECK(b.status == 2);
    CHECK(b.out.find(named) != std::string::npos);
}

// A scene in `dir` of one material `body` exits 2, its message names `named`, and `unwritten`
// (under dir/out) is not made.
inline void check_scene_refused(const fs::path& dir, const std::string& body, const std::string& named, const fs::path& unwritten) {
    std::ofstream(dir / "s.toml") << "[[materials]]\nname = \"m\"\n" << body;
    const auto b = run_shell(std::string(NORMZOO_VERIFY_BIN) + " --scene '" + (dir / "s.toml").string() + "' --out '" +
                             (dir / "out").string() + "' 2>&1");
    CAPTURE(body, b.out);
    CHECK(b.status == 2);
    CHECK(b.out.find(named) != std::string::npos);
    CHECK(!fs::exists(dir / "out" / unwritten));
}

// stdout and stderr together, run from `cwd` without NORMZOO_RESULTS_DIR: a default output
// folder lands in cwd, never in the project's results/.
inline run_result run_in(const fs::path& cwd, const std::string& args) {
    return run_shell("cd '" + cwd.string() + "' && env -u NORMZOO_RESULTS_DIR " + NORMZOO_VERIFY_BIN + " " + args +
                     " 2>&1");
}

// The lines of a text that begin with `prefix`.
inline std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.rfind(prefix, 0) == 0) out.push_back(line);
    return out;
}

inline std::string xml_unescaped(std::string s) {
    const std::pair<std::string, std::string> entities[] = {{"&quot;", "\""}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}};
    for (const auto& [from, to] : entities)
        for (std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size()))
            s.replace(p, from.size(), to);
    return s;
}

// The text of attribute `name` in the first element at or after `from`.
inline std::string xml_attribute(const std::string& xml, const std::string& name, std::size_t from) {
    const std::size_t at = xml.find(" " + name + "=\"", from);
    if (at == std::string::npos) return {};
    const std::size_t start = at + name.size() + 3;
    return xml_unescaped(xml.substr(start, xml.find('"', start) - start));
}

using normzoo_test::fresh_dir;
using normzoo_test::slurp;

// The command with its stderr after its stdout, and NORMZOO_RESULTS_DIR set when `results` is
// given (as ./verify sets it to the checkout's results/).
inline run_result run_with_stderr(const std::string& args, const fs::path& results = {}) {
    const std::string env = results.empty() ? std::string() : "NORMZOO_RESULTS_DIR='" + results.string() + "' ";
    return run_shell(env + NORMZOO_VERIFY_BIN + " " + args + " 2>&1");
}

// Every file under `dir` by its path relative to it, with its bytes.
inline std::map<std::string, std::string> tree(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = slurp(e.path());
    return files;
}

// The files added, removed or changed from `before` to `after`.
inline std::vector<std::string> changed(const std::map<std::string, std::string>& before,
                                 const std::map<std::string, std::string>& after) {
    std::vector<std::string> names;
    for (const auto& [name, text] : after)
        if (!before.count(name) || before.at(name) != text) names.push_back(name);
    for (const auto& [name, text] : before)
        if (!after.count(name)) names.push_back(name + " (removed)");
    return names;
}

}  // namespace cli_test
