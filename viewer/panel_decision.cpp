// The decision path of the current event: which tests of the Fig. 9 tree ran, in order, and
// how each came out, ending in the action taken; above them, the event narrated in a sentence.
#include <imgui.h>

#include "narrate.h"
#include "panels.h"

namespace flood::view {

void drawDecision(Ui& ui) {
    Model& m = ui.model;
    const Rect& col = ui.layout.left;
    placeWindow({col.x, col.y + col.h * 0.38, col.w, col.h * 0.27});
    ImGui::Begin("Decision", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    const Event* e = m.currentEvent();
    if (!e) {
        ImGui::TextDisabled("no event yet: step forward to see the decision tree at work");
        ImGui::End();
        return;
    }
    ImGui::PushTextWrapPos(0);
    // What happened and why, in one sentence of the flood metaphor (core/narrate.h).
    ImGui::TextUnformatted(narrate(m.polygon(), *e).c_str());
    ImGui::Separator();
    for (int i = 0; i < int(Test::Count); ++i) {
        Test t = Test(i);
        if (!e->didTest(t)) {
            ImGui::TextDisabled("  -  %s", testText(t));
            continue;
        }
        bool yes = e->testResult(t);
        ImGui::TextColored(yes ? ImVec4(0.5f, 0.95f, 0.5f, 1) : ImVec4(1, 0.55f, 0.45f, 1), "%s %s",
                           yes ? "yes" : "no ", testText(t));
    }
    ImGui::Separator();
    ImGui::TextColored(toImVec4(palette::action(e->action)), "=> %s (C is %s)",
                       actionName(e->action), e->side == Side::Left ? "Left" : "Right");
    if (e->sagTests) ImGui::TextDisabled("%u inside() tests against the sag list", e->sagTests);
    if (ImGui::SmallButton("Predicates...")) ui.showPredicates = true;
    if (e->action == Action::Forbidden)
        ImGui::TextColored(toImVec4(palette::kCulprit), "%s", forbiddenText(e->reason));
    ImGui::PopTextWrapPos();
    ImGui::End();
}

}  // namespace flood::view
