// The polygon canvas: the scene goes to the renderer (GL, under ImGui); text labels and
// tooltips go to ImGui's background draw list, clipped to the canvas rectangle.
#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "panels.h"

namespace flood::view {

namespace {

void canvasInput(Ui& ui) {
    Model& m = ui.model;
    ImGuiIO& io = ImGui::GetIO();
    Vec2 mouse{io.MousePos.x, io.MousePos.y};
    // Only when no ImGui window wants the mouse: panels keep their clicks and scrolls.
    if (io.WantCaptureMouse || !ui.layout.canvas.contains(mouse)) return;
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0) ||
        ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0))
        m.camera.pan(io.MouseDelta.x, io.MouseDelta.y);
    if (io.MouseWheel != 0) m.camera.zoomAt(mouse, std::pow(1.15, double(io.MouseWheel)));

    Index v = m.pickVertex(mouse, 7 * ui.scale);
    int64_t t = v == kNone ? m.pickTriangle(mouse) : -1;
    if (v != kNone) {
        const Polygon& p = m.polygon();
        Index ring = p.ringOf(v);
        ImGui::BeginTooltip();
        ImGui::Text("vertex %u  (ring %u, #%u in ring)", v, ring, v - p.rings[ring].first);
        ImGui::Text("(%.17g, %.17g)", p.vertices[v].x, p.vertices[v].y);
        ImGui::Text("class: %s", vertexClassName(m.classes()[v]));
        const Fingers& f = m.state().fingers;
        if (v == f.left) ImGui::TextColored(toImVec4(palette::kLeft), "Left");
        if (v == f.right) ImGui::TextColored(toImVec4(palette::kRight), "Right");
        if (v == f.nextLeft) ImGui::TextColored(toImVec4(palette::kNextLeft), "NextLeft");
        if (v == f.nextRight) ImGui::TextColored(toImVec4(palette::kNextRight), "NextRight");
        if (v == m.state().water) ImGui::Text("water level");
        ImGui::TextDisabled("right-click: break when it becomes Left/Right/Next");
        ImGui::EndTooltip();
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
            m.breakpoints.vertex = v;
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

}  // namespace

void drawCanvas(Ui& ui) {
    Model& m = ui.model;
    const Rect& area = ui.layout.canvas;
    if (m.needsFit) {
        m.camera.fit(m.polygon(), area);
        m.needsFit = false;
    }
    m.camera.setViewport(area);
    canvasInput(ui);

    Scene sc = buildScene(m, ui.sceneOptions);
    Renderer& r = ui.renderer;
    const Camera& cam = m.camera;
    const float s = ui.scale;
    r.clear();
    r.setFillColor(palette::kPolygonFill);
    for (const auto& ring : sc.rings) {
        std::vector<Vec2> pts;
        pts.reserve(ring.size());
        for (Point p : ring) pts.push_back(cam.toScreen(p));
        r.addRing(pts);
    }
    for (const auto& t : sc.water)
        r.addTriangle(Layer::Water, cam.toScreen(t.a), cam.toScreen(t.b), cam.toScreen(t.c), t.color);
    for (const auto& t : sc.current)
        r.addTriangle(Layer::Triangles, cam.toScreen(t.a), cam.toScreen(t.b), cam.toScreen(t.c),
                      t.color);
    for (const auto& l : sc.lines) {
        if (l.arrow)
            r.addArrow(Layer::Lines, cam.toScreen(l.a), cam.toScreen(l.b), l.width * s, 10 * s,
                       l.color);
        else
            r.addLine(Layer::Lines, cam.toScreen(l.a), cam.toScreen(l.b), l.width * s, l.color);
    }
    for (const auto& mk : sc.markers) {
        Vec2 c = cam.toScreen(mk.p);
        float rad = mk.radius * s;
        switch (mk.shape) {
            case Scene::Shape::Disc: r.addDisc(Layer::Markers, c, rad, mk.color); break;
            case Scene::Shape::Ring: r.addCircle(Layer::Markers, c, rad, 2 * s, mk.color); break;
            case Scene::Shape::Finger:
                // A pointing hand, abstracted: a triangle whose tip touches the vertex from below.
                r.addTriangle(Layer::Markers, c, {c.x - rad * 0.6, c.y + rad * 1.6},
                              {c.x + rad * 0.6, c.y + rad * 1.6}, mk.color);
                break;
        }
    }

    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    dl->PushClipRect(ImVec2(float(area.x), float(area.y)),
                     ImVec2(float(area.x + area.w), float(area.y + area.h)), true);
    double px2 = cam.scale() * cam.scale();
    for (const auto& l : sc.labels) {
        if (l.worldArea > 0 && l.worldArea * px2 < l.minArea * s * s) continue;
        Vec2 c = cam.toScreen(l.p);
        ImVec2 size = ImGui::CalcTextSize(l.text.c_str());
        ImVec2 at(float(c.x + l.dx * s), float(c.y + l.dy * s));
        if (l.worldArea > 0) at = ImVec2(float(c.x) - size.x / 2, float(c.y) - size.y / 2);
        dl->AddText(at, toImU32(l.color), l.text.c_str());
    }
    if (m.polygon().vertices.empty()) {
        const char* msg = m.inputDiagnostic().ok() ? "no polygon: open one (Ctrl+O or Open...)"
                                                   : m.inputDiagnostic().message.c_str();
        dl->AddText(ImVec2(float(area.x + 20 * s), float(area.y + 20 * s)),
                    toImU32(palette::kCulprit), msg);
    }
    dl->PopClipRect();
}

}  // namespace flood::view
