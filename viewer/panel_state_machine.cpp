// The flood machine of §4 as a graph: six states (Fig. 10: R, B, S, J, F and the forbidden X)
// as pills on an ellipse. Every transition that occurs in the trace is drawn faintly with its count; the
// last one taken is drawn bold, and the current state filled.
#include <imgui.h>

#include <algorithm>
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

const char* nodeName(Action a, bool letter) { return letter ? actionLetter(a) : actionName(a); }

// How far from a pill's centre its outline is along the unit direction (ux, uy).
float pillReach(ImVec2 half, float ux, float uy) {
    const float ax = std::abs(ux), ay = std::abs(uy);
    return std::min(ax > 1e-6f ? half.x / ax : 1e9f, ay > 1e-6f ? half.y / ay : 1e9f);
}

// An arrow from pill a to pill b (half sizes ha, hb), from outline to outline.
void arrow(ImDrawList* dl, ImVec2 a, ImVec2 ha, ImVec2 b, ImVec2 hb, ImU32 col, float thick) {
    float dx = b.x - a.x, dy = b.y - a.y, len = std::sqrt(dx * dx + dy * dy);
    if (len < 1) return;
    float ux = dx / len, uy = dy / len;
    const float from = pillReach(ha, ux, uy) + 2, to = pillReach(hb, ux, uy) + 2;
    if (len < from + to + 1) return;
    // Offset sideways so A->B and B->A do not overlap.
    float ox = -uy * 4, oy = ux * 4;
    ImVec2 s(a.x + ux * from + ox, a.y + uy * from + oy), e(b.x - ux * to + ox, b.y - uy * to + oy);
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
    // Each state is a pill around its name, so no name crosses its outline; the pills sit on
    // an ellipse as wide as the panel allows with the widest pill inside it (in a short panel
    // a circle would put the names on top of one another).
    // A panel too narrow for the names (a large UI scale) shows the paper's letters (Fig. 10)
    // rather than cut them: the side pills must clear each other and the panel's edges.
    const float padX = 6 * ui.scale, padY = 3 * ui.scale;
    ImVec2 half[kNodeCount];
    float widest = 0;
    bool letters = false;
    auto measure = [&] {
        widest = 0;
        for (int i = 0; i < kNodeCount; ++i) {
            const ImVec2 ts = ImGui::CalcTextSize(nodeName(kNodes[i], letters));
            half[i] = ImVec2(ts.x / 2 + padX, ts.y / 2 + padY);
            widest = std::max(widest, half[i].x);
        }
    };
    measure();
    if (avail.x < 4.4f * widest + 4) letters = true, measure();
    const float tall = half[0].y;
    const float Rx = std::max(widest, avail.x / 2 - widest - 2);
    // The side pills clear the top and bottom ones: they sit half the radius lower, which
    // must be a pill's height and a gap.
    const float Ry = std::max(side * 0.36f, 4 * tall + 6);
    side = std::max(side, 2 * Ry + 2 * tall + 4);
    ImVec2 c(origin.x + avail.x / 2, origin.y + side / 2);
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
            arrow(dl, pos[a], half[a], pos[b], half[b], IM_COL32(120, 120, 130, 140), 1);
            ImVec2 mid((pos[a].x * 0.6f + pos[b].x * 0.4f), (pos[a].y * 0.6f + pos[b].y * 0.4f));
            dl->AddText(mid, IM_COL32(150, 150, 160, 255), std::to_string(n).c_str());
        }
    if (from >= 0 && to >= 0 && from != to)
        arrow(dl, pos[from], half[from], pos[to], half[to], ImGui::GetColorU32(ImGuiCol_Text),
              3);  // the theme's ink
    for (int i = 0; i < kNodeCount; ++i) {
        Rgba color = palette::action(kNodes[i]);
        bool active = i == to;
        const ImVec2 p0(pos[i].x - half[i].x, pos[i].y - half[i].y),
            p1(pos[i].x + half[i].x, pos[i].y + half[i].y);
        if (active) dl->AddRectFilled(p0, p1, toImU32(color), half[i].y);
        else dl->AddRectFilled(p0, p1, ImGui::GetColorU32(ImGuiCol_WindowBg), half[i].y);
        dl->AddRect(p0, p1, toImU32(color), half[i].y, 0, active ? 3.f : 1.5f);
        if (active && from == to)  // a self-loop (Raise after Raise): a ring around the node
            dl->AddRect(ImVec2(p0.x - 4, p0.y - 4), ImVec2(p1.x + 4, p1.y + 4),
                        ImGui::GetColorU32(ImGuiCol_Text), half[i].y + 4, 0, 2);
        const char* name = nodeName(kNodes[i], letters);
        const ImVec2 ts = ImGui::CalcTextSize(name);
        dl->AddText(ImVec2(pos[i].x - ts.x / 2, pos[i].y - ts.y / 2),
                    active ? IM_COL32(0, 0, 0, 255) : ImGui::GetColorU32(ImGuiCol_Text), name);
    }
    ui.stateDiagram = {origin.x, origin.y, avail.x, side};
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
