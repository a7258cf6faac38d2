// Presenter mode: Tab shows only the canvas and this caption (the step, the action's name in
// its colour, the narration sentence, in a large font); F11 fullscreen; Ctrl +/-/0 scale;
// P saves the canvas as a PNG.
#include <imgui.h>

#include "panels.h"
#include "platform_glfw.h"

namespace flood::view {

void handlePresenterKeys(Ui& ui) {
    ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsKeyPressed(platform::kKeyF11, false)) platform::toggleFullscreen();
    auto pressed = [](const int(&keys)[2]) {
        return ImGui::IsKeyPressed(keys[0]) || ImGui::IsKeyPressed(keys[1]);
    };
    bool zoomed = false;
    if (io.KeyCtrl && pressed(platform::kKeyPlus)) zoomed = ui.uiScale.zoomIn();
    if (io.KeyCtrl && pressed(platform::kKeyMinus)) zoomed = ui.uiScale.zoomOut();
    if (io.KeyCtrl && pressed(platform::kKeyZero)) zoomed = ui.uiScale.resetZoom();
    if (zoomed)
        ui.message = "UI scale " + std::to_string(int(ui.uiScale.zoom() * 100 + 0.5f)) + "%";
    // A text field keeps its Tab. The camera keeps its centre and zoom, so Tab twice gives
    // back the same view (F fits the polygon to the larger canvas).
    if (!io.WantTextInput && !io.KeyCtrl && ImGui::IsKeyPressed(platform::kKeyTab, false))
        ui.presenter = !ui.presenter;
    // P: Save PNG, in either view (the canvas alone: what the class sees).
    if (!io.WantTextInput && !io.KeyCtrl && ImGui::IsKeyPressed('P', false)) requestSavePng(ui);
}

void drawCaption(Ui& ui) {
    const Rect& r = ui.layout.bottom;
    // A caption taller than half the window (a long sentence at a large zoom) scrolls.
    beginTiled("##caption", {r.x, r.y, r.w, std::max(r.h, 1.0)},
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing);
    const Caption c = buildCaption(ui.model);
    if (ui.captionFont) ImGui::PushFont(ui.captionFont);
    ImGui::TextUnformatted(c.heading.c_str());
    if (c.hasAction) {
        ImGui::SameLine();
        ImGui::TextColored(toImVec4(palette::action(c.action)), "%s", actionName(c.action));
    }
    ImGui::PushTextWrapPos(0);
    ImGui::TextUnformatted(c.sentence.c_str());
    ImGui::PopTextWrapPos();
    if (ui.captionFont) ImGui::PopFont();
    // The layout gives the caption this much next frame: all of it, never clipped.
    const ImGuiStyle& style = ImGui::GetStyle();
    ui.captionHeight = ImGui::GetCursorPosY() - style.ItemSpacing.y + style.WindowPadding.y;
    ImVec2 p = ImGui::GetWindowPos(), s = ImGui::GetWindowSize();
    ui.captionRect = {p.x, p.y, s.x, s.y};
    ImGui::End();
}

}  // namespace flood::view
