// Opening polygons: the teaching gallery (polygons/gallery.json) with its descriptions, then
// the files of polygons/ (the same ones the tests and benchmarks use),
// recently opened files, and any path typed in. Files can also be dropped on the window.
#include <imgui.h>

#include <cstring>

#include "panels.h"

namespace flood::view {

void drawOpen(Ui& ui) {
    if (!ui.showOpen) return;
    Model& m = ui.model;
    ImGui::SetNextWindowSize(ImVec2(460 * ui.scale, 420 * ui.scale), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowPos(ImVec2(float(ui.layout.canvas.x + 20 * ui.scale),
                                   float(ui.layout.canvas.y + 20 * ui.scale)),
                            ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Open polygon", &ui.showOpen)) {
        ImGui::End();
        return;
    }
    static char path[1024] = "";
    bool go = ImGui::InputText("path", path, sizeof path, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    go |= ImGui::Button("Open");
    std::string chosen = go ? std::string(path) : std::string();

    if (!m.recentFiles().empty() && ImGui::CollapsingHeader("Recent", ImGuiTreeNodeFlags_DefaultOpen))
        for (const auto& f : m.recentFiles())
            if (ImGui::Selectable(f.c_str(), f == m.path())) chosen = f;

    std::string dir = polygonsDir();
    // The teaching gallery first (polygons/gallery.json, docs/TUTORIAL.md), in teaching order,
    // each with its one-line description. Read once: it changes with the sources only.
    static const std::vector<GalleryEntry> gallery = readGallery(dir);
    if (!gallery.empty() && ImGui::CollapsingHeader("Gallery", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::PushTextWrapPos(0);
        for (size_t i = 0; i < gallery.size(); ++i) {
            const GalleryEntry& g = gallery[i];
            std::string label = std::to_string(i + 1) + ". " + g.title + "##gallery" + std::to_string(i);
            if (ImGui::Selectable(label.c_str(), g.file == m.path())) chosen = g.file;
            if (!g.description.empty()) {
                ImGui::Indent();
                ImGui::TextDisabled("%s", g.description.c_str());
                ImGui::Unindent();
            }
        }
        ImGui::PopTextWrapPos();
    }
    if (ImGui::CollapsingHeader(("Polygons in " + dir).c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
        // Listing a directory every frame is cheap next to a frame, and stays current while the
        // polygons change on disk.
        auto files = listPolygonFiles(dir);
        if (files.empty()) ImGui::TextDisabled("no *.json or *.wkt files");
        for (const auto& f : files) {
            std::string name = f.substr(f.find_last_of('/') + 1);
            if (ImGui::Selectable(name.c_str(), f == m.path())) chosen = f;
        }
    }
    if (!chosen.empty()) {
        m.open(chosen);
        std::strncpy(path, chosen.c_str(), sizeof path - 1);
        ui.message = "opened " + chosen;
    }
    ImGui::End();
}

}  // namespace flood::view
