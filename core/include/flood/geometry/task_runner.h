// How a caller lends its threads to the core: the core starts no thread itself (its web build
// has none), so the caller's runner decides how many tasks run at once.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace flood {

// Runs task(0), ..., task(n - 1), in any order, perhaps several at once, and returns once all
// have run. Given to a large read (`flood check -j`), to validate() and to triangulate() on a
// MultiPolygon (`flood triangulate -j`); an empty runner means one thread, the serial path.
using TaskRunner = std::function<void(size_t n, const std::function<void(size_t)>& task)>;

// The n tasks given to `run`, or run here one after the other when there is no runner.
inline void runTasks(const TaskRunner& run, size_t n, const std::function<void(size_t)>& task) {
    if (run) return run(n, task);
    for (size_t i = 0; i < n; ++i) task(i);
}

// Cuts the items 0 .. n - 1, in order, into at most `pieces` runs of about equal weight
// (`weight(i)`, any size_t), a task each: returns the runs' starts, then n. For n > 0 no run is empty.
template <class Weight>
std::vector<size_t> cutEvenly(size_t n, size_t pieces, Weight&& weight) {
    uint64_t total = 0;  // 64 bits: size_t is 32 on the web build
    for (size_t i = 0; i < n; ++i) total += weight(i);
    std::vector<size_t> starts{0};
    uint64_t sum = 0;
    for (size_t i = 0; i + 1 < n; ++i) {
        sum += weight(i);
        if (starts.size() < pieces && sum * pieces >= total * starts.size())
            starts.push_back(i + 1);
    }
    starts.push_back(n);
    return starts;
}

}  // namespace flood
