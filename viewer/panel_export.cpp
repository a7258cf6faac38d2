// The Export panel: the canvas alone as PNG (at any size) or SVG, or a range of steps as an
// animated GIF or a numbered PNG sequence, with the caption optional. The export itself runs
// in slices after each frame (export_job.h); this panel starts it and shows its progress.
#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "export_job.h"
#include "panels.h"

namespace flood::view {

namespace {

enum ExportFormat { CanvasPng, CanvasSvg, Gif, PngSequence, FormatCount };
const char* const kFormatNames[FormatCount] = {"PNG (canvas)", "SVG (canvas)", "GIF (animated)",
                                               "PNG sequence"};

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
    if (!ui.showExport) return;
    Model& m = ui.model;
    if (!beginFloating(ui, "Export", &ui.showExport, 360, 300, 40, 60)) return;
    ExportSettings& s = ui.exportSettings;
    const bool running = ui.exportJob != nullptr;
    ImGui::BeginDisabled(running);

    int format = std::clamp(ui.exportFormat, 0, FormatCount - 1);
    if (ImGui::Combo("format", &format, kFormatNames, FormatCount)) ui.exportPath[0] = 0;
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

}  // namespace flood::view
