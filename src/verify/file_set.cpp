// Files written so that a failed or interrupted run changes nothing (writers.hpp): a single file
// written to a temporary and renamed into place, file_set's staged files renamed together, and
// the checks, before anything is computed, that the output folder or JUnit file can be written.
#include "writers.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "args.hpp"

namespace verify {

namespace {
// Writes a whole file or throws (removing what was half written).
void write_file(const std::filesystem::path& path, const std::string& content) {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f << content;
    f.flush();
    if (!f) {
        f.close();
        std::error_code ignored;
        std::filesystem::remove(path, ignored);
        throw std::runtime_error("cannot write " + path.string());
    }
}
}  // namespace

void write_atomically(const std::filesystem::path& path, const std::string& content) {
    const auto temp = path.parent_path() / ("." + path.filename().string() + ".tmp." + std::to_string(::getpid()));
    write_file(temp, content);
    std::filesystem::rename(temp, path);
}

void check_output_folder(const std::filesystem::path& dir, const std::string& option) {
    namespace fs = std::filesystem;
    const std::string named = option + ": '" + dir.string() + "'";
    std::error_code ec;
    const auto st = fs::status(dir, ec);  // a missing path sets ec too: not an error here
    if (ec && st.type() != fs::file_type::not_found) throw bad_input(named + ": " + ec.message());
    if (fs::exists(st)) {
        if (!fs::is_directory(st)) throw bad_input(named + " is not a folder");
        if (::access(dir.c_str(), W_OK | X_OK) != 0)
            throw bad_input(named + ": cannot write into it: " + std::strerror(errno));
        return;
    }
    // Make each missing folder on the way, then remove what was made, deepest first.
    std::vector<fs::path> made;
    auto undo = [&] {
        std::error_code ignored;
        for (auto it = made.rbegin(); it != made.rend(); ++it) fs::remove(*it, ignored);
    };
    fs::path p;
    for (const auto& part : fs::absolute(dir).lexically_normal()) {
        p /= part;
        const auto s = fs::status(p, ec);
        if (ec && s.type() != fs::file_type::not_found) {
            undo();
            throw bad_input(named + " cannot be made: " + p.string() + ": " + ec.message());
        }
        if (fs::is_directory(s)) continue;
        if (fs::exists(s)) {
            undo();
            throw bad_input(named + " cannot be made: " + p.string() + " is not a folder");
        }
        if (!fs::create_directory(p, ec) || ec) {
            undo();
            throw bad_input(named + " cannot be made: " + (ec ? ec.message() : std::string("it cannot be created")));
        }
        made.push_back(p);
    }
    undo();
}

void check_output_file(const std::filesystem::path& file, const std::string& option) {
    namespace fs = std::filesystem;
    const std::string named = option + ": '" + file.string() + "'";
    std::error_code ec;
    const auto st = fs::status(file, ec);
    if (ec && st.type() != fs::file_type::not_found) throw bad_input(named + ": " + ec.message());
    if (fs::is_directory(st)) throw bad_input(named + " is a folder, not a file");
    // The temporary write_atomically writes, made and removed: the folder exists and takes files.
    const auto dir = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    const auto probe = dir / ("." + file.filename().string() + ".tmp." + std::to_string(::getpid()));
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) throw bad_input(named + " cannot be written: " + std::strerror(errno));
    ::close(fd);
    ::unlink(probe.c_str());
}

std::filesystem::path file_set::temp_path(const std::string& name) const {
    return dir_ / ("." + name + ".tmp." + std::to_string(::getpid()));
}

void file_set::stage(const std::string& name, const std::string& content) {
    const auto temp = temp_path(name);
    write_file(temp, content);
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
