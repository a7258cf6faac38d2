// The flood direction dial: the paper's "chosen vertical" (§3) turned to any angle. Turning it
// floods the polygon again along the new direction (heights stay exact: flood/geometry/up.h) and
// shows how the decomposition changed against the direction before: the gorges, the vertex classes
// and each action (the decomposition into gorges is not unique). The floods go through the
// editor's (viewer/edit.h): in the background, one at a time, so dragging the dial over a
// large polygon skips the angles passed while a flood runs and the UI never waits for one.
#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "palette.h"
#include "panels.h"

namespace flood::view {

void drawDirection(Ui& ui) {
    if (!ui.showDirection) return;
    Model& m = ui.model;
    Editor& editor = ui.edit.editor;
    if (!beginFloating(ui, "Flood direction", &ui.showDirection, 330, 360, 60, 60)) return;
    const Up up = editor.up();  // the one asked for: the dial follows the mouse, not the flood
    float degrees = float(upDegrees(up));
    ImGui::TextDisabled("degrees counter-clockwise from +x; 90 is +y");
    ImGui::SetNextItemWidth(-1);
    if (ImGui::SliderFloat("##angle", &degrees, 0, 360, "%.1f°") &&
        std::fabs(degrees - upDegrees(up)) > 1e-4)
        editor.setUp(upFromDegrees(double(degrees)));
    const struct {
        const char* label;
        Up up;
    } axes[] = {{"+x", Up::PlusX}, {"+y", Up::PlusY}, {"-x", Up::MinusX}, {"-y", Up::MinusY}};
    for (const auto& a : axes) {
        if (a.up != axes[0].up) ImGui::SameLine();
        if (ImGui::Button(a.label)) editor.setUp(a.up);
    }
    ImGui::Text("up = %s", upName(up).c_str());
    if (!(m.up() == up)) {
        ImGui::SameLine();
        ImGui::TextDisabled("(flooding...)");
    }
    ImGui::Separator();
    const FloodSummary now = m.summary();
    if (!m.hasPreviousSummary()) {
        ImGui::TextWrapped("Turn the dial: the table compares each run with the one before.");
    }
    const FloodSummary& before = m.hasPreviousSummary() ? m.previousSummary() : now;
    if (ImGui::BeginTable("changes", 3,
                          ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("");
        ImGui::TableSetupColumn("before");
        ImGui::TableSetupColumn("now");
        ImGui::TableHeadersRow();
        for (const SummaryChange& c : compareSummaries(before, now)) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(c.what.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%lld", static_cast<long long>(c.before));
            ImGui::TableNextColumn();
            if (c.changed())
                ImGui::TextColored(toImVec4(palette::kCurrent), "%lld (%+lld)",
                                   static_cast<long long>(c.after),
                                   static_cast<long long>(c.after - c.before));
            else ImGui::Text("%lld", static_cast<long long>(c.after));
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace flood::view
