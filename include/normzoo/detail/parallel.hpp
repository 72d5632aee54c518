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

template <class F>
void parallel_for(std::size_t count, unsigned jobs, const F& fn) {
    if (jobs <= 1 || count <= 1) {
        for (std::size_t i = 0; i < count; ++i) fn(i);
        return;
    }
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto worker = [&] {
        for (std::size_t i; (i = next.fetch_add(1)) < count;) {
            try {
                fn(i);
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
