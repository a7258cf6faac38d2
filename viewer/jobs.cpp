#include "jobs.h"

#include <algorithm>
#include <exception>
#include <memory>

#include "flood/io/gdal/read_any.h"

namespace flood::view {

void ShrinkJob::start(const Polygon& polygon, ShrinkOptions options) {
    reset();
    maxTries_ = options.maxTries;
    if (inWorker()) {
        worker_.start(polygon, options);
        return;
    }
    options.onTry = [this, user = std::move(options.onTry)](size_t tries, size_t vertices) {
        job_.setProgress(tries);
        vertices_.store(vertices);
        if (user && !user(tries, vertices)) return false;
        return !job_.cancelRequested();
    };
    job_.start([this, polygon, options](Job&) {
        try {
            result_ = shrink(polygon, options);
        } catch (const std::exception& ex) {
            result_ = {};
            result_.polygon = polygon;
            result_.failure.kind = Failure::Kind::Crash;
            result_.failure.message = std::string("the shrinker failed: ") + ex.what();
        }
    });
}

void ShrinkJob::poll() {
    if (!inWorker() || !worker_.started() || ended_) return;
    report_ = worker_.poll();
    if (report_.end == WorkerReport::End::Running) return;
    stoppedNote_ = workerStopNote(report_);
    if (report_.end == WorkerReport::End::Finished)
        result_ = shrinkResultFromWorker(report_, "the repro");
    ended_ = true;
}

void ShrinkJob::cancel() {
    if (inWorker()) {
        worker_.cancel();
        poll();
    } else {
        job_.cancel();
    }
}

void ShrinkJob::requestCancel() {
    if (inWorker()) cancel();  // terminating a worker does not wait for it
    else job_.requestCancel();
}

void ShrinkJob::reset() {
    job_.reset();
    worker_.reset();
    report_ = {};
    result_ = {};
    stoppedNote_.clear();
    ended_ = false;
    vertices_.store(0);
}

FeatureVerdict judgeFeature(const FeatureRead& f) {
    FeatureVerdict v;
    v.index = size_t(f.fid);
    v.id = f.id;
    v.name = f.name;
    v.vertices = f.read.polygon.vertices.size();
    try {
        ReadResult read = f.read;  // validation records T-junctions in the polygon
        Judgement j = judge(read, "feature " + std::to_string(f.index));
        v.kind = j.verdict;
        // The checker's reason without the name the list shows already.
        v.reason = j.verdict == Verdict::Checker
                       ? "the exact checker rejects the triangulation: " + j.check.reason
                       : j.diagnostic.message;
    } catch (const std::exception& ex) {
        v.kind = Verdict::Internal;
        v.reason = std::string("exception: ") + ex.what();
    }
    return v;
}

void orderFailingFirst(std::vector<FeatureVerdict>& list) {
    std::stable_sort(list.begin(), list.end(),
                     [](const FeatureVerdict& a, const FeatureVerdict& b) {
                         return a.failure() != b.failure() ? a.failure() : a.index < b.index;
                     });
}

void FeatureScan::start(const std::string& path) {
    job_.cancel();
    path_ = path;
    features_.clear();
    diag_ = {};
    // Steps: the read, then one feature each (a thread runs them one after another, the web
    // page a slice between frames); the list is ordered once every feature is judged.
    auto d = std::make_shared<DatasetRead>();
    auto list = std::make_shared<std::vector<FeatureVerdict>>();
    job_.startSteps([this, path, d, list, read = false](Job& job) mutable {
        if (!read) {
            read = true;
            try {
                *d = readFeaturesFile(path, kDefaultMaxInputBytes, false);
            } catch (const std::exception& ex) {
                diag_ = {Status::Malformed, path + ": " + ex.what()};
            }
            if (d->features.size() == 1 && d->features[0].wholeFile) {
                diag_ = d->features[0].read.diagnostic;  // not a collection: nothing to list
                d->features.clear();
            }
            job.setTotal(d->features.size());
        } else if (list->size() < d->features.size()) {
            list->push_back(judgeFeature(d->features[list->size()]));
            job.setProgress(list->size());
        }
        if (list->size() < d->features.size() && !job.cancelRequested()) return true;
        orderFailingFirst(*list);
        features_ = std::move(*list);
        return false;
    });
}

}  // namespace flood::view
