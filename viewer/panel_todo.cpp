// The to-do list of §4 at the current step (flood/teach/todo_list.h): the pending gorges in stack
// order, the next to be flooded first, and the held gorges with their tops and jump pointers.
// Clicking one brings it into view and draws its chain and top on the canvas until another is
// chosen, the window closes, or the step no longer has it.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "panels.h"

namespace flood::view {

namespace {

// The chosen gorge's chain (and top) over the canvas.
void drawChosen(Ui& ui, const Gorge& g) {
    const Model& m = ui.model;
    const auto& v = m.polygon().vertices;
    const Rect& area = ui.layout.canvas;
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    dl->PushClipRect(ImVec2(float(area.x), float(area.y)),
                     ImVec2(float(area.x + area.w), float(area.y + area.h)), true);
    const float s = ui.scale;
    const ImU32 colour = toImU32(g.held ? palette::kJump : palette::kDormant);
    std::vector<ImVec2> pts;
    for (Index i : g.chain) {
        if (i >= v.size()) continue;
        Vec2 p = m.camera().toScreen(v[i]);
        pts.emplace_back(float(p.x), float(p.y));
    }
    if (pts.size() > 1) dl->AddPolyline(pts.data(), int(pts.size()), colour, 0, 4 * s);
    for (const ImVec2& p : pts) dl->AddCircleFilled(p, 3.5f * s, colour);
    if (g.top < v.size()) {
        Vec2 p = m.camera().toScreen(v[g.top]);
        dl->AddCircle(ImVec2(float(p.x), float(p.y)), 11 * s, colour, 0, 3 * s);
    }
    dl->PopClipRect();
}

// Centres the view on the gorge's chain and top; zooms out only if they do not fit.
void bringIntoView(Ui& ui, const Gorge& g) {
    Model& m = ui.model;
    const auto& v = m.polygon().vertices;
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    auto add = [&](Index i) {
        if (i >= v.size() || !std::isfinite(v[i].x) || !std::isfinite(v[i].y)) return;
        x0 = std::min(x0, v[i].x), x1 = std::max(x1, v[i].x);
        y0 = std::min(y0, v[i].y), y1 = std::max(y1, v[i].y);
    };
    for (Index i : g.chain) add(i);
    add(g.top);
    if (!(x0 <= x1)) return;
    const Rect& vp = m.camera().viewport();
    const double scale = m.camera().scale();
    if ((x1 - x0) * scale > vp.w * 0.9 || (y1 - y0) * scale > vp.h * 0.9) m.fitBox(x0, y0, x1, y1);
    else m.centerOn({(x0 + x1) / 2, (y0 + y1) / 2});
    m.keepView();
}

// One row: the gorge, its chain's ends and (held) its top and jump pointer; the vertex numbers
// find their vertex, the rest of the row chooses the gorge.
void row(Ui& ui, const ReplayState& st, const TodoEntry& t, int position, bool held) {
    const Gorge& g = st.dormant[t.dormant];
    ImGui::PushID(int(t.gorge));
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    char label[32];
    std::snprintf(label, sizeof label, "%d. gorge %u", position, t.gorge);
    if (ImGui::Selectable(label, ui.todoGorge == t.gorge, ImGuiSelectableFlags_SpanAllColumns)) {
        ui.todoGorge = t.gorge;
        bringIntoView(ui, g);
    }
    auto vertex = [&](Index i) {
        ImGui::TableNextColumn();
        char num[16];
        if (i == kNone) std::snprintf(num, sizeof num, "-");
        else std::snprintf(num, sizeof num, "%u", i);
        clickable(ui, num, 'v');
    };
    vertex(t.left);
    vertex(t.right);
    ImGui::TableNextColumn();
    ImGui::Text("%zu", g.chain.size());
    if (held) {
        vertex(t.top);
        vertex(t.jumpTarget);
    }
    ImGui::PopID();
}

bool table(Ui& ui, const char* id, const ReplayState& st, const std::vector<TodoEntry>& list,
           bool held) {
    if (list.empty()) return false;
    const int columns = held ? 6 : 4;
    if (!ImGui::BeginTable(
            id, columns,
            ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit))
        return false;
    for (const char* h : {"gorge", "Left", "Right", "chain"}) ImGui::TableSetupColumn(h);
    if (held) ImGui::TableSetupColumn("top"), ImGui::TableSetupColumn("jump to");
    ImGui::TableHeadersRow();
    ImGuiListClipper clip;  // thousands of gorges may wait at once
    clip.Begin(int(list.size()));
    while (clip.Step())
        for (int i = clip.DisplayStart; i < clip.DisplayEnd; ++i)
            row(ui, st, list[size_t(i)], i + 1, held);
    ImGui::EndTable();
    return true;
}

}  // namespace

void drawTodo(Ui& ui) {
    if (!ui.showTodo) {
        ui.todoGorge = kNone;
        return;
    }
    const ReplayState& st = ui.model.state();
    // Read once per step: thousands of gorges may wait at once.
    if (ui.todoFor != std::array<uint64_t, 2>{ui.model.generation(), ui.model.step()}) {
        ui.todo = todoList(st);
        ui.todoFor = {ui.model.generation(), ui.model.step()};
    }
    const TodoList& list = ui.todo;
    // The chosen gorge, while this step still has it.
    const Gorge* chosen = nullptr;
    for (const Gorge& g : st.dormant)
        if (g.id == ui.todoGorge) chosen = &g;
    if (chosen) drawChosen(ui, *chosen);
    // First shown in the canvas's lower right corner, clear of the middle where gorges are.
    const float w = 420, h = 260, s = std::max(ui.scale, 0.01f);
    const float dx = std::max(0.0f, float(ui.layout.canvas.w) / s - w - 10),
                dy = std::max(0.0f, float(ui.layout.canvas.h) / s - h - 10);
    if (!beginFloating(ui, "To-do list", &ui.showTodo, w, h, dx, dy)) return;
    ImGui::TextDisabled("step %u: %zu pending, %zu held; click a gorge to see it", ui.model.step(),
                        list.pending.size(), list.held.size());
    ImGui::Separator();
    ImGui::TextUnformatted("Pending (Bridge halves), next to flood first");
    if (!table(ui, "pending", st, list.pending, false)) ImGui::TextDisabled("none");
    ImGui::Separator();
    ImGui::TextUnformatted("Held at a top (Spill), latest first");
    if (!table(ui, "held", st, list.held, true)) ImGui::TextDisabled("none");
    ImGui::End();
}

}  // namespace flood::view
