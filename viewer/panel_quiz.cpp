// The quiz (flood/teach/quiz.h; the session is the Model's): predict the next action. Before an
// asked step the panel asks which action comes next, with the five choices as buttons (keys
// 1-5 or R B S J F); once answered, the step is shown and the panel says whether the answer
// was right, the tests that decided it (the Decision panel lights the same Fig. 9 path; in
// presenter view the panel draws the tree itself) and the score. Q starts and stops it.
#include <imgui.h>

#include <algorithm>
#include <string>

#include "flood/teach/decision_tree.h"
#include "panels.h"

namespace flood::view {

namespace {

void toggleQuiz(Ui& ui) {
    Model& m = ui.model;
    if (m.quizOn()) {
        m.stopQuiz();
        ui.message = "quiz off";
        return;
    }
    m.startQuiz(ui.quizAsked);
    ui.message = "quiz on: " + std::to_string(m.quiz().size()) + " questions about " +
                 quizActionsText(ui.quizAsked);
}

// The actions asked about, as checkboxes; a change starts the quiz again (the questions change).
void askedBoxes(Ui& ui) {
    ImGui::TextDisabled("ask about:");
    QuizActions asked = ui.quizAsked;
    for (Action a : kQuizChoices) {
        sameLineOrWrap(ImGui::GetFrameHeight() + ImGui::CalcTextSize(actionName(a)).x +
                       2 * ImGui::GetStyle().ItemInnerSpacing.x);
        bool on = asked.has(a);
        if (ImGui::Checkbox(actionName(a), &on)) asked.set(a, on);
    }
    if (asked.bits != ui.quizAsked.bits && !asked.empty()) {
        ui.quizAsked = asked;
        ui.model.startQuiz(asked);
    }
}

// The five choices, one under the other, the full width: large targets, names never cut.
void choiceButtons(Ui& ui, float height) {
    const float w = ImGui::GetContentRegionAvail().x;
    for (size_t k = 0; k < kQuizChoices.size(); ++k) {
        const Action a = kQuizChoices[k];
        ImGui::PushStyleColor(ImGuiCol_Button, toImVec4(palette::action(a)));
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0, 0, 0, 1));
        const std::string label = std::to_string(k + 1) + "  " + actionName(a);
        if (ImGui::Button(label.c_str(), ImVec2(w, height))) ui.model.answerQuiz(a);
        ImGui::PopStyleColor(2);
    }
}

void reveal(Ui& ui, int q, bool presenter) {
    Model& m = ui.model;
    const QuizSession& quiz = m.quiz();
    const Action truth = quiz.truth(size_t(q)), given = quiz.given(size_t(q));
    ImGui::Text("Question %d: it was", q + 1);
    ImGui::SameLine();
    ImGui::TextColored(toImVec4(palette::action(truth)), "%s", actionName(truth));
    ImGui::SameLine();
    if (quiz.correct(size_t(q))) ImGui::TextColored(toImVec4(palette::kOk), "- right!");
    else ImGui::TextColored(toImVec4(palette::kCulprit), "- you said %s", actionName(given));
    ImGui::TextDisabled("decided by (Fig. 9):");
    const Event& e = m.trace().events[quiz.event(size_t(q))];
    for (const QuizPredicate& p : decidingPredicates(e)) {
        ImGui::Bullet();
        ImGui::TextUnformatted(testText(p.test));
        ImGui::SameLine();
        ImGui::TextColored(toImVec4(p.answer ? palette::tree().yes : palette::tree().no), "%s",
                           p.answer ? "yes" : "no");
    }
    // The lit path: the Decision panel shows it beside; presenter view has no Decision panel.
    if (presenter) {
        const float h = std::max(ImGui::GetContentRegionAvail().y - ImGui::GetFrameHeight(),
                                 float(6 * decisionTree().rows) * ui.scale);
        drawDecisionTree(ui, ImVec2(ImGui::GetContentRegionAvail().x, h), decisionPath(e));
    }
}

}  // namespace

bool quizShortcuts(Ui& ui) {
    ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureKeyboard || io.WantTextInput || io.KeyCtrl) return false;
    if (ImGui::IsKeyPressed('Q', false)) toggleQuiz(ui);
    if (ui.model.pendingQuestion() < 0) return false;
    // Digits and the actions' initials, as keys (GLFW's key codes are the ASCII capitals).
    for (char key : std::string("12345RBSJF"))
        if (ImGui::IsKeyPressed(key, false)) {
            ui.model.answerQuiz(quizChoiceOfKey(key));
            return true;
        }
    return false;
}

void drawQuiz(Ui& ui) {
    Model& m = ui.model;
    ui.quizBox = {};
    if (!m.quizOn()) return;
    // Tiled, never over the canvas: the right column in place of the Events and Transcript
    // panels (which list the steps to come), or in presenter view the column main carved out
    // of the canvas, in the caption's font.
    const bool presenter = ui.presenter;
    beginTiled("Quiz: predict the next action", presenter ? ui.quizColumn : ui.layout.right);
    if (presenter && ui.captionFont) ImGui::PushFont(ui.captionFont);
    const QuizSession& quiz = m.quiz();
    ImGui::Text("Score %zu / %zu", quiz.score(), quiz.answeredCount());
    ImGui::SameLine();
    if (ImGui::SmallButton("Stop (Q)")) m.stopQuiz();
    ImGui::TextDisabled("%zu questions: %s", quiz.size(), quizActionsText(quiz.asked()).c_str());
    if (!presenter) askedBoxes(ui);
    ImGui::Separator();
    ImGui::PushTextWrapPos(0);
    if (const int q = m.pendingQuestion(); q >= 0) {
        ImGui::Text("Question %d of %zu, step %u: which action comes next?", q + 1, quiz.size(),
                    m.step() + 1);
        choiceButtons(ui, ImGui::GetFrameHeight() * 1.4f);
        ImGui::TextDisabled("keys 1-5 or R B S J F");
        const uint64_t key = m.generation() << 32 | m.step();
        if (ui.quizPrompt.first != key)
            ui.quizPrompt = {key, quizPrompt(m.polygon(), m.trace().events, m.step(), m.classes())};
        if (!presenter) ImGui::TextDisabled("%s", ui.quizPrompt.second.c_str());
    } else if (const int r = m.revealedQuestion(); r >= 0) {
        reveal(ui, r, presenter);
        ImGui::TextDisabled("Right: on to the next question");
    } else if (quiz.questionOf(m.step()) < 0 &&
               (quiz.size() == 0 || m.step() > quiz.event(quiz.size() - 1))) {
        ImGui::Text("No question ahead: %zu of %zu answered, %zu right.", quiz.answeredCount(),
                    quiz.size(), quiz.score());
    } else {
        ImGui::TextDisabled("Right or Space: on to the next question");
    }
    ImGui::PopTextWrapPos();
    if (presenter && ui.captionFont) ImGui::PopFont();
    ui.quizBox = windowRect();
    ImGui::End();
}

}  // namespace flood::view
