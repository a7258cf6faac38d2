#include <imgui.h>

#include <cstdio>
#include <fstream>

#include "download.h"
#include "flood/io/output.h"  // atomic files
#include "panels.h"
#include "platform_glfw.h"

namespace flood::view {

void beginTiled(const char* title, const Rect& r, int flags) {
    ImGui::SetNextWindowPos(ImVec2(float(r.x), float(r.y)), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(float(r.w), float(r.h)), ImGuiCond_Always);
    ImGui::Begin(
        title, nullptr,
        flags | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
}

bool beginFloating(Ui& ui, const char* title, bool* open, float w, float h, float dx, float dy) {
    // At a large scale or on a small window a floating panel still fits in the window.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), display);
    ImGui::SetNextWindowSize(ImVec2(w * ui.scale, h * ui.scale), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowPos(ImVec2(float(ui.layout.canvas.x + dx * ui.scale),
                                   float(ui.layout.canvas.y + dy * ui.scale)),
                            ImGuiCond_FirstUseEver);
    if (ImGui::Begin(title, open)) return true;
    ImGui::End();
    return false;
}

void clickable(Ui& ui, const char* text, char kind) {
    ImGui::TextUnformatted(text);
    if (text[0] == '-' || !ImGui::IsItemHovered()) return;
    ImGui::SetTooltip("click: find %c%s", kind, text);
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left))
        ui.message = ui.model.find(kind + std::string(text)).message;
}

void sameLineOrWrap(float width) {
    const float right = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width;
    if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

Rect windowRect() {
    ImVec2 p = ImGui::GetWindowPos(), s = ImGui::GetWindowSize();
    return {p.x, p.y, s.x, s.y};
}

Rect itemRect() {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    return {a.x, a.y, b.x - a.x, b.y - a.y};
}

void textOneLine(const std::string& text, float width, const ImVec4* colour) {
    std::string shown = text;
    if (ImGui::CalcTextSize(text.c_str()).x > width && text.size() > 2) {
        // The longest middle cut that fits: as many characters kept as the width allows,
        // the start and the end (a path's folder and its file name) both kept.
        const std::string dots = "...";  // the default font has no ellipsis glyph
        size_t lo = 0, hi = text.size();
        while (lo < hi) {
            size_t keep = (lo + hi + 1) / 2;
            std::string t =
                text.substr(0, keep / 2) + dots + text.substr(text.size() - (keep - keep / 2));
            if (ImGui::CalcTextSize(t.c_str()).x <= width) lo = keep;
            else hi = keep - 1;
        }
        shown = text.substr(0, lo / 2) + dots + text.substr(text.size() - (lo - lo / 2));
    }
    if (colour) ImGui::TextColored(*colour, "%s", shown.c_str());
    else ImGui::TextUnformatted(shown.c_str());
    if (shown != text && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text.c_str());
}

float buttonWidth(const char* label) {
    return ImGui::CalcTextSize(label, nullptr, true).x + 2 * ImGui::GetStyle().FramePadding.x;
}

void clickableRange(Ui& ui, uint32_t first, uint32_t count, char kind) {
    char a[16], b[16];
    std::snprintf(a, sizeof a, "%u", first);
    clickable(ui, a, kind);
    if (count < 2) return;
    std::snprintf(b, sizeof b, "%u", first + count - 1);
    ImGui::SameLine(0, 0);
    ImGui::TextUnformatted("-");
    ImGui::SameLine(0, 0);
    clickable(ui, b, kind);
}

void clickableVertex(Ui& ui, const char* label, Index v) {
    if (v == kNone) return;
    char num[16];
    std::snprintf(num, sizeof num, "%u", v);
    ImGui::TextDisabled("%s", label);
    ImGui::SameLine(0, 4 * ui.scale);
    clickable(ui, num, 'v');
}

const char* actionLetter(Action a) {
    switch (a) {
        case Action::Raise: return "R";
        case Action::Fill: return "F";
        case Action::Bridge: return "B";
        case Action::Spill: return "S";
        case Action::Jump: return "J";
        case Action::Forbidden: return "X";
        default: return "start";
    }
}

ImVec4 toImVec4(Rgba c) { return ImVec4(c.r / 255.f, c.g / 255.f, c.b / 255.f, c.a / 255.f); }
unsigned toImU32(Rgba c) { return IM_COL32(c.r, c.g, c.b, c.a); }

std::string exportSvg(Ui& ui) {
    // Beside Save PNG's pictures (export.h: pictureFolder), never into the source tree.
    const std::string out = pictureFolder(ui.lastExportDir) + "/" + exportBaseName(ui.model) +
                            "-step" + std::to_string(ui.model.step()) + ".svg";
    Output f(out);  // atomic, as every export (export_job.h)
    writeSceneSvg(f.stream(), buildScene(ui.model, ui.sceneOptions), ui.model.polygon(), 1000);
    std::string error;
    const bool ok = f.commit(&error) == Status::Ok && offerDownload(out, &error);
    if (ok) ui.lastExportDir = folderOf(out);
    showToast(ui, ok ? "wrote " + out : error, !ok);
    ui.message = ok ? "wrote " + out : error;
    return out;
}

void requestSavePng(Ui& ui) {
    ui.pngRequest = pictureFolder(ui.lastExportDir) + "/" + stepPngName(ui.model);
}

void showToast(Ui& ui, const std::string& text, bool failed) {
    ui.toast = text;
    ui.toastFailed = failed;
    ui.toastUntil = platform::time() + 6;
}

Rect beginCanvasBar(Ui& ui, const char* id, bool right) {
    const Rect& area = ui.layout.canvas;
    const float s = ui.scale;
    ImGui::SetNextWindowPos(
        ImVec2(float(right ? area.x + area.w - 8 * s : area.x + 8 * s), float(area.y + 8 * s)),
        ImGuiCond_Always, ImVec2(right ? 1.f : 0.f, 0.f));
    ImGui::SetNextWindowBgAlpha(0.75f);
    ImGui::Begin(id, nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing);
    return windowRect();
}

}  // namespace flood::view
