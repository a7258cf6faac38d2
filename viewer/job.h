// One background job: a function run in a thread, with the three things the UI thread polls
// each frame — progress, a cancel request, done. The invariant scan, the shrinker, a dataset's
// feature list, the flood of an edit and an open in the window (open_job.h) are each one Job
// and the result they write.
//
// The work writes its result before it returns; done() (acquire) makes that write visible,
// so the result is read only once done() is true. In the web page there are no threads
// (web/inline_threads.c): work given to start() runs to completion inside it, while work given
// to startSteps() runs a slice at a time from the page's frame loop (runSlices), so the page
// never holds still for it.
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
    // The same work cut in steps: `step` is called until it returns false or a cancel is
    // asked. On the desktop the steps run one after another in the thread; in the page,
    // runSlices() runs them between frames.
    void startSteps(std::function<bool(Job&)> step, std::function<void()> onDone = {});
    // The page's frame loop: runs the steps of every stepped job for about `seconds`, and
    // says whether any is left (then the loop does not idle). No-ops on the desktop.
    static void runSlices(double seconds);
    static bool slicesPending();
    bool started() const { return thread_.joinable() || step_ || done(); }  // since reset()
    bool running() const { return (thread_.joinable() || step_) && !done(); }
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
    void finish();                    // done, then onDone_
    std::function<bool(Job&)> step_;  // a stepped job in the page: what runSlices calls
    std::function<void()> onDone_;
    std::thread thread_;
    std::atomic<bool> cancel_{false}, done_{false};
    std::atomic<uint32_t> progress_{0}, total_{0};
};

}  // namespace flood::view
