// Opening polygons: the teaching gallery (polygons/gallery.json) with its descriptions, then
// the files of polygons/ (the same ones the tests and benchmarks use),
// recently opened files, and any path typed in. Files can also be dropped on the window.
// A FeatureCollection's features are listed with their verdicts, failing ones first.
#include <imgui.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "flood/io/gdal/read_any.h"
#include "panels.h"

namespace flood::view {

// A file whose features the Open panel lists: a polygon document, not a trace or a shrink.
static bool polygonDocument(const std::string& f) {
    return !f.empty() && f.find("(shrunk)") == std::string::npos &&
           (f.size() < 6 || f.compare(f.size() - 6, 6, ".jsonl") != 0);
}

// The features of the loaded file (or of a collection that failed to open whole: its
// features are separate polygons), judged in the background: a dataset may hold thousands.
// Listed when the panel is open; and a collection that cannot be read whole (one feature
// broken) gets its list shown at once, as a GIS lists a layer's features, rather than an
// empty canvas.
static void scanFeatures(Ui& ui) {
    Model& m = ui.model;
    if (m.generation() != ui.featuresGeneration) {
        const bool unreadable =
            m.polygon().vertices.empty() && m.inputDiagnostic().status == Status::Malformed;
        if (!ui.showOpen && !unreadable) return;  // chosen when the panel opens
        ui.featuresGeneration = m.generation();
        std::string file =
            m.feature() == Model::kNoFeature ? m.path() : m.path().substr(0, m.path().rfind('#'));
        if (polygonDocument(file) && ui.features.path() != file) ui.features.start(file);
        ui.featuresOffered = unreadable;
    }
    if (ui.featuresOffered && ui.features.done()) {
        ui.featuresOffered = false;
        if (ui.features.features().size() > 1) ui.showOpen = true;
    }
}

void drawOpen(Ui& ui) {
    Model& m = ui.model;
    if (m.galleryOpens() != ui.openPanel.galleryOpensSeen)  // a gallery file was opened
        ui.openPanel.galleryOpensSeen = m.galleryOpens(), ui.showOpen = true;
    scanFeatures(ui);
    if (!ui.showOpen) return;
    if (!beginFloating(ui, "Open polygon", &ui.showOpen, 460, 420, 20, 20)) return;
    char* path = ui.openPanel.path;
    bool go = ImGui::InputText("path", path, sizeof ui.openPanel.path,
                               ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    go |= ImGui::Button("Open");
    std::string chosen = go ? std::string(path) : std::string();

    scanFeatures(ui);  // the panel has just opened: its file's features
    size_t openFeature = Model::kNoFeature;
    const FeatureScan& scan = ui.features;
    if (!scan.path().empty() && (!scan.done() || !scan.features().empty()) &&
        ImGui::CollapsingHeader(("Features of " + scan.path()).c_str(),
                                ImGuiTreeNodeFlags_DefaultOpen)) {
        if (!scan.done()) {
            std::string label =
                std::to_string(scan.progress()) + " / " + std::to_string(scan.total());
            ImGui::ProgressBar(
                float(double(scan.progress()) / double(std::max<size_t>(1, scan.total()))),
                ImVec2(-1, 0), label.c_str());
        } else {
            const bool thisFile =
                m.feature() != Model::kNoFeature && m.path().rfind(scan.path() + "#", 0) == 0;
            for (const FeatureVerdict& f : scan.features()) {
                std::string label = "#" + std::to_string(f.index) + " " +
                                    (f.name.empty() ? f.id : f.name) + "  " +
                                    std::to_string(f.vertices) + " v  " + verdictName(f.kind) +
                                    "##feature" + std::to_string(f.index);
                if (f.failure()) ImGui::PushStyleColor(ImGuiCol_Text, toImVec4(palette::kCulprit));
                if (ImGui::Selectable(label.c_str(), thisFile && m.feature() == f.index))
                    openFeature = f.index;
                if (f.failure()) ImGui::PopStyleColor();
                if (!f.reason.empty() && ImGui::IsItemHovered())
                    ImGui::SetTooltip("%s", f.reason.c_str());
            }
        }
    }
    if (openFeature != Model::kNoFeature) {
        const std::string file = scan.path();
        ui.openFailed = !m.openFeature(file, openFeature);
        ui.message = ui.openFailed ? m.openDiagnostic().message : "opened " + m.path();
    }

    if (!m.recentFiles().empty() &&
        ImGui::CollapsingHeader("Recent", ImGuiTreeNodeFlags_DefaultOpen))
        for (const auto& f : m.recentFiles())
            if (ImGui::Selectable(f.c_str(), f == m.path())) chosen = f;

    const std::string dir = m.galleryDir();
    // The teaching gallery first (polygons/gallery.json, docs/TUTORIAL.md), in teaching order,
    // each with its one-line description.
    if (!ui.openPanel.galleryRead || ui.openPanel.galleryDir != dir) {
        ui.openPanel.gallery = readGallery(dir), ui.openPanel.galleryRead = true;
        ui.openPanel.galleryDir = dir;
    }
    const std::vector<GalleryEntry>& gallery = ui.openPanel.gallery;
    ui.openPanel.galleryRows.clear();
    if (!gallery.empty() && ImGui::CollapsingHeader("Gallery", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::PushTextWrapPos(0);
        for (size_t i = 0; i < gallery.size(); ++i) {
            const GalleryEntry& g = gallery[i];
            std::string label =
                std::to_string(i + 1) + ". " + g.title + "##gallery" + std::to_string(i);
            if (ImGui::Selectable(label.c_str(), g.file == m.path())) chosen = g.file;
            ui.openPanel.galleryRows.push_back(itemRect());
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
        auto files = polygonFiles(dir);
        if (files.empty()) ImGui::TextDisabled("no *.json or *.wkt files");
        for (const auto& f : files) {
            std::string name = f.substr(f.find_last_of('/') + 1);
            if (ImGui::Selectable(name.c_str(), f == m.path())) chosen = f;
        }
    }
    // Any folder: its subfolders to walk into, and the polygons and traces in it.
    if (ImGui::CollapsingHeader("Browse")) {
        namespace fs = std::filesystem;
        std::error_code ec;
        if (ui.browseDir.empty()) ui.browseDir = fs::absolute(dir, ec).lexically_normal().string();
        ImGui::TextDisabled("%s", ui.browseDir.c_str());
        std::vector<std::string> dirs, files;
        for (const auto& e : fs::directory_iterator(ui.browseDir, ec)) {
            std::string name = e.path().filename().string();
            std::string ext = e.path().extension().string();
            if (e.is_directory(ec)) dirs.push_back(name);
            // Polygons, traces, and GIS datasets (opened through GDAL).
            else if (ext == ".jsonl" || gdal::listedFile(name)) files.push_back(name);
        }
        std::sort(dirs.begin(), dirs.end());
        std::sort(files.begin(), files.end());
        std::string into;
        if (ImGui::Selectable("../")) into = fs::path(ui.browseDir).parent_path().string();
        for (const auto& d : dirs)
            if (ImGui::Selectable((d + "/").c_str())) into = (fs::path(ui.browseDir) / d).string();
        for (const auto& f : files) {
            std::string full = (fs::path(ui.browseDir) / f).string();
            if (ImGui::Selectable(f.c_str(), full == m.path())) chosen = full;
        }
        if (!into.empty()) ui.browseDir = fs::path(into).lexically_normal().string();
    }
    if (!chosen.empty()) {
        // In the background: noteOpened says how it went once it is done.
        m.openInBackground(chosen);
        std::strncpy(path, chosen.c_str(), sizeof path - 1);
        ui.openFailed = false;
        ui.message = "opening " + chosen;
    }
    if (ui.openFailed) {
        ImGui::PushTextWrapPos(0);
        ImGui::TextColored(toImVec4(palette::kCulprit), "%s", m.openDiagnostic().message.c_str());
        ImGui::PopTextWrapPos();
    }
    ImGui::End();
}

void noteOpened(Ui& ui, const std::string& path) {
    const Model& m = ui.model;
    // A failed open keeps what was loaded; say why in red.
    ui.openFailed = !m.openDiagnostic().ok();
    ui.message = ui.openFailed ? m.openDiagnostic().message : "opened " + path;
    if (ui.openFailed && polygonDocument(path)) ui.features.start(path);  // a collection?
}

}  // namespace flood::view
