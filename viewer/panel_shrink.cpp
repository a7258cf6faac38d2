// Shrink from the viewer (issue 11): on any failure, shrink the polygon (flood/tools/shrink.h) in
// the background with a progress bar and Cancel, open the minimal repro with the original one
// click away (and in Recent), and save it as GeoJSON.
#include <imgui.h>

#include <cstring>
#include <string>

#include "download.h"
#include "panels.h"

namespace flood::view {
namespace {

// "dir/name.ext" or "dir/name.geojson#3" -> "dir/name-shrunk.geojson" (feature 3: "-3-shrunk").
std::string reproPath(const std::string& original) {
    std::string base = original, feature;
    if (size_t hash = base.rfind('#'); hash != std::string::npos) {
        feature = "-" + base.substr(hash + 1);
        base.resize(hash);
    }
    size_t slash = base.find_last_of('/');
    size_t dot = base.find_last_of('.');
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) base.resize(dot);
    return base + feature + "-shrunk.geojson";
}

}  // namespace

void drawShrink(Ui& ui) {
    Model& m = ui.model;
    ShrinkJob& job = ui.shrink;
    const bool running = job.started() && !job.done();
    ui.shrinkBox = {};
    if (!running && !m.shrunk() && (!m.failed() || m.polygon().vertices.empty())) return;

    // First shown under the Edit box at the canvas's right edge: clear of the find box and its
    // Show error button, whatever the window's width.
    ImGui::SetNextWindowPos(ImVec2(float(ui.layout.canvas.x + ui.layout.canvas.w - 8 * ui.scale),
                                   float(ui.layout.canvas.y + 52 * ui.scale)),
                            ImGuiCond_FirstUseEver, ImVec2(1, 0));
    // Its content changes with the job's stage: fit it each frame, text wrapped to a column.
    if (!ImGui::Begin("Shrink", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ui.shrinkBox = windowRect();  // collapsed: its title bar
        ImGui::End();
        return;
    }
    ui.shrinkBox = windowRect();
    if (running) {
        // The shrinker does not know how many tries it will need: the bar is out of the most
        // it may make, the label says how many so far.
        std::string label = std::to_string(job.tries()) + " tries";
        ImGui::ProgressBar(float(double(job.tries()) / double(std::max<size_t>(1, job.maxTries()))),
                           ImVec2(320 * ui.scale, 0), label.c_str());
        // Not joined here: a classification in flight may take up to its time limit; the
        // frame goes on and the repro found so far opens once the thread has stopped.
        if (ImGui::Button("Cancel")) job.requestCancel();
    } else if (job.done()) {
        ShrinkResult r = job.result();
        job.reset();
        // A shrink of a polygon that is no longer open is of no use.
        if (m.generation() == ui.shrinkGeneration) {
            if (r.failure.kind == Failure::Kind::None) {
                ui.shrinkNote = "the shrinker finds no failure to keep (" + r.failure.message + ")";
            } else {
                const size_t was = m.polygon().vertices.size();
                m.openShrunk(r);
                std::strncpy(ui.savePath, reproPath(m.originName()).c_str(),
                             sizeof ui.savePath - 1);
                ui.shrinkNote = "shrunk " + std::to_string(was) + " -> " +
                                std::to_string(r.polygon.vertices.size()) + " vertices in " +
                                std::to_string(r.tries) + " tries" +
                                (r.cancelled ? " (cancelled)" : "") + ": " + r.failure.message;
            }
        }
    } else if (m.failed() && ImGui::Button("Shrink")) {
        ShrinkOptions o;  // in a forked child, so a crash or a hang is a failure, not ours
        ui.shrinkGeneration = m.generation();
        ui.shrinkNote.clear();
        job.start(m.polygon(), o);
    }

    if (m.shrunk()) {
        ImGui::PushTextWrapPos(320 * ui.scale);
        ImGui::Text("minimal repro: %zu vertices, from", m.polygon().vertices.size());
        ImGui::TextDisabled("%s", m.originName().c_str());
        ImGui::PopTextWrapPos();
        if (ImGui::Button("Back to the original")) m.openOrigin();
        ImGui::InputText("##save", ui.savePath, sizeof ui.savePath);
        ImGui::SameLine();
        if (ImGui::Button("Save")) {
            Diagnostic d = saveGeoJson(m.polygon(), ui.savePath);
            std::string error;  // in the page, the file reaches the user as a download
            if (d.ok() && !offerDownload(ui.savePath, &error)) d = {Status::WriteFailed, error};
            ui.shrinkNote = d.ok() ? std::string("wrote ") + ui.savePath : d.message;
            ui.message = ui.shrinkNote;
        }
    }
    if (!ui.shrinkNote.empty()) {
        ImGui::PushTextWrapPos(320 * ui.scale);
        ImGui::TextDisabled("%s", ui.shrinkNote.c_str());
        ImGui::PopTextWrapPos();
    }
    ImGui::End();
}

}  // namespace flood::view
