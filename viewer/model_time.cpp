// The model's time: the step, playback, breakpoints, and what the current event decided.
#include "model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <utility>

#include "flood/check/diagnostic_where.h"
#include "flood/geometry/predicates.h"
#include "flood/io/gdal/read_any.h"
#include "flood/io/io.h"
#include "flood/log/trace_io.h"
#include "view_fit.h"

namespace flood::view {

const Event* Model::currentEvent() const {
    return step_ == 0 || step_ > steps() ? nullptr : &trace_->events[step_ - 1];
}

void Model::seek(uint32_t step) {
    step_ = std::min(step, steps());
    replay_->seek(step_);
}

const std::vector<Index>& Model::chainBefore() const {
    const uint64_t key = generation_ << 32 | step_;
    if (chainBeforeFor_ != key) {
        chainBeforeFor_ = key;
        chainBefore_.clear();
        if (step_ > 0) {  // the replay ends where it was: state() is unchanged
            chainBefore_ = replay_->seek(step_ - 1).chain;
            replay_->seek(step_);
        }
    }
    return chainBefore_;
}

bool Model::seekAction(Action a, int direction) {
    const auto& ev = trace_->events;
    if (direction > 0) {
        for (uint32_t s = step_ + 1; s <= ev.size(); ++s)
            if (ev[s - 1].action == a) return seek(s), true;
    } else {
        for (uint32_t s = step_; s-- > 1;)
            if (ev[s - 1].action == a) return seek(s), true;
    }
    return false;
}

bool Model::runToBreakpoint(int direction) {
    const auto& ev = trace_->events;
    if (direction > 0) {
        for (uint32_t s = step_ + 1; s <= ev.size(); ++s)
            if (hits(breakpoints_, ev[s - 1])) return seek(s), true;
        last();
    } else {
        for (uint32_t s = step_; s-- > 1;)
            if (hits(breakpoints_, ev[s - 1])) return seek(s), true;
        first();
    }
    return false;
}

void Model::setPlaying(bool on) {
    if (on == playing_) return;
    playing_ = on;
    playClock_ = 0;
    if (playing_ && step_ >= steps()) seek(0);  // play again from the start
}

void Model::advance(double seconds) {
    if (!playing_) return;
    playClock_ += seconds * std::max(speed_, 0.01);
    while (playClock_ >= 1 && playing_) {
        playClock_ -= 1;
        if (step_ >= steps() || pendingQuestion() >= 0) {  // the end, or a question
            playing_ = false;
            break;
        }
        stepForward();
        if (breakpoints_.any() && hits(breakpoints_, *currentEvent())) playing_ = false;
    }
    if (step_ >= steps()) playing_ = false;
}

void Model::setBreakpoints(const Breakpoints& b) {
    breakpoints_ = b;
    findBreakpointSteps();
}

void Model::findBreakpointSteps() {
    breakpointSteps_.clear();
    if (breakpoints_.any())
        for (const Event& e : trace_->events)
            if (hits(breakpoints_, e)) breakpointSteps_.push_back(e.step + 1);
}

const std::vector<PredicateRow>& Model::inspection() {
    uint64_t key = generation_ << 32 | step_;
    if (key == inspectedFor_) return inspection_;
    inspectedFor_ = key;
    inspection_.clear();
    if (const Event* e = currentEvent()) {
        uint32_t at = step_;
        inspection_ = inspectDecision(*trace_, replay_->seek(at - 1), *e, classes_);
        replay_->seek(at);
    }
    return inspection_;
}

}  // namespace flood::view
