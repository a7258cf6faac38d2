// The quiz's keys through the viewer's shortcut handling (panel_help.cpp, panel_quiz.cpp), in a
// window-free Dear ImGui: Q starts and stops the quiz, a digit or an action's initial answers the
// pending question, and F answers Fill there instead of fitting the view.
#include <gtest/gtest.h>
#include <imgui.h>

#include "panels.h"
#include "windowless_imgui.h"

using namespace flood;
using namespace flood::view;

namespace {

class QuizKeys : public ::testing::Test {
protected:
    void SetUp() override {
        createWindowlessImGui(1280, 800);
        model.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json");
        ui.layout = computeLayout(1280, 800, 1);
        ui.quizAsked.set(Action::Raise, false);
        ui.quizAsked.set(Action::Jump, false);
        ui.quizAsked.set(Action::Fill, false);
    }
    void TearDown() override { ImGui::DestroyContext(); }

    // A frame with `key` held (0: none), then one with it released, as a hand presses it.
    void press(int key) {
        for (bool down : {true, false}) {
            ImGui::GetIO().KeysDown[key] = down;
            ImGui::NewFrame();
            handleShortcuts(ui);
            drawQuiz(ui);
            ImGui::EndFrame();
        }
    }
    // The step before the first event of `a` at or after `from`.
    uint32_t before(Action a, uint32_t from = 0) const {
        const auto& events = model.trace().events;
        while (from < events.size() && events[from].action != a) ++from;
        return from;
    }

    Model model;
    Renderer renderer;  // never initialised: nothing here draws
    Ui ui{model, renderer};
};

}  // namespace

TEST_F(QuizKeys, QStartsDigitsAndInitialsAnswerFIsFillNotFit) {
    press('Q');
    ASSERT_TRUE(model.quizOn());
    EXPECT_TRUE(model.quiz().asked().has(Action::Bridge));
    EXPECT_FALSE(model.quiz().asked().has(Action::Raise));
    // Before the first spill: F answers Fill (wrong) and asks for no fit.
    const uint32_t spill = before(Action::Spill);
    model.seek(spill);
    model.keepView();
    ASSERT_EQ(model.pendingQuestion(), 0);
    press('F');
    EXPECT_EQ(model.quiz().given(0), Action::Fill);
    EXPECT_EQ(model.step(), spill + 1);
    EXPECT_FALSE(model.fitPending());
    // Nothing pending: F fits again.
    press('F');
    EXPECT_TRUE(model.fitPending());
    // Before the first bridge: 2 answers Bridge (right).
    const uint32_t bridge = before(Action::Bridge);
    model.seek(bridge);
    const int q = model.pendingQuestion();
    ASSERT_GE(q, 0);
    press('2');
    EXPECT_EQ(model.quiz().given(size_t(q)), Action::Bridge);
    EXPECT_EQ(model.quiz().score(), 1u);
    // The next question by its initial: S.
    const uint32_t next = model.quiz().event(size_t(q) + 1);
    model.seek(next);
    press('S');
    EXPECT_EQ(model.quiz().given(size_t(q) + 1), Action::Spill);
    // A key that is no choice answers nothing.
    model.seek(model.quiz().event(size_t(q) + 2));
    press('X');
    EXPECT_FALSE(model.quiz().answered(size_t(q) + 2));
    press('Q');
    EXPECT_FALSE(model.quizOn());
}
