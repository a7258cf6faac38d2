// The viewer's background work besides the model's own invariant scan: shrinking a failing
// polygon, and judging the features of a dataset. Each is one Job (job.h) and its result.
#pragma once
#include <atomic>
#include <string>
#include <vector>

#include "flood/check/verdict.h"
#include "flood/io/io.h"
#include "flood/tools/shrink.h"
#include "job.h"
#include "shrink_worker.h"

namespace flood::view {

// Shrink from the viewer: flood/tools/shrink.h run as a Job, with the tries made as
// progress and a Cancel that stops it before its next classification. An `onTry` in the
// options is still called (before the cancel is looked at). In the web page the shrink runs
// in a Web Worker instead (shrink_worker.h): the same calls, but a cancel keeps no repro and
// a crash ends the shrink with stoppedNote().
class ShrinkJob {
public:
    void start(const Polygon& polygon, ShrinkOptions options);  // cancels a running one first
    bool started() const { return inWorker() ? worker_.started() : job_.started(); }
    bool done() const { return inWorker() ? ended_ : job_.done(); }
    size_t tries() const { return inWorker() ? report().tries : job_.progress(); }
    // The smallest failing polygon's vertex count so far (0 before the first try).
    size_t vertices() const { return inWorker() ? report().vertices : vertices_.load(); }
    size_t maxTries() const { return maxTries_; }
    void cancel();                // stops before the next try and joins; the result so far stays
    void requestCancel();         // without joining
    void wait() { job_.wait(); }  // joins (tests)
    const ShrinkResult& result() const { return result_; }  // once done()
    // Once done: why the shrink ended without a result (its worker crashed, or was cancelled,
    // in the page); "" when result() is the shrink's.
    const std::string& stoppedNote() const { return stoppedNote_; }
    void poll();   // the page: asks the worker how it is doing (each frame); no-op natively
    void reset();  // cancels and forgets the result

private:
    static bool inWorker() { return ShrinkWorker::available(); }
    const WorkerReport& report() const { return report_; }
    size_t maxTries_ = 0;
    std::atomic<size_t> vertices_{0};
    ShrinkResult result_;
    std::string stoppedNote_;
    bool ended_ = false;  // the page: the worker's shrink ended and result_ is set
    WorkerReport report_;
    ShrinkWorker worker_;
    Job job_;  // declared last, so it is joined before what its work writes is destroyed
};

// ----------------------------------------------------------------------------------------
// The features of a FeatureCollection with their verdicts (read, validate, flood, exact
// check: the first failure), as `flood check` judges them.
struct FeatureVerdict {
    size_t index = 0;  // the feature's FID (FeatureRead::fid): what openFeature() takes
    std::string id, name;
    size_t vertices = 0;
    Verdict kind = Verdict::Ok;
    std::string reason;  // the diagnostic's message; "" when ok
    bool failure() const { return kind != Verdict::Ok; }
};
FeatureVerdict judgeFeature(const FeatureRead& feature);
// Failing features first, each group in collection order.
void orderFailingFirst(std::vector<FeatureVerdict>& list);

// Judges a collection's features as a Job (a dataset may hold thousands).
class FeatureScan {
public:
    void start(const std::string& path);  // cancels a running scan first
    const std::string& path() const { return path_; }
    bool done() const { return job_.done(); }
    size_t progress() const { return job_.progress(); }  // judged so far
    size_t total() const { return job_.total(); }        // known once read
    void cancel() { job_.cancel(); }
    void wait() { job_.wait(); }
    // Once done: the verdicts, failing first; empty when the file is not a FeatureCollection.
    const std::vector<FeatureVerdict>& features() const { return features_; }
    const Diagnostic& diagnostic() const { return diag_; }  // the file could not be read

private:
    std::string path_;
    std::vector<FeatureVerdict> features_;
    Diagnostic diag_;
    Job job_;  // declared last, so it is joined before what its work writes is destroyed
};

}  // namespace flood::view
