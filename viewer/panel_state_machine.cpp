// The flood machine of §4 as a graph: six states (Fig. 10: R, B, S, J, F and the forbidden X)
// on a circle. Every transition that occurs in the trace is drawn faintly with its count; the
// last one taken is drawn bold, and the current state filled.
#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "panels.h"

namespace flood::view {

namespace {

constexpr Action kNodes[] = {Action::Raise, Action::Bridge, Action::Spill,
                             Action::Jump,  Action::Fill,   Action::Forbidden};
constexpr int kNodeCount = 6;

int nodeOf(Action a) {
    for (int i = 0; i < kNodeCount; ++i)
        if (kNodes[i] == a) return i;
    return -1;  // Start is the entry, not a state
}

void arrow(ImDrawList* dl, ImVec2 a, ImVec2 b, float inset, ImU32 col, float thick) {
    float dx = b.x - a.x, dy = b.y - a.y, len = std::sqrt(dx * dx + dy * dy);
    if (len < 2 * inset + 1) return;
    float ux = dx / len, uy = dy / len;
    // Offset sideways so A->B and B->A do not overlap.
    float ox = -uy * 4, oy = ux * 4;
    ImVec2 s(a.x + ux * inset + ox, a.y + uy * inset + oy),
        e(b.x - ux * inset + ox, b.y - uy * inset + oy);
    dl->AddLine(s, e, col, thick);
    float hs = 4 + thick * 2;
    dl->AddTriangleFilled(e, ImVec2(e.x - ux * hs - uy * hs / 2, e.y - uy * hs + ux * hs / 2),
                          ImVec2(e.x - ux * hs + uy * hs / 2, e.y - uy * hs - ux * hs / 2), col);
}

// The step and the vertices and triangles of its event, each number clickable (find).
void where(Ui& ui, const Event& e) {
    const float gap = 10 * ui.scale;
    ImGui::TextDisabled("step");
    ImGui::SameLine(0, 4 * ui.scale);
    char step[16];
    std::snprintf(step, sizeof step, "%u", e.step + 1);
    clickable(ui, step, 's');
    ImGui::SameLine(0, gap);
    clickableVertex(ui, "at", e.culprit);
    if (e.culprit != kNone) ImGui::SameLine(0, gap);
    clickableVertex(ui, "and", e.culprit2);
    if (e.culprit2 != kNone) ImGui::SameLine(0, gap);
    if (e.triangleCount) {
        ImGui::TextDisabled("cut");
        ImGui::SameLine(0, 4 * ui.scale);
        clickableRange(ui, e.firstTriangle, e.triangleCount, 't');
    } else {
        ImGui::NewLine();
    }
    // The fingers after it, two to a line so a narrow column shows them whole.
    const char* names[] = {"Left", "Right", "NextLeft", "NextRight"};
    const Index fingers[] = {e.after.left, e.after.right, e.after.nextLeft, e.after.nextRight};
    for (int k = 0; k < 4; k += 2) {
        clickableVertex(ui, names[k], fingers[k]);
        if (fingers[k] != kNone && fingers[k + 1] != kNone) ImGui::SameLine(0, gap);
        clickableVertex(ui, names[k + 1], fingers[k + 1]);
    }
}

}  // namespace

void drawStateMachine(Ui& ui) {
    Model& m = ui.model;
    const Rect& col = ui.layout.left;
    beginTiled("State machine", {col.x, col.y, col.w, col.h * 0.38});
    const auto& ev = m.trace().events;
    const Event* cur = m.currentEvent();

    int from = -1, to = cur ? nodeOf(cur->action) : -1;
    if (m.step() >= 2) from = nodeOf(ev[m.step() - 2].action);

    ImDrawList* dl = ImGui::GetWindowDrawList();
    ImVec2 origin = ImGui::GetCursorScreenPos();
    ImVec2 avail = ImGui::GetContentRegionAvail();
    float textH = ImGui::GetTextLineHeightWithSpacing() * 6;  // button, state, step, 2 of fingers
    float side = std::max(40.f, std::min(avail.x, avail.y - textH));
    ImVec2 c(origin.x + avail.x / 2, origin.y + side / 2);
    float R = side * 0.36f, nodeR = std::max(12.f, side * 0.1f);
    // The states sit on an ellipse as wide as the panel: in a short panel a circle would put the
    // names on top of one another, and names are wider than they are tall.
    float widest = 0;
    for (Action a : kNodes) widest = std::max(widest, ImGui::CalcTextSize(actionName(a)).x);
    const float lineH = ImGui::GetTextLineHeight();
    const float Rx = std::max(R, avail.x / 2 - widest / 2 - 2);
    const float Ry = std::max(R, lineH * 1.05f);  // the side names clear the top and bottom ones
    side = std::max(side, 2 * Ry + lineH + 2);
    c.y = origin.y + side / 2;
    ImVec2 pos[kNodeCount];
    for (int i = 0; i < kNodeCount; ++i) {
        float a = float(-M_PI / 2 + 2 * M_PI * i / kNodeCount);
        pos[i] = ImVec2(c.x + Rx * std::cos(a), c.y + Ry * std::sin(a));
    }
    // Every transition between two states that occurs in the run, with its count.
    const Model::Transitions& counts = m.transitions();
    for (int a = 0; a < kNodeCount; ++a)
        for (int b = 0; b < kNodeCount; ++b) {
            const uint32_t n = counts[size_t(kNodes[a])][size_t(kNodes[b])];
            if (a == b || n == 0) continue;
            arrow(dl, pos[a], pos[b], nodeR, IM_COL32(120, 120, 130, 140), 1);
            ImVec2 mid((pos[a].x * 0.6f + pos[b].x * 0.4f), (pos[a].y * 0.6f + pos[b].y * 0.4f));
            dl->AddText(mid, IM_COL32(150, 150, 160, 255), std::to_string(n).c_str());
        }
    if (from >= 0 && to >= 0 && from != to)
        arrow(dl, pos[from], pos[to], nodeR, ImGui::GetColorU32(ImGuiCol_Text),
              3);  // the theme's ink
    for (int i = 0; i < kNodeCount; ++i) {
        Rgba color = palette::action(kNodes[i]);
        bool active = i == to;
        if (active) dl->AddCircleFilled(pos[i], nodeR, toImU32(color));
        dl->AddCircle(pos[i], nodeR, toImU32(color), 0, active ? 3.f : 1.5f);
        if (active && from == to)  // a self-loop (Raise after Raise): a ring around the node
            dl->AddCircle(pos[i], nodeR + 4, ImGui::GetColorU32(ImGuiCol_Text), 0, 2);
        const char* name = actionName(kNodes[i]);
        ImVec2 ts = ImGui::CalcTextSize(name);
        dl->AddText(ImVec2(pos[i].x - ts.x / 2, pos[i].y - ts.y / 2),
                    active ? IM_COL32(0, 0, 0, 255) : ImGui::GetColorU32(ImGuiCol_Text), name);
    }
    ImGui::Dummy(ImVec2(avail.x, side));
    if (ImGui::SmallButton("State table...")) ui.showStateTable = true;  // Fig. 10
    ImGui::SameLine();
    if (ImGui::SmallButton("Direction...")) ui.showDirection = true;  // the flood direction dial

    ImGui::PushTextWrapPos(0);
    if (!cur) {
        ImGui::TextDisabled("before Start: the water waits at the lowest bottom");
    } else if (cur->action == Action::Forbidden) {
        ImGui::TextColored(toImVec4(palette::kCulprit), "Forbidden (%s): %s",
                           forbiddenName(cur->reason), forbiddenText(cur->reason));
    } else {
        ImGui::TextColored(toImVec4(palette::action(cur->action)), "%s", actionName(cur->action));
        ImGui::SameLine();
        ImGui::TextDisabled("%s", actionMeaning(cur->action));
    }
    ImGui::PopTextWrapPos();
    if (cur) where(ui, *cur);
    ImGui::End();
}

}  // namespace flood::view
