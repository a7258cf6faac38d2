// The bottom panel: transport buttons, go-to, play speed, event-kind navigation, and the
// timeline strip with one mark per event. Marks narrower than ~3 px are folded into one
// per 3 px bucket, coloured by the most telling action in it (Tracy's trick for huge traces).
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "panels.h"

namespace flood::view {

namespace {

// Rarer actions win a folded bucket: a single Forbidden or Spill must stay visible among
// hundreds of Raises.
int weight(Action a) {
    switch (a) {
        case Action::Forbidden: return 6;
        case Action::Spill: return 5;
        case Action::Jump: return 4;
        case Action::Bridge: return 3;
        case Action::Fill: return 2;
        case Action::Start: return 1;
        default: return 0;
    }
}

void strip(Ui& ui) {
    Model& m = ui.model;
    const auto& ev = m.trace().events;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    ImVec2 p0 = ImGui::GetCursorScreenPos();
    float w = ImGui::GetContentRegionAvail().x, h = 26 * ui.scale;
    ImGui::InvisibleButton("##timeline", ImVec2(std::max(w, 1.f), h));
    dl->AddRectFilled(p0, ImVec2(p0.x + w, p0.y + h), IM_COL32(20, 20, 24, 255));
    uint32_t n = uint32_t(ev.size());
    if (n == 0) return;
    // Step s sits at the right edge of event s-1's mark: the strip reads left to right.
    double perEvent = w / n;
    const float minMark = 3;
    if (perEvent >= minMark) {
        for (uint32_t i = 0; i < n; ++i) {
            float x0 = p0.x + float(i * perEvent), x1 = p0.x + float((i + 1) * perEvent) - 1;
            dl->AddRectFilled(ImVec2(x0, p0.y + 3), ImVec2(std::max(x1, x0 + 1), p0.y + h - 3),
                              toImU32(palette::action(ev[i].action)));
        }
    } else {
        // Folding scans the whole log: redo it only for a new trace or a new strip width.
        static uint64_t foldedFor = ~0ull;
        static std::vector<Action> folded;
        int buckets = int(w / minMark);
        if (foldedFor != m.generation() || folded.size() != size_t(buckets)) {
            folded.assign(size_t(buckets), Action::Start);
            for (int b = 0; b < buckets; ++b) {
                uint32_t i0 = uint32_t(double(b) / buckets * n), i1 = uint32_t(double(b + 1) / buckets * n);
                Action best = ev[std::min(i0, n - 1)].action;
                for (uint32_t i = i0; i < i1 && i < n; ++i)
                    if (weight(ev[i].action) > weight(best)) best = ev[i].action;
                folded[size_t(b)] = best;
            }
            foldedFor = m.generation();
        }
        for (int b = 0; b < buckets; ++b) {
            float x0 = p0.x + b * minMark;
            dl->AddRectFilled(ImVec2(x0, p0.y + 3), ImVec2(x0 + minMark - 1, p0.y + h - 3),
                              toImU32(palette::action(folded[size_t(b)])));
        }
    }
    float cx = p0.x + float(m.step() * perEvent);
    dl->AddLine(ImVec2(cx, p0.y), ImVec2(cx, p0.y + h), IM_COL32(255, 255, 255, 255), 2 * ui.scale);
    if (ImGui::IsItemActive()) {  // click or drag scrubs
        float x = ImGui::GetIO().MousePos.x - p0.x;
        m.playing = false;
        m.seek(uint32_t(std::clamp(std::lround(x / perEvent), 0l, long(n))));
    }
    if (ImGui::IsItemHovered()) {
        float x = ImGui::GetIO().MousePos.x - p0.x;
        uint32_t i = uint32_t(std::clamp(long(x / perEvent), 0l, long(n) - 1));
        ImGui::SetTooltip("step %u: %s", i + 1, describeEvent(m.trace(), ev[i]).c_str());
    }
}

}  // namespace

void drawTimeline(Ui& ui) {
    Model& m = ui.model;
    placeWindow(ui.layout.bottom);
    ImGui::Begin("Timeline", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoTitleBar);
    if (ImGui::Button("|<")) m.first();
    ImGui::SameLine();
    ImGui::PushButtonRepeat(true);
    if (ImGui::Button("<")) m.stepBack();
    ImGui::SameLine();
    if (ImGui::Button(m.playing ? "Pause" : "Play ")) m.togglePlay();
    ImGui::SameLine();
    if (ImGui::Button(">")) m.stepForward();
    ImGui::PopButtonRepeat();
    ImGui::SameLine();
    if (ImGui::Button(">|")) m.last();
    ImGui::SameLine();
    int step = int(m.step());
    ImGui::SetNextItemWidth(110 * ui.scale);
    if (ImGui::InputInt("step", &step, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue))
        m.seek(uint32_t(std::max(step, 0)));
    ImGui::SameLine();
    ImGui::Text("/ %u", m.steps());
    ImGui::SameLine();
    float speed = float(m.speed);
    ImGui::SetNextItemWidth(120 * ui.scale);
    if (ImGui::SliderFloat("steps/s", &speed, 0.5f, 200.f, "%.1f", ImGuiSliderFlags_Logarithmic))
        m.speed = speed;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(100 * ui.scale);
    if (ImGui::BeginCombo("##kind", actionName(ui.seekKind))) {
        for (int a = 0; a < int(Action::Count); ++a)
            if (ImGui::Selectable(actionName(Action(a)), ui.seekKind == Action(a)))
                ui.seekKind = Action(a);
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::Button("prev")) m.seekAction(ui.seekKind, -1);
    ImGui::SameLine();
    if (ImGui::Button("next")) m.seekAction(ui.seekKind, +1);
    ImGui::SameLine();
    if (ImGui::Button("Open...")) ui.showOpen = true;
    ImGui::SameLine();
    if (ImGui::Button("Fit")) m.needsFit = true;
    ImGui::SameLine();
    if (ImGui::Button("Save PNG")) {
        std::string name = "flood-step" + std::to_string(m.step()) + ".png";
        ui.pngRequest = name;
    }
    ImGui::SameLine();
    if (ImGui::Button("SVG")) exportSvg(ui);
    ImGui::SameLine();
    if (ImGui::Button("Help")) ui.showHelp = true;

    strip(ui);

    const Event* e = m.currentEvent();
    ImGui::PushTextWrapPos(0);
    ImGui::TextUnformatted(m.path().c_str());
    ImGui::SameLine();
    if (e) {
        ImGui::TextColored(toImVec4(palette::action(e->action)), "step %u: %s", m.step(),
                           describeEvent(m.trace(), *e).c_str());
    } else {
        ImGui::TextDisabled("step 0: before the first event");
    }
    const std::string& verdict = m.verdict();
    bool bad = !m.inputDiagnostic().ok() || verdict.rfind("ok:", 0) != 0;
    ImGui::TextColored(bad ? toImVec4(palette::kCulprit) : ImVec4(0.6f, 0.9f, 0.6f, 1), "%s",
                       verdict.c_str());
    for (const auto& w : m.warnings()) ImGui::TextDisabled("warning: %s", w.c_str());
    if (!ui.message.empty()) ImGui::TextDisabled("%s", ui.message.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

}  // namespace flood::view
