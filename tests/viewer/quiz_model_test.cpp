// The viewer's quiz session (viewer/model.h, model_quiz.cpp) without a window: stepping stops
// before each asked step until it is answered, answering shows the step, the score counts.
// Compiles to nothing when the viewer's model is not built.
#if __has_include("model.h")
#include <gtest/gtest.h>

#include "model.h"
#include "test_support.h"

using namespace flood;
using namespace flood::view;
using flood::testing::sourcePath;

namespace {
QuizActions bridgesAndSpills() {
    QuizActions q;
    q.set(Action::Bridge, true);
    q.set(Action::Spill, true);
    return q;
}
// The first event at or after `from` that is a Bridge or a Spill.
uint32_t nextAsked(const Model& m, uint32_t from) {
    const auto& events = m.trace().events;
    for (uint32_t i = from; i < events.size(); ++i)
        if (events[i].action == Action::Bridge || events[i].action == Action::Spill) return i;
    return uint32_t(events.size());
}
}  // namespace

TEST(QuizModel, SteppingStopsBeforeEachQuestionUntilAnswered) {
    Model m;
    m.open(sourcePath("polygons/paper-figure-7.json"));
    m.first();
    m.startQuiz(bridgesAndSpills());
    ASSERT_TRUE(m.quizOn());
    const uint32_t first = nextAsked(m, 0);
    ASSERT_LT(first, m.steps());
    // Forward until the step before the first spill: no further, however often.
    for (uint32_t i = 0; i < first + 5; ++i) m.stepForward();
    EXPECT_EQ(m.step(), first);
    EXPECT_EQ(m.pendingQuestion(), 0);
    EXPECT_EQ(m.revealedQuestion(), -1);
    // Playback stops there too.
    m.setPlaying(true);
    m.advance(10);
    EXPECT_EQ(m.step(), first);
    EXPECT_FALSE(m.playing());
    // A wrong answer: the step is shown, the question revealed, no point.
    const Action truth = m.trace().events[first].action;
    const Action wrong = truth == Action::Bridge ? Action::Raise : Action::Bridge;
    EXPECT_FALSE(m.answerQuiz(Action::Start));  // not a choice
    ASSERT_TRUE(m.answerQuiz(wrong));
    EXPECT_EQ(m.step(), first + 1);
    EXPECT_EQ(m.revealedQuestion(), 0);
    EXPECT_EQ(m.pendingQuestion(), -1);
    EXPECT_EQ(m.quiz().given(0), wrong);
    EXPECT_EQ(m.quiz().score(), 0u);
    EXPECT_FALSE(m.answerQuiz(truth));  // nothing pending now
    // On to the second question, answered right.
    const uint32_t second = nextAsked(m, first + 1);
    for (uint32_t i = 0; i < m.steps(); ++i) m.stepForward();
    EXPECT_EQ(m.step(), second);
    EXPECT_EQ(m.pendingQuestion(), 1);
    ASSERT_TRUE(m.answerQuiz(m.trace().events[second].action));
    EXPECT_EQ(m.quiz().score(), 1u);
    EXPECT_EQ(m.quiz().answeredCount(), 2u);
    // Back before the first question: it is answered, so stepping passes it.
    m.seek(first);
    EXPECT_EQ(m.pendingQuestion(), -1);
    m.stepForward();
    EXPECT_EQ(m.step(), first + 1);
    EXPECT_EQ(m.revealedQuestion(), 0);
    // Off: stepping is free again.
    m.stopQuiz();
    m.seek(nextAsked(m, second + 1));
    const uint32_t at = m.step();
    m.stepForward();
    EXPECT_EQ(m.step(), at + 1);
}

TEST(QuizModel, ANewTraceStartsTheSameQuizAfresh) {
    Model m;
    m.open(sourcePath("polygons/paper-figure-7.json"));
    m.startQuiz(bridgesAndSpills());
    const uint32_t first = nextAsked(m, 0);
    m.seek(first);
    ASSERT_TRUE(m.answerQuiz(m.trace().events[first].action));
    EXPECT_EQ(m.quiz().score(), 1u);
    m.open(sourcePath("polygons/two-gorges.json"));  // one spill, no bridge
    EXPECT_TRUE(m.quizOn());
    EXPECT_EQ(m.quiz().answeredCount(), 0u);
    EXPECT_EQ(m.quiz().size(), 1u);
    EXPECT_TRUE(m.quiz().asked().has(Action::Bridge));
    EXPECT_FALSE(m.quiz().asked().has(Action::Raise));
}

#endif
