// The polygon canvas: static world-space buffers uploaded once per trace, the per-step
// overlay uploaded when the step changes, the camera handed to the renderer as a uniform
// (GL, under ImGui); text labels and tooltips go to ImGui's background draw list, clipped to
// the canvas rectangle. Labels are culled through a grid so a huge polygon costs what is
// on screen.
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "geometry/number_text.h"
#include "gorge_focus.h"
#include "label_layout.h"
#include "panels.h"
#include "platform_glfw.h"
#include "scene_labels.h"

namespace flood::view {

namespace {

// Side of a cell of the marker thinning grid, in pixels before UI scale: nearly four radii
// of a class dot, so where thinning bites the dots cover a quarter of the screen at most.
constexpr double kMarkerCell = 16;
// From this many vertices the thin boundary is decimated to the pixel grid (pixelBoundary):
// below it a face draws every edge, as the pixel tests' small faces always have.
constexpr size_t kPixelBoundaryFrom = 20000;

// The thin boundary for the camera: decimated when that leaves at most half the edges, else
// none (every edge drawn). FLOOD_VIEWER_EXACT_BOUNDARY=1 draws every edge (a test's baseline,
// and the exact picture should one be wanted).
std::vector<uint32_t> decimatedBoundary(const Model& m) {
    static const bool exact = [] {
        const char* e = std::getenv("FLOOD_VIEWER_EXACT_BOUNDARY");
        return e && *e && std::string(e) != "0";
    }();
    const Polygon& P = m.polygon();
    if (exact || P.vertices.size() < kPixelBoundaryFrom) return {};
    const float ratio = std::max(ImGui::GetIO().DisplayFramebufferScale.x, 1.f);
    std::vector<uint32_t> lines = pixelBoundary(P, m.camera(), 1.0 / ratio);
    if (lines.size() > P.vertices.size()) return {};  // more than half of the 2n indices
    return lines;
}

void canvasInput(Ui& ui) {
    Model& m = ui.model;
    ImGuiIO& io = ImGui::GetIO();
    Vec2 mouse{io.MousePos.x, io.MousePos.y};
    // Only when no ImGui window wants the mouse: panels keep their clicks and scrolls.
    if (io.WantCaptureMouse || !ui.layout.canvas.contains(mouse)) return;
    // ---- live editing (panel_edit.cpp): edit mode takes the left button when it grabs a
    // vertex, a ring or places a corner, and has its own hover; wheel and middle drag still
    // move the view, a left drag on empty space still pans.
    const bool editing = ui.edit.on;
    const bool leftTaken = editing && editCanvasInput(ui, mouse);
    if ((ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0) && !leftTaken) ||
        ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0))
        m.pan(io.MouseDelta.x, io.MouseDelta.y);
    if (io.MouseWheel != 0) m.zoomAt(mouse, std::pow(1.15, double(io.MouseWheel)));
    if (editing) return;
    // ---- end of live editing

    CanvasState& cs = ui.canvas;
    std::array<double, 6> key{
        mouse.x,         mouse.y, m.camera().center().x, m.camera().center().y, m.camera().scale(),
        double(m.step())};
    if (key != cs.pickKey) {
        cs.pickKey = key;
        cs.pickedVertex = m.pickVertex(mouse, 7 * ui.scale);
        cs.pickedTriangle = cs.pickedVertex == kNone ? m.pickTriangle(mouse) : -1;
    }
    Index v = cs.pickedVertex;
    int64_t t = cs.pickedTriangle;
    if (v != kNone) {
        const Polygon& p = m.polygon();
        Index ring = p.ringOf(v);
        ImGui::BeginTooltip();
        ImGui::Text("vertex %u  (ring %u, #%u in ring)", v, ring, v - p.rings[ring].first);
        ImGui::TextUnformatted(formatPoint(p.vertices[v]).c_str());
        ImGui::Text("class: %s", vertexClassName(m.classes()[v]));
        const Fingers& f = m.state().fingers;
        if (v == f.left) ImGui::TextColored(toImVec4(palette::kLeft), "Left");
        if (v == f.right) ImGui::TextColored(toImVec4(palette::kRight), "Right");
        if (v == f.nextLeft) ImGui::TextColored(toImVec4(palette::kNextLeft), "NextLeft");
        if (v == f.nextRight) ImGui::TextColored(toImVec4(palette::kNextRight), "NextRight");
        if (v == m.state().water) ImGui::Text("water level");
        for (auto [top, to] : m.state().jumps)
            if (top == v) ImGui::TextColored(toImVec4(palette::kJump), "jump pointer -> %u", to);
        ImGui::TextDisabled("right-click: break when it becomes Left/Right/Next");
        ImGui::EndTooltip();
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
            Breakpoints b = m.breakpoints();
            b.vertex = v;
            m.setBreakpoints(b);
            ui.message = "breakpoint on vertex " + std::to_string(v);
        }
    } else if (t >= 0) {
        const Triangle& tri = m.trace().triangles[size_t(t)];
        uint32_t step = m.triangleStep(uint32_t(t));
        ImGui::BeginTooltip();
        ImGui::Text("triangle %lld: %u %u %u", (long long)t, tri[0], tri[1], tri[2]);
        if (step > 0) {
            const Event& e = m.trace().events[step - 1];
            ImGui::Text("cut at step %u by %s", step, actionName(e.action));
            ImGui::TextDisabled("click: go to that step");
        }
        ImGui::EndTooltip();
        if (step > 0 && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
            io.MouseDragMaxDistanceSqr[0] < io.MouseDragThreshold * io.MouseDragThreshold)
            m.seek(step);
    }
}

// Uploads what changed since the last frame: the whole geometry after an open (prepared with
// the run, off the UI thread: prepared_run.h), the overlay after a step or a display option
// changed.
void syncBuffers(Ui& ui) {
    Model& m = ui.model;
    CanvasState& cs = ui.canvas;
    if (cs.generation != m.generation()) {
        std::shared_ptr<PreparedCanvas> prepared = m.takeCanvas();
        if (!prepared) prepared = prepareCanvas(m);
        PreparedCanvas& p = *prepared;
        const CanvasGeometry& g = p.geometry;
        ui.renderer.setGeometry(g);
        cs.origin = g.origin;
        std::copy(g.bbox, g.bbox + 4, cs.bbox);
        cs.grid = std::move(p.grid);
        cs.vertexGrid = std::move(p.vertexGrid);
        cs.vertexMarkers = std::move(p.vertexMarkers);
        cs.generation = m.generation();
        cs.overlayStep = ~0u;
    }
    const SceneOptions& o = ui.sceneOptions;
    const SceneOptions& was = cs.overlayOptions;
    if (cs.overlayStep != m.step() || o.dormant != was.dormant || o.jumps != was.jumps ||
        o.ghost != was.ghost) {
        cs.overlay = buildCanvasOverlay(m, o, cs.origin);
        ui.renderer.setOverlay(cs.overlay.lines);
        cs.overlayStep = m.step();
        cs.overlayOptions = o;
        cs.thinKey = {};
    }
    // Markers thinned to one per cell of a screen grid: redone when the camera moves.
    const Camera& cam = m.camera();
    const Rect& r = cam.viewport();
    std::array<double, 8> key{cam.center().x,  cam.center().y, cam.scale(), r.w, r.h, r.x, r.y,
                              double(m.step())};
    if (key != cs.thinKey) {
        cs.thinKey = key;
        const double cell = kMarkerCell * ui.scale;
        const auto& all = cs.overlay.markers;
        std::vector<MarkerVertex> gorges(all.begin(), all.begin() + cs.overlay.gorgeMarkers);
        std::vector<MarkerVertex> overlay = thinMarkers(gorges, cs.origin, cam, cell);
        overlay.insert(overlay.end(), all.begin() + cs.overlay.gorgeMarkers, all.end());
        ui.renderer.setMarkers(thinMarkers(cs.vertexMarkers, cs.origin, cam, cell), overlay);
        const std::vector<uint32_t> boundary = decimatedBoundary(m);
        ui.renderer.setPixelBoundary(boundary);
        cs.pixelBoundaryLines = boundary.size() / 2;
    }
}

// Whether a small number gives way: its box would cover a placed label, or a label names
// its vertex or triangle already (`vertex` or `triangle` kNone: not asked).
bool givesWay(const std::vector<ShownLabel>& shown, const Rect& box, Index vertex,
              uint32_t triangle) {
    return std::any_of(shown.begin(), shown.end(), [&](const ShownLabel& l) {
        const bool named = l.label->kind == Scene::LabelKind::Named &&
                           ((vertex != kNone && l.label->vertex == vertex) ||
                            (triangle != kNone && l.label->triangle == triangle));
        return named || overlap(l.at.box, box, 1);
    });
}

// Triangle numbers, only when few enough are on screen to read (visibleLabels), except
// where a placed label is (a named triangle's label says its number).
void triangleLabels(Ui& ui, ImDrawList* dl, const std::vector<ShownLabel>& shown) {
    const Model& m = ui.model;
    const Camera& cam = m.camera();
    const float s = ui.scale;
    uint32_t n = std::min<uint32_t>(m.state().triangleCount, uint32_t(m.trace().triangles.size()));
    const Event* ev = m.currentEvent();
    uint32_t curFirst = ev ? ev->firstTriangle : n;
    char text[16];
    // px², about four times a label's own footprint
    for (uint32_t t : visibleLabels(ui.canvas.grid, cam, n, 700 * s * s)) {
        Vec2 c = cam.toScreen(ui.canvas.grid.centroid(t));
        std::snprintf(text, sizeof text, "%u", t);
        ImVec2 size = ImGui::CalcTextSize(text);
        const Rect box{c.x - size.x / 2, c.y - size.y / 2, size.x, size.y};
        if (givesWay(shown, box, kNone, t)) continue;
        Rgba color = t >= curFirst ? Rgba{0, 0, 0, 255} : Rgba{230, 240, 255, 255};
        dl->AddText(ImVec2(float(box.x), float(box.y)), toImU32(color), text);
    }
}

// The caption's large font (the presenter's), rebuilt at the UI scale: what a class reads.
ImFont* largeFont(const Ui& ui) { return ui.captionFont ? ui.captionFont : ImGui::GetFont(); }

// Vertex numbers beside their vertex, through the same culling: a vertex's room is the
// distance to its nearest neighbour, which must be longer on screen than a six-digit label.
// In presenter view they are in the large font (and need as much more room). A placed label
// keeps its place: a number that would cover one is left out.
void vertexLabels(Ui& ui, ImDrawList* dl, const std::vector<ShownLabel>& shown) {
    const Model& m = ui.model;
    const Camera& cam = m.camera();
    const float s = ui.scale;
    ImFont* font = ui.presenter ? largeFont(ui) : ImGui::GetFont();
    const float k = font->FontSize / ImGui::GetFont()->FontSize;
    const double room = 44 * s * k;
    char text[16];
    for (uint32_t i : visibleLabels(ui.canvas.vertexGrid, cam,
                                    uint32_t(m.polygon().vertices.size()), room * room)) {
        Vec2 c = cam.toScreen(m.polygon().vertices[i]);
        std::snprintf(text, sizeof text, "%u", i);
        const ImVec2 size = font->CalcTextSizeA(font->FontSize, FLT_MAX, 0, text);
        const Rect box{c.x + 5 * s, c.y - 16 * s * k, size.x, size.y};
        if (givesWay(shown, box, i, kNone)) continue;
        dl->AddText(font, font->FontSize, ImVec2(float(box.x), float(box.y)),
                    toImU32(palette::kVertexNumber), text);
    }
}

// The font a step label is drawn in: the sentence's names in the large font, and in
// presenter view the fingers and their ghosts too, readable from the back of a room.
ImFont* labelFont(const Ui& ui, const Scene::Label& l) {
    using Kind = Scene::LabelKind;
    const bool large = l.kind == Kind::Named ||
                       (ui.presenter && (l.kind == Kind::Finger || l.kind == Kind::Ghost));
    return large ? largeFont(ui) : ImGui::GetFont();
}

constexpr float kLabelPad = 2;  // around a label's text, before UI scale

std::vector<ShownLabel> placeStepLabels(const Ui& ui, const std::vector<Scene::Label>& labels) {
    const float s = ui.scale;
    auto size = [&](const Scene::Label& l) {
        ImFont* f = labelFont(ui, l);
        const ImVec2 t = f->CalcTextSizeA(f->FontSize, FLT_MAX, 0, l.text.c_str());
        return Vec2{t.x + 2 * kLabelPad * s, t.y + 2 * kLabelPad * s};
    };
    return placeSceneLabels(labels, ui.model.camera(), ui.layout.canvas, ui.canvas.obstacles, size,
                            s);
}

// The sentence's names on a plate of the background, so they read over water and land;
// the others as text. A label moved away from its point, and a finger's, is tied to it by a
// line.
void drawStepLabels(Ui& ui, ImDrawList* dl, const std::vector<ShownLabel>& shown) {
    const float s = ui.scale;
    Rgba plate = palette::kBackground;
    plate.a = 215;
    for (const ShownLabel& sl : shown) {
        const Scene::Label& l = *sl.label;
        const Rect& b = sl.at.box;
        const bool named = l.kind == Scene::LabelKind::Named;
        // A finger's letter is tied to its marker even beside it: where L, R and the fingers
        // crowd one corner, which letter is whose must not be a guess.
        const bool finger = l.kind == Scene::LabelKind::Finger || l.kind == Scene::LabelKind::Ghost;
        if (sl.at.leader || finger)
            dl->AddLine(ImVec2(float(sl.at.from.x), float(sl.at.from.y)),
                        ImVec2(float(sl.at.to.x), float(sl.at.to.y)), toImU32(l.color),
                        (named ? 1.5f : 1.f) * s);
        if (named)
            dl->AddRectFilled(ImVec2(float(b.x), float(b.y)),
                              ImVec2(float(b.x + b.w), float(b.y + b.h)), toImU32(plate), 3 * s);
        ImFont* f = labelFont(ui, l);
        dl->AddText(f, f->FontSize, ImVec2(float(b.x + kLabelPad * s), float(b.y + kLabelPad * s)),
                    toImU32(l.color), l.text.c_str());
        const std::string what = l.vertex != kNone     ? "vertex-" + std::to_string(l.vertex)
                                 : l.triangle != kNone ? "triangle-" + std::to_string(l.triangle)
                                                       : "gorge";
        const char* kind[] = {"named-", "finger-", "ghost-", "gorge-", "number-"};
        ui.stepLabels.push_back({kind[int(l.kind)] + what, b});
    }
}

// "Current gorge only": everything outside the active gorge's outline dimmed like the error
// view (gorge_focus.h), the dim rows rebuilt only when the step or the camera moved.
void gorgeFocus(Ui& ui) {
    const Model& m = ui.model;
    const Rect& area = ui.layout.canvas;
    CanvasState& cs = ui.canvas;
    const Camera& cam = m.camera();
    std::array<double, 8> key{
        cam.center().x, cam.center().y,
        cam.scale(),    area.x,
        area.y,         area.w,
        area.h,         double(m.step()) + double(m.generation()) * 4294967296.0};
    if (key != cs.focusKey) {
        cs.focusKey = key;
        std::vector<Vec2> outline;
        for (Point p : activeGorgeOutline(m)) outline.push_back(cam.toScreen(p));
        cs.focusDim = outline.size() >= 3 ? outsideOf(outline, area) : std::vector<Rect>{};
    }
    Rgba dim = palette::kBackground;
    dim.a = 200;
    for (const Rect& r : cs.focusDim) {
        ui.renderer.addTriangle(Layer::Lines, {r.x, r.y}, {r.x + r.w, r.y}, {r.x + r.w, r.y + r.h},
                                dim);
        ui.renderer.addTriangle(Layer::Lines, {r.x, r.y}, {r.x + r.w, r.y + r.h}, {r.x, r.y + r.h},
                                dim);
    }
}

// A culprit label's text: "v205 (ring 0 #205)", or for coincident vertices one label
// "v205 = v207 (ring 0 #205, #207)" (rings apart: "v3 (ring 0 #3) = v9 (ring 1 #0)").
std::string culpritLabel(const Polygon& P, const std::vector<Index>& group) {
    std::string names, where;
    bool oneRing = true;
    for (Index v : group) oneRing = oneRing && P.ringOf(v) == P.ringOf(group.front());
    for (Index v : group) {
        const Index r = P.ringOf(v);
        const std::string at = "#" + std::to_string(v - P.rings[r].first);
        names += (names.empty() ? "v" : " = v") + std::to_string(v);
        if (oneRing) where += (where.empty() ? "ring " + std::to_string(r) + " " : ", ") + at;
        else names += " (ring " + std::to_string(r) + " " + at + ")";
    }
    return oneRing ? names + " (" + where + ")" : names;
}

// The error view: the canvas dimmed; the current finding's culprit edges thick (only they:
// a ring named as context, such as the outer ring a hole lies outside of, stays thin), its
// point ringed, the other findings' points small rings; each culprit vertex labelled once
// ("v205 = v207" for coincident ones), the labels kept apart and out from under the boxes
// over the canvas (label_layout.h). Model::showFinding framed them.
void errorOverlay(Ui& ui, ImDrawList* dl) {
    const Model& m = ui.model;
    const Camera& cam = m.camera();
    const Rect& area = ui.layout.canvas;
    const Polygon& P = m.polygon();
    const Culprits& c = m.errorCulprits();
    const float s = ui.scale;
    Renderer& r = ui.renderer;
    Vec2 a{area.x, area.y}, b{area.x + area.w, area.y}, d{area.x, area.y + area.h},
        e{area.x + area.w, area.y + area.h};
    Rgba dim = palette::kBackground;
    dim.a = 200;
    r.addTriangle(Layer::Lines, a, b, e, dim);
    r.addTriangle(Layer::Lines, a, e, d, dim);
    auto edgeEnd = [&](Index v) {
        const Ring& ring = P.rings[P.ringOf(v)];
        return v + 1 == ring.first + ring.count ? ring.first : v + 1;
    };
    for (Index v : c.edges)
        if (v < P.vertices.size())
            r.addLine(Layer::Lines, cam.toScreen(P.vertices[v]),
                      cam.toScreen(P.vertices[edgeEnd(v)]), 6 * s, palette::kCulprit);
    for (uint32_t t : c.triangles)
        if (t < m.trace().triangles.size()) {
            const Triangle& tri = m.trace().triangles[t];
            if (tri[0] < P.vertices.size() && tri[1] < P.vertices.size() &&
                tri[2] < P.vertices.size())
                for (int k = 0; k < 3; ++k)
                    r.addLine(Layer::Lines, cam.toScreen(P.vertices[tri[k]]),
                              cam.toScreen(P.vertices[tri[(k + 1) % 3]]), 4 * s, palette::kCulprit);
        }
    // Only rings blamed: the ring at fault (a validation finding's first ring: the hole
    // outside its outer ring, the hole inside another) thick, the others it names thin, as
    // context; a machine's or checker's rings (the fingers' rings) are all context. Up to a
    // bound, so a huge ring stays a frame's work.
    const bool validation =
        !m.findings().empty() && m.findings()[m.currentFinding()].kind == Verdict::Invalid;
    if (c.edges.empty() && c.triangles.empty() && !c.hasPoint) {
        size_t budget = 50000;
        Rgba context = palette::kCulprit;
        context.a = 150;
        for (size_t k = 0; k < c.rings.size(); ++k) {
            const Index ring = c.rings[k];
            if (ring >= P.rings.size()) continue;
            const bool atFault = validation && k == 0;
            const Ring& g = P.rings[ring];
            for (Index i = 0; i < g.count && budget; ++i, --budget)
                r.addLine(Layer::Lines, cam.toScreen(P.vertices[g.first + i]),
                          cam.toScreen(P.vertices[g.first + (i + 1) % g.count]),
                          (atFault ? 3.f : 1.5f) * s, atFault ? palette::kCulprit : context);
        }
    }
    // The other findings, where they are: a small ring each (the current one is ringed large).
    Rgba other = palette::kCulprit;
    other.a = 170;
    for (size_t i = 0; i < m.findings().size() && i < 1000; ++i) {
        const Finding& f = m.findings()[i];
        if (i == m.currentFinding() || !f.hasPoint) continue;
        Vec2 p = cam.toScreen(f.point);
        if (area.contains(p)) r.addCircle(Layer::Markers, p, 7 * s, 1.5f * s, other);
    }
    Point x;
    if (m.errorPoint(x))
        r.addCircle(Layer::Markers, cam.toScreen(x), 12 * s, 3 * s, palette::kCulprit);
    // The culprit vertices: a dot each, and a label per point (coincident vertices share one).
    std::vector<Index> shown;
    std::vector<Point> at;
    for (Index v : c.vertices) {
        if (v >= P.vertices.size() || shown.size() >= 64) continue;
        Vec2 p = cam.toScreen(P.vertices[v]);
        r.addDisc(Layer::Markers, p, 4 * s, palette::kCulprit);
        if (!area.contains(p)) continue;
        shown.push_back(v);
        at.push_back(P.vertices[v]);
    }
    std::vector<LabelRequest> requests;
    std::vector<std::string> texts;
    for (const PointGroup& g : groupCoincident(at)) {
        std::vector<Index> group;
        for (size_t k : g.members) group.push_back(shown[k]);
        texts.push_back(culpritLabel(P, group));
        ImVec2 size = ImGui::CalcTextSize(texts.back().c_str());
        const double pad = 2 * s;
        requests.push_back({cam.toScreen(g.at), size.x + 2 * pad, size.y + 2 * pad, false, {}});
    }
    std::vector<PlacedLabel> placed =
        placeLabels(requests, area, ui.canvas.obstacles, 3 * s, 14 * s, 260 * s);
    ui.labels.clear();
    Rgba back = palette::kBackground;
    back.a = 215;
    for (size_t i = 0; i < placed.size(); ++i) {
        const PlacedLabel& l = placed[i];
        if (l.leader)
            dl->AddLine(ImVec2(float(l.from.x), float(l.from.y)),
                        ImVec2(float(l.to.x), float(l.to.y)), toImU32(palette::kCulprit), 1.5f * s);
        const ImVec2 p0(float(l.box.x), float(l.box.y)),
            p1(float(l.box.x + l.box.w), float(l.box.y + l.box.h));
        dl->AddRectFilled(p0, p1, toImU32(back), 3 * s);
        dl->AddText(ImVec2(p0.x + 2 * s, p0.y + 2 * s), toImU32(palette::kCulprit),
                    texts[i].c_str());
        ui.labels.push_back(l.box);
    }
}

// The locator inset: when the view is far inside the face, the whole face small in the
// canvas's bottom-right corner and a box where the view is (a cross when the box is a dot).
// Its rectangle, or an empty one when the view is not zoomed far in.
Rect insetRect(const Ui& ui) {
    const Model& m = ui.model;
    const CanvasState& cs = ui.canvas;
    const Rect& area = ui.layout.canvas;
    if (m.polygon().vertices.empty() || cs.generation != m.generation()) return {};
    const double fw = double(cs.bbox[2]) - cs.bbox[0], fh = double(cs.bbox[3]) - cs.bbox[1];
    const WorldBox view = visibleBox(m.camera());
    if (!(fw > 0 || fh > 0) || view.empty()) return {};
    // Far in: the view shows less than a sixth of the face across.
    if (std::max(view.w() / std::max(fw, 1e-300), view.h() / std::max(fh, 1e-300)) > 1.0 / 6)
        return {};
    const float s = ui.scale;
    double w = 150 * s, h = 110 * s;  // the face's shape, at most this large
    if (fw * h > fh * w) h = w * fh / fw;
    else w = h * fw / fh;
    w = std::max(w, 40.0 * s), h = std::max(h, 40.0 * s);
    if (area.w < 3 * w || area.h < 3 * h) return {};
    const double pad = 8 * s;
    return {area.x + area.w - w - pad - 2 * s, area.y + area.h - h - pad - 2 * s, w + 4 * s,
            h + 4 * s};
}

void drawInset(Ui& ui, ImDrawList* dl) {
    const Rect& box = ui.inset;
    if (box.w <= 0) return;
    const Model& m = ui.model;
    const CanvasState& cs = ui.canvas;
    const Polygon& P = m.polygon();
    const float s = ui.scale;
    const double inner = 2 * s;
    const double x0 = cs.origin.x + cs.bbox[0], y0 = cs.origin.y + cs.bbox[1];
    const double fw = std::max(double(cs.bbox[2]) - cs.bbox[0], 1e-300),
                 fh = std::max(double(cs.bbox[3]) - cs.bbox[1], 1e-300);
    const double k = std::min((box.w - 2 * inner) / fw, (box.h - 2 * inner) / fh);
    const double ox = box.x + (box.w - fw * k) / 2, oy = box.y + (box.h + fh * k) / 2;
    auto map = [&](Point p) {
        return ImVec2(float(ox + (p.x - x0) * k), float(oy - (p.y - y0) * k));
    };
    Rgba back = palette::kBackground;
    back.a = 230;
    dl->AddRectFilled(ImVec2(float(box.x), float(box.y)),
                      ImVec2(float(box.x + box.w), float(box.y + box.h)), toImU32(back), 3 * s);
    dl->AddRect(ImVec2(float(box.x), float(box.y)),
                ImVec2(float(box.x + box.w), float(box.y + box.h)), toImU32(palette::kBoundary),
                3 * s);
    // The rings, a point every half pixel or more apart (a million vertices: a few hundred
    // segments), gathered once per trace and inset.
    CanvasState& cache = ui.canvas;
    const std::array<double, 5> key{double(m.generation()), box.x, box.y, box.w, box.h};
    if (cache.insetKey != key) {
        cache.insetKey = key;
        cache.insetSegments.clear();
        for (const Ring& g : P.rings) {
            if (g.count < 2) continue;
            ImVec2 last = map(P.vertices[g.first]), first = last;
            for (Index i = 1; i <= g.count; ++i) {
                ImVec2 q = i == g.count ? first : map(P.vertices[g.first + i]);
                if (std::abs(q.x - last.x) + std::abs(q.y - last.y) < 0.5f && i != g.count)
                    continue;
                cache.insetSegments.push_back({last.x, last.y});
                cache.insetSegments.push_back({q.x, q.y});
                last = q;
            }
        }
    }
    const ImU32 line = toImU32(palette::kBoundary);
    for (size_t i = 0; i + 1 < cache.insetSegments.size(); i += 2) {
        const Vec2 p = cache.insetSegments[i], q = cache.insetSegments[i + 1];
        dl->AddLine(ImVec2(float(p.x), float(p.y)), ImVec2(float(q.x), float(q.y)), line, 1);
    }
    // Where the view is.
    const WorldBox view = visibleBox(m.camera());
    ImVec2 a = map({view.x0, view.y1}), b = map({view.x1, view.y0});
    const ImU32 mark = toImU32(palette::kCulprit);
    if (b.x - a.x < 4 && b.y - a.y < 4) {
        const ImVec2 c((a.x + b.x) / 2, (a.y + b.y) / 2);
        const float arm = 6 * s;
        dl->AddLine(ImVec2(c.x - arm, c.y), ImVec2(c.x + arm, c.y), mark, 1.5f * s);
        dl->AddLine(ImVec2(c.x, c.y - arm), ImVec2(c.x, c.y + arm), mark, 1.5f * s);
    }
    dl->AddRect(a, ImVec2(std::max(b.x, a.x + 2), std::max(b.y, a.y + 2)), mark, 0, 0, 1.5f * s);
}

// The find box and the "Show error" button, floating at the canvas's top-left corner.
void canvasBar(Ui& ui) {
    Model& m = ui.model;
    const float s = ui.scale;
    ui.findBox = beginCanvasBar(ui, "##canvasbar", false);
    ImGuiIO& io = ImGui::GetIO();
    bool keys = !io.WantTextInput;
    if (ui.focusFind || (io.KeyCtrl && ImGui::IsKeyPressed(platform::kKeyF, false))) {
        ImGui::SetKeyboardFocusHere();
        ui.focusFind = false;
    }
    ImGui::SetNextItemWidth(140 * s);
    if (ImGui::InputTextWithHint("##find", "find v12 t3 s40 r1", ui.findText, sizeof ui.findText,
                                 ImGuiInputTextFlags_EnterReturnsTrue)) {
        FindTarget f = m.find(ui.findText);
        ui.message = f.message;
        ui.findFailed = !f.ok;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Ctrl+F: v<vertex>, t<triangle>, s<step>, r<ring>");
    if (m.failed()) {
        ImGui::SameLine();
        bool go = ImGui::Button(m.errorView() ? "Hide error (E)" : "Show error (E)");
        go |= keys && !io.KeyCtrl && ImGui::IsKeyPressed('E', false);
        if (go) {
            if (m.errorView()) m.hideError();
            else if (!m.showError()) ui.message = "no culprit to show";
        }
    }
    if (!ui.message.empty() && ui.findFailed)
        ImGui::TextColored(toImVec4(palette::kCulprit), "%s", ui.message.c_str());
    ImGui::End();
}

// The up arrow's words, in the large font in presenter view (read from the back of a room).
std::string upArrowText(Up up) {
    char text[48];
    std::snprintf(text, sizeof text, "water rises %.0f°", upDegrees(up));
    return text;
}
ImFont* upArrowFont(const Ui& ui) { return ui.presenter ? largeFont(ui) : ImGui::GetFont(); }

// The turned flood direction on the canvas: a round plate in upArrowRect with an arrow the way
// the water rises and its angle, so the picture says why the gorges lie as they do.
void drawUpArrow(Ui& ui, ImDrawList* dl) {
    const Rect box = upArrowRect(ui);
    if (box.w <= 0) return;
    const float s = ui.scale;
    const Up up = ui.model.up();
    const double len = std::hypot(up.x, up.y);
    const float ux = float(up.x / len), uy = float(-up.y / len);  // screen y grows down
    const float r = 30 * s;
    const ImVec2 c(float(box.x + box.w / 2), float(box.y + r + 4 * s));
    Rgba plate = palette::kBackground;
    plate.a = 215;
    dl->AddCircleFilled(c, r, toImU32(plate), 48);
    dl->AddCircle(c, r, toImU32(palette::kBoundary), 48, 1.5f * s);
    const ImU32 ink = toImU32(palette::kWaterLevel);
    const ImVec2 tail(c.x - ux * r * 0.7f, c.y - uy * r * 0.7f),
        tip(c.x + ux * r * 0.45f, c.y + uy * r * 0.45f);
    const float head = 12 * s;
    dl->AddLine(tail, tip, ink, 3.5f * s);
    dl->AddTriangleFilled(ImVec2(tip.x + ux * head, tip.y + uy * head),
                          ImVec2(tip.x - uy * head * 0.6f, tip.y + ux * head * 0.6f),
                          ImVec2(tip.x + uy * head * 0.6f, tip.y - ux * head * 0.6f), ink);
    const std::string text = upArrowText(up);
    ImFont* f = upArrowFont(ui);
    const ImVec2 t = f->CalcTextSizeA(f->FontSize, FLT_MAX, 0, text.c_str());
    const ImVec2 at(float(box.x + (box.w - t.x) / 2), float(box.y + box.h - t.y - 2 * s));
    dl->AddRectFilled(ImVec2(at.x - 2 * s, at.y - 1 * s), ImVec2(at.x + t.x + 2 * s, at.y + t.y),
                      toImU32(plate), 3 * s);
    dl->AddText(f, f->FontSize, at, ink, text.c_str());
}

// Save PNG's confirmation: the full path wrapped over the canvas's bottom, on a plate, for a
// few seconds (a status line would clip it).
void drawToast(Ui& ui, ImDrawList* dl) {
    if (ui.toast.empty() || platform::time() > ui.toastUntil) return;
    const Rect& area = ui.layout.canvas;
    const float s = ui.scale, pad = 8 * s;
    const float wrap = float(std::max(60.0, area.w - 4 * pad));
    const ImVec2 t = ImGui::CalcTextSize(ui.toast.c_str(), nullptr, false, wrap);
    const ImVec2 p0(float(area.x + (area.w - t.x) / 2 - pad),
                    float(area.y + area.h - t.y - 3 * pad));
    Rgba plate = palette::kBackground;
    plate.a = 235;
    const Rgba ink = ui.toastFailed ? palette::kCulprit : palette::kOk;
    dl->AddRectFilled(p0, ImVec2(p0.x + t.x + 2 * pad, p0.y + t.y + 2 * pad), toImU32(plate),
                      4 * s);
    dl->AddRect(p0, ImVec2(p0.x + t.x + 2 * pad, p0.y + t.y + 2 * pad), toImU32(ink), 4 * s, 0,
                1.5f * s);
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(p0.x + pad, p0.y + pad),
                toImU32(ink), ui.toast.c_str(), nullptr, wrap);
}

}  // namespace

Rect upArrowRect(const Ui& ui) {
    const Model& m = ui.model;
    const Up up = m.up();
    if (m.polygon().vertices.empty() || !up.valid() || std::fabs(upDegrees(up) - 90) < 1e-9)
        return {};
    const Rect& area = ui.layout.canvas;
    const float s = ui.scale;
    ImFont* f = upArrowFont(ui);
    const ImVec2 t = f->CalcTextSizeA(f->FontSize, FLT_MAX, 0, upArrowText(up).c_str());
    const double w = std::max(120.0 * s, t.x + 8.0 * s), h = 72 * s + t.y, pad = 8 * s;
    if (area.w < 3 * w || area.h < 3 * h) return {};
    return {area.x + pad, area.y + area.h - h - pad, w, h};
}

std::vector<Rect> canvasOverlays(const Ui& ui) {
    std::vector<Rect> over;
    if (!ui.presenter)
        for (const Rect& r :
             {ui.findBox, ui.editBox, ui.shrinkBox, ui.directionBox, ui.stateTableBox})
            if (r.w > 0 && r.h > 0) over.push_back(r);
    if (const Rect r = upArrowRect(ui); r.w > 0) over.push_back(r);
    if (ui.openingBox.w > 0) over.push_back(ui.openingBox);  // in either view
    return over;
}

void drawCanvas(Ui& ui) {
    Model& m = ui.model;
    const Rect& area = ui.layout.canvas;
    if (m.fitPending()) m.fitCamera(area, ui.fitOverlays);
    m.setViewport(area);
    editFrame(ui);  // live editing: a finished flood adopted, a drag carried on
    canvasInput(ui);
    // What floats over the canvas, as last drawn: the labels keep out from under it. (An
    // export paints the canvas alone: nothing floats over it then.)
    ui.inset = ui.presenter ? Rect{} : insetRect(ui);
    ui.canvas.obstacles = canvasOverlays(ui);  // the boxes, the dial, the State table, the arrow
    if (!ui.presenter && ui.inset.w > 0) ui.canvas.obstacles.push_back(ui.inset);
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    paintCanvas(ui, dl);
    ui.canvas.obstacles.clear();
    if (ui.inset.w > 0) {
        dl->PushClipRect(ImVec2(float(area.x), float(area.y)),
                         ImVec2(float(area.x + area.w), float(area.y + area.h)), true);
        drawInset(ui, dl);
        dl->PopClipRect();
    }
    drawToast(ui, dl);
    if (!ui.presenter) {  // presenter view: nothing over the canvas but the polygon
        canvasBar(ui);
        editBar(ui);
    } else {
        ui.findBox = ui.editBox = {};  // not drawn: nothing to keep out from under
    }
}

void paintCanvas(Ui& ui, ImDrawList* dl) {
    Model& m = ui.model;
    const Rect& area = ui.layout.canvas;
    syncBuffers(ui);

    CanvasState& cs = ui.canvas;
    const Camera& cam = m.camera();
    const float s = ui.scale;
    const SceneOptions& o = ui.sceneOptions;
    const uint32_t n =
        std::min<uint32_t>(m.state().triangleCount, uint32_t(m.trace().triangles.size()));
    const Event* ev = m.currentEvent();
    WorldView& w = cs.view;
    w.center = {cam.center().x - cs.origin.x, cam.center().y - cs.origin.y};
    w.scale = cam.scale();
    w.viewport = area;
    w.waterEnd = ev ? std::min(ev->firstTriangle, n) : n;
    w.currentEnd = n;
    // Fold what is denser than a few pixels apart (Tracy's rule): at full zoom-out a million
    // edges or vertex markers are a smear that costs the rasteriser a million primitives.
    // Density is the polygon's screen area over the count: uniform spread assumed.
    const Polygon& poly = m.polygon();
    double px = 0;
    if (!poly.vertices.empty()) {
        Vec2 lo = cam.toScreen({cs.origin.x + cs.bbox[0], cs.origin.y + cs.bbox[1]});
        Vec2 hi = cam.toScreen({cs.origin.x + cs.bbox[2], cs.origin.y + cs.bbox[3]});
        px = std::abs(hi.x - lo.x) * std::abs(hi.y - lo.y);  // screen area of the polygon's box
    }
    auto sparse = [&](size_t count, double minPx2) { return px >= double(count) * minPx2 * s * s; };
    w.edgeEnd = o.triangleEdges && sparse(m.trace().triangles.size(), 40) ? n : 0;
    w.bridgeCount = o.bridges ? uint32_t(m.state().bridges.size()) : 0;
    w.classes = o.vertexClasses;
    w.thinBoundary = !sparse(poly.vertices.size(), 16);
    w.uiScale = s;

    // Arrowheads depend on the zoom (they are pixels long): the only per-frame geometry.
    Renderer& r = ui.renderer;
    r.clear();
    for (const auto& l : cs.overlay.arrows) {
        Vec2 a = cam.toScreen(l.a), b = cam.toScreen(l.b);
        double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
        if (len < 1e-9) continue;
        double head = std::min(10.0 * s, len / 2), ux = dx / len, uy = dy / len;
        Vec2 base{b.x - ux * head, b.y - uy * head};
        r.addTriangle(Layer::Lines, b, {base.x - uy * head / 2, base.y + ux * head / 2},
                      {base.x + uy * head / 2, base.y - ux * head / 2}, l.color);
    }

    dl->PushClipRect(ImVec2(float(area.x), float(area.y)),
                     ImVec2(float(area.x + area.w), float(area.y + area.h)), true);
    if (!m.errorView()) ui.labels.clear();
    if (m.errorView()) errorOverlay(ui, dl);
    else if (o.gorgeFocus) gorgeFocus(ui);
    // The step's labels placed first (scene_labels.h); the small numbers give way to them.
    ui.stepLabels.clear();
    if (!m.errorView()) {
        const std::vector<ShownLabel> shown = placeStepLabels(ui, cs.overlay.labels);
        if (o.triangleNumbers) triangleLabels(ui, dl, shown);
        if (o.vertexNumbers) vertexLabels(ui, dl, shown);
        drawStepLabels(ui, dl, shown);
    }
    // The predicate inspector's hovered row: its arguments, numbered in the predicate's order.
    for (size_t i = 0; i < ui.highlight.size(); ++i) {
        if (ui.highlight[i] >= m.polygon().vertices.size()) continue;
        Vec2 c = cam.toScreen(m.polygon().vertices[ui.highlight[i]]);
        dl->AddCircle(ImVec2(float(c.x), float(c.y)), 9 * s, IM_COL32(80, 220, 255, 255), 0,
                      2.5f * s);
        dl->AddText(ImVec2(float(c.x + 10 * s), float(c.y - 18 * s)), IM_COL32(80, 220, 255, 255),
                    std::to_string(i + 1).c_str());
    }
    if (m.polygon().vertices.empty() && !ui.edit.on) {
        std::string msg = m.inputDiagnostic().ok() ? "no polygon: open one (Ctrl+O or Open...)"
                                                   : m.inputDiagnostic().message;
        const FeatureScan& scan = ui.features;
        if (!m.inputDiagnostic().ok() && scan.path() == m.path() && scan.done() &&
            scan.features().size() > 1)
            msg += "\n\nIts " + std::to_string(scan.features().size()) +
                   " features open one at a time: the Open panel lists them with their verdicts.";
        // Wrapped to the canvas, a third of the way down: clear of the find and Edit bars.
        const float margin = float(20 * s);
        dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(),
                    ImVec2(float(area.x) + margin, float(area.y + area.h / 3)),
                    toImU32(palette::kCulprit), msg.c_str(), nullptr,
                    std::max(1.f, float(area.w) - 2 * margin));
    }
    editOverlay(ui, dl);
    if (!m.errorView()) drawUpArrow(ui, dl);
    dl->PopClipRect();
}

}  // namespace flood::view
