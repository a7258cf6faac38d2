// Keys, the glossary of the paper's words as the viewer uses them, and the key handling
// itself so the two cannot drift apart.
#include <imgui.h>

#include "panels.h"
#include "platform_glfw.h"

namespace flood::view {

void handleShortcuts(Ui& ui) {
    ImGuiIO& io = ImGui::GetIO();
    // Stepping keys come from the platform's queue, one step per press however slow the
    // frame; the queue is drained even when a text field has the keys.
    std::vector<KeyPress> presses = platform::takeKeyPresses();
    // Keys belong to text fields and focused widgets first.
    if (io.WantCaptureKeyboard || io.WantTextInput) return;
    Model& m = ui.model;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space), false)) m.togglePlay();
    for (const KeyPress& k : presses) {
        if (k.key != platform::kKeyLeft && k.key != platform::kKeyRight) continue;
        int direction = k.key == platform::kKeyRight ? +1 : -1;
        m.setPlaying(false);
        if (k.shift) m.runToBreakpoint(direction);
        else direction > 0 ? m.stepForward() : m.stepBack();
    }
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Home), false)) m.first();
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_End), false)) m.last();
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_PageDown))) m.seekAction(ui.seekKind, +1);
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_PageUp))) m.seekAction(ui.seekKind, -1);
    const bool answered = quizShortcuts(ui);  // F answers a quiz question before it fits
    if (ImGui::IsKeyPressed(platform::kKeyF, false) && !io.KeyCtrl && !answered) m.requestFit();
    if (ImGui::IsKeyPressed(platform::kKeyF1, false)) ui.showHelp = !ui.showHelp;
    if (io.KeyCtrl && ImGui::IsKeyPressed('O', false)) ui.showOpen = true;
    for (ImWchar c : io.InputQueueCharacters)
        if (c == '?') ui.showHelp = !ui.showHelp;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
        ui.showHelp = false;
        ui.showOpen = false;
    }
    editShortcuts(ui);
}

void drawHelp(Ui& ui) {
    if (!ui.showHelp) return;
    if (!beginFloating(ui, "Help", &ui.showHelp, 520, 480, 40, 40)) return;
    static const char* const keys[][2] = {
        {"Space", "play / pause"},
        {"Left / Right", "one step back / forward"},
        {"Shift+Left / Right", "run back / forward to a breakpoint"},
        {"Home / End", "first / last step"},
        {"PageUp / PageDown", "previous / next event of the kind chosen in the timeline"},
        {"F",
         "fit the polygon in the canvas, clear of the boxes over it (a layout change refits "
         "until you zoom or pan)"},
        {"P",
         "Save PNG: the canvas alone, as <polygon>-step<N>.png in the last export's folder, "
         "else Pictures, else home"},
        {"F1 or ?", "this window"},
        {"Ctrl+O", "open a polygon or a trace (*.jsonl), or drop a file on the window"},
        {"E", "error view: frame the current finding's culprits (again: back)"},
        {"F8 / Shift+F8",
         "next / previous finding of a failing face, framed (the findings panel under the canvas; "
         "a click on a finding frames it too)"},
        {"Ctrl+F", "find and frame v<vertex>, t<triangle>, s<step>, r<ring>"},
        {"drag / wheel", "pan / zoom at the cursor"},
        {"timeline: click / wheel / right-drag", "go to the hovered step / zoom / pan the strip"},
        {"hover", "vertex or triangle details"},
        {"click a triangle", "go to the step that cut it"},
        {"right-click a vertex", "break when it becomes Left, Right, NextLeft or NextRight"},
        {"Q", "quiz: predict the next action (again: off); the Quiz panel chooses what is asked"},
        {"1-5 or R B S J F (quiz)", "answer: raise, bridge, spill, jump, fill"},
        {"Tab", "presenter view: only the canvas and a large caption (again: back)"},
        {"F11", "fullscreen on the window's monitor (again: back)"},
        {"Ctrl + / Ctrl - / Ctrl+0", "larger / smaller UI and fonts / back to 100%"},
        {"M",
         "edit mode: drag a vertex, double-click an edge to insert one, Delete removes the hovered "
         "one"},
        {"Shift+drag (edit mode)", "move the whole ring"},
        {"H (edit mode)",
         "new ring: click corners, Enter or the first corner closes (a hole inside, a part "
         "outside)"},
        {"Ctrl+Z / Ctrl+Shift+Z, Ctrl+Y", "undo / redo an edit"},
        {"Ctrl+S", "save the edited polygon as GeoJSON"},
        {"Ctrl+N", "new empty canvas: draw your own outer ring"},
    };
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
        for (auto& k : keys) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(k[0]);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(k[1]);
        }
        ImGui::EndTable();
    }
    ImGui::Separator();
    ImGui::PushTextWrapPos(0);
    ImGui::TextUnformatted(
        "Glossary (Ronfard & Rossignac 1994). The polygon is flooded from its lowest bottom; "
        "triangles are numbered in the order the water covers them.\n"
        "bottom / sag: convex / concave local minimum.  top / ceiling: concave / convex local "
        "maximum.\n"
        "gorge: a monotonic region being filled; its two sides are banks.\n"
        "active chain: the concave line from Left to Right at the water's surface. NextLeft "
        "precedes Left, NextRight follows Right (the fingers).\n"
        "Raise: the lower finger joins the chain and a wedge of triangles is cut.\n"
        "Bridge: a sag inside the gorge is joined to the chain; one half waits as a pending "
        "gorge.\n"
        "Spill: the water overflows a top; its jump pointer is set and a new gorge begins at "
        "the next unmatched bottom.\n"
        "Jump: the water reaches a top whose jump pointer is set, from its far side.\n"
        "Fill: NextLeft == NextRight; the gorge is closed with a fan.\n"
        "Forbidden: a state the machine cannot be in for valid input (Fig. 10, 11).");
    ImGui::PopTextWrapPos();
    ImGui::End();
}

}  // namespace flood::view
