// Runs fn(i) for i in [0, count) on `jobs` threads; results go where fn puts them (by index),
// so the output order never depends on scheduling.
#pragma once
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace normzoo::detail {

// Tasks started and finished, for a caller that shows how far a long run is (the verify
// command's progress line, docs/command-line.md, "Command reference"). The library only counts, it never
// prints: every parallel_for adds its count to `total` when it starts and 1 to `done` per task
// finished.
struct task_counter {
    std::atomic<std::size_t> total{0}, done{0};
};

// The counter every parallel_for reports to; null (the default) counts nothing.
inline std::atomic<task_counter*>& task_counter_hook() noexcept {
    static std::atomic<task_counter*> hook{nullptr};
    return hook;
}

template <class F>
void parallel_for(std::size_t count, unsigned jobs, const F& fn) {
    task_counter* const counter = task_counter_hook().load(std::memory_order_acquire);
    if (counter) counter->total.fetch_add(count, std::memory_order_relaxed);
    auto finished = [counter] {
        if (counter) counter->done.fetch_add(1, std::memory_order_relaxed);
    };
    if (jobs <= 1 || count <= 1) {
        for (std::size_t i = 0; i < count; ++i) {
            fn(i);
            finished();
        }
        return;
    }
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto worker = [&] {
        for (std::size_t i; (i = next.fetch_add(1)) < count;) {
            try {
                fn(i);
                finished();
            } catch (...) {
                std::lock_guard<std::mutex> lock(error_mutex);
                if (!error) error = std::current_exception();
            }
        }
    };
    std::vector<std::thread> pool;
    const unsigned n = jobs < count ? jobs : static_cast<unsigned>(count);
    for (unsigned j = 1; j < n; ++j) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace normzoo::detail
