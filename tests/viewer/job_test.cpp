// The viewer's one background-job type (viewer/job.h): its work runs off the calling thread,
// reports progress, stops when asked, and is joined before anything it writes goes away.
#include "job.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

using flood::view::Job;

namespace {
// A gate the test opens: the work waits on it, so the test sees the job while it runs.
struct Gate {
    std::mutex m;
    std::condition_variable cv;
    bool open = false;
    void wait() {
        std::unique_lock<std::mutex> lock(m);
        cv.wait(lock, [&] { return open; });
    }
    void release() {
        {
            std::lock_guard<std::mutex> lock(m);
            open = true;
        }
        cv.notify_all();
    }
};
}  // namespace

TEST(Job, NotStartedUntilStartThenDoneOnceTheWorkReturned) {
    Job job;
    EXPECT_FALSE(job.started());
    EXPECT_FALSE(job.done());
    Gate gate;
    std::thread::id ran;
    int result = 0;
    std::atomic<int> doneCalls{0};
    job.start(
        [&](Job& j) {
            ran = std::this_thread::get_id();
            j.setTotal(3);
            for (int i = 1; i <= 3; ++i) j.setProgress(uint64_t(i));
            gate.wait();
            result = 42;
        },
        [&] { ++doneCalls; });
    EXPECT_TRUE(job.started());
    EXPECT_TRUE(job.running());
    EXPECT_FALSE(job.done()) << "done before the work returned";
    gate.release();
    job.wait();
    EXPECT_TRUE(job.done());
    EXPECT_FALSE(job.running());
    EXPECT_EQ(result, 42);
    EXPECT_NE(ran, std::this_thread::get_id()) << "the work ran on the caller's thread";
    EXPECT_EQ(job.progress(), 3u);
    EXPECT_EQ(job.total(), 3u);
    EXPECT_EQ(doneCalls.load(), 1);
}

TEST(Job, CancelStopsTheWorkAndJoinsIt) {
    Job job;
    std::atomic<uint64_t> rounds{0};
    job.start([&](Job& j) {
        while (!j.cancelRequested()) {
            j.setProgress(++rounds);
            std::this_thread::sleep_for(std::chrono::microseconds(50));
        }
    });
    while (job.progress() < 3) std::this_thread::yield();
    job.cancel();
    EXPECT_TRUE(job.done()) << "cancel() returned before the work did";
    const uint64_t at = rounds.load();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    EXPECT_EQ(rounds.load(), at) << "the work went on after cancel()";
}

TEST(Job, StartingAgainCancelsTheJobBeforeAndStartsClean) {
    Job job;
    std::atomic<bool> firstStopped{false};
    job.start([&](Job& j) {
        while (!j.cancelRequested()) std::this_thread::yield();
        firstStopped = true;
    });
    job.start([&](Job& j) {
        EXPECT_FALSE(j.cancelRequested()) << "the cancel of the job before leaked into this one";
        EXPECT_EQ(j.progress(), 0u);
    });
    EXPECT_TRUE(firstStopped.load()) << "the job before was not joined first";
    job.wait();
    EXPECT_TRUE(job.done());
}

TEST(Job, ResetForgetsAFinishedJob) {
    Job job;
    job.start([](Job& j) { j.setProgress(7); });
    job.wait();
    ASSERT_TRUE(job.done());
    job.reset();
    EXPECT_FALSE(job.started());
    EXPECT_FALSE(job.done());
    EXPECT_EQ(job.progress(), 0u);
}

TEST(Job, ProgressBeyondThirtyTwoBitsIsClampedNotWrapped) {
    Job job;
    job.start([](Job& j) {
        j.setTotal(uint64_t(1) << 40);
        j.setProgress((uint64_t(1) << 32) + 5);
    });
    job.wait();
    EXPECT_EQ(job.total(), UINT32_MAX);
    EXPECT_EQ(job.progress(), UINT32_MAX);
}

TEST(Job, DestroyingARunningJobStopsAndJoinsIt) {
    std::atomic<bool> stopped{false};
    {
        Job job;
        job.start([&](Job& j) {
            while (!j.cancelRequested()) std::this_thread::yield();
            stopped = true;
        });
    }
    EXPECT_TRUE(stopped.load());
}

TEST(Job, StepsRunInOrderUntilTheLastSaysNoMore) {
    Job job;
    std::vector<int> seen;  // written by the steps, read once done
    job.startSteps([&, n = 0](Job& j) mutable {
        seen.push_back(n++);
        j.setProgress(uint64_t(n));
        return n < 5;
    });
    job.wait();
    ASSERT_TRUE(job.done());
    EXPECT_EQ(seen, (std::vector<int>{0, 1, 2, 3, 4}));
    EXPECT_EQ(job.progress(), 5u);
    EXPECT_FALSE(Job::slicesPending()) << "a desktop job left steps for the page's frame loop";
}

TEST(Job, ACancelStopsSteppedWorkBetweenSteps) {
    Job job;
    std::atomic<int> steps{0};
    job.startSteps([&](Job&) {
        ++steps;
        std::this_thread::sleep_for(std::chrono::microseconds(50));
        return true;  // never ends by itself
    });
    while (steps.load() < 3) std::this_thread::yield();
    job.cancel();
    EXPECT_TRUE(job.done());
    const int at = steps.load();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    EXPECT_EQ(steps.load(), at);
}
