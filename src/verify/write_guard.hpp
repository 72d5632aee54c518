// What makes a run's writing all-or-nothing against the world outside it: while a write_guard
// lives, other runs that write to the same folder wait (flock on the folder), and SIGINT,
// SIGTERM, SIGHUP and SIGQUIT wait (blocked). Before its files are renamed into place a run asks
// interrupted(): if a signal came, it removes what it staged and lets the signal end it, so the
// folder is exactly as it was; once the renames begin they finish, and the signal ends the run
// after. Interruptions before the guard need nothing: a run writes no file until every table
// is computed.
#pragma once
#include <filesystem>
#include <stdexcept>

#include <csignal>

namespace verify {

struct interrupted : std::runtime_error {
    interrupted() : std::runtime_error("interrupted before its results were written; the folder is unchanged") {}
};

class write_guard {
public:
    explicit write_guard(const std::filesystem::path& dir);
    ~write_guard();  // unlocks, then unblocks: a signal that waited ends the process now
    write_guard(const write_guard&) = delete;
    write_guard& operator=(const write_guard&) = delete;
    bool interrupted() const;  // a terminating signal is pending

private:
    int dir_fd_ = -1;
    sigset_t previous_{};
};

}  // namespace verify
