#include "job.h"

#include <algorithm>
#include <chrono>
#include <utility>
#include <vector>

namespace flood::view {

namespace {
// The page's stepped jobs, run by runSlices() (one thread: no lock). Empty on the desktop.
std::vector<Job*>& sliced() {
    static std::vector<Job*> jobs;
    return jobs;
}
void forget(Job* job) {
    auto& jobs = sliced();
    jobs.erase(std::remove(jobs.begin(), jobs.end(), job), jobs.end());
}
}  // namespace

void Job::finish() {
    done_.store(true, std::memory_order_release);
    if (onDone_) onDone_();
}

void Job::start(std::function<void(Job&)> work, std::function<void()> onDone) {
    reset();
    onDone_ = std::move(onDone);
    thread_ = std::thread([this, work = std::move(work)] {
        work(*this);
        finish();
    });
}

void Job::startSteps(std::function<bool(Job&)> step, std::function<void()> onDone) {
#ifdef __EMSCRIPTEN__
    reset();
    onDone_ = std::move(onDone);
    step_ = std::move(step);
    sliced().push_back(this);
#else
    start(
        [step = std::move(step)](Job& job) {
            while (!job.cancelRequested() && step(job)) {
            }
        },
        std::move(onDone));
#endif
}

void Job::runSlices(double seconds) {
    using Clock = std::chrono::steady_clock;
    const auto until = Clock::now() + std::chrono::duration<double>(seconds);
    // A copy: a step may start or cancel another job.
    for (Job* job : std::vector<Job*>(sliced())) {
        if (std::find(sliced().begin(), sliced().end(), job) == sliced().end()) continue;
        bool more = true;
        while (more && !job->cancelRequested() && Clock::now() < until) more = job->step_(*job);
        if (!more || job->cancelRequested()) {
            forget(job);
            job->step_ = nullptr;
            job->finish();
        }
    }
}

bool Job::slicesPending() { return !sliced().empty(); }

void Job::cancel() {
    requestCancel();
    wait();
}

void Job::wait() {
    if (thread_.joinable()) thread_.join();
    if (step_) {  // a stepped job in the page: its remaining steps, now (tests, a cancel)
        forget(this);
        while (!cancelRequested() && step_(*this)) {
        }
        step_ = nullptr;
        finish();
    }
}

void Job::reset() {
    cancel();
    cancel_.store(false);
    done_.store(false);
    progress_.store(0);
    total_.store(0);
    onDone_ = nullptr;
}

}  // namespace flood::view
