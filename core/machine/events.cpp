#include "machine/events.h"

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

}  // namespace flood
