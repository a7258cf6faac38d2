// The run told like the caption of the paper's Fig. 7 ("Raise 0-7, Spill; ..."), flowing
// like text; the item holding the current step is highlighted, and clicking an item goes there.
#include <imgui.h>

#include "panels.h"
#include "transcript.h"

namespace flood::view {

void drawTranscript(Ui& ui) {
    Model& m = ui.model;
    const Rect& col = ui.layout.right;
    placeWindow({col.x, col.y + col.h * 0.6, col.w, col.h * 0.4});
    ImGui::Begin("Transcript", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    const auto& items = m.transcript();
    if (ImGui::SmallButton("Copy")) ImGui::SetClipboardText(transcript(m.trace().events).c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("(%zu items, %u events)", items.size(), m.steps());
    ImGui::BeginChild("text");
    uint32_t curEvent = m.step() == 0 ? ~0u : m.step() - 1;
    float right = ImGui::GetContentRegionAvail().x;
    float x = 0, spacing = ImGui::GetStyle().ItemSpacing.x;
    for (size_t i = 0; i < items.size(); ++i) {
        const TranscriptItem& it = items[i];
        ImVec2 size = ImGui::CalcTextSize(it.text.c_str());
        if (i > 0 && x + size.x <= right) ImGui::SameLine();
        else x = 0;
        x += size.x + spacing;
        bool current = curEvent >= it.firstEvent && curEvent <= it.lastEvent;
        ImGui::PushID(int(i));
        const Event& first = m.trace().events[it.firstEvent];
        ImGui::PushStyleColor(ImGuiCol_Text, toImVec4(palette::action(first.action)));
        if (ImGui::Selectable(it.text.c_str(), current, 0, size)) m.seek(it.lastEvent + 1);
        ImGui::PopStyleColor();
        if (current && ui.transcriptScrolledTo != m.step()) {
            ImGui::SetScrollHereY(0.5f);
            ui.transcriptScrolledTo = m.step();
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("steps %u-%u", it.firstEvent + 1, it.lastEvent + 1);
        ImGui::PopID();
    }
    ImGui::EndChild();
    ImGui::End();
}

}  // namespace flood::view
