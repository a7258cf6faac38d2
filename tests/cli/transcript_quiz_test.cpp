// `flood transcript --quiz` (a handout: questions, then answers apart) and `--table` (the
// complete Fig. 10 with the run's counts), through the binary.
#include <gtest/gtest.h>

#include <string>

#include "flood/teach/quiz.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {
size_t occurrences(const std::string& s, const std::string& part) {
    size_t n = 0;
    for (size_t at = s.find(part); at != std::string::npos; at = s.find(part, at + 1)) ++n;
    return n;
}
}  // namespace

TEST(CliQuiz, QuestionsThenAnswersOnTheirOwnPage) {
    const std::string fig7 = sourcePath("polygons/paper-figure-7.json");
    RunResult r =
        runShell(std::string(FLOOD_CLI) + " transcript --quiz --quiz-actions bridge,spill " + fig7 +
                 " 2>/dev/null");
    ASSERT_EQ(r.code, 0) << r.out;
    const size_t page = r.out.find("\f\nAnswers\n");
    ASSERT_NE(page, std::string::npos) << r.out;
    const std::string questions = r.out.substr(0, page), answers = r.out.substr(page);
    // As many questions as the run has bridges and spills, numbered, none giving its answer.
    Trace t = record(readOrFail(fig7));
    QuizActions asked;
    asked.set(Action::Bridge, true);
    asked.set(Action::Spill, true);
    const std::vector<uint32_t> q = quizQuestions(t.events, asked);
    EXPECT_NE(questions.find("Predict the next action (bridge, spill): " +
                             std::to_string(q.size()) + " questions"),
              std::string::npos)
        << questions;
    EXPECT_EQ(occurrences(questions, "Which action comes next"), q.size());
    EXPECT_EQ(occurrences(questions, "Bridge"), 0u);
    EXPECT_EQ(occurrences(questions, "Spill"), 0u);
    for (size_t k = 0; k < q.size(); ++k) {
        const std::string n = std::to_string(k + 1) + ". ";
        EXPECT_NE(questions.find("\n" + n + "Before step " + std::to_string(q[k] + 1) + ":"),
                  std::string::npos)
            << n;
        // The answer: the event's own action and the tests that decided it.
        EXPECT_NE(answers.find("\n" + n + "step " + std::to_string(q[k] + 1) + ": " +
                               actionName(t.events[q[k]].action) +
                               ". Decided by: " + testText(flood::Test::SameNext)),
                  std::string::npos)
            << n << answers;
    }
}

TEST(CliQuiz, AnswersToAFileAndBadActions) {
    const std::string hole = sourcePath("polygons/hole.json");
    auto dir = scratch("cli-quiz");
    const std::string file = (dir / "answers.txt").string();
    RunResult r = runShell(std::string(FLOOD_CLI) + " transcript --quiz --answers " + file + " " +
                           hole + " 2>&1");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(r.out.find("Answers"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("1. Before step 2:"), std::string::npos) << r.out;
    const std::string answers = slurp(file);
    EXPECT_EQ(answers.rfind("Answers\n1. step 2: ", 0), 0u) << answers;
    // An action that is not one: usage (2), naming it; nothing printed on stdout.
    RunResult bad =
        runShell(std::string(FLOOD_CLI) + " transcript --quiz --quiz-actions bridge,flood " + hole +
                 " 2>&1 >/dev/null");
    EXPECT_EQ(bad.code, 2);
    EXPECT_NE(bad.out.find("'flood' is not an action to ask about"), std::string::npos) << bad.out;
    // --quiz-actions without --quiz, --quiz with --narrate: usage.
    EXPECT_EQ(runCli("transcript --quiz-actions bridge " + hole).code, 2);
    EXPECT_EQ(runCli("transcript --quiz --narrate " + hole).code, 2);
    // An answers file that cannot be written: an output error (8).
    RunResult unwritable =
        runCli("transcript --quiz --answers " + (dir / "no/such/dir/a.txt").string() + " " + hole);
    EXPECT_EQ(unwritable.code, 8) << unwritable.out;
    std::filesystem::remove_all(dir);
}

TEST(CliQuiz, TableListsEveryCombinationWithTheRunsCounts) {
    RunResult r = runCli("transcript --table " + sourcePath("polygons/two-gorges.json"));
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(r.out.rfind("Raise 0, Spill; Raise 1, Jump; Raise 2, Fill 3-4\n", 0), 0u) << r.out;
    EXPECT_NE(r.out.find("Fig. 10: vertex combinations and states"), std::string::npos);
    // Five rows of C classes in each grid, the Fill counted where the fingers meet.
    for (const char* c : {"\nbottom ", "\nsag ", "\nregular ", "\ntop ", "\nceiling "})
        EXPECT_EQ(occurrences(r.out, c), 2u) << c;
    EXPECT_NE(r.out.substr(r.out.find("Fingers meet")).find("F1"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("No chain yet: Start 1"), std::string::npos) << r.out;
}
