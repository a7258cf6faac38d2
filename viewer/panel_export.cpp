// The Export panel: the canvas alone as PNG (at any size) or SVG, or a range of steps as an
// animated GIF or a numbered PNG sequence, with the caption optional. The export itself runs
// in slices after each frame (export_job.h); this panel starts it and shows its progress.
#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "export_job.h"
#include "panels.h"

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#endif

namespace flood::view {

namespace {

enum ExportFormat { CanvasPng, CanvasSvg, Gif, PngSequence, FormatCount };
const char* const kFormatNames[FormatCount] = {"PNG (canvas)", "SVG (canvas)", "GIF (animated)",
                                               "PNG sequence"};

// Where the panel's controls were drawn in the last frame (the page's tests click them): the
// toolbar's Export... button, the format combo (while closed), Export, Cancel, then the combo's
// list items while it is open; w = 0 when not shown.
enum Control {
    Opener,
    FormatCombo,
    ExportButton,
    CancelButton,
    FirstFormat,
    ControlCount = FirstFormat + FormatCount
};
Rect g_controls[ControlCount];
const std::string* g_note = nullptr;

std::string suggestedPath(const Model& m, int format) {
    std::string base = exportBaseName(m);
    switch (format) {
        case CanvasPng: return base + "-step" + std::to_string(m.step()) + ".png";
        case CanvasSvg: return base + "-step" + std::to_string(m.step()) + ".svg";
        case Gif: return base + ".gif";
        default: return base + "-frames";
    }
}

}  // namespace

void drawExport(Ui& ui) {
    for (Rect& r : g_controls) r = {};
    g_controls[Opener] = ui.exportOpener;
    g_note = &ui.exportNote;
    if (!ui.showExport) return;
    Model& m = ui.model;
    if (!beginFloating(ui, "Export", &ui.showExport, 360, 300, 40, 60)) return;
    ExportSettings& s = ui.exportSettings;
    const bool running = ui.exportJob != nullptr;
    ImGui::BeginDisabled(running);

    int format = std::clamp(ui.exportFormat, 0, FormatCount - 1);
    // ImGui::Combo's list, written out so that its items' places are known.
    if (!ImGui::BeginCombo("format", kFormatNames[format])) {
        g_controls[FormatCombo] = itemRect();  // (once open, the last item is its list's window)
    } else {
        for (int f = 0; f < FormatCount; ++f) {
            if (ImGui::Selectable(kFormatNames[f], f == format)) format = f, ui.exportPath[0] = 0;
            g_controls[FirstFormat + f] = itemRect();
        }
        ImGui::EndCombo();
    }
    ui.exportFormat = format;
    int size[2] = {s.width, s.height};
    if (ImGui::InputInt2("size (px)", size))
        s.width = std::clamp(size[0], 64, 16384), s.height = std::clamp(size[1], 64, 16384);
    const bool animated = format == Gif || format == PngSequence;
    if (animated) {
        int range[2] = {int(std::min(s.first, m.steps())), int(std::min(s.last, m.steps()))};
        if (ImGui::InputInt2("steps A..B", range)) {
            s.first = uint32_t(std::clamp(range[0], 0, int(m.steps())));
            s.last = uint32_t(std::clamp(range[1], int(s.first), int(m.steps())));
        }
        int every = int(s.every);
        if (ImGui::InputInt("every K steps", &every)) s.every = uint32_t(std::max(every, 1));
        if (format == Gif) {
            float fps = float(s.fps);
            if (ImGui::SliderFloat("frames/s", &fps, float(kMinFps), float(kMaxFps), "%.1f",
                                   ImGuiSliderFlags_Logarithmic))
                s.fps = fps;
        }
        size_t frames = exportSteps(s.first, s.last, s.every, m.steps()).size();
        ImGui::TextDisabled("%zu frames, the last at step %u", frames, std::min(s.last, m.steps()));
    } else {
        ImGui::TextDisabled("the current step, %u, as the canvas shows it", m.step());
    }
    ImGui::Checkbox("caption (step, action, narration)", &s.caption);
    if (!ui.exportPath[0])
        std::snprintf(ui.exportPath, sizeof ui.exportPath, "%s", suggestedPath(m, format).c_str());
    ImGui::InputText(format == PngSequence ? "directory" : "file", ui.exportPath,
                     sizeof ui.exportPath);
#ifndef FLOOD_GIF
    if (format == Gif)
        ImGui::TextColored(toImVec4(palette::kCulprit), "built without giflib (FLOOD_GIF)");
#endif
    bool go = ImGui::Button("Export");
    g_controls[ExportButton] = itemRect();
    ImGui::EndDisabled();

    if (go && !running) {
        ExportSettings job = s;
        job.png = job.svg = job.gif = job.pngDir = "";
        std::string path = ui.exportPath;
        (format == CanvasPng   ? job.png
         : format == CanvasSvg ? job.svg
         : format == Gif       ? job.gif
                               : job.pngDir) = path;
        ui.exportNote.clear();
        ui.exportJob = std::make_shared<ExportJob>(ui, job);
    }
    if (ui.exportJob) {
        ImGui::ProgressBar(float(ui.exportJob->progress()), ImVec2(-1, 0));
        if (ImGui::Button("Cancel")) ui.exportJob->cancel();
        g_controls[CancelButton] = itemRect();
    }
    if (!ui.exportNote.empty()) {
        ImGui::PushTextWrapPos(0);
        if (ui.exportFailed)
            ImGui::TextColored(toImVec4(palette::kCulprit), "%s", ui.exportNote.c_str());
        else ImGui::TextDisabled("%s", ui.exportNote.c_str());
        ImGui::PopTextWrapPos();
    }
    ImGui::End();
}

#ifdef __EMSCRIPTEN__
// For the page's tests (tests/web/page_test.mjs): component k (x, y, w, h) of a control above
// (-1 when not shown), and the last export's note.
extern "C" {
EMSCRIPTEN_KEEPALIVE double flood_web_export_rect(int which, int k) {
    if (which < 0 || which >= ControlCount || k < 0 || k > 3 || g_controls[which].w <= 0) return -1;
    const Rect& r = g_controls[which];
    return k == 0 ? r.x : k == 1 ? r.y : k == 2 ? r.w : r.h;
}
EMSCRIPTEN_KEEPALIVE const char* flood_web_export_note() { return g_note ? g_note->c_str() : ""; }
}
#endif

}  // namespace flood::view
