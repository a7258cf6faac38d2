#include "flood/log/replay.h"

#include <algorithm>
#include <cstdint>
#include <optional>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace flood {

namespace {
struct Recorder : Listener {
    std::vector<Event>* events;
    size_t growth = 0;  // events added to the log's reserve when it runs out
    void onEvent(const Event& e) override {
        // Not doubling: the log would hold up to twice the events it needs until the end.
        if (events->size() == events->capacity()) events->reserve(events->size() + growth);
        events->push_back(e);
    }
};

// A large log is fresh memory the kernel maps page by page on first touch; 2 MB pages make
// that hundreds of times fewer faults, and mapping them in one call spares the faults while
// recording (the log is written front to back, into what was reserved). Advice only.
void backWithHugePages(void* data, size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const uintptr_t huge = uintptr_t(2) << 20;
    uintptr_t a = (uintptr_t(data) + huge - 1) & ~(huge - 1),
              e = (uintptr_t(data) + bytes) & ~(huge - 1);
    if (e <= a) return;
    // NOLINTNEXTLINE(performance-no-int-to-ptr): the buffer rounded in to huge-page bounds
    madvise(reinterpret_cast<void*>(a), e - a, MADV_HUGEPAGE);
#if defined(MADV_POPULATE_WRITE)
    // Map it all in one call (Linux 5.14+) rather than one fault per page while recording.
    madvise(reinterpret_cast<void*>(a), e - a, MADV_POPULATE_WRITE);  // NOLINT: as above
#endif
#else
    (void)data, (void)bytes;
#endif
}

}  // namespace

// The trace is filled in place: the machine floods its polygon and the recorder appends to
// its log, so neither moves while the run lasts.
struct Recording::State {
    Trace t;
    Recorder rec;
    std::optional<SteppedRun> run;
};

Recording::Recording(const Polygon& polygon, const Options& options) : s_(new State) {
    Trace& t = s_->t;
    t.polygon = polygon;
    t.up = options.up;
    s_->rec.events = &t.events;
    // Runs take about 1.5 events per vertex: reserve once rather than regrow (and copy) the log.
    t.events.reserve(expectedSteps());
    backWithHugePages(t.events.data(), t.events.capacity() * sizeof(Event));
    s_->rec.growth = polygon.vertices.size() / 2 + 64;
    s_->run.emplace(t.polygon, &s_->rec, options);
}
Recording::~Recording() = default;

bool Recording::advance(uint64_t steps) { return s_->run->advance(steps); }
uint32_t Recording::steps() const { return s_->run->steps(); }
size_t Recording::expectedSteps() const {
    const size_t n = s_->t.polygon.vertices.size();
    return n + n / 2 + 64;
}

Trace Recording::take() {
    Trace t = std::move(s_->t);  // the run is over: nothing refers to it any more
    FloodResult& r = s_->run->result();
    // The log is most of a trace's memory: it keeps just its events (one copy of it, once),
    // unless its slack is a few percent (the copy would cost more than it frees).
    if (t.events.capacity() - t.events.size() > t.events.size() / 32) t.events.shrink_to_fit();
    t.triangles = std::move(r.triangles);
    t.diagnostic = r.diagnostic;
    return t;
}

Trace record(const Polygon& polygon, const Options& options) {
    Recording recording(polygon, options);
    while (recording.advance(UINT64_MAX)) {
    }
    return recording.take();
}

Replay::Replay(const Trace& trace, uint32_t keyframeInterval)
    : trace_(&trace), interval_(std::max<uint32_t>(1, keyframeInterval)) {
    // Work is counted in 64ths of an event: an event costs 64 plus what apply() moves (a
    // memmove of 64 indices costs about one event).
    const uint64_t budget = uint64_t(interval_) * 64;
    uint64_t work = 0, events = 0;
    building_ = true;
    addKeyframe();
    for (const Event& e : trace.events) {
        work += 64 + apply(e);
        ++events;
        if (work < budget) continue;
        // A costly keyframe (a long chain, many gorges changed) waits for enough work that it
        // stays a fixed fraction of the log: memory O(events), seek O(state size).
        uint64_t own = 16 + state_.chain.size() + 4 * (state_.dormant.size() - dormantLow_) +
                       2 * (state_.jumps.size() - jumpsLow_) + fresh_;
        if (own > kKeyframeRatio * events && work < kMaxWorkFactor * budget) continue;
        addKeyframe();
        work = events = 0;
    }
    building_ = false;
    bridges_ = std::move(state_.bridges);  // every state's bridges are a prefix of the last's
    state_.bridges.clear();
    std::vector<uint32_t>().swap(dormantChains_);
    dormantTree_.finish();
    jumpsTree_.finish();
    keyframes_.shrink_to_fit(), chainPool_.shrink_to_fit(),
        chainEnds_.shrink_to_fit();        // no more growth
    keyframeSteps_.push_back(size() + 1);  // a seek re-applies at most up to the next keyframe
    for (size_t k = 0; k + 1 < keyframeSteps_.size(); ++k)
        maxSeekEvents_ = std::max(maxSeekEvents_, keyframeSteps_[k + 1] - 1 - keyframeSteps_[k]);
    keyframeSteps_.pop_back();
    restore(0);
}

void Replay::addKeyframe() {
    Keyframe k;
    std::vector<Gorge> dormant = std::move(state_.dormant);
    std::vector<std::pair<Index, Index>> jumps = std::move(state_.jumps),
                                         bridges = std::move(state_.bridges);
    k.head = state_;
    k.bridgeCount = uint32_t(bridges.size());
    // Gorges dormant since the last keyframe keep their place and their copied chain; only
    // those pushed or moved since are stored again.
    for (size_t i = dormantLow_; i < dormant.size(); ++i) {
        if (dormantChains_[i] != kNoChain) continue;
        dormantChains_[i] = uint32_t(chainEnds_.size());
        chainPool_.insert(chainPool_.end(), dormant[i].chain.begin(), dormant[i].chain.end());
        chainEnds_.push_back(chainPool_.size());
    }
    k.dormantCount = uint32_t(dormant.size());
    k.dormantHead = dormantTree_.store(dormant.size(), dormantLow_, [&](size_t i) {
        return Dormant{dormant[i].id, dormant[i].top, dormantChains_[i], dormant[i].held};
    });
    k.jumpsCount = uint32_t(jumps.size());
    k.jumpsHead = jumpsTree_.store(jumps.size(), jumpsLow_, [&](size_t i) { return jumps[i]; });
    dormantLow_ = dormant.size(), jumpsLow_ = jumps.size(), fresh_ = 0;
    state_.dormant = std::move(dormant);
    state_.jumps = std::move(jumps);
    state_.bridges = std::move(bridges);
    keyframeSteps_.push_back(state_.step);
    keyframes_.push_back(std::move(k));
}

void Replay::restore(size_t index) {
    const Keyframe& k = keyframes_[index];
    // Dormant gorges and jumps the state still shares with the keyframe it was restored from,
    // when that one shares them with k, stay: stepping back one step rewrites only what the
    // steps since that keyframe changed.
    size_t keepDormant = 0, keepJumps = 0;
    if (restored_ != kNoKeyframe) {
        const Keyframe& from = keyframes_[restored_];
        keepDormant =
            std::min(dormantLow_, dormantTree_.commonPrefix(from.dormantHead, from.dormantCount,
                                                            k.dormantHead, k.dormantCount));
        keepJumps = std::min(jumpsLow_, jumpsTree_.commonPrefix(from.jumpsHead, from.jumpsCount,
                                                                k.jumpsHead, k.jumpsCount));
    }
    std::vector<Gorge> dormant = std::move(state_.dormant);
    std::vector<std::pair<Index, Index>> jumps = std::move(state_.jumps),
                                         bridges = std::move(state_.bridges);
    state_ = k.head;
    if (bridges.size() > k.bridgeCount) bridges.resize(k.bridgeCount);
    else
        bridges.insert(bridges.end(), bridges_.begin() + long(bridges.size()),
                       bridges_.begin() + long(k.bridgeCount));
    jumps.resize(k.jumpsCount);
    jumpsTree_.load(k.jumpsHead, k.jumpsCount, keepJumps,
                    [&](size_t i, const std::pair<Index, Index>& j) { jumps[i] = j; });
    dormant.resize(k.dormantCount);
    dormantTree_.load(k.dormantHead, k.dormantCount, keepDormant, [&](size_t i, const Dormant& d) {
        dormant[i].id = d.id, dormant[i].held = d.held, dormant[i].top = d.top;
        dormant[i].chain.assign(chainPool_.begin() + long(d.chain ? chainEnds_[d.chain - 1] : 0),
                                chainPool_.begin() + long(chainEnds_[d.chain]));
    });
    state_.dormant = std::move(dormant);
    state_.jumps = std::move(jumps);
    state_.bridges = std::move(bridges);
    restored_ = index;
    lastSeekRestored_ = k.dormantCount - keepDormant + k.jumpsCount - keepJumps;
    dormantLow_ = k.dormantCount, jumpsLow_ = k.jumpsCount;
}

size_t Replay::keyframeBytes() const {
    size_t bytes = keyframes_.capacity() * sizeof(Keyframe) +
                   bridges_.capacity() * sizeof(bridges_[0]) +
                   chainPool_.capacity() * sizeof(Index) + chainEnds_.capacity() * sizeof(size_t) +
                   dormantTree_.bytes() + jumpsTree_.bytes();
    for (const Keyframe& k : keyframes_) bytes += k.head.chain.capacity() * sizeof(Index);
    return bytes;
}

const ReplayState& Replay::seek(uint32_t step) {
    step = std::min(step, size());
    size_t k = size_t(std::upper_bound(keyframeSteps_.begin(), keyframeSteps_.end(), step) -
                      keyframeSteps_.begin()) -
               1;
    // Stepping forward from where we are is cheapest unless a keyframe lies in between.
    lastSeekRestored_ = 0;
    if (step < state_.step || keyframeSteps_[k] > state_.step) restore(k);
    lastSeekEvents_ = 0;
    for (; state_.step < step; ++lastSeekEvents_) apply(trace_->events[state_.step]);
    return state_;
}

void Replay::pushGorge(Gorge&& g) {
    if (building_) {
        fresh_ += g.chain.size();
        dormantChains_.push_back(kNoChain);
    }
    state_.dormant.push_back(std::move(g));
}

// Moves gorge `id` out of the dormant list; empty chain if the log names no such gorge. The
// to-do list is a stack, so the search starts from the end.
std::vector<Index> Replay::takeGorge(uint32_t id, uint64_t& moved) {
    std::vector<Gorge>& gorges = state_.dormant;
    std::vector<Index> chain;
    for (size_t i = gorges.size(); i-- > 0;) {
        if (gorges[i].id != id) continue;
        moved += 4 * (gorges.size() - i);
        chain = std::move(gorges[i].chain);
        gorges.erase(gorges.begin() + long(i));
        if (building_) {
            if (dormantChains_[i] == kNoChain) fresh_ -= chain.size();  // never to be copied
            dormantChains_.erase(dormantChains_.begin() + long(i));
        }
        dormantLow_ = std::min(dormantLow_, i);
        return chain;
    }
    moved += 4 * gorges.size();  // searched them all
    return chain;
}

// Applies one event to the visible state. Mirrors the machine's actions on vertex indices.
uint64_t Replay::apply(const Event& e) {
    ReplayState& s = state_;
    std::vector<Index>& chain = s.chain;
    uint64_t moved = 0;
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
                moved = chain.size();
            } else {
                chain.resize(chain.size() - k);
                chain.push_back(e.after.right);
                moved = k;
            }
            break;
        }
        case Action::Bridge: {
            size_t i = std::min<size_t>(e.chainIndex, chain.empty() ? 0 : chain.size() - 1);
            size_t keepLeft = i + 1 >= e.cutLeft ? i + 1 - e.cutLeft : 0;
            // What stays right of the sag: the copy of the chain vertex and the chain after
            // it, less the wedge cut there.
            std::vector<Index> rightPart(
                chain.begin() + long(std::min(chain.size(), i + e.cutRight)), chain.end());
            moved = rightPart.size();
            chain.resize(keepLeft);
            chain.push_back(e.sag);
            if (e.gorgePushed == kNone) {  // a Steiner point: the chain runs on through it
                chain.insert(chain.end(), rightPart.begin(), rightPart.end());
            } else {
                Gorge other;
                other.id = e.gorgePushed;
                other.chain.push_back(e.sag);
                other.chain.insert(other.chain.end(), rightPart.begin(), rightPart.end());
                pushGorge(std::move(other));
            }
            s.bridges.emplace_back(e.sag, e.bridgeTo);
            break;
        }
        case Action::Spill: {
            Gorge held;
            held.id = e.gorgePushed;
            held.held = true;
            held.top = e.top;
            held.chain = std::move(chain);
            pushGorge(std::move(held));
            jumpsLow_ = std::min(jumpsLow_, s.jumps.size());
            s.jumps.emplace_back(e.top, e.jumpTarget);
            if (e.gorgePopped != kNone) chain = takeGorge(e.gorgePopped, moved);
            else chain.assign(1, e.bottom);
            break;
        }
        case Action::Jump: {
            std::vector<Index> held = takeGorge(e.gorgePopped, moved);
            // The held chain and the active chain share the top at their meeting ends.
            if (e.side == Side::Right) {
                if (!held.empty()) chain.insert(chain.end(), held.begin() + 1, held.end());
                moved += held.size();
            } else {
                if (!held.empty()) held.pop_back();
                held.insert(held.end(), chain.begin(), chain.end());
                moved += chain.size();
                chain = std::move(held);
            }
            // Jump pointers too are set and cleared last first: search from the end.
            for (size_t j = s.jumps.size(); j-- > 0;) {
                if (s.jumps[j].first != e.top) continue;
                moved += 2 * (s.jumps.size() - j);
                s.jumps.erase(s.jumps.begin() + long(j));
                jumpsLow_ = std::min(jumpsLow_, j);
                break;
            }
            break;
        }
        case Action::Fill:
            chain.clear();
            if (e.gorgePopped != kNone) chain = takeGorge(e.gorgePopped, moved);
            else if (e.bottom != kNone) chain.assign(1, e.bottom);
            break;
        case Action::Forbidden:
        case Action::Count: s.forbidden = true; break;
    }
    s.fingers = e.after;
    s.water = e.water;
    s.triangleCount = e.firstTriangle + e.triangleCount;
    s.step = e.step + 1;
    return moved;
}

bool operator==(const Gorge& a, const Gorge& b) {
    return a.id == b.id && a.held == b.held && a.top == b.top && a.chain == b.chain;
}

bool operator==(const ReplayState& a, const ReplayState& b) {
    return a.step == b.step && a.part == b.part && a.fingers == b.fingers && a.water == b.water &&
           a.triangleCount == b.triangleCount && a.chain == b.chain && a.dormant == b.dormant &&
           a.jumps == b.jumps && a.bridges == b.bridges && a.forbidden == b.forbidden;
}
// A field added to Gorge or ReplayState must be compared above: the sizes say when one was.
// They depend on the pointer width (a vector is three pointers): 64-bit, and 32-bit (wasm32).
static_assert(sizeof(void*) == 8 ? sizeof(Gorge) == 40 && sizeof(ReplayState) == 136
                                 : sizeof(Gorge) == 24 && sizeof(ReplayState) == 84,
              "Gorge or ReplayState changed: compare the new field in operator==");

}  // namespace flood
