// The run told like the caption of the paper's Fig. 7 ("Raise 0-7, Spill; ..."), flowing
// like text with the paper's ", " and "; " between items (the core's, flood/teach/transcript.h); the
// item holding the current step is highlighted, and clicking an item goes there.
#include <imgui.h>

#include <algorithm>
#include <vector>

#include "flood/teach/transcript.h"
#include "panels.h"

namespace flood::view {

void drawTranscript(Ui& ui) {
    Model& m = ui.model;
    const Rect& col = ui.layout.right;
    beginTiled("Transcript", {col.x, col.y + col.h * 0.6, col.w, col.h * 0.4});
    const auto& items = m.transcript();
    if (ImGui::SmallButton("Copy")) ImGui::SetClipboardText(transcript(items).c_str());
    ui.transcriptCopy = itemRect();
    ImGui::SameLine();
    ImGui::TextDisabled("(%zu items, %u events)", items.size(), m.steps());
    ImGui::BeginChild("text");
    uint32_t curEvent = m.step() == 0 ? ~0u : m.step() - 1;
    float right = ImGui::GetContentRegionAvail().x;
    // The text flows into lines; lay them out once per trace and width, then submit only the
    // visible lines, so a million-event transcript scrolls like a short one.
    TranscriptLines& laid = ui.transcriptLines;
    std::vector<uint32_t>& lineStart = laid.start;
    if (laid.generation != m.generation() || laid.width != right) {
        lineStart.clear();
        float x = 0;
        for (size_t i = 0; i < items.size(); ++i) {
            float w = ImGui::CalcTextSize((items[i].text + items[i].separator).c_str()).x;
            if (i == 0 || x + w > right) lineStart.push_back(uint32_t(i)), x = 0;
            x += w;  // the separator carries the space: items touch, like text
        }
        lineStart.push_back(uint32_t(items.size()));
        laid.generation = m.generation(), laid.width = right;
    }
    const float lineH = ImGui::GetTextLineHeightWithSpacing();
    auto current =
        std::upper_bound(items.begin(), items.end(), curEvent,
                         [](uint32_t e, const TranscriptItem& it) { return e < it.firstEvent; });
    if (current != items.begin() && ui.transcriptScrolledTo != m.step()) {
        size_t item = size_t(current - items.begin()) - 1;
        size_t line =
            size_t(std::upper_bound(lineStart.begin(), lineStart.end(), item) - lineStart.begin()) -
            1;
        ImGui::SetScrollY(std::max(0.f, line * lineH - ImGui::GetWindowHeight() / 2));
        ui.transcriptScrolledTo = m.step();
    }
    ImGuiListClipper clipper;
    clipper.Begin(int(lineStart.size()) - 1, lineH);
    while (clipper.Step())
        for (int line = clipper.DisplayStart; line < clipper.DisplayEnd; ++line)
            for (uint32_t i = lineStart[size_t(line)]; i < lineStart[size_t(line) + 1]; ++i) {
                const TranscriptItem& it = items[i];
                if (i > lineStart[size_t(line)]) ImGui::SameLine(0, 0);
                bool cur = curEvent >= it.firstEvent && curEvent <= it.lastEvent;
                ImGui::PushID(int(i));
                const Event& first = m.trace().events[it.firstEvent];
                ImGui::PushStyleColor(ImGuiCol_Text, toImVec4(palette::action(first.action)));
                if (ImGui::Selectable(it.text.c_str(), cur, 0,
                                      ImGui::CalcTextSize(it.text.c_str())))
                    m.seek(it.lastEvent + 1);
                ImGui::PopStyleColor();
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip("steps %u-%u", it.firstEvent + 1, it.lastEvent + 1);
                if (!it.separator.empty()) {  // the paper's ", " and "; ", right after the item
                    ImGui::SameLine(0, 0);
                    ImGui::TextUnformatted(it.separator.c_str());
                }
                ImGui::PopID();
            }
    ImGui::EndChild();
    ImGui::End();
}

}  // namespace flood::view
