#include "replay.h"

#include <algorithm>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace flood {

namespace {
struct Recorder : Listener {
    std::vector<Event>* events;
    void onEvent(const Event& e) override { events->push_back(e); }
};

// A large log is fresh memory the kernel maps page by page on first touch; 2 MB pages make
// that hundreds of times fewer faults, and mapping them in one call spares the faults while
// recording (the log is written front to back, into what was reserved). Advice only.
void backWithHugePages(void* data, size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const uintptr_t huge = uintptr_t(2) << 20;
    uintptr_t a = (uintptr_t(data) + huge - 1) & ~(huge - 1), e = (uintptr_t(data) + bytes) & ~(huge - 1);
    if (e <= a) return;
    madvise(reinterpret_cast<void*>(a), e - a, MADV_HUGEPAGE);
#if defined(MADV_POPULATE_WRITE)
    // Map it all in one call (Linux 5.14+) rather than one fault per page while recording.
    madvise(reinterpret_cast<void*>(a), e - a, MADV_POPULATE_WRITE);
#endif
#else
    (void)data, (void)bytes;
#endif
}

// Moves gorge `id` out of the dormant list; empty chain if the log names no such gorge.
std::vector<Index> takeGorge(std::vector<Gorge>& gorges, uint32_t id) {
    std::vector<Index> chain;
    for (size_t i = 0; i < gorges.size(); ++i) {
        if (gorges[i].id != id) continue;
        chain = std::move(gorges[i].chain);
        gorges.erase(gorges.begin() + long(i));
        break;
    }
    return chain;
}
}  // namespace

Trace record(const Polygon& polygon, const Options& options) {
    Trace t;
    t.polygon = polygon;
    Recorder rec;
    rec.events = &t.events;
    // Runs take about 1.5 events per vertex: reserve once rather than regrow (and copy) the log.
    t.events.reserve(polygon.vertices.size() + polygon.vertices.size() / 2 + 64);
    backWithHugePages(t.events.data(), t.events.capacity() * sizeof(Event));
    FloodResult r = triangulate(t.polygon, &rec, options);
    t.triangles = std::move(r.triangles);
    t.diagnostic = r.diagnostic;
    return t;
}

Replay::Replay(const Trace& trace, uint32_t keyframeInterval)
    : trace_(&trace), interval_(std::max<uint32_t>(1, keyframeInterval)) {
    keyframes_.push_back(state_);
    for (const Event& e : trace.events) {
        apply(e);
        if (state_.step % interval_ == 0) keyframes_.push_back(state_);
    }
    state_ = keyframes_.front();
}

const ReplayState& Replay::seek(uint32_t step) {
    step = std::min(step, size());
    // Stepping forward from where we are is cheapest; otherwise start at a keyframe.
    if (step < state_.step || step - state_.step > interval_) state_ = keyframes_[step / interval_];
    while (state_.step < step) apply(trace_->events[state_.step]);
    return state_;
}

// Applies one event to the visible state. Mirrors the machine's actions on vertex indices.
void Replay::apply(const Event& e) {
    ReplayState& s = state_;
    std::vector<Index>& chain = s.chain;
    s.forbidden = false;
    switch (e.action) {
        case Action::Start:
            chain.assign(1, e.bottom);
            s.part = e.part;
            break;
        case Action::Raise: {
            size_t k = std::min<size_t>(e.triangleCount, chain.size());
            if (e.side == Side::Left) {
                chain.erase(chain.begin(), chain.begin() + long(k));
                chain.insert(chain.begin(), e.after.left);
            } else {
                chain.resize(chain.size() - k);
                chain.push_back(e.after.right);
            }
            break;
        }
        case Action::Bridge: {
            size_t i = std::min<size_t>(e.chainIndex, chain.empty() ? 0 : chain.size() - 1);
            size_t keepLeft = i + 1 >= e.cutLeft ? i + 1 - e.cutLeft : 0;
            Gorge other;
            other.id = e.gorgePushed;
            other.chain.push_back(e.sag);
            other.chain.insert(other.chain.end(), chain.begin() + long(std::min(chain.size(), i + e.cutRight)),
                               chain.end());
            chain.resize(keepLeft);
            chain.push_back(e.sag);
            s.dormant.push_back(std::move(other));
            s.bridges.emplace_back(e.sag, e.bridgeTo);
            break;
        }
        case Action::Spill: {
            Gorge held;
            held.id = e.gorgePushed;
            held.held = true;
            held.top = e.top;
            held.chain = std::move(chain);
            s.dormant.push_back(std::move(held));
            s.jumps.emplace_back(e.top, e.jumpTarget);
            if (e.gorgePopped != kNone) chain = takeGorge(s.dormant, e.gorgePopped);
            else chain.assign(1, e.bottom);
            break;
        }
        case Action::Jump: {
            std::vector<Index> held = takeGorge(s.dormant, e.gorgePopped);
            // The held chain and the active chain share the top at their meeting ends.
            if (e.side == Side::Right) {
                if (!held.empty()) chain.insert(chain.end(), held.begin() + 1, held.end());
            } else {
                if (!held.empty()) held.pop_back();
                held.insert(held.end(), chain.begin(), chain.end());
                chain = std::move(held);
            }
            auto it = std::find_if(s.jumps.begin(), s.jumps.end(),
                                   [&](const std::pair<Index, Index>& j) { return j.first == e.top; });
            if (it != s.jumps.end()) s.jumps.erase(it);
            break;
        }
        case Action::Fill:
            chain.clear();
            if (e.gorgePopped != kNone) chain = takeGorge(s.dormant, e.gorgePopped);
            else if (e.bottom != kNone) chain.assign(1, e.bottom);
            break;
        case Action::Forbidden:
        case Action::Count:
            s.forbidden = true;
            break;
    }
    s.fingers = e.after;
    s.water = e.water;
    s.triangleCount = e.firstTriangle + e.triangleCount;
    s.step = e.step + 1;
}

}  // namespace flood
