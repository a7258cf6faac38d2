#include "task_runner.h"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace flood::cli {

TaskRunner threadRunner(unsigned threads) {
    if (threads <= 1) return {};
    return [threads](size_t n, const std::function<void(size_t)>& task) {
        std::atomic<size_t> next{0};
        std::exception_ptr failed;
        std::mutex m;
        auto work = [&] {
            for (size_t k; (k = next++) < n;) {
                try {
                    task(k);
                } catch (...) {
                    std::lock_guard<std::mutex> lock(m);
                    if (!failed) failed = std::current_exception();
                    next = n;  // the others stop at their next task
                }
            }
        };
        std::vector<std::thread> helpers;
        for (size_t t = 1; t < std::min<size_t>(threads, n); ++t) helpers.emplace_back(work);
        work();
        for (std::thread& h : helpers) h.join();
        if (failed) std::rethrow_exception(failed);
    };
}

unsigned availableCores() {
#ifdef __GLIBC__  // the web build's libc has no affinity
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
#endif
    return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace flood::cli
