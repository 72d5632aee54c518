#include "write_guard.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace verify {

namespace {
sigset_t terminating_signals() {
    sigset_t set;
    sigemptyset(&set);
    for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaddset(&set, s);
    return set;
}
}  // namespace

write_guard::write_guard(const std::filesystem::path& dir) {
    const sigset_t set = terminating_signals();
    pthread_sigmask(SIG_BLOCK, &set, &previous_);
    dir_fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir_fd_ < 0 || ::flock(dir_fd_, LOCK_EX) != 0) {
        const std::string why = std::strerror(errno);
        if (dir_fd_ >= 0) ::close(dir_fd_);
        pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
        throw std::runtime_error("cannot lock " + dir.string() + " for writing: " + why);
    }
}

write_guard::~write_guard() {
    ::flock(dir_fd_, LOCK_UN);
    ::close(dir_fd_);
    pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
}

bool write_guard::interrupted() const {
    sigset_t pending;
    sigpending(&pending);
    for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT})
        if (sigismember(&pending, s)) return true;
    return false;
}

}  // namespace verify
