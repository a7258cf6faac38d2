// The flood direction dial: the paper's "chosen vertical" (§3) turned to any angle. Turning it
// floods the polygon again along the new direction (heights stay exact: flood/geometry/up.h) and
// shows how the decomposition changed against the direction before: the gorges, the vertex classes
// and each action (the decomposition into gorges is not unique). The floods go through the
// editor's (viewer/edit.h): in the background, one at a time, so dragging the dial over a
// large polygon skips the angles passed while a flood runs and the UI never waits for one.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "palette.h"
#include "panels.h"

namespace flood::view {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The round dial: a ring, the +x/+y/-x/-y ticks, an arrow from the centre the way the water
// rises; a press or drag anywhere on it turns the arrow to the pointer. Returns the degrees
// chosen this frame, or a negative number when the dial was not touched.
double dial(const Ui& ui, double degrees, float size) {
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##dial", ImVec2(size, size));
    const bool active = ImGui::IsItemActive();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("drag the arrow: the water rises that way");
    const ImVec2 c(at.x + size / 2, at.y + size / 2);
    const float r = size / 2 - 4 * ui.scale;
    double chosen = -1;
    if (active) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        const double dx = mouse.x - c.x, dy = c.y - mouse.y;  // screen y grows down
        if (dx * dx + dy * dy > 4) {
            chosen = std::atan2(dy, dx) * 180 / kPi;
            if (chosen < 0) chosen += 360;
            // Within 3 degrees of an axis: the axis, whose floods are exact and fast.
            const double axis = std::round(chosen / 90) * 90;
            if (std::fabs(chosen - axis) < 3) chosen = std::fmod(axis, 360);
            degrees = chosen;
        }
    }
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImU32 ring = toImU32(palette::kBoundary);
    dl->AddCircle(c, r, ring, 64, 1.5f * ui.scale);
    for (int k = 0; k < 4; ++k) {
        const double a = k * kPi / 2;
        const float ux = float(std::cos(a)), uy = -float(std::sin(a));
        dl->AddLine(ImVec2(c.x + ux * r * 0.85f, c.y + uy * r * 0.85f),
                    ImVec2(c.x + ux * r, c.y + uy * r), ring, 1.5f * ui.scale);
    }
    const double a = degrees * kPi / 180;
    const float ux = float(std::cos(a)), uy = -float(std::sin(a));
    const ImU32 arrow = toImU32(active ? palette::kHover : palette::kWaterLevel);
    const ImVec2 tip(c.x + ux * r * 0.8f, c.y + uy * r * 0.8f);
    const float head = 10 * ui.scale;
    dl->AddLine(c, tip, arrow, 3 * ui.scale);
    dl->AddTriangleFilled(ImVec2(tip.x + ux * head, tip.y + uy * head),
                          ImVec2(tip.x - uy * head * 0.6f, tip.y + ux * head * 0.6f),
                          ImVec2(tip.x + uy * head * 0.6f, tip.y - ux * head * 0.6f), arrow);
    dl->AddCircleFilled(c, 4 * ui.scale, arrow);
    return chosen;
}

}  // namespace

void drawDirection(Ui& ui) {
    ui.directionBox = {};
    if (!ui.showDirection) return;
    Model& m = ui.model;
    Editor& editor = ui.edit.editor;
    // First shown in the canvas's bottom-right corner; over the canvas it counts as an overlay,
    // so a fit keeps the polygon clear of it (canvasOverlays).
    const float w = 330, h = 360, s = ui.scale;
    const float dx = std::max(0.f, float(ui.layout.canvas.w) / s - w - 8),
                dy = std::max(0.f, float(ui.layout.canvas.h) / s - h - 8);
    if (!beginFloating(ui, "Flood direction", &ui.showDirection, w, h, dx, dy)) return;
    ui.directionBox = windowRect();
    const Up up = editor.up();  // the one asked for: the dial follows the mouse, not the flood
    float degrees = float(upDegrees(up));
    const double turned = dial(ui, degrees, 120 * s);
    if (turned >= 0 && std::fabs(turned - upDegrees(up)) > 1e-4)
        editor.setUp(upFromDegrees(turned));
    ImGui::SameLine();
    ImGui::BeginGroup();
    ImGui::TextDisabled("degrees from +x,\ncounter-clockwise");
    ImGui::SetNextItemWidth(110 * s);
    if (ImGui::InputFloat("##degrees", &degrees, 1, 15, "%.1f°",
                          ImGuiInputTextFlags_EnterReturnsTrue) &&
        std::fabs(degrees - upDegrees(up)) > 1e-4)
        editor.setUp(upFromDegrees(double(degrees)));
    const struct {
        const char* label;
        Up up;
    } axes[] = {{"+y", Up::PlusY}, {"+x", Up::PlusX}, {"-y", Up::MinusY}, {"-x", Up::MinusX}};
    for (int i = 0; i < 4; ++i) {
        if (i % 2) ImGui::SameLine();
        if (ImGui::Button(axes[i].label, ImVec2(52 * s, 0))) editor.setUp(axes[i].up);
    }
    ImGui::EndGroup();
    ImGui::TextWrapped("up = %s", upName(up).c_str());
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
