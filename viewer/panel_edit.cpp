// Live editing on the canvas (issue 12): the mouse and keys turned into viewer/edit.h's
// commands, the Edit toolbar at the canvas's top-right corner, the save panel, and what edit
// mode draws over the canvas (the hovered handle, the ring being drawn, the diagnostic of an
// invalid edit live).
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "download.h"
#include "panels.h"
#include "platform_glfw.h"

namespace flood::view {

EditUi::EditUi(Model& m) : editor(m) {
    // A few thousand vertices flood in tens of milliseconds (docs/BENCHMARKS.md): off the UI thread.
    editor.background = true;
    editor.onReady = platform::wake;
}

namespace {

// A clicked point rounded to the power of ten a pixel spans at this zoom: the saved file
// reads 3.25, not 3.2487713. Display-side only; what is stored is then exact.
Point snap(const Camera& cam, Point p) {
    const double k = std::clamp(std::ceil(std::log10(cam.scale())), -15.0, 15.0);
    Point q = p;
    if (k <= 0) {
        const double step = std::pow(10.0, -k);
        q = {std::round(p.x / step) * step, std::round(p.y / step) * step};
    } else {
        const double inv = std::pow(10.0, k);
        q = {std::round(p.x * inv) / inv, std::round(p.y * inv) / inv};
    }
    return std::isfinite(q.x) && std::isfinite(q.y) ? q : p;
}

void openSave(Ui& ui) {
    EditUi& e = ui.edit;
    std::snprintf(e.savePath, sizeof e.savePath, "%s", e.editor.defaultSavePath().c_str());
    e.overwrite = false;
    e.saveNote.clear();
    e.showSave = true;
}

void startDrawing(Ui& ui) {
    ui.edit.on = true;
    ui.edit.ringTool = true;
    ui.edit.editor.corners.clear();
}

void say(Ui& ui, bool ok) {
    const std::string& why = ui.edit.editor.message();
    if (!why.empty() || ok) ui.message = why;
}

}  // namespace

void editFrame(Ui& ui) {
    EditUi& e = ui.edit;
    e.editor.poll();
    e.hoverVertex = e.hoverEdge = kNone;    // found again by editCanvasInput when over the canvas
    const Polygon& p = e.editor.polygon();  // follows an open: drop a drag of what is gone
    if (e.dragVertex >= p.vertices.size()) e.dragVertex = kNone;
    if (e.dragRing >= p.rings.size()) e.dragRing = kNone;
    if (e.selected >= p.vertices.size()) e.selected = kNone;
    if (e.dragVertex == kNone && e.dragRing == kNone) return;
    // A drag goes on outside the canvas and ends wherever the button is let go.
    ImGuiIO& io = ImGui::GetIO();
    const Camera& cam = ui.model.camera();
    Vec2 mouse{io.MousePos.x, io.MousePos.y};
    if (io.MouseDelta.x != 0 || io.MouseDelta.y != 0) {
        Point at = cam.toWorld(mouse);
        if (e.dragVertex != kNone) e.editor.moveVertex(e.dragVertex, snap(cam, at));
        else e.editor.moveRing(e.dragRing, snap(cam, {at.x - e.dragStart.x, at.y - e.dragStart.y}));
    }
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        e.editor.endGesture();
        e.dragVertex = e.dragRing = kNone;
    }
}

bool editCanvasInput(Ui& ui, Vec2 mouse) {
    EditUi& e = ui.edit;
    Editor& ed = e.editor;
    const Camera& cam = ui.model.camera();
    const float s = ui.scale;
    if (e.dragVertex != kNone || e.dragRing != kNone) return true;
    const Point world = cam.toWorld(mouse);
    if (e.ringTool) {
        e.hoverVertex = e.hoverEdge = kNone;
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            // The first corner again closes the ring.
            const auto& c = ed.corners;
            Vec2 first = c.empty() ? Vec2{} : cam.toScreen(c.front());
            if (c.size() >= 3 && std::hypot(first.x - mouse.x, first.y - mouse.y) <= 8 * s) {
                bool ok = ed.closeRing();
                say(ui, ok);
                if (ok) e.ringTool = false;
            } else {
                ed.corners.push_back(snap(cam, world));
            }
        }
        return true;
    }
    e.hoverVertex = ed.pickVertex(mouse, 7 * s);
    e.hoverEdge = e.hoverVertex == kNone ? ed.pickEdge(mouse, 5 * s, &e.onEdge) : kNone;
    const bool shift = ImGui::GetIO().KeyShift;
    if (e.hoverVertex != kNone || e.hoverEdge != kNone) {
        ImGui::BeginTooltip();
        if (e.hoverVertex != kNone)
            ImGui::Text("vertex %u: drag to move, Delete removes it", e.hoverVertex);
        else ImGui::Text("edge from vertex %u: double-click inserts a vertex", e.hoverEdge);
        ImGui::TextDisabled("Shift+drag: move the whole ring");
        ImGui::EndTooltip();
    }
    if (e.hoverEdge != kNone && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
        bool ok = ed.insertVertex(e.hoverEdge, snap(cam, e.onEdge));
        say(ui, ok);
        if (ok) e.selected = e.hoverEdge + 1;
        return true;
    }
    if (!ImGui::IsMouseClicked(ImGuiMouseButton_Left)) return false;
    const Index grabbed = e.hoverVertex != kNone ? e.hoverVertex : e.hoverEdge;
    if (grabbed == kNone) return false;  // empty space: the drag pans
    ed.beginGesture();
    if (shift) {
        e.dragRing = ed.polygon().ringOf(grabbed);
        e.dragStart = world;
    } else if (e.hoverVertex != kNone) {
        e.dragVertex = e.hoverVertex;
        e.selected = e.hoverVertex;
    } else {
        ed.endGesture();  // a click on an edge: the double-click inserts
        return false;
    }
    return true;
}

void editOverlay(Ui& ui, ImDrawList* dl) {
    EditUi& e = ui.edit;
    if (!e.on) return;
    Editor& ed = e.editor;
    const Model& m = ui.model;
    const Camera& cam = m.camera();
    const float s = ui.scale;
    const Polygon& p = ed.polygon();
    const ImU32 handle = toImU32(palette::kHover), culprit = toImU32(palette::kCulprit);
    auto at = [&](Point q) {
        Vec2 v = cam.toScreen(q);
        return ImVec2(float(v.x), float(v.y));
    };
    // A flood still running: the canvas shows the old trace, the edited outline goes on top.
    if (ed.pending()) {
        size_t budget = 20000;
        for (const Ring& g : p.rings)
            for (Index i = 0; i < g.count && budget; ++i, --budget)
                dl->AddLine(at(p.vertices[g.first + i]),
                            at(p.vertices[g.first + (i + 1) % g.count]), handle, 1.5f * s);
    }
    if (e.hoverEdge != kNone && e.hoverEdge < p.vertices.size()) {
        const Ring& g = p.rings[p.ringOf(e.hoverEdge)];
        Index next = e.hoverEdge + 1 == g.first + g.count ? g.first : e.hoverEdge + 1;
        dl->AddLine(at(p.vertices[e.hoverEdge]), at(p.vertices[next]), handle, 3 * s);
        dl->AddCircle(at(e.onEdge), 4 * s, handle, 0, 1.5f * s);
    }
    for (Index v : {e.hoverVertex, e.selected, e.dragVertex})
        if (v < p.vertices.size()) {
            ImVec2 c = at(p.vertices[v]);
            dl->AddRect(ImVec2(c.x - 5 * s, c.y - 5 * s), ImVec2(c.x + 5 * s, c.y + 5 * s), handle,
                        0, 0, 2 * s);
        }
    // The ring being drawn, with a rubber band to the mouse.
    if (e.ringTool) {
        const auto& c = ed.corners;
        for (size_t i = 0; i + 1 < c.size(); ++i)
            dl->AddLine(at(c[i]), at(c[i + 1]), handle, 2 * s);
        ImVec2 mouse = ImGui::GetIO().MousePos;
        if (!c.empty()) dl->AddLine(at(c.back()), mouse, handle, 1 * s);
        for (size_t i = 0; i < c.size(); ++i)
            dl->AddCircleFilled(at(c[i]), (i == 0 ? 6 : 4) * s, handle);
    }
    // An invalid edit: the validator's culprits marked where they are, and its sentence.
    if (!m.inputDiagnostic().ok() && !ed.pending() && !m.errorView()) {
        const Culprits& k = m.errorCulprits();
        const Polygon& P = m.polygon();
        for (Index v : k.edges)
            if (v < P.vertices.size()) {
                const Ring& g = P.rings[P.ringOf(v)];
                dl->AddLine(at(P.vertices[v]),
                            at(P.vertices[v + 1 == g.first + g.count ? g.first : v + 1]), culprit,
                            4 * s);
            }
        for (Index v : k.vertices)
            if (v < P.vertices.size()) dl->AddCircleFilled(at(P.vertices[v]), 5 * s, culprit);
        Point x;
        if (m.errorPoint(x)) dl->AddCircle(at(x), 12 * s, culprit, 0, 3 * s);
        const Rect& area = ui.layout.canvas;
        dl->AddText(ImVec2(float(area.x + 12 * s), float(area.y + area.h - 24 * s)), culprit,
                    m.inputDiagnostic().message.c_str());
    }
    if (p.vertices.empty() && ed.corners.empty()) {
        const Rect& area = ui.layout.canvas;
        dl->AddText(ImVec2(float(area.x + 20 * s), float(area.y + 44 * s)), handle,
                    "draw your own: click the corners of the outer ring; Enter or a click on the "
                    "first corner closes it");
    }
}

void editBar(Ui& ui) {
    EditUi& e = ui.edit;
    Editor& ed = e.editor;
    const float s = ui.scale;
    ui.editBox = beginCanvasBar(ui, "##editbar", true);
    if (ImGui::Checkbox("Edit (M)", &e.on) && !e.on) e.ringTool = false;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("drag a vertex, double-click an edge, Delete, Shift+drag a ring");
    if (e.on) {
        ImGui::SameLine();
        if (ImGui::Checkbox("New ring (H)", &e.ringTool)) ed.corners.clear();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "click corners; Enter or the first corner closes: a hole inside, a new part "
                "outside");
        ImGui::SameLine();
        ImGui::BeginDisabled(!ed.canUndo());
        if (ImGui::Button("Undo")) say(ui, ed.undo());
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled) && ed.canUndo())
            ImGui::SetTooltip("Ctrl+Z: %s", ed.undoLabel().c_str());
        ImGui::EndDisabled();
        ImGui::SameLine();
        ImGui::BeginDisabled(!ed.canRedo());
        if (ImGui::Button("Redo")) say(ui, ed.redo());
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled) && ed.canRedo())
            ImGui::SetTooltip("Ctrl+Shift+Z or Ctrl+Y: %s", ed.redoLabel().c_str());
        ImGui::EndDisabled();
        ImGui::SameLine();
        if (ImGui::Button("Save...")) openSave(ui);
        ImGui::SameLine();
        if (ImGui::Button("New")) {
            ed.newEmpty();
            startDrawing(ui);
        }
        if (ed.pending()) ImGui::TextDisabled("flooding the edit...");
    }
    ImGui::End();

    if (!e.showSave) return;
    if (!beginFloating(ui, "Save polygon", &e.showSave, 460, 130, 60, 60)) return;
    ImGui::SetNextItemWidth(-80 * s);
    bool go = ImGui::InputText("##savepath", e.savePath, sizeof e.savePath,
                               ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    go |= ImGui::Button("Save");
    std::error_code ec;
    const bool exists = e.savePath[0] && std::filesystem::exists(e.savePath, ec);
    if (exists) ImGui::Checkbox("the file exists: overwrite it", &e.overwrite);
    if (go) {
        if (exists && !e.overwrite) {
            e.saveNote = std::string(e.savePath) + " exists: tick \"overwrite it\" to replace it";
        } else {
            Diagnostic d = ed.save(e.savePath, e.overwrite);
            std::string error;  // in the page, the file reaches the user as a download
            if (d.ok() && !offerDownload(e.savePath, &error)) d = {Status::WriteFailed, error};
            e.saveNote = d.ok() ? "saved " + std::string(e.savePath) : d.message;
            if (d.ok()) ui.message = e.saveNote;
        }
    }
    ImGui::TextWrapped("%s",
                       e.saveNote.empty() ? "GeoJSON, written atomically" : e.saveNote.c_str());
    ImGui::End();
}

void editShortcuts(Ui& ui) {
    ImGuiIO& io = ImGui::GetIO();
    EditUi& e = ui.edit;
    Editor& ed = e.editor;
    auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
    if (io.KeyCtrl) {
        if (pressed('Z')) say(ui, io.KeyShift ? ed.redo() : ed.undo());
        if (pressed('Y')) say(ui, ed.redo());
        if (pressed('S')) openSave(ui);
        if (pressed('N')) {
            ed.newEmpty();
            startDrawing(ui);
        }
        return;
    }
    if (pressed('M')) {
        e.on = !e.on;
        if (!e.on) e.ringTool = false;
    }
    if (!e.on) return;
    if (pressed('H')) {
        e.ringTool = !e.ringTool;
        ed.corners.clear();
    }
    if (e.ringTool && pressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) {
        bool ok = ed.closeRing();
        say(ui, ok);
        if (ok) e.ringTool = false;
    }
    if (e.ringTool && pressed(ImGui::GetKeyIndex(ImGuiKey_Backspace)) && !ed.corners.empty())
        ed.corners.pop_back();
    if (pressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
        ed.corners.clear();
        e.ringTool = false;
    }
    if (pressed(ImGui::GetKeyIndex(ImGuiKey_Delete))) {
        Index v = e.hoverVertex != kNone ? e.hoverVertex : e.selected;
        if (v != kNone) {
            say(ui, ed.deleteVertex(v));
            e.selected = e.hoverVertex = kNone;
        }
    }
}

}  // namespace flood::view
