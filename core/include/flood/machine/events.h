// The event log: one record per action of the flood machine (§4), the only thing that
// crosses from the core to the viewer, the trace files and the transcript.
// Every kind is declared once in the lists below; they generate the enums and the names.
// Events hold vertex indices and numbers only, never pointers, so traces serialize and replay.
#pragma once
#include <cstddef>
#include <cstdint>

#include "flood/geometry/polygon.h"

namespace flood {

// 2: an event leaves out the fields its action does not use and those at their initial value.
constexpr int kTraceFormatVersion = 2;

// X(name, word in transcripts, one-line meaning)
#define FLOOD_ACTIONS(X)                                                                 \
    X(Start, "Start", "the water starts at the lowest bottom of a part")                 \
    X(Raise, "Raise", "Next joins the active chain; triangles cut from the chain to it") \
    X(Bridge, "Bridge", "a sag in the gorge is joined to the chain; the gorge splits")   \
    X(Spill, "Spill", "a top overflows; flooding moves to the gorge beyond it")          \
    X(Jump, "Jump", "the water reaches a top from its far side; back to the other bank") \
    X(Fill, "Fill", "NextLeft and NextRight meet; the gorge is filled to its ceiling")   \
    X(Forbidden, "Forbidden", "a forbidden state or transition: the input is invalid")

enum class Action : uint8_t {
#define FLOOD_X(name, word, meaning) name,
    FLOOD_ACTIONS(FLOOD_X)
#undef FLOOD_X
        Count
};

// The tests of the decision tree (Fig. 9) in the order they run. An event records which
// ran (Event::tested) and their outcomes (Event::passed), one bit each.
#define FLOOD_TESTS(X)                                                     \
    X(SameNext, "NextLeft == NextRight")                                   \
    X(LeftLower, "NextLeft below NextRight (Next is NextLeft, C is Left)") \
    X(NextAbove, "Next above C (the bank goes up)")                        \
    X(SagInside, "a sag lies inside Left, Right, NextRight, NextLeft")     \
    X(CIsTop, "C is concave (a top, not a ceiling)")                       \
    X(JumpSet, "C has a jump pointer")                                     \
    X(WalkLanded, "the walk down the far side of the top found the gorge")

enum class Test : uint8_t {
#define FLOOD_X(name, text) name,
    FLOOD_TESTS(FLOOD_X)
#undef FLOOD_X
        Count
};

// Why the machine stopped in a forbidden state. X(name, explanation in flood vocabulary)
#define FLOOD_FORBIDDEN(X)                                                                       \
    X(None, "")                                                                                  \
    X(NotFinite, "a coordinate is not a finite number: heights cannot be compared")              \
    X(ShortLoop, "a ring has fewer than three vertices: it bounds no area and makes no loop")    \
    X(StartNotBottom,                                                                            \
      "the lowest vertex of the outer loop is not a bottom: the loop is not a simple polygon "   \
      "boundary (Fig. 11-A)")                                                                    \
    X(CeilingAsEnd,                                                                              \
      "an end of the active chain is a ceiling while NextLeft and NextRight differ: a valid "    \
      "gorge closes at a ceiling only when both fingers meet there (Fig. 11-B)")                 \
    X(JumpWrongSide, "the water reached a top from the bank it spilled from: banks cross")       \
    X(SpillNoBottom, "spilling over a top found no bottom to flood: the loop folds over itself") \
    X(BadTriangle, "a triangle to be cut is inverted or flat: an edge crosses the gorge")        \
    X(FillOpen, "the fingers met but the gorge is not closed: loops cross each other")           \
    X(LeftBehind,                                                                                \
      "the to-do list is empty but vertices were never flooded: a hole lies outside or loops "   \
      "cross")                                                                                   \
    X(NoProgress, "the machine made no progress: the loops are inconsistent")

enum class Forbidden : uint8_t {
#define FLOOD_X(name, text) name,
    FLOOD_FORBIDDEN(FLOOD_X)
#undef FLOOD_X
        Count
};

enum class Side : uint8_t { Left = 0, Right = 1 };

// Left, Right, NextLeft, NextRight as vertex indices (kNone when there is no active chain).
struct Fingers {
    Index left = kNone, right = kNone, nextLeft = kNone, nextRight = kNone;
};
inline bool operator==(const Fingers& a, const Fingers& b) {
    return a.left == b.left && a.right == b.right && a.nextLeft == b.nextLeft &&
           a.nextRight == b.nextRight;
}

// Every field of an event, declared once: X(kind, type, name, initial value). The list
// generates the members, operator== and the trace writer and reader (core/log/trace_io.cpp), where
// the kind says how the field is written: a name, a list of test names, a vertex index or a
// gorge id (null for kNone), a number, or the four fingers. The list's own fields are stored
// each in its place; the subject fields after them share storage (see Event).
#define FLOOD_EVENT_FIELDS(X)                                                         \
    FLOOD_EVENT_OWN_FIELDS(X)                                                         \
    /* The subject: Bridge: the sag joined to chain vertex `bridgeTo`. */             \
    X(Vertex, Index, sag, kNone)                                                      \
    X(Vertex, Index, bridgeTo, kNone)                                                 \
    /* Spill / Jump: the top, and the jump pointer set (Spill) or followed (Jump). */ \
    X(Vertex, Index, top, kNone)                                                      \
    X(Vertex, Index, jumpTarget, kNone)                                               \
    /* Forbidden: the vertices involved (up to two besides the fingers). */           \
    X(Vertex, Index, culprit, kNone)                                                  \
    X(Vertex, Index, culprit2, kNone)

#define FLOOD_EVENT_OWN_FIELDS(X)                                                               \
    X(ActionName, Action, action, Action::Start)                                                \
    X(SideName, Side, side, Side::Left) /* C: the acting end (Raise, Spill, Jump) */            \
    X(TestNames, uint8_t, tested, 0)    /* bit i: Test(i) was evaluated */                      \
    X(TestNames, uint8_t, passed, 0)    /* bit i: Test(i) was true */                           \
    X(ReasonName, Forbidden, reason, Forbidden::None)                                           \
    X(Number, uint32_t, step, 0) /* position in the log */                                      \
    X(Number, uint32_t, part, 0) /* part of a multipolygon being flooded */                     \
    X(FingerVertices, Fingers, before, {})                                                      \
    X(FingerVertices, Fingers, after, {})                                                       \
    X(Vertex, Index, water, kNone)        /* vertex at the water level after the action */      \
    X(Number, uint32_t, firstTriangle, 0) /* triangles cut by this action */                    \
    X(Number, uint32_t, triangleCount, 0)                                                       \
    X(Number, uint32_t, sagTests, 0) /* inside() evaluations made searching the sag list */     \
    /* Bridge: the sag is joined at position `chainIndex` of the chain; the wedge cut on the */ \
    /* chain's left of it has `cutLeft` triangles, `cutRight` on the right. */                  \
    X(Number, uint32_t, chainIndex, 0)                                                          \
    X(Number, uint32_t, cutLeft, 0)                                                             \
    X(Number, uint32_t, cutRight, 0)                                                            \
    /* Gorges put on the to-do list (Bridge: the other half; Spill: the chain held at the */    \
    /* top) and taken from it (Fill, Spill landing on a pending gorge): ids, kNone if none. */  \
    X(GorgeId, uint32_t, gorgePushed, kNone)                                                    \
    X(GorgeId, uint32_t, gorgePopped, kNone)                                                    \
    X(Vertex, Index, bottom, kNone) /* Start / Spill: the bottom where the new gorge begins */

// The fields, numbered in list order (Field::sag), to ask which ones an action uses.
enum class Field : uint8_t {
#define FLOOD_X(kind, type, name, initial) name,
    FLOOD_EVENT_FIELDS(FLOOD_X)
#undef FLOOD_X
        Count
};

// Whether field `f` means anything in an event of action `a`: every field does except the
// subject fields, which only their own actions give a meaning. A Forbidden event stopped
// mid-action keeps that action's counts and gorges, not its subject (the culprits replace it).
constexpr bool usesField(Action a, Field f) {
    switch (f) {
        case Field::sag:
        case Field::bridgeTo: return a == Action::Bridge;
        case Field::top:
        case Field::jumpTarget: return a == Action::Spill || a == Action::Jump;
        case Field::culprit:
        case Field::culprit2: return a == Action::Forbidden;
        default: return true;
    }
}

// One record per action: 96 bytes, most of a trace's memory. No action has more than one
// subject pair, so the three pairs share storage: in an event, read the pair of its action
// (usesField()); the others alias it. (GCC and Clang define reading a union member other than
// the one last written, as C does; the members here are all the same type.)
struct Event {
#define FLOOD_X(kind, type, name, initial) type name = initial;
    FLOOD_EVENT_OWN_FIELDS(FLOOD_X)
#undef FLOOD_X
    union {
        Index sag = kNone;
        Index top;
        Index culprit;
    };
    union {
        Index bridgeTo = kNone;
        Index jumpTarget;
        Index culprit2;
    };

    bool didTest(Test t) const { return tested >> int(t) & 1; }
    bool testResult(Test t) const { return passed >> int(t) & 1; }
};

inline bool operator==(const Event& a, const Event& b) {
#define FLOOD_X(kind, type, name, initial) \
    if (!(a.name == b.name)) return false;
    FLOOD_EVENT_FIELDS(FLOOD_X)
#undef FLOOD_X
    return true;
}
// A field added to Event outside FLOOD_EVENT_FIELDS would be neither compared nor traced, and
// one added to the list changes what traces hold: either way, bump kTraceFormatVersion and
// this size.
static_assert(sizeof(Event) == 96,
              "Event changed: list its fields in FLOOD_EVENT_FIELDS, bump kTraceFormatVersion");

// What is wrong with event `e` for the replay (replay.h), the invariant checker
// (invariants.h) and the viewer, which index the polygon's vertices with its fields and take
// the chain's ends from them; nullptr when nothing is. Every event the machine records passes
// (tests/trace_mutation_test.cpp); parseTrace() refuses a trace with one that does not. Checked:
// every vertex field is a vertex of the polygon or none, and `part` a part of it; the fingers
// before and after name all four vertices or none; the water is a vertex when the fingers
// after are; and the action has what the replay builds its chain from (Start: its bottom;
// Raise, Bridge, Spill, Jump: the fingers after; Bridge: its sag and bridgeTo; Spill and Jump:
// the top and its jump target; Spill: the bottom it starts from when it takes no gorge).
const char* eventProblem(const Event& e, size_t vertexCount, size_t partCount);

const char* actionName(Action a);  // "Raise"
const char* actionMeaning(Action a);
const char* testText(Test t);
const char* forbiddenName(Forbidden f);
const char* forbiddenText(Forbidden f);

// Receives every event as it happens. Recording costs one branch when nobody listens.
class Listener {
public:
    virtual ~Listener() = default;
    virtual void onEvent(const Event& e) = 0;
};

}  // namespace flood
