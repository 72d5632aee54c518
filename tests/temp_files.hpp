// Temporary folders, whole-file reads and shell runs for the tests that run the command.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace normzoo_test {

// An empty folder of its own under the system's temporary folder (per name and process).
inline std::filesystem::path fresh_dir(const std::string& name) {
    const auto d = std::filesystem::temp_directory_path() / ("normzoo-test-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

// A test case's own folder (fresh_dir), removed at its end, and files written into it.
struct temp_dir {
    std::filesystem::path path;
    explicit temp_dir(const std::string& name) : path(fresh_dir(name)) {}
    ~temp_dir() { std::filesystem::remove_all(path); }
    temp_dir(const temp_dir&) = delete;
    temp_dir& operator=(const temp_dir&) = delete;
    // The path of `name` in the folder, written with `bytes`.
    std::string file(const std::string& name, const std::string& bytes) const {
        const std::string p = (path / name).string();
        std::ofstream(p, std::ios::binary) << bytes;
        return p;
    }
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

struct run_result {
    int status;
    std::string out;
};

// A shell command's exit status and what it printed on stdout.
inline run_result run_shell(const std::string& cmd) {
    FILE* p = popen(cmd.c_str(), "r");
    std::string out;
    std::array<char, 4096> buf{};
    while (std::size_t k = std::fread(buf.data(), 1, buf.size(), p)) out.append(buf.data(), k);
    const int st = pclose(p);
    return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, out};
}

}  // namespace normzoo_test
