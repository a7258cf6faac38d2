// Every event of the log in a table. Long traces stay cheap: ImGuiListClipper submits only
// the visible rows.
#include <imgui.h>

#include "panels.h"

namespace flood::view {

namespace {
const char* vname(Index v, char* buf, size_t n) {
    if (v == kNone) return "-";
    snprintf(buf, n, "%u", v);
    return buf;
}
}  // namespace

void drawEvents(Ui& ui) {
    Model& m = ui.model;
    const Rect& col = ui.layout.right;
    beginTiled("Events", {col.x, col.y, col.w, col.h * 0.6});
    const auto& ev = m.trace().events;
    const ImGuiTableFlags flags = ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg |
                                  ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    if (ImGui::BeginTable("events", 7, flags)) {
        ImGui::TableSetupScrollFreeze(0, 1);
        ImGui::TableSetupColumn("step");
        ImGui::TableSetupColumn("action");
        ImGui::TableSetupColumn("L");
        ImGui::TableSetupColumn("R");
        ImGui::TableSetupColumn("NL");
        ImGui::TableSetupColumn("NR");
        ImGui::TableSetupColumn("triangles", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableHeadersRow();
        float rowH = ImGui::GetTextLineHeightWithSpacing();
        // Follow the current step when it changed elsewhere (timeline, keys, play).
        if (ui.eventsScrolledTo != m.step() && m.step() > 0) {
            float y = (m.step() - 1) * rowH;
            float top = ImGui::GetScrollY(), h = ImGui::GetWindowHeight() - 2 * rowH;
            if (y < top || y > top + h) ImGui::SetScrollY(y - h / 2);
            ui.eventsScrolledTo = m.step();
        }
        ImGuiListClipper clipper;
        clipper.Begin(int(ev.size()), rowH);
        while (clipper.Step()) {
            for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
                const Event& e = ev[size_t(i)];
                char b[4][16];
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                char label[32];
                snprintf(label, sizeof label, "%d", i + 1);
                if (ImGui::Selectable(label, uint32_t(i + 1) == m.step(),
                                      ImGuiSelectableFlags_SpanAllColumns |
                                          ImGuiSelectableFlags_AllowItemOverlap)) {
                    m.seek(uint32_t(i + 1));
                    ui.eventsScrolledTo = m.step();  // the user scrolled here: do not jump
                }
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip("%s", describeEvent(m.trace().polygon, e).c_str());
                ImGui::TableNextColumn();
                ImGui::TextColored(toImVec4(palette::action(e.action)), "%s", actionName(e.action));
                ImGui::TableNextColumn();
                clickable(ui, vname(e.after.left, b[0], 16), 'v');
                ImGui::TableNextColumn();
                clickable(ui, vname(e.after.right, b[1], 16), 'v');
                ImGui::TableNextColumn();
                clickable(ui, vname(e.after.nextLeft, b[2], 16), 'v');
                ImGui::TableNextColumn();
                clickable(ui, vname(e.after.nextRight, b[3], 16), 'v');
                ImGui::TableNextColumn();
                if (e.triangleCount) clickableRange(ui, e.firstTriangle, e.triangleCount, 't');
            }
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace flood::view
