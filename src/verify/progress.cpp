#include "progress.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace verify {

namespace {

using clock_type = std::chrono::steady_clock;

// Often enough to look alive, rarely enough to cost nothing and not to flicker.
constexpr auto repaint_every = std::chrono::milliseconds(250);
// A step that ends sooner shows nothing: a run of quick tables stays quiet.
constexpr auto quiet_for = std::chrono::seconds(1);

std::string with_thousands(std::size_t x) {
    std::string digits = std::to_string(x), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

std::string duration_text(double seconds) {
    const long s = static_cast<long>(seconds + 0.5);
    char buf[32];
    if (s >= 3600) std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
    return buf;
}

// The terminal's width, so that the line never wraps (a wrapped line cannot be rewritten by '\r').
std::size_t terminal_columns() {
    winsize w{};
    if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col > 0) return w.ws_col;
    return 80;
}

void write_stderr(const std::string& s) {
    std::fwrite(s.data(), 1, s.size(), stderr);
    std::fflush(stderr);
}

}  // namespace

bool progress::wanted(bool json) { return !json && ::isatty(STDERR_FILENO) == 1; }

progress::progress(bool enabled) : enabled_(enabled) {
    if (!enabled_) return;
    step_start_ = clock_type::now();
    normzoo::detail::task_counter_hook().store(&counter_, std::memory_order_release);
    painter_ = std::thread([this] { show_until_finished(); });
}

progress::~progress() { finish(); }

void progress::step(const std::string& label, const std::string& unit) {
    if (!enabled_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    // Steps run one after the other: no task of the last one is still counting.
    counter_.total.store(0, std::memory_order_relaxed);
    counter_.done.store(0, std::memory_order_relaxed);
    label_ = label;
    unit_ = unit;
    step_start_ = clock_type::now();
}

void progress::finish() {
    if (!enabled_) return;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (finished_) return;
        finished_ = true;
    }
    wake_.notify_all();
    painter_.join();
    normzoo::detail::task_counter_hook().store(nullptr, std::memory_order_release);
    if (shown_width_) write_stderr("\r" + std::string(std::min(shown_width_, terminal_columns() - 1), ' ') + "\r");
    shown_width_ = 0;
}

std::string progress::line(clock_type::time_point now) const {
    const std::size_t total = counter_.total.load(std::memory_order_relaxed);
    const std::size_t done = std::min(counter_.done.load(std::memory_order_relaxed), total);
    if (label_.empty() || total == 0 || now - step_start_ < quiet_for) return {};
    std::string s = "verify: " + label_ + " " + with_thousands(done) + "/" + with_thousands(total) + " " + unit_;
    // The rate so far, over what is left. The total grows when a table starts its next sweep, so
    // this estimates the sweep under way.
    const double elapsed = std::chrono::duration<double>(now - step_start_).count();
    if (done > 0 && done < total) s += ", " + duration_text(elapsed * static_cast<double>(total - done) / done) + " left";
    return s;
}

void progress::show_until_finished() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, repaint_every, [this] { return finished_; })) {
        std::string s = line(clock_type::now());
        if (s.empty() && !shown_width_) continue;
        const std::size_t width = terminal_columns() - 1;
        if (s.size() > width) s.resize(width);
        // Blanks over what the last line showed beyond this one's end.
        const std::size_t pad = std::min(shown_width_ > s.size() ? shown_width_ - s.size() : 0, width - s.size());
        write_stderr("\r" + s + std::string(pad, ' '));
        shown_width_ = s.size() + pad;
    }
}

}  // namespace verify
