// Shrink from the viewer (issue 11): on any failure, shrink the polygon (flood/tools/shrink.h) in
// the background with a progress bar and Cancel, open the minimal repro with the original one
// click away (and in Recent), and save it as GeoJSON.
#include <imgui.h>

#include <cstring>
#include <string>

#include "download.h"
#include "panels.h"

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#endif

namespace flood::view {
namespace {

// Where the panel's buttons were drawn in the last frame (the page's tests click them): Shrink,
// Cancel, Save; w = 0 when not shown.
Rect g_buttons[3];
void drawn(int which) { g_buttons[which] = itemRect(); }
const std::string* g_note = nullptr;

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
    job.poll();  // the page's worker (shrink_worker.h)
    const bool running = job.started() && !job.done();
    ui.shrinkBox = {};
    g_buttons[0] = g_buttons[1] = g_buttons[2] = {};
    g_note = &ui.shrinkNote;
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
        if (job.vertices() > 0) label += ", " + std::to_string(job.vertices()) + " vertices";
        ImGui::ProgressBar(float(double(job.tries()) / double(std::max<size_t>(1, job.maxTries()))),
                           ImVec2(320 * ui.scale, 0), label.c_str());
        // Not joined here: a classification in flight may take up to its time limit; the
        // frame goes on and the repro found so far opens once the thread has stopped.
        const bool cancel = ImGui::Button("Cancel");
        drawn(1);
        if (cancel) job.requestCancel();
    } else if (job.done()) {
        ShrinkResult r = job.result();
        const std::string stopped = job.stoppedNote();
        job.reset();
        // A shrink of a polygon that is no longer open is of no use.
        if (m.generation() == ui.shrinkGeneration) {
            if (!stopped.empty()) {  // the page's worker crashed or was cancelled
                ui.shrinkNote = stopped;
            } else if (r.failure.kind == Failure::Kind::None) {
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
    } else if (m.failed()) {
        const bool go = ImGui::Button("Shrink");
        drawn(0);
        if (go) {
            // Each try in a forked child (the page: all in one Web Worker), so a crash or a
            // hang is a failure, not ours.
            ShrinkOptions o;
            ui.shrinkGeneration = m.generation();
            ui.shrinkNote.clear();
            job.start(m.polygon(), o);
        }
    }

    if (m.shrunk()) {
        ImGui::PushTextWrapPos(320 * ui.scale);
        ImGui::Text("minimal repro: %zu vertices, from", m.polygon().vertices.size());
        ImGui::TextDisabled("%s", m.originName().c_str());
        ImGui::PopTextWrapPos();
        if (ImGui::Button("Back to the original")) m.openOrigin();
        ImGui::InputText("##save", ui.savePath, sizeof ui.savePath);
        ImGui::SameLine();
        const bool save = ImGui::Button("Save");
        drawn(2);
        if (save) {
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

#ifdef __EMSCRIPTEN__
// For the page's tests (tests/web/page_test.mjs): component k (x, y, w, h) of a button above
// (-1 when not shown), whether a shrink runs, and the panel's note.
extern "C" {
EMSCRIPTEN_KEEPALIVE double flood_web_shrink_rect(int which, int k) {
    if (which < 0 || which > 2 || k < 0 || k > 3 || g_buttons[which].w <= 0) return -1;
    const Rect& r = g_buttons[which];
    return k == 0 ? r.x : k == 1 ? r.y : k == 2 ? r.w : r.h;
}
EMSCRIPTEN_KEEPALIVE const char* flood_web_shrink_note() { return g_note ? g_note->c_str() : ""; }
}
#endif

}  // namespace flood::view
