// ImGui's look: the default font rasterised again at the UI scale's pixel size (sharp at any
// scale, unlike FontGlobalScale's stretched glyphs), a larger one for the presenter's
// caption, and the style's sizes and colours for the scale and the current theme.
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "panels.h"

namespace flood::view {

void applyStyle(Ui& ui) {
    ImGuiIO& io = ImGui::GetIO();
    // Before the first frame the backend creates the texture itself; after, it is uploaded
    // again here. Asked first: building the atlas forgets the texture's id.
    const bool uploaded = io.Fonts->TexID != nullptr;
    io.Fonts->Clear();
    ImFontConfig body;
    body.SizePixels = ui.uiScale.fontPixels(13);
    io.Fonts->AddFontDefault(&body);
    ImFontConfig caption;
    caption.SizePixels = ui.uiScale.fontPixels(20);
    ui.captionFont = io.Fonts->AddFontDefault(&caption);
    io.Fonts->Build();
    if (uploaded) {
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
    }
    // From the defaults each time: ScaleAllSizes multiplies what is there.
    ImGuiStyle style;
    if (palette::theme() == Theme::Light) ImGui::StyleColorsLight(&style);
    else ImGui::StyleColorsDark(&style);
    style.ScaleAllSizes(ui.uiScale.value());
    ImGui::GetStyle() = style;
}

}  // namespace flood::view
