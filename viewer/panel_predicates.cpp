// The predicate inspector: for the current step, every test of the decision path with its
// predicate, arguments, floating-point value, exact result and the stage of the exact
// predicate that decided it (Model::inspection()). Hovering a row rings its arguments on
// the canvas, numbered in the predicate's order.
#include <imgui.h>

#include <cstdio>

#include "geometry/number_text.h"
#include "panels.h"

namespace flood::view {

namespace {
const char* testName(Test t) {
    static const char* const names[] = {
#define FLOOD_X(name, text) #name,
        FLOOD_TESTS(FLOOD_X)
#undef FLOOD_X
    };
    return t < Test::Count ? names[int(t)] : "?";
}
}  // namespace

void drawPredicates(Ui& ui) {
    ui.highlight.clear();
    if (!ui.showPredicates) return;
    Model& m = ui.model;
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImGui::GetIO().DisplaySize);  // fits at 2x
    ImGui::SetNextWindowSize(ImVec2(640 * ui.scale, 300 * ui.scale), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowPos(ImVec2(float(ui.layout.canvas.x + 20 * ui.scale),
                                   float(ui.layout.canvas.y + ui.layout.canvas.h * 0.55)),
                            ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Predicates", &ui.showPredicates)) {
        ImGui::End();
        return;
    }
    const std::vector<PredicateRow>& rows = m.inspection();
    if (rows.empty()) ImGui::TextDisabled("no decision at this step (Start, or no active chain)");
    const Polygon& p = m.polygon();
    if (!rows.empty() &&
        ImGui::BeginTable("predicates", 6,
                          ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders |
                              ImGuiTableFlags_Resizable | ImGuiTableFlags_ScrollY)) {
        ImGui::TableSetupScrollFreeze(0, 1);
        for (const char* h : {"test", "predicate", "arguments", "float value", "exact", "stage"})
            ImGui::TableSetupColumn(h);
        ImGui::TableHeadersRow();
        for (size_t i = 0; i < rows.size(); ++i) {
            const PredicateRow& r = rows[i];
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::PushID(int(i));
            bool hovered = false;
            ImGui::Selectable(r.test == Test::Count ? "  inside" : testName(r.test), false,
                              ImGuiSelectableFlags_SpanAllColumns);
            hovered = ImGui::IsItemHovered();
            ImGui::PopID();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(r.predicate.c_str());
            ImGui::TableNextColumn();
            for (Index v : r.args) {  // one line each: the number finds the vertex when clicked
                if (v >= p.vertices.size()) {
                    ImGui::TextUnformatted("-");
                    continue;
                }
                char num[16];
                std::snprintf(num, sizeof num, "%u", v);
                clickable(ui, num, 'v');
                ImGui::SameLine(0, 4 * ui.scale);
                ImGui::TextDisabled("%s", formatPoint(p.vertices[v]).c_str());
            }
            ImGui::TableNextColumn();
            if (r.hasValue) ImGui::Text("%.6g", r.value);
            else ImGui::TextDisabled("-");
            ImGui::TableNextColumn();
            bool mismatch = r.hasRecorded && r.recorded != r.result;
            ImVec4 colour = mismatch   ? toImVec4(palette::kCulprit)
                            : r.result ? ImVec4(0.5f, 0.95f, 0.5f, 1)
                                       : ImVec4(1, 0.55f, 0.45f, 1);
            if (r.hasValue) ImGui::TextColored(colour, "%+d: %s", r.sign, r.result ? "yes" : "no");
            else ImGui::TextColored(colour, "%s", r.result ? "yes" : "no");
            if (mismatch) ImGui::TextColored(colour, "recorded %s", r.recorded ? "yes" : "no");
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(r.stage.c_str());
            if (hovered) ui.highlight = r.args;
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace flood::view
