// The progress line of a long run (docs/command-line.md, "Command reference"): on a terminal, one plain line on
// stderr, "verify: audit 12,345/50,000 cases, 0:23 left", rewritten in place with '\r' a few
// times a second and cleared when the run has computed its tables. Nothing at all when stderr is
// not a terminal or with --json: logs, pipes and CI get no control characters.
#pragma once
#include <normzoo/detail/parallel.hpp>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace verify {

class progress {
public:
    // Whether a run shows progress: stderr is a terminal and stdout is not the JSON document.
    static bool wanted(bool json);

    // Shows nothing unless `enabled`; then counts the tasks of every parallel_for of the library
    // (normzoo::detail::task_counter) until finish().
    explicit progress(bool enabled);
    ~progress();  // finish()
    progress(const progress&) = delete;
    progress& operator=(const progress&) = delete;

    // From now on the line names `label` (a table, "scene NAME") and counts its tasks as `unit`.
    void step(const std::string& label, const std::string& unit = "tasks");
    // Clears the line and stops counting; what the run prints next starts on a clean line.
    void finish();

private:
    void show_until_finished();
    std::string line(std::chrono::steady_clock::time_point now) const;  // under mutex_

    bool enabled_;
    normzoo::detail::task_counter counter_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool finished_ = false;
    std::string label_, unit_;
    std::chrono::steady_clock::time_point step_start_;
    std::size_t shown_width_ = 0;  // what the line on the terminal holds now, to clear it
    std::thread painter_;
};

}  // namespace verify
