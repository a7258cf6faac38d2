// The paper's Fig. 10 drawn live: the vertex combinations the run met (classes of C and Next,
// fingers meeting) against the states R F B S J X, each cell's count over the whole trace, and
// the cell of the current step lit. The table itself is core/teach/state_table.h.
#include <imgui.h>

#include <string>

#include "flood/teach/state_table.h"
#include "panels.h"

namespace flood::view {

namespace {
const char* className(int c) { return c == kNoClass ? "-" : vertexClassName(VertexClass(c)); }
}  // namespace

void drawStateTable(Ui& ui) {
    if (!ui.showStateTable) return;
    Model& m = ui.model;
    if (!beginFloating(ui, "State table (Fig. 10)", &ui.showStateTable, 520, 320, 40, 40)) return;
    const StateTable& table = m.stateTable();  // one scan of the log per opened trace
    const StateCell* cur =
        m.step() == 0 || m.step() > table.cellOf.size() ? nullptr : &table.cellOf[m.step() - 1];
    ImGui::TextDisabled("C: the end of the chain that acts; Next: its finger; rows the run met");
    constexpr int kLead = 3;
    if (ImGui::BeginTable("fig10", kLead + StateTable::kColumns,
                          ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders |
                              ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupScrollFreeze(0, 1);
        ImGui::TableSetupColumn("C");
        ImGui::TableSetupColumn("Next");
        ImGui::TableSetupColumn("meet");
        for (Action a : kStateColumns) ImGui::TableSetupColumn(actionLetter(a));
        ImGui::TableHeadersRow();
        for (int r = 0; r < StateTable::kRows; ++r) {
            bool curRow = cur && cur->row == r;
            if (table.rowTotal(r) == 0 && !curRow) continue;
            Combination k = Combination::ofRow(r);
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(className(k.c));
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(className(k.next));
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(k.meet ? "yes" : "no");
            for (int c = 0; c < StateTable::kColumns; ++c) {
                ImGui::TableNextColumn();
                uint64_t n = table.count(r, c);
                if (curRow && cur->column == c)
                    ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg,
                                           toImU32(palette::action(kStateColumns[size_t(c)])));
                if (n) ImGui::Text("%llu", static_cast<unsigned long long>(n));
            }
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace flood::view
