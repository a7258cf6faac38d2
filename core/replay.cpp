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

// What apply() moves for `e` on state `s`, in indices (a memmove of 64 costs about one
// event): only keyframe spacing uses it, so a rough bound is enough.
uint64_t movedByApply(const Event& e, const ReplayState& s) {
    switch (e.action) {
        case Action::Raise: return e.side == Side::Left ? s.chain.size() : e.triangleCount;
        case Action::Bridge:  // the part right of the bridge is copied to the new gorge
            return s.chain.size() - std::min<uint64_t>(s.chain.size(), uint64_t(e.chainIndex) + e.cutRight);
        case Action::Jump: return s.chain.size() + 4 * s.dormant.size();
        case Action::Spill:
        case Action::Fill: return e.gorgePopped != kNone ? 4 * s.dormant.size() : 0;
        default: return 0;
    }
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
    // Work is counted in 64ths of an event: an event costs 64 plus what apply() moves.
    const uint64_t budget = uint64_t(interval_) * 64;
    uint64_t work = 0, events = 0, fresh = 0;  // fresh: indices of chains pushed since, a bound
    std::vector<uint32_t> pushed;  // gorges pushed since the last keyframe: their chains are new
    addKeyframe(pushed);
    for (const Event& e : trace.events) {
        work += 64 + movedByApply(e, state_);
        ++events;
        apply(e);
        if ((e.action == Action::Bridge || e.action == Action::Spill) && e.gorgePushed != kNone) {  // a Steiner bridge pushes none
            pushed.push_back(e.gorgePushed);
            if (!state_.dormant.empty()) fresh += state_.dormant.back().chain.size();
        }
        if (work < budget) continue;
        // A big state (a long chain, thousands of dormant gorges) waits for enough work that
        // its copy stays a fixed fraction of the log: memory O(events), seek O(state size).
        uint64_t own = 16 + state_.chain.size() + 2 * state_.jumps.size() +
                       4 * state_.dormant.size() + fresh;
        if (own > kKeyframeRatio * events && work < kMaxWorkFactor * budget) continue;
        addKeyframe(pushed);
        pushed.clear();
        work = events = fresh = 0;
    }
    bridges_ = std::move(state_.bridges);  // every state's bridges are a prefix of the last's
    state_.bridges.clear();
    for (auto& slot : slots_) std::vector<int32_t>().swap(slot);
    restore(keyframes_.front());
}

void Replay::addKeyframe(const std::vector<uint32_t>& pushedSince) {
    Keyframe k;
    std::vector<Gorge> dormant = std::move(state_.dormant);
    std::vector<std::pair<Index, Index>> bridges = std::move(state_.bridges);
    k.head = state_;
    k.bridgeCount = uint32_t(bridges.size());
    state_.dormant = std::move(dormant);
    state_.bridges = std::move(bridges);

    // A gorge keeps its chain while dormant: share it with the previous keyframe when its id
    // is unique in both and it was not pushed again since. Ids index a table, so huge ids
    // (only in hand-made traces) are simply not shared.
    const size_t maxId = 4 * trace_->events.size() + 64;
    const int32_t kAbsent = -1, kTwice = -2;
    auto mark = [&](const std::vector<Keyframe::Dormant>& list, std::vector<int32_t>& slot) {
        for (size_t i = 0; i < list.size(); ++i) {
            if (list[i].id >= maxId) continue;
            if (slot.size() <= list[i].id) slot.resize(list[i].id + 1, kAbsent);
            int32_t& s = slot[list[i].id];
            s = s == kAbsent ? int32_t(i) : kTwice;
        }
    };
    std::vector<int32_t>& prevSlot = slots_[0];
    std::vector<int32_t>& curSlot = slots_[1];
    const Keyframe* prev = keyframes_.empty() ? nullptr : &keyframes_.back();
    k.dormant.resize(state_.dormant.size());
    for (size_t i = 0; i < state_.dormant.size(); ++i)
        k.dormant[i] = {state_.dormant[i].id, state_.dormant[i].top, 0, state_.dormant[i].held};
    if (prev) mark(prev->dormant, prevSlot);
    mark(k.dormant, curSlot);
    for (uint32_t id : pushedSince)
        if (id < prevSlot.size()) prevSlot[id] = kTwice;
    for (size_t i = 0; i < k.dormant.size(); ++i) {
        uint32_t id = k.dormant[i].id;
        bool shared = id < prevSlot.size() && prevSlot[id] >= 0 && curSlot[id] >= 0;
        if (shared) {
            k.dormant[i].chain = prev->dormant[size_t(prevSlot[id])].chain;
        } else {
            k.dormant[i].chain = uint32_t(chains_.size());
            chains_.push_back(state_.dormant[i].chain);
        }
    }
    // Leave the tables all absent for the next keyframe, touching only what was marked.
    using List = const std::vector<Keyframe::Dormant>*;
    for (List list : {prev ? &prev->dormant : List(nullptr), List(&k.dormant)})
        if (list)
            for (const auto& d : *list)
                for (auto* slot : {&prevSlot, &curSlot})
                    if (d.id < slot->size()) (*slot)[d.id] = kAbsent;
    for (uint32_t id : pushedSince)
        if (id < prevSlot.size()) prevSlot[id] = kAbsent;
    keyframeSteps_.push_back(state_.step);
    keyframes_.push_back(std::move(k));
}

void Replay::restore(const Keyframe& k) {
    std::vector<Gorge> dormant = std::move(state_.dormant);
    std::vector<std::pair<Index, Index>> bridges = std::move(state_.bridges);
    state_ = k.head;
    if (bridges.size() > k.bridgeCount) bridges.resize(k.bridgeCount);
    else bridges.insert(bridges.end(), bridges_.begin() + long(bridges.size()),
                        bridges_.begin() + long(k.bridgeCount));
    dormant.resize(k.dormant.size());
    for (size_t i = 0; i < dormant.size(); ++i) {
        const Keyframe::Dormant& d = k.dormant[i];
        dormant[i].id = d.id, dormant[i].held = d.held, dormant[i].top = d.top;
        dormant[i].chain = chains_[d.chain];
    }
    state_.dormant = std::move(dormant);
    state_.bridges = std::move(bridges);
}

size_t Replay::keyframeBytes() const {
    size_t bytes = keyframes_.capacity() * sizeof(Keyframe) + bridges_.capacity() * sizeof(bridges_[0]) +
                   chains_.capacity() * sizeof(chains_[0]);
    for (const auto& c : chains_) bytes += c.capacity() * sizeof(Index);
    for (const Keyframe& k : keyframes_)
        bytes += k.head.chain.capacity() * sizeof(Index) +
                 k.head.jumps.capacity() * sizeof(k.head.jumps[0]) +
                 k.dormant.capacity() * sizeof(Keyframe::Dormant);
    return bytes;
}

const ReplayState& Replay::seek(uint32_t step) {
    step = std::min(step, size());
    size_t k = size_t(std::upper_bound(keyframeSteps_.begin(), keyframeSteps_.end(), step) -
                      keyframeSteps_.begin()) - 1;
    // Stepping forward from where we are is cheapest unless a keyframe lies in between.
    if (step < state_.step || keyframeSteps_[k] > state_.step) restore(keyframes_[k]);
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
            // What stays right of the sag: the copy of the chain vertex and the chain after
            // it, less the wedge cut there.
            std::vector<Index> rightPart(chain.begin() + long(std::min(chain.size(), i + e.cutRight)), chain.end());
            chain.resize(keepLeft);
            chain.push_back(e.sag);
            if (e.gorgePushed == kNone) {  // a Steiner point: the chain runs on through it
                chain.insert(chain.end(), rightPart.begin(), rightPart.end());
            } else {
                Gorge other;
                other.id = e.gorgePushed;
                other.chain.push_back(e.sag);
                other.chain.insert(other.chain.end(), rightPart.begin(), rightPart.end());
                s.dormant.push_back(std::move(other));
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
