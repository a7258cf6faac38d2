// Predict the next action (flood/teach/quiz.h): which steps are asked, the answer and the
// predicates that decided it are the machine's own, and the score counts first answers only.
#include <gtest/gtest.h>

#include <algorithm>

#include "flood/teach/quiz.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {
size_t countOf(const std::vector<Event>& events, Action a) {
    return size_t(
        std::count_if(events.begin(), events.end(), [a](const Event& e) { return e.action == a; }));
}
}  // namespace

TEST(Quiz, ParsesTheActionsToAsk) {
    QuizActions q;
    std::string error;
    ASSERT_TRUE(parseQuizActions("bridge, Spill", q, error)) << error;
    EXPECT_TRUE(q.has(Action::Bridge));
    EXPECT_TRUE(q.has(Action::Spill));
    EXPECT_FALSE(q.has(Action::Raise));
    EXPECT_FALSE(q.has(Action::Fill));
    EXPECT_EQ(quizActionsText(q), "bridge, spill");
    ASSERT_TRUE(parseQuizActions("all", q, error));
    EXPECT_EQ(quizActionsText(q), "raise, bridge, spill, jump, fill");
    EXPECT_FALSE(parseQuizActions("bridge,flod", q, error));
    EXPECT_NE(error.find("'flod'"), std::string::npos) << error;
    EXPECT_FALSE(parseQuizActions("start", q, error));  // Start is never asked
    EXPECT_FALSE(parseQuizActions("", q, error));
    EXPECT_EQ(quizActionsText(q), "raise, bridge, spill, jump, fill");  // unchanged on failure
}

TEST(Quiz, KeysNameTheChoices) {
    EXPECT_EQ(quizChoiceOfKey('1'), Action::Raise);
    EXPECT_EQ(quizChoiceOfKey('2'), Action::Bridge);
    EXPECT_EQ(quizChoiceOfKey('5'), Action::Fill);
    EXPECT_EQ(quizChoiceOfKey('b'), Action::Bridge);
    EXPECT_EQ(quizChoiceOfKey('J'), Action::Jump);
    EXPECT_EQ(quizChoiceOfKey('S'), Action::Spill);
    EXPECT_EQ(quizChoiceOfKey('6'), Action::Count);
    EXPECT_EQ(quizChoiceOfKey('x'), Action::Count);
}

// Fig. 7: "Raise 0-7, Spill; Raise 8-12, Jump; Raise 13-18, Bridge, ...": asked about bridges
// and spills, the quiz asks exactly at those events, and their answers are the events'.
TEST(Quiz, QuestionsAreTheEventsOfTheChosenActions) {
    Polygon p = readOrFail(sourcePath("polygons/paper-figure-7.json"));
    Trace t = record(p);
    QuizActions asked;
    asked.set(Action::Bridge, true);
    asked.set(Action::Spill, true);
    QuizSession quiz(t.events, asked);
    EXPECT_EQ(quiz.size(), countOf(t.events, Action::Bridge) + countOf(t.events, Action::Spill));
    EXPECT_GE(quiz.size(), 5u);  // the paper's run has 3 bridges and 3 spills
    for (size_t q = 0; q < quiz.size(); ++q) {
        EXPECT_EQ(quiz.truth(q), t.events[quiz.event(q)].action);
        EXPECT_EQ(quiz.questionOf(quiz.event(q)), int(q));
        if (q) {
            EXPECT_LT(quiz.event(q - 1), quiz.event(q));
        }
    }
    EXPECT_EQ(quiz.questionOf(0), -1);  // Start is never asked
    QuizSession everything(t.events, QuizActions::all());
    EXPECT_EQ(everything.size(), t.events.size() - countOf(t.events, Action::Start));
}

TEST(Quiz, ScoreCountsFirstAnswersThatMatchTheMachine) {
    Polygon p = readOrFail(sourcePath("polygons/paper-figure-7.json"));
    Trace t = record(p);
    QuizSession quiz(t.events, QuizActions::all());
    ASSERT_GE(quiz.size(), 10u);
    EXPECT_EQ(quiz.score(), 0u);
    EXPECT_EQ(quiz.answeredCount(), 0u);
    // Right on even questions, wrong (the next choice round) on odd ones.
    for (size_t q = 0; q < quiz.size(); ++q) {
        Action truth = quiz.truth(q);
        size_t k = size_t(std::find(kQuizChoices.begin(), kQuizChoices.end(), truth) -
                          kQuizChoices.begin());
        ASSERT_LT(k, kQuizChoices.size());
        Action pick = q % 2 ? kQuizChoices[(k + 1) % kQuizChoices.size()] : truth;
        EXPECT_TRUE(quiz.answer(q, pick));
        EXPECT_EQ(quiz.correct(q), q % 2 == 0);
        // A second answer does not count, right or wrong.
        EXPECT_FALSE(quiz.answer(q, truth));
        EXPECT_EQ(quiz.given(q), pick);
    }
    EXPECT_EQ(quiz.answeredCount(), quiz.size());
    EXPECT_EQ(quiz.score(), (quiz.size() + 1) / 2);
    QuizSession fresh(t.events, QuizActions::all());
    EXPECT_FALSE(fresh.answer(0, Action::Start));  // not a choice
    EXPECT_FALSE(fresh.answer(fresh.size(), Action::Raise));
    EXPECT_EQ(fresh.answeredCount(), 0u);
}

// The predicates shown after an answer are the tests the machine ran, on the event's path.
TEST(Quiz, DecidingPredicatesAreTheMachinesTests) {
    Polygon p = readOrFail(sourcePath("polygons/paper-figure-7.json"));
    Trace t = record(p);
    size_t seen[size_t(Action::Count)] = {};
    for (const Event& e : t.events) {
        if (e.action == Action::Start) continue;
        std::vector<QuizPredicate> tests = decidingPredicates(e);
        ASSERT_FALSE(tests.empty());
        EXPECT_EQ(tests.front().test, flood::Test::SameNext);
        for (const QuizPredicate& q : tests) {
            EXPECT_TRUE(e.didTest(q.test));
            EXPECT_EQ(q.answer, e.testResult(q.test));
        }
        const QuizPredicate& last = tests.back();
        switch (e.action) {
            case Action::Fill:
            case Action::Bridge:
            case Action::Raise:
                EXPECT_EQ(last.test, flood::Test::SagInside);
                EXPECT_EQ(last.answer, e.action == Action::Bridge);
                break;
            case Action::Jump: EXPECT_TRUE(last.test == flood::Test::JumpSet && last.answer); break;
            case Action::Spill: {
                bool jumpUnset =
                    std::any_of(tests.begin(), tests.end(), [](const QuizPredicate& q) {
                        return q.test == flood::Test::JumpSet && !q.answer;
                    });
                EXPECT_TRUE(jumpUnset);
                break;
            }
            default: break;
        }
        ++seen[size_t(e.action)];
        std::string answer = quizAnswer(p, e);
        EXPECT_EQ(answer.rfind(actionName(e.action), 0), 0u) << answer;
        EXPECT_NE(answer.find(std::string(testText(flood::Test::SameNext)) +
                              (e.testResult(flood::Test::SameNext) ? "? yes" : "? no")),
                  std::string::npos)
            << answer;
    }
    for (Action a : kQuizChoices) EXPECT_GT(seen[size_t(a)], 0u) << actionName(a);
}

// The question says what the student needs and nothing of the answer: the fingers with their
// classes, the water, the tops held by earlier spills, the sags not bridged yet.
TEST(Quiz, PromptDescribesTheStateBeforeTheStep) {
    Polygon p = readOrFail(sourcePath("polygons/paper-figure-7.json"));
    Trace t = record(p);
    std::vector<VertexClass> classes = classifyVertices(p);
    QuizSession quiz(t.events, QuizActions::all());
    bool sawHeld = false;
    for (size_t q = 0; q < quiz.size(); ++q) {
        const uint32_t i = quiz.event(q);
        const Event& e = t.events[i];
        const std::string prompt = quizPrompt(p, t.events, i, classes);
        SCOPED_TRACE(prompt);
        EXPECT_NE(prompt.find("Before step " + std::to_string(i + 1) + ":"), std::string::npos);
        EXPECT_NE(prompt.find("vertex " + std::to_string(e.before.nextLeft) + " (" +
                              vertexClassName(classes[e.before.nextLeft]) + ")"),
                  std::string::npos);
        EXPECT_NE(prompt.find("Left is vertex " + std::to_string(e.before.left)),
                  std::string::npos);
        EXPECT_NE(prompt.find("The water is at vertex " + std::to_string(t.events[i - 1].water)),
                  std::string::npos);
        for (Action a : kQuizChoices)  // the choices are named in lower case only
            EXPECT_EQ(prompt.find(actionName(a)), std::string::npos);
        if (e.action == Action::Jump) {  // the top it jumps from was held by a spill
            EXPECT_NE(prompt.find("vertex " + std::to_string(e.top) + " (to vertex"),
                      std::string::npos);
            sawHeld = true;
        }
        if (e.action == Action::Bridge) {  // the sag it bridges is still listed
            ASSERT_NE(prompt.find("Sags not bridged yet:"), std::string::npos);
            std::string sags = prompt.substr(prompt.find("Sags not bridged yet:"));
            if (sags.find(" more") == std::string::npos) {  // ten are listed
                EXPECT_NE(sags.find(" " + std::to_string(e.sag)), std::string::npos);
            }
        }
    }
    EXPECT_TRUE(sawHeld);
}
