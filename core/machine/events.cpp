#include "flood/machine/events.h"

namespace flood {

namespace {
#define FLOOD_X(name, word, meaning) word,
const char* const kActionWords[] = {FLOOD_ACTIONS(FLOOD_X)};
#undef FLOOD_X
#define FLOOD_X(name, word, meaning) meaning,
const char* const kActionMeanings[] = {FLOOD_ACTIONS(FLOOD_X)};
#undef FLOOD_X
#define FLOOD_X(name, text) text,
const char* const kTestTexts[] = {FLOOD_TESTS(FLOOD_X)};
const char* const kForbiddenTexts[] = {FLOOD_FORBIDDEN(FLOOD_X)};
#undef FLOOD_X
#define FLOOD_X(name, text) #name,
const char* const kForbiddenNames[] = {FLOOD_FORBIDDEN(FLOOD_X)};
#undef FLOOD_X
}  // namespace

const char* actionName(Action a) { return a < Action::Count ? kActionWords[int(a)] : "?"; }
const char* actionMeaning(Action a) { return a < Action::Count ? kActionMeanings[int(a)] : "?"; }
const char* testText(Test t) { return t < Test::Count ? kTestTexts[int(t)] : "?"; }
const char* forbiddenName(Forbidden f) {
    return f < Forbidden::Count ? kForbiddenNames[int(f)] : "?";
}
const char* forbiddenText(Forbidden f) {
    return f < Forbidden::Count ? kForbiddenTexts[int(f)] : "?";
}

const char* eventProblem(const Event& e, size_t vertexCount, size_t partCount) {
    if (e.action >= Action::Count) return "the action is unknown";
    auto vertex = [&](Index v) { return v != kNone && v < vertexCount; };
    auto noneOrVertex = [&](Index v) { return v == kNone || v < vertexCount; };
    auto named = [&](const Fingers& f) {
        return int(vertex(f.left)) + vertex(f.right) + vertex(f.nextLeft) + vertex(f.nextRight);
    };
    auto fingersBad = [&](const Fingers& f) {
        const int n = named(f);
        return (n != 0 && n != 4) || !noneOrVertex(f.left) || !noneOrVertex(f.right) ||
               !noneOrVertex(f.nextLeft) || !noneOrVertex(f.nextRight);
    };
    if (e.part >= partCount) return "\"part\" is not a part of the polygon";
    if (fingersBad(e.before))
        return "\"before\" names some of the fingers: all four are vertices, or none is";
    if (fingersBad(e.after))
        return "\"after\" names some of the fingers: all four are vertices, or none is";
    if (!noneOrVertex(e.water) || (named(e.after) == 4 && !vertex(e.water)))
        return "\"water\" is not a vertex while the fingers after are";
    if (!noneOrVertex(e.bottom)) return "\"bottom\" is not a vertex";
    // The subject pair: each action reads its own (usesField()); the others alias it.
    if (!noneOrVertex(e.sag) || !noneOrVertex(e.bridgeTo)) return "a subject is not a vertex";
    const bool moves = e.action == Action::Raise || e.action == Action::Bridge ||
                       e.action == Action::Spill || e.action == Action::Jump;
    if (moves && named(e.after) != 4)
        return "the fingers after are missing: the chain's ends come from them";
    switch (e.action) {
        case Action::Start:
            if (!vertex(e.bottom)) return "\"bottom\" is missing: the water starts there";
            break;
        case Action::Bridge:
            if (!vertex(e.sag) || !vertex(e.bridgeTo))
                return "\"sag\" or \"bridgeTo\" is missing: a Bridge joins a sag to the chain";
            break;
        case Action::Spill:
        case Action::Jump:
            if (!vertex(e.top) || !vertex(e.jumpTarget))
                return "\"top\" or \"jumpTarget\" is missing: the jump pointer joins them";
            if (e.action == Action::Spill && e.gorgePopped == kNone && !vertex(e.bottom))
                return "\"bottom\" is missing: a Spill that takes no gorge starts at a bottom";
            break;
        default: break;
    }
    return nullptr;
}

}  // namespace flood
