// The bottom panel: transport buttons, go-to, play speed, event-kind navigation, and the
// timeline strip with one mark per event, ticks for breakpoints, the first error and the
// invariant lane. Marks narrower than ~3 px are folded into one
// per 3 px bucket, coloured by the most telling action in it (Tracy's trick for huge traces).
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
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

// The strip shows m.timeline's window of the log: wheel zooms at the cursor, right or middle
// drag pans, a left click or drag scrubs to the step the tooltip names.
void strip(Ui& ui) {
    Model& m = ui.model;
    TimelineView& tv = m.timeline;
    const auto& ev = m.trace().events;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    ImVec2 p0 = ImGui::GetCursorScreenPos();
    float w = std::max(ImGui::GetContentRegionAvail().x, 1.f), h = 26 * ui.scale,
          lane = 8 * ui.scale;
    ImGui::InvisibleButton("##timeline", ImVec2(w, h + lane),
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    dl->AddRectFilled(p0, ImVec2(p0.x + w, p0.y + h), IM_COL32(20, 20, 24, 255));
    dl->AddRectFilled(ImVec2(p0.x, p0.y + h), ImVec2(p0.x + w, p0.y + h + lane),
                      IM_COL32(34, 30, 40, 255));
    uint32_t n = uint32_t(ev.size());
    if (n == 0) return;
    ImGuiIO& io = ImGui::GetIO();
    float mx = io.MousePos.x - p0.x;
    if (ImGui::IsItemHovered() && io.MouseWheel != 0)
        tv.zoomAt(mx, w, std::pow(1.25, io.MouseWheel), n);
    if (ImGui::IsItemActive() && (ImGui::IsMouseDragging(ImGuiMouseButton_Right) ||
                                  ImGui::IsMouseDragging(ImGuiMouseButton_Middle)))
        tv.pan(io.MouseDelta.x, w, n);
    dl->PushClipRect(p0, ImVec2(p0.x + w, p0.y + h + lane), true);
    const double perEvent = tv.perEvent(w, n);
    const uint32_t i0 = tv.eventAt(0, w, n), i1 = std::min(n, tv.eventAt(w, w, n) + 1);
    auto xOf = [&](uint32_t step) { return p0.x + float(tv.xOfStep(step, w, n)); };
    const float minMark = 3;
    if (perEvent >= minMark) {
        for (uint32_t i = i0; i < i1; ++i) {
            float x0 = xOf(i), x1 = xOf(i + 1) - 1;
            dl->AddRectFilled(ImVec2(x0, p0.y + 3), ImVec2(std::max(x1, x0 + 1), p0.y + h - 3),
                              toImU32(palette::action(ev[i].action)));
        }
    } else {
        // Folding scans the visible events: redo it only when the trace or the window changes.
        TimelineFold& fold = ui.timelineFold;
        std::vector<Action>& folded = fold.buckets;
        int buckets = int(w / minMark);
        if (fold.generation != m.generation() || folded.size() != size_t(buckets) ||
            fold.first != tv.first || fold.span != tv.span) {
            folded.assign(size_t(buckets), Action::Start);
            for (int b = 0; b < buckets; ++b) {
                uint32_t b0 = tv.eventAt(b * minMark, w, n),
                         b1 = tv.eventAt((b + 1) * minMark, w, n);
                Action best = ev[b0].action;
                for (uint32_t i = b0; i < b1; ++i)
                    if (weight(ev[i].action) > weight(best)) best = ev[i].action;
                folded[size_t(b)] = best;
            }
            fold.generation = m.generation(), fold.first = tv.first, fold.span = tv.span;
        }
        for (int b = 0; b < buckets; ++b) {
            float x0 = p0.x + b * minMark;
            dl->AddRectFilled(ImVec2(x0, p0.y + 3), ImVec2(x0 + minMark - 1, p0.y + h - 3),
                              toImU32(palette::action(folded[size_t(b)])));
        }
    }
    // The quiz: the steps to come are veiled, their colours would give the answers away.
    if (m.quizOn() && xOf(m.step()) < p0.x + w) {
        ImVec4 veil = ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled);
        veil.w = 1;  // opaque: nothing of the marks shows through
        dl->AddRectFilled(ImVec2(std::max(p0.x, xOf(m.step())), p0.y + 3),
                          ImVec2(p0.x + w, p0.y + h - 3), ImGui::GetColorU32(veil));
    }
    // Ticks: breakpoints above, the first error across, invariant violations in the lane.
    auto tick = [&](uint32_t step, float y0, float y1, ImU32 colour, float width) {
        if (step + 1 < i0 || step > i1 + 1) return;
        float x = xOf(step);  // a step sits at the right edge of its event's mark
        dl->AddLine(ImVec2(x, y0), ImVec2(x, y1), colour, width);
    };
    for (uint32_t s : m.breakpointSteps())
        tick(s, p0.y, p0.y + 6 * ui.scale, IM_COL32(255, 220, 60, 255), 2);
    for (const Violation& v : m.violations())
        tick(v.step, p0.y + h, p0.y + h + lane, IM_COL32(255, 120, 40, 255), 2);
    // The first error: the forbidden event, a triangle the checker rejects, or where an invalid
    // input first shows.
    if (m.firstErrorStep() != kNone)
        tick(m.firstErrorStep(), p0.y, p0.y + h + lane, toImU32(palette::kCulprit), 3 * ui.scale);
    tick(m.step(), p0.y, p0.y + h, IM_COL32(255, 255, 255, 255), 2 * ui.scale);
    dl->PopClipRect();
    if (ImGui::IsItemActive() &&
        ImGui::IsMouseDown(ImGuiMouseButton_Left)) {  // click or drag scrubs
        m.setPlaying(false);
        m.seek(tv.stepAt(mx, w, n));
    }
    if (ImGui::IsItemHovered()) {
        uint32_t i = tv.eventAt(mx, w, n);
        ImGui::SetTooltip("step %u: %s", i + 1, describeEvent(m.trace().polygon, ev[i]).c_str());
    }
}

// The invariant lane's status: progress while the background scan runs, then what it found;
// nothing is claimed of an open's outline, which has no run.
void invariantStatus(Ui& ui) {
    Model& m = ui.model;
    if (m.landOnFirstViolation())
        ui.message = "moved to the first broken invariant (the machine stops later)";
    using S = Model::InvariantStatus;
    switch (m.invariantStatus()) {
        case S::NoRun:
            ImGui::TextDisabled(m.opening() ? "invariants: checked once it is flooded"
                                            : "invariants: not checked (not flooded)");
            return;
        case S::Checking:
            ImGui::TextDisabled("invariants: checking step %u of %u", m.invariantProgress(),
                                m.steps());
            ImGui::SameLine();
            if (ImGui::SmallButton("Cancel##invariants")) m.cancelInvariants();
            return;
        case S::Cancelled:
            ImGui::TextDisabled("invariants: cancelled at step %u", m.invariantProgress());
            return;
        case S::NoneBroken:
            ImGui::TextColored(toImVec4(palette::kOk), "invariants: none broken");
            return;
        case S::Broken: break;
    }
    const std::vector<Violation>& v = m.violations();
    ImGui::TextColored(ImVec4(1, 0.55f, 0.2f, 1),
                       "invariants: %zu steps break one; first at step %u: %s (%s)", v.size(),
                       v.front().step, invariantName(v.front().which), v.front().detail.c_str());
    if (ImGui::IsItemHovered())  // the rule itself, beside the line saying how it broke
        ImGui::SetTooltip("%s: %s", invariantName(v.front().which), invariantText(v.front().which));
    ImGui::SameLine();
    if (ImGui::SmallButton("Go##invariant")) m.goToViolation(v.front());
    if (m.forbiddenStep()) {
        ImGui::SameLine();
        ImGui::TextDisabled("(the machine stops at step %u)", m.forbiddenStep());
    }
}

}  // namespace

void drawTimeline(Ui& ui) {
    Model& m = ui.model;
    // No scrollbar: one appearing for the lines under the strip would narrow the toolbar and
    // wrap it (those lines still scroll with the wheel).
    beginTiled("Timeline", ui.layout.bottom,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
    // The toolbar wraps onto more lines when the window is narrow or the scale large.
    const ImGuiStyle& style = ImGui::GetStyle();
    auto labelled = [&](float width, const char* label) {
        return width + style.ItemInnerSpacing.x + ImGui::CalcTextSize(label, nullptr, true).x;
    };
    if (ImGui::Button("|<")) m.first();
    sameLineOrWrap(buttonWidth("<"));
    ImGui::PushButtonRepeat(true);
    if (ImGui::Button("<")) m.stepBack();
    sameLineOrWrap(buttonWidth("Pause"));
    if (ImGui::Button(m.playing() ? "Pause" : "Play ")) m.togglePlay();
    sameLineOrWrap(buttonWidth(">"));
    if (ImGui::Button(">")) m.stepForward();
    ImGui::PopButtonRepeat();
    sameLineOrWrap(buttonWidth(">|"));
    if (ImGui::Button(">|")) m.last();
    sameLineOrWrap(labelled(110 * ui.scale, "step"));
    int step = int(m.step());
    ImGui::SetNextItemWidth(110 * ui.scale);
    if (ImGui::InputInt("step", &step, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue))
        m.seek(uint32_t(std::max(step, 0)));
    const std::string total = "/ " + std::to_string(m.steps());
    sameLineOrWrap(ImGui::CalcTextSize(total.c_str()).x);
    ImGui::TextUnformatted(total.c_str());
    sameLineOrWrap(labelled(120 * ui.scale, "steps/s"));
    float speed = float(m.speed());
    ImGui::SetNextItemWidth(120 * ui.scale);
    if (ImGui::SliderFloat("steps/s", &speed, 0.5f, 200.f, "%.1f", ImGuiSliderFlags_Logarithmic))
        m.setSpeed(speed);
    sameLineOrWrap(100 * ui.scale);
    ImGui::SetNextItemWidth(100 * ui.scale);
    if (ImGui::BeginCombo("##kind", actionName(ui.seekKind))) {
        for (int a = 0; a < int(Action::Count); ++a)
            if (ImGui::Selectable(actionName(Action(a)), ui.seekKind == Action(a)))
                ui.seekKind = Action(a);
        ImGui::EndCombo();
    }
    sameLineOrWrap(buttonWidth("prev"));
    if (ImGui::Button("prev")) m.seekAction(ui.seekKind, -1);
    sameLineOrWrap(buttonWidth("next"));
    if (ImGui::Button("next")) m.seekAction(ui.seekKind, +1);
    sameLineOrWrap(buttonWidth("Open..."));
    if (ImGui::Button("Open...")) ui.showOpen = true;
    sameLineOrWrap(buttonWidth("Fit"));
    if (ImGui::Button("Fit")) m.requestFit();
    sameLineOrWrap(buttonWidth("Save PNG"));
    if (ImGui::Button("Save PNG")) requestSavePng(ui);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the canvas alone, as the next frame shows it (P)");
    sameLineOrWrap(buttonWidth("SVG"));
    if (ImGui::Button("SVG")) exportSvg(ui);
    const char* themeButton = ui.theme == Theme::Light ? "Dark theme" : "Light theme";
    sameLineOrWrap(buttonWidth(themeButton));
    if (ImGui::Button(themeButton))
        ui.theme = ui.theme == Theme::Light ? Theme::Dark : Theme::Light;
    sameLineOrWrap(buttonWidth("Present (Tab)"));
    if (ImGui::Button("Present (Tab)")) ui.presenter = true;
    sameLineOrWrap(buttonWidth("Export..."));
    if (ImGui::Button("Export...")) ui.showExport = true;
    ui.exportOpener = itemRect();
    sameLineOrWrap(buttonWidth("Help"));
    if (ImGui::Button("Help")) ui.showHelp = true;
    ImVec2 end0 = ImGui::GetItemRectMin(), end1 = ImGui::GetItemRectMax();
    ui.toolbarEnd = {end0.x, end0.y, end1.x - end0.x, end1.y - end0.y};

    strip(ui);
    invariantStatus(ui);
    // The layout gives the timeline at least this much next frame: the toolbar however many
    // lines it wraps to, the strip and its lane's status; the lines below may scroll.
    ui.bottomWanted = ImGui::GetCursorPosY() - style.ItemSpacing.y + style.WindowPadding.y;

    // The verdict first, on one line: ok, or how many findings (each whole in the findings
    // panel under the canvas); then the file and the step, each on one line, never wrapping.
    const float width = ImGui::GetContentRegionAvail().x;
    const ImVec4 red = toImVec4(palette::kCulprit), green = toImVec4(palette::kOk);
    if (!m.findings().empty()) {
        const Finding& first = m.findings().front();
        std::string line =
            std::to_string(m.findings().size() + m.findingsOmitted()) +
            (m.findings().size() + m.findingsOmitted() == 1 ? " finding" : " findings") +
            " (listed under the canvas); the first: " + first.message;
        textOneLine(line, width, &red);
    }
    for (const VerdictLine& line : m.verdictLines()) {
        if (line.failure()) continue;  // in the findings panel
        const ImVec4 grey = ImGui::GetStyle().Colors[ImGuiCol_TextDisabled];
        textOneLine(line.text, width, line.note ? &grey : &green);
    }
    const Event* e = m.currentEvent();
    const float pathWidth = std::min(width * 0.4f, ImGui::CalcTextSize(m.path().c_str()).x);
    textOneLine(m.path(), pathWidth);
    ImGui::SameLine();
    const float rest = std::max(40.f, width - pathWidth - ImGui::GetStyle().ItemSpacing.x);
    if (e) {
        const ImVec4 colour = toImVec4(palette::action(e->action));
        textOneLine(
            "step " + std::to_string(m.step()) + ": " + describeEvent(m.trace().polygon, *e), rest,
            &colour);
    } else {
        ImGui::TextDisabled("step 0: before the first event");
    }
    if (!ui.message.empty()) textOneLine(ui.message, width);
    ImGui::PushTextWrapPos(0);
    for (const auto& w : m.warnings()) ImGui::TextDisabled("warning: %s", w.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

}  // namespace flood::view
