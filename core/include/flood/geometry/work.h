// Work counters: deterministic measures of how much the validator and the flood machine did,
// so tests can hold growth to linear without clocks (tests/machine/growth_test.cpp). Counting costs
// one add; the counters are per thread, so parallel runs do not disturb each other.
#pragma once
#include <cstdint>

namespace flood {

struct WorkCounters {
    uint64_t orientCalls = 0;  // exact orientation tests (every predicate rests on them)
    uint64_t nodeVisits = 0;   // nodes the machine touches: loop nodes its set-up, steps, walks,
                               // fills, spills and merges visit; sag-tree boxes and sags searched
    uint64_t sagTests = 0;     // sags the sag search tests with `inside`
    uint64_t validatorSteps = 0;  // pair tests and wedge comparisons of validate()
    uint64_t touchSteps = 0;      // grid cells walked and point-edge tests of findTouches()
    uint64_t checkerSteps = 0;    // edges the checker's parts sweep scans, cuts and inserts
    uint64_t sagSearch = 0;       // the sag search's share of the three machine counts above
        // (its sweep, lists, tree and tests), to weigh it against the rest
    uint64_t invariantSteps = 0;  // grid cells and vertices the invariant checker visits
    uint64_t heightCalls = 0;     // exact height tests along a direction off the axes (heightSign)
    uint64_t touchSearchNodes = 0;  // nodes the flood machine hashed looking for rings that touch
    uint64_t nestingSteps = 0;      // parts, holes and hole edges verify's complement looks at to
                                    // put islands in their lakes (core/verify.cpp)
};

inline thread_local WorkCounters tWork;

// This thread's counters; reset with `work() = {}` before the run to be measured.
inline WorkCounters& work() { return tWork; }

}  // namespace flood
