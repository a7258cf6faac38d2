// One background job: a function run in a thread, with the three things the UI thread polls
// each frame — progress, a cancel request, done. The invariant scan, the shrinker, a dataset's
// feature list, the flood of an edit and an open in the window (open_job.h) are each one Job
// and the result they write.
//
// The work writes its result before it returns; done() (acquire) makes that write visible,
// so the result is read only once done() is true. In the web page without threads
// (web/inline_threads.c) the work runs to completion inside start().
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>

namespace flood::view {

class Job {
public:
    Job() = default;
    Job(const Job&) = delete;
    Job& operator=(const Job&) = delete;
    ~Job() { cancel(); }

    // Runs `work` in a thread, after cancelling and joining the job before it. `onDone`, if
    // set, is called from the thread once the work returned (the viewer wakes its loop).
    void start(std::function<void(Job&)> work, std::function<void()> onDone = {});
    bool started() const { return thread_.joinable() || done(); }  // since the last reset()
    bool running() const { return thread_.joinable() && !done(); }
    bool done() const { return done_.load(std::memory_order_acquire); }
    void requestCancel() { cancel_.store(true, std::memory_order_relaxed); }  // no join
    void cancel();  // asks the work to stop and joins it; its result so far stays
    void wait();    // joins it
    void reset();   // cancels and forgets: not started, progress 0

    // For the work: whether to stop, and how far it is (the total when known, else 0).
    bool cancelRequested() const { return cancel_.load(std::memory_order_relaxed); }
    uint32_t progress() const { return progress_.load(std::memory_order_relaxed); }
    uint32_t total() const { return total_.load(std::memory_order_relaxed); }
    void setProgress(uint64_t n) { progress_.store(clamp(n), std::memory_order_relaxed); }
    void setTotal(uint64_t n) { total_.store(clamp(n), std::memory_order_relaxed); }
    // The flags themselves, for core functions that take them (checkInvariants).
    std::atomic<bool>& cancelFlag() { return cancel_; }
    std::atomic<uint32_t>& progressCounter() { return progress_; }

private:
    static uint32_t clamp(uint64_t n) { return n > UINT32_MAX ? UINT32_MAX : uint32_t(n); }
    std::thread thread_;
    std::atomic<bool> cancel_{false}, done_{false};
    std::atomic<uint32_t> progress_{0}, total_{0};
};

}  // namespace flood::view
