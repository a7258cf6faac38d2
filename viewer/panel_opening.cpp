// An open under way (Model::openInBackground): a box over the top of the canvas with the
// file, a progress bar naming the phase, and Cancel. The outline, once read, is drawn below
// it and pans and zooms as any polygon does.
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "panels.h"

namespace flood::view {

void drawOpening(Ui& ui) {
    Model& m = ui.model;
    if (!m.opening()) {
        ui.openingBox = {};
        return;
    }
    const Rect& c = ui.layout.canvas;
    const float s = ui.scale;
    const float width = float(std::min(c.w - 16.0 * s, 460.0 * s));
    // Below the canvas's find and Edit boxes, clear of them.
    const double top = std::max(ui.findBox.y + ui.findBox.h, ui.editBox.y + ui.editBox.h);
    ImGui::SetNextWindowPos(ImVec2(float(c.x + c.w / 2), float(std::max(c.y, top) + 8 * s)),
                            ImGuiCond_Always, ImVec2(0.5f, 0));
    ImGui::SetNextWindowSize(ImVec2(width, 0), ImGuiCond_Always);
    ImGui::Begin("##opening", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
    const std::string& path = m.openingPath();
    ImGui::TextUnformatted(("Opening " + path.substr(path.find_last_of('/') + 1)).c_str());
    const uint32_t total = std::max<uint32_t>(1, m.openTotal());
    const float done = float(std::min(m.openProgress(), total)) / float(total);
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%s %d%%", openPhaseName(m.openPhase()),
                  int(done * 100));
    const float cancelW = ImGui::CalcTextSize("Cancel").x + 2 * ImGui::GetStyle().FramePadding.x;
    ImGui::ProgressBar(done, ImVec2(-cancelW - ImGui::GetStyle().ItemSpacing.x, 0), overlay);
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
        m.cancelOpen();
        ui.message = "cancelled opening " + path;
    }
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    ui.openingBox = {pos.x, pos.y, size.x, size.y};
    ImGui::End();
}

}  // namespace flood::view
