// Predict the next action (issue 27 §2): at a step the student picks the action the machine
// takes next (raise, bridge, spill, jump or fill) before it is shown; the answer is the
// event's own action, and what decided it is the event's Fig. 9 path (decision_tree.h) with
// its tests' answers. Shared by `flood transcript --quiz` (the questions and the answers as
// text) and the viewer, whose model holds a QuizSession.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/machine/events.h"
#include "flood/machine/vertex_class.h"

namespace flood {

// The choices, in the order of the keys 1-5 (the letters R B S J F work too).
constexpr std::array<Action, 5> kQuizChoices = {Action::Raise, Action::Bridge, Action::Spill,
                                                Action::Jump, Action::Fill};

// The actions asked about, one bit per Action. A step whose action is not asked is shown as
// usual; Start and forbidden states are never asked.
struct QuizActions {
    uint8_t bits = 0;
    static QuizActions all();
    bool has(Action a) const { return bits >> int(a) & 1; }
    void set(Action a, bool on);
    bool empty() const { return bits == 0; }
};
// "bridge,spill" (the choices' names in any case, comma separated) or "all". False, with
// `error` naming the word, when a word is no choice or nothing is named.
bool parseQuizActions(const std::string& text, QuizActions& out, std::string& error);
std::string quizActionsText(QuizActions asked);  // "raise, bridge"

// The choice a key means: '1'-'5' or r, b, s, j, f in either case; Action::Count otherwise.
Action quizChoiceOfKey(char key);

// The events asked about (indices into `events`), in log order: each whose action is asked.
std::vector<uint32_t> quizQuestions(const std::vector<Event>& events, QuizActions asked);

// What the student sees before event `i`, in words: the fingers and the ends with their
// classes (§3), which finger is lower, the water, the tops holding a gorge (a jump pointer
// set by an earlier spill) and the sags not bridged yet; `classes` from classifyVertices().
std::string quizPrompt(const Polygon& polygon, const std::vector<Event>& events, uint32_t i,
                       const std::vector<VertexClass>& classes);

// The tests on the event's Fig. 9 path, each with its answer ("NextLeft == NextRight: no"),
// the ones the machine ran, in order: what decided the action.
struct QuizPredicate {
    Test test = Test::Count;
    bool answer = false;
};
std::vector<QuizPredicate> decidingPredicates(const Event& e);
// "Bridge. Decided by: NextLeft == NextRight? no; ...; a sag lies inside ...? yes. <narration>"
std::string quizAnswer(const Polygon& polygon, const Event& e);

// A handout (`flood transcript --quiz`): the numbered questions, each the prompt above, and
// the answers under the same numbers ("3. step 14: Bridge. Decided by: ..."), one per line.
std::string quizQuestionsText(const Polygon& polygon, const std::vector<Event>& events,
                              QuizActions asked, Up up = Up::PlusY);
std::string quizAnswersText(const Polygon& polygon, const std::vector<Event>& events,
                            QuizActions asked);

// A quiz being played: its questions, the answers given (the first answer to a question
// counts), the score.
class QuizSession {
public:
    QuizSession() = default;
    QuizSession(const std::vector<Event>& events, QuizActions asked);

    QuizActions asked() const { return asked_; }
    size_t size() const { return questions_.size(); }
    uint32_t event(size_t q) const { return questions_[q]; }  // the event question q asks
    Action truth(size_t q) const { return truth_[q]; }
    // The question asked before event `i`: its index, or -1 when that event is not asked.
    int questionOf(uint32_t i) const;
    // Records `choice` for question q: true when it counted (the first answer, a choice).
    bool answer(size_t q, Action choice);
    bool answered(size_t q) const { return given_[q] != Action::Count; }
    Action given(size_t q) const { return given_[q]; }
    bool correct(size_t q) const { return answered(q) && given_[q] == truth_[q]; }
    size_t answeredCount() const;
    size_t score() const;  // answered correctly

private:
    QuizActions asked_;
    std::vector<uint32_t> questions_;
    std::vector<Action> truth_, given_;  // given: Action::Count until answered
};

}  // namespace flood
