// The findings panel (issue 26): under the canvas whenever the open face fails, one row per
// finding (Model::findings: every validation finding, then the forbidden transition or the
// checker's rejection), each whole, wrapped, never cut. A click frames the finding (the
// error view), F8 / Shift+F8 go to the next / previous one.
#include <imgui.h>

#include <algorithm>
#include <string>

#include "panels.h"
#include "platform_glfw.h"

namespace flood::view {

namespace {

const char* kindTag(Verdict k) {
    switch (k) {
        case Verdict::Malformed: return "unreadable";
        case Verdict::Invalid: return "invalid";
        case Verdict::Forbidden: return "forbidden";
        case Verdict::Checker: return "checker";
        case Verdict::Internal: return "internal";
        default: return "";
    }
}

// "3 findings: 2 invalid input, forbidden at step 12".
std::string summary(const Model& m) {
    const auto& f = m.findings();
    size_t invalid = 0;
    std::string rest;
    for (const Finding& x : f) {
        if (x.kind == Verdict::Invalid) ++invalid;
        else if (x.kind == Verdict::Forbidden) rest += ", forbidden at " + x.where;
        else if (x.kind == Verdict::Checker) rest += ", the exact checker rejects it";
        else if (x.kind == Verdict::Internal) rest += ", an internal failure";
        else if (x.kind == Verdict::Malformed) rest += ", unreadable";
    }
    std::string s = std::to_string(f.size() + m.findingsOmitted()) +
                    (f.size() + m.findingsOmitted() == 1 ? " finding" : " findings");
    std::string what;
    if (invalid) what = std::to_string(invalid + m.findingsOmitted()) + " invalid input";
    what += rest;
    if (what.rfind(", ", 0) == 0) what.erase(0, 2);
    return s + ": " + what;
}

}  // namespace

double findingsHeight(const Model& m, float scale) {
    if (m.findings().empty()) return 0;
    const ImGuiStyle& style = ImGui::GetStyle();
    const double line = ImGui::GetTextLineHeightWithSpacing();
    // The header and its notes, then up to four findings of two lines each; more scroll.
    const size_t rows = std::min<size_t>(m.findings().size(), 4);
    const size_t notes = 1 + (m.findingsOmitted() > 0) + !m.findingsComplete();
    return 2 * style.WindowPadding.y + double(notes) * line +
           double(rows) * (2 * line + style.ItemSpacing.y) + 4 * scale;
}

void drawFindings(Ui& ui) {
    Model& m = ui.model;
    ui.findingRows.clear();
    if (m.findings().empty() || ui.layout.findings.h <= 0) return;
    ImGuiIO& io = ImGui::GetIO();
    // F8 / Shift+F8: the next / previous finding, framed (also in screenshots: --press f8).
    const bool next = !io.WantTextInput && ImGui::IsKeyPressed(platform::kKeyF8, true);
    if (next && !m.nextFinding(io.KeyShift ? -1 : +1)) ui.message = "no finding to frame";

    beginTiled("Findings", ui.layout.findings, ImGuiWindowFlags_NoTitleBar);
    const float s = ui.scale;
    const std::string head = summary(m);
    const float width = ImGui::GetContentRegionAvail().x;
    const ImVec4 red = toImVec4(palette::kCulprit);
    const float headW = std::min(width, ImGui::CalcTextSize(head.c_str()).x);
    textOneLine(head, headW, &red);
    const char* hint = "click or F8 / Shift+F8: frame it";
    const float hintW = ImGui::CalcTextSize(hint).x, spacing = ImGui::GetStyle().ItemSpacing.x;
    if (headW + spacing + hintW <= width) {  // the hint where it fits, right-aligned
        ImGui::SameLine(ImGui::GetCursorPosX() + width - hintW);
        ImGui::TextDisabled("%s", hint);
    }
    if (m.findingsOmitted()) {
        size_t listed = 0;
        for (const Finding& f : m.findings()) listed += f.kind == Verdict::Invalid;
        ImGui::TextDisabled(
            "%zu more validation findings not listed (the first %zu are; `flood check "
            "--max-findings N` lists more)",
            m.findingsOmitted(), listed);
    }
    if (!m.findingsComplete())
        ImGui::TextDisabled(
            "the search for crossings stopped at its work limit: there may be more");

    ImGui::BeginChild("##rows", ImVec2(0, 0), false);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImGuiStyle& style = ImGui::GetStyle();
    const float avail = ImGui::GetContentRegionAvail().x;
    const float tagW = ImGui::CalcTextSize("unreadable").x + style.ItemSpacing.x;
    const float numW = ImGui::CalcTextSize("100").x + style.ItemSpacing.x;
    float whereW = 0;  // as wide as the widest place, up to a third of the row
    for (const Finding& f : m.findings())
        whereW = std::max(whereW, ImGui::CalcTextSize(f.where.c_str()).x);
    whereW = std::clamp(whereW, 60 * s, avail / 3);
    // Narrow (a large scale): what is wrong goes under the place, the row's whole width.
    const float besideW = avail - numW - tagW - whereW - style.ItemSpacing.x;
    const bool stacked = besideW < avail * 0.45f;
    if (stacked) whereW = std::max(40.f, avail - numW - tagW);
    const float whatW = stacked ? std::max(40.f, avail - numW) : besideW;
    const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
    const ImU32 dim = ImGui::GetColorU32(ImGuiCol_TextDisabled);
    const ImU32 redText = toImU32(palette::kCulprit);
    ImFont* font = ImGui::GetFont();
    const float size = ImGui::GetFontSize();
    for (size_t i = 0; i < m.findings().size(); ++i) {
        const Finding& f = m.findings()[i];
        const std::string num = std::to_string(i + 1);
        const float whereH =
            std::max(ImGui::GetTextLineHeight(),
                     ImGui::CalcTextSize(f.where.c_str(), nullptr, false, whereW).y);
        const float whatH = ImGui::CalcTextSize(f.reason.c_str(), nullptr, false, whatW).y;
        const float h = stacked ? whereH + whatH : std::max(whereH, whatH);
        const ImVec2 p = ImGui::GetCursorScreenPos();
        const bool current = m.errorView() && m.currentFinding() == i;
        // F8 moved: the row scrolled into view, asked again until it is there (a child
        // window's first frame knows no content height to scroll in).
        bool scrollTo = false;
        if (current && ui.findingsScrolledTo != i) {
            const float top = ImGui::GetCursorPosY(), at = ImGui::GetScrollY();
            const float seen = ImGui::GetWindowHeight();
            if (top >= at - 0.5f && (top + h <= at + seen + 0.5f || top <= at + 0.5f))
                ui.findingsScrolledTo = i;
            else scrollTo = true;
        }
        ImGui::PushID(int(i));
        if (ImGui::Selectable("##finding", current, ImGuiSelectableFlags_None, ImVec2(avail, h))) {
            if (!m.showFinding(i)) ui.message = "finding " + num + ": nothing to frame";
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", f.message.c_str());
        if (scrollTo) ImGui::SetScrollHereY(0.0f);  // the item just submitted, at the top
        ImGui::PopID();
        ui.findingRows.push_back({p.x, p.y, avail, h});
        float x = p.x;
        dl->AddText(font, size, ImVec2(x, p.y), dim, num.c_str());
        x += numW;
        dl->AddText(font, size, ImVec2(x, p.y), redText, kindTag(f.kind));
        x += tagW;
        dl->AddText(font, size, ImVec2(x, p.y), text, f.where.c_str(), nullptr, whereW);
        if (stacked)
            dl->AddText(font, size, ImVec2(p.x + numW, p.y + whereH), text, f.reason.c_str(),
                        nullptr, whatW);
        else
            dl->AddText(font, size, ImVec2(x + whereW + style.ItemSpacing.x, p.y), text,
                        f.reason.c_str(), nullptr, whatW);
    }
    if (!m.errorView()) ui.findingsScrolledTo = ~size_t(0);
    ImGui::EndChild();
    ImGui::End();
}

}  // namespace flood::view
