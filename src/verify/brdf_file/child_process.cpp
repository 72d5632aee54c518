#include "child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "../args.hpp"

extern char** environ;

namespace verify {

namespace {

// A whole number or a decimal from the environment, in [lo, hi]; bad_input naming the variable.
double environment_number(const char* name, double fallback, double lo, double hi) {
    const char* text = std::getenv(name);
    if (!text || !*text) return fallback;
    char* end = nullptr;
    const double x = std::strtod(text, &end);
    if (end == text || *end != '\0' || !std::isfinite(x) || x < lo || x > hi || std::isspace(static_cast<unsigned char>(*text)))
        throw bad_input(std::string(name) + ": '" + text + "' is not a number in [" + std::to_string(static_cast<long long>(lo)) +
                        ", " + std::to_string(static_cast<long long>(hi)) + "] (docs/brdf-code.md#caps)");
    return x;
}

std::size_t environment_count(const char* name, std::size_t fallback, std::size_t lo, std::size_t hi) {
    const double x = environment_number(name, static_cast<double>(fallback), static_cast<double>(lo), static_cast<double>(hi));
    if (x != std::floor(x)) throw bad_input(std::string(name) + ": '" + std::getenv(name) + "' is not a whole number (docs/brdf-code.md#caps)");
    return static_cast<std::size_t>(x);
}

void close_both(int p[2]) {
    ::close(p[0]);
    ::close(p[1]);
}

// In the child, between fork and exec: only async-signal-safe calls.
[[noreturn]] void exec_child(char* const* argv, char* const* envp, const char* cwd, int out, int err, std::size_t memory) {
    ::setpgid(0, 0);  // its own group: the caps stop what it starts too
    const int in = ::open("/dev/null", O_RDONLY);
    if (in < 0 || ::dup2(in, 0) < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0) ::_exit(126);
    if (*cwd && ::chdir(cwd) != 0) ::_exit(126);
    const rlimit as{memory, memory};
    const rlimit core{0, 0};
    if (::setrlimit(RLIMIT_AS, &as) != 0 || ::setrlimit(RLIMIT_CORE, &core) != 0) ::_exit(126);
    ::execvpe(argv[0], argv, envp);
    ::_exit(errno == ENOENT ? 127 : 126);  // 126: it exists, but could not start (too little memory to load it)
}

}  // namespace

shader_caps shader_caps_from_environment() {
    shader_caps c;
    c.seconds = environment_number("NORMZOO_SHADER_SECONDS", c.seconds, 1, 86400);
    c.memory_mb = environment_count("NORMZOO_SHADER_MEMORY_MB", c.memory_mb, 16, std::size_t(1) << 20);
    c.text_mb = environment_count("NORMZOO_SHADER_TEXT_MB", c.text_mb, 1, 4096);
    return c;
}

bool child_result::out_of_memory() const {
    if (how != ending::exited && how != ending::signaled) return false;
    if (ok()) return false;
    std::string e = err;
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const char* said : {"bad_alloc", "out of memory", "memory exhausted", "cannot allocate memory", "failed to allocate"})
        if (e.find(said) != std::string::npos) return true;
    return false;
}

child_result run_child(const std::vector<std::string>& args, const child_limits& limits, const std::string& cwd) {
    // everything the child needs, made before fork (the child may only exec)
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    std::vector<std::string> env_text{"LC_ALL=C"};
    for (char** e = environ; *e; ++e)
        if (std::strncmp(*e, "LC_ALL=", 7) != 0) env_text.push_back(*e);
    std::vector<char*> envp;
    for (auto& e : env_text) envp.push_back(e.data());
    envp.push_back(nullptr);
    child_result r;
    int out[2], err[2];
    if (::pipe2(out, O_CLOEXEC) != 0) return r.how = child_result::ending::not_started, r;
    if (::pipe2(err, O_CLOEXEC) != 0) return close_both(out), r.how = child_result::ending::not_started, r;
    const pid_t pid = ::fork();
    if (pid < 0) return close_both(out), close_both(err), r.how = child_result::ending::not_started, r;
    if (pid == 0) exec_child(argv.data(), envp.data(), cwd.c_str(), out[1], err[1], limits.memory_bytes);
    ::setpgid(pid, pid);  // as the child does: whichever runs first, the group exists before a kill
    ::close(out[1]);
    ::close(err[1]);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limits.seconds);
    pollfd fds[2] = {{out[0], POLLIN, 0}, {err[0], POLLIN, 0}};
    std::string* into[2] = {&r.out, &r.err};
    const std::size_t caps[2] = {limits.output_bytes, 64 << 10};
    int open_pipes = 2;
    char buffer[65536];
    while (open_pipes > 0) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0) {
            r.how = child_result::ending::timed_out;
            break;
        }
        if (::poll(fds, 2, static_cast<int>(std::min<long long>(left, 1000))) < 0 && errno != EINTR) break;
        for (int k = 0; k < 2; ++k) {
            if (fds[k].fd < 0 || !(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            const ssize_t n = ::read(fds[k].fd, buffer, sizeof buffer);
            if (n <= 0) {
                ::close(fds[k].fd);
                fds[k].fd = -1, --open_pipes;
                continue;
            }
            const std::size_t room = caps[k] >= into[k]->size() ? caps[k] - into[k]->size() : 0;
            into[k]->append(buffer, std::min(room, static_cast<std::size_t>(n)));
            if (k == 0 && static_cast<std::size_t>(n) > room) r.how = child_result::ending::output_capped;
        }
        if (r.how == child_result::ending::output_capped) break;
    }
    for (auto& f : fds)
        if (f.fd >= 0) ::close(f.fd);
    // its output closed, it may still run: the time cap holds until it ends
    int status = 0;
    bool reaped = false;
    while (r.how == child_result::ending::exited && !reaped) {
        const pid_t w = ::waitpid(pid, &status, WNOHANG);
        if (w == pid) reaped = true;
        else if (w < 0 && errno != EINTR) r.how = child_result::ending::not_started;  // not ours to wait for: never
        else if (std::chrono::steady_clock::now() >= deadline) r.how = child_result::ending::timed_out;
        else ::usleep(2000);
    }
    if (!reaped) {
        ::kill(-pid, SIGKILL);
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    }
    if (r.how == child_result::ending::exited) {
        if (WIFSIGNALED(status)) r.how = child_result::ending::signaled, r.status = WTERMSIG(status);
        else r.status = WEXITSTATUS(status);
    }
    return r;
}

std::string cap_tripped(const child_result& r, const child_limits& limits, const char* seconds_variable) {
    using e = child_result::ending;
    const std::string variable = seconds_variable ? std::string(" (") + seconds_variable + ")" : "";
    if (r.how == e::timed_out) {
        char s[32];
        std::snprintf(s, sizeof s, "%g", limits.seconds);
        return std::string("took longer than its cap of ") + s + " s" + variable;
    }
    if (r.how == e::output_capped)
        return "wrote more than its cap of " + std::to_string(limits.output_bytes >> 20) + " MB (NORMZOO_SHADER_TEXT_MB)";
    if (r.how == e::exited && r.status == 126 && r.err.empty())
        return "could not start under its memory cap of " + std::to_string(limits.memory_bytes >> 20) + " MB (NORMZOO_SHADER_MEMORY_MB)";
    if (r.out_of_memory())
        return "ran out of memory under its memory cap of " + std::to_string(limits.memory_bytes >> 20) + " MB (NORMZOO_SHADER_MEMORY_MB)";
    if (r.how == e::signaled)
        return std::string("stopped by signal ") + std::to_string(r.status) + " (" + strsignal(r.status) + ") under its memory cap of " +
               std::to_string(limits.memory_bytes >> 20) + " MB (NORMZOO_SHADER_MEMORY_MB)";
    return "";
}

}  // namespace verify
