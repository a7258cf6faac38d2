// Breakpoints (the conditions live in the model, which runs to them), the colour legend and
// what the canvas shows.
#include <imgui.h>

#include "panels.h"

namespace flood::view {

namespace {
void swatch(Rgba c, const char* text) {
    ImGui::ColorButton(text, toImVec4(c), ImGuiColorEditFlags_NoTooltip, ImVec2(12, 12));
    ImGui::SameLine();
    ImGui::TextUnformatted(text);
}
}  // namespace

void drawBreakpoints(Ui& ui) {
    Model& m = ui.model;
    const Rect& col = ui.layout.left;
    beginTiled("Breakpoints & legend", {col.x, col.y + col.h * 0.65, col.w, col.h * 0.35});
    // Edited as a copy, given back to the model when a widget changed it.
    Breakpoints b = m.breakpoints();
    bool changed = false;
    if (ImGui::Button("<< run back")) m.runToBreakpoint(-1);
    ImGui::SameLine();
    if (ImGui::Button("run >>")) {
        if (!m.runToBreakpoint(+1)) ui.message = "no breakpoint hit: stopped at the end";
    }
    ImGui::SameLine();
    if (ImGui::Button("clear")) b = Breakpoints{}, changed = true;
    for (int a = 1; a < int(Action::Count); ++a) {  // Start happens once per part: not useful
        changed |= ImGui::Checkbox(actionName(Action(a)), &b.actions[size_t(a)]);
        if (a % 3 != 0) ImGui::SameLine();
    }
    changed |= ImGui::Checkbox("any forbidden state", &b.forbidden);
    int v = b.vertex == kNone ? -1 : int(b.vertex);
    ImGui::SetNextItemWidth(90 * ui.scale);
    if (ImGui::InputInt("vertex becomes L/R/Next", &v))
        b.vertex = v < 0 ? kNone : Index(v), changed = true;
    int t = int(b.triangle);
    ImGui::SetNextItemWidth(90 * ui.scale);
    if (ImGui::InputInt("triangle is cut", &t)) b.triangle = t < 0 ? -1 : t, changed = true;
    if (changed) m.setBreakpoints(b);

    if (ImGui::CollapsingHeader("Legend", ImGuiTreeNodeFlags_DefaultOpen)) {
        swatch(palette::kBottom, "bottom"), ImGui::SameLine(), swatch(palette::kSag, "sag");
        ImGui::SameLine(), swatch(palette::kTop, "top"), ImGui::SameLine();
        swatch(palette::kCeiling, "ceiling"), ImGui::SameLine(),
            swatch(palette::kRegular, "regular");
        swatch(palette::kLeft, "Left"), ImGui::SameLine(), swatch(palette::kRight, "Right");
        ImGui::SameLine(), swatch(palette::kNextLeft, "NextLeft"), ImGui::SameLine();
        swatch(palette::kNextRight, "NextRight");
        swatch(palette::kChain, "active chain"), ImGui::SameLine();
        swatch(palette::kWaterLevel, "water level");
        swatch(palette::kWater, "flooded"), ImGui::SameLine(),
            swatch(palette::kCurrent, "just cut");
        ImGui::SameLine(), swatch(palette::kBridge, "bridge");
        swatch(palette::kJump, "jump pointer"), ImGui::SameLine();
        swatch(palette::kDormant, "pending/held gorge"), ImGui::SameLine();
        swatch(palette::kCulprit, "offender");
    }
    if (ImGui::CollapsingHeader("Show")) {
        SceneOptions& o = ui.sceneOptions;
        ImGui::Checkbox("vertex classes", &o.vertexClasses);
        ImGui::SameLine(), ImGui::Checkbox("triangle numbers", &o.triangleNumbers);
        ImGui::Checkbox("triangle edges", &o.triangleEdges);
        ImGui::SameLine(), ImGui::Checkbox("jump pointers", &o.jumps);
        ImGui::Checkbox("bridges", &o.bridges);
        ImGui::SameLine(), ImGui::Checkbox("pending/held gorges", &o.dormant);
        ImGui::Checkbox("vertex numbers", &o.vertexNumbers);
        ImGui::SameLine(), ImGui::Checkbox("current gorge only", &o.gorgeFocus);
        ImGui::Checkbox("step before (ghost)", &o.ghost);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the chain and fingers before the step, faint");
    }
    ImGui::End();
}

}  // namespace flood::view
