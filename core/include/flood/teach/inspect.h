// The predicate inspector (the viewer's Predicates panel): the tests of one event's decision
// path (Fig. 9) recomputed from the replay state before it, with the exact predicates' stages.
#pragma once
#include <string>
#include <vector>

#include "flood/log/replay.h"
#include "flood/machine/events.h"
#include "flood/machine/vertex_class.h"

namespace flood {

// Predicate inspector: the tests of one event's decision path (Fig. 9), recomputed from the
// replay state before the event, each with its predicate, arguments, floating-point value,
// exact result and the stage of the exact predicate that decided it.
struct PredicateRow {
    Test test = Test::Count;  // Test::Count: one of the sag search's inside() tests
    std::string predicate;    // "below(NextLeft, NextRight)", "orient(prev C, C, next C) <= 0", ...
    std::vector<Index> args;  // vertex ids, in the predicate's order
    bool result = false;      // recomputed
    bool recorded = false;    // what the event says (decision tests only)
    bool hasRecorded = false;
    bool hasValue = false;  // orient-based: `value` and `stage` mean something
    double value = 0;       // the filter's determinant
    int sign = 0;           // exact sign (orient) or the comparison's outcome
    std::string stage;      // "filter" / "expansion" / "rationals" / "comparison" / "identity"
};
// The sag search's inside() tests are listed for the sags it could test: unbridged sags
// strictly between the water and Next (at most `maxSags` of them; the machine's sag index
// tests fewer, Event::sagTests of them).
std::vector<PredicateRow> inspectDecision(const Trace& trace, const ReplayState& before,
                                          const Event& e, const std::vector<VertexClass>& classes,
                                          size_t maxSags = 64);

}  // namespace flood
