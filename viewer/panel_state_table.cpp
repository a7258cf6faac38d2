// The paper's Fig. 10 drawn live and whole: every vertex combination, as two grids (fingers
// apart, fingers meeting) of C's class against Next's, each cell listing the states the
// decision tree allows there (flood/teach/state_table.h, allowedStates) or X, a forbidden
// combination. A state the run reached shows its count and tints the cell; an allowed state
// never reached stays dim, the cell empty of colour; the current step's cell is outlined in its
// action's colour.
#include <imgui.h>

#include <algorithm>
#include <string>

#include "flood/teach/state_table.h"
#include "panels.h"

namespace flood::view {

namespace {

constexpr int kClasses = int(VertexClass::Count);

// Draws a cell's states: each allowed one (dim when not reached, else with its count in its
// action's colour), an X for a forbidden combination, and any state the run went to.
void drawCell(const StateTable& table, int row) {
    const uint8_t allowed = allowedStates(Combination::ofRow(row));
    const int x = columnOf(Action::Forbidden);
    bool first = true;
    for (int c = 0; c < StateTable::kColumns; ++c) {
        const Action a = kStateColumns[size_t(c)];
        const uint64_t n = table.count(row, c);
        const bool shown = (allowed >> c & 1) || n || (c == x && !allowed);
        if (!shown || a == Action::Start) continue;
        if (!first) ImGui::SameLine(0, 4);
        first = false;
        if (n) {
            ImGui::TextColored(toImVec4(palette::action(a)), "%s%llu", actionLetter(a),
                               static_cast<unsigned long long>(n));
        } else if (c == x) {
            ImGui::TextColored(toImVec4(palette::kCulprit), "X");
        } else {
            ImGui::TextDisabled("%s", actionLetter(a));
        }
    }
}

void drawGrid(const StateTable& table, bool meet, const StateCell* cur) {
    ImGui::TextUnformatted(meet ? "Fingers meet (C: Left; Next: where NextLeft and NextRight meet)"
                                : "Fingers apart (C: the end that acts; Next: its finger)");
    if (!ImGui::BeginTable(meet ? "fig10meet" : "fig10apart", kClasses + 1,
                           ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchSame))
        return;
    ImGui::TableSetupColumn("C \\ Next");
    for (int n = 0; n < kClasses; ++n) ImGui::TableSetupColumn(vertexClassName(VertexClass(n)));
    ImGui::TableHeadersRow();
    for (int c = 0; c < kClasses; ++c) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(vertexClassName(VertexClass(c)));
        for (int n = 0; n < kClasses; ++n) {
            ImGui::TableNextColumn();
            const int row = Combination{c, n, meet}.row();
            const bool forbidden = forbiddenCombination(row);
            const bool reached = table.rowTotal(row) > 0;
            // Reached: tinted; forbidden: a faint red; allowed, never reached: no colour.
            if (reached || forbidden) {
                Rgba tint = reached ? palette::kTreePath : palette::kCulprit;
                tint.a = reached ? 70 : 40;
                ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, toImU32(tint));
            }
            if (cur && cur->row == row) {
                const ImVec2 p = ImGui::GetCursorScreenPos();
                const float w = ImGui::GetContentRegionAvail().x, h = ImGui::GetTextLineHeight();
                ImGui::GetWindowDrawList()->AddRect(
                    ImVec2(p.x - 2, p.y - 1), ImVec2(p.x + w + 2, p.y + h + 1),
                    toImU32(palette::action(kStateColumns[size_t(cur->column)])), 0, 0, 2);
            }
            drawCell(table, row);
        }
    }
    ImGui::EndTable();
}

}  // namespace

void drawStateTable(Ui& ui) {
    ui.stateTableBox = {};
    if (!ui.showStateTable) return;
    Model& m = ui.model;
    // First shown in the canvas's bottom-right corner; over the canvas it counts as an overlay,
    // so a fit keeps the polygon clear of it (canvasOverlays).
    const float w = 560, h = 350, s = ui.scale;  // its two grids, no more
    const float dx = std::max(0.f, float(ui.layout.canvas.w) / s - w - 8),
                dy = std::max(0.f, float(ui.layout.canvas.h) / s - h - 8);
    if (!beginFloating(ui, "State table (Fig. 10)", &ui.showStateTable, w, h, dx, dy)) return;
    ui.stateTableBox = windowRect();
    const StateTable& table = m.stateTable();  // one scan of the log per opened trace
    const StateCell* cur =
        m.step() == 0 || m.step() > table.cellOf.size() ? nullptr : &table.cellOf[m.step() - 1];
    ImGui::PushTextWrapPos(0);
    ImGui::TextDisabled(
        "R raise, F fill, B bridge, S spill, J jump, X forbidden. A count: this run went there "
        "that often (tinted); dim: allowed, never reached; X alone: a forbidden combination.");
    ImGui::PopTextWrapPos();
    drawGrid(table, false, cur);
    ImGui::Spacing();
    drawGrid(table, true, cur);
    const int none = Combination{}.row();
    ImGui::TextDisabled(
        "No chain yet: Start %llu, forbidden before a chain %llu",
        static_cast<unsigned long long>(table.count(none, columnOf(Action::Start))),
        static_cast<unsigned long long>(table.count(none, columnOf(Action::Forbidden))));
    ImGui::End();
}

}  // namespace flood::view
