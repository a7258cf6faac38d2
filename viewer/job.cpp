#include "job.h"

#include <utility>

namespace flood::view {

void Job::start(std::function<void(Job&)> work, std::function<void()> onDone) {
    reset();
    thread_ = std::thread([this, work = std::move(work), onDone = std::move(onDone)] {
        work(*this);
        done_.store(true, std::memory_order_release);
        if (onDone) onDone();
    });
}

void Job::cancel() {
    requestCancel();
    wait();
}

void Job::wait() {
    if (thread_.joinable()) thread_.join();
}

void Job::reset() {
    cancel();
    cancel_.store(false);
    done_.store(false);
    progress_.store(0);
    total_.store(0);
}

}  // namespace flood::view
