#include "scene.h"

#include <algorithm>
#include <cmath>
#include <ostream>

#include "flood/io/svg.h"
#include "flood/teach/narrate.h"
#include "scene_labels.h"

namespace flood::view {

namespace {

bool valid(const Polygon& p, Index v) { return v != kNone && v < p.vertices.size(); }

// A ghost's colour: the same hue, faint.
Rgba faint(Rgba c) { return {c.r, c.g, c.b, 150}; }

double area(Point a, Point b, Point c) {
    return std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2;
}

// The water level along a direction off +y: the same segment in the frame of the direction
// (heights along it, positions across it), for drawing only.
bool tiltedWaterLevel(const Polygon& poly, const ReplayState& s, Up up, Point& a, Point& b) {
    const auto& v = poly.vertices;
    const Point w = v[s.water];
    const double n = std::hypot(up.x, up.y);
    const Point d{up.x / n, up.y / n}, t{d.y, -d.x};
    auto height = [&](Point p) { return d.x * (p.x - w.x) + d.y * (p.y - w.y); };
    auto across = [&](Point p) { return t.x * (p.x - w.x) + t.y * (p.y - w.y); };
    double t0 = 0, t1 = 0;
    auto cross = [&](Index i, Index j) {
        if (!valid(poly, i) || !valid(poly, j)) return;
        const double hp = height(v[i]), hq = height(v[j]), tp = across(v[i]), tq = across(v[j]);
        if (hp * hq > 0) return;
        if (hp == hq) {
            t0 = std::min({t0, tp, tq}), t1 = std::max({t1, tp, tq});
            return;
        }
        const double x = tp + (0 - hp) / (hq - hp) * (tq - tp);
        t0 = std::min(t0, x), t1 = std::max(t1, x);
    };
    for (size_t i = 0; i + 1 < s.chain.size(); ++i) cross(s.chain[i], s.chain[i + 1]);
    cross(s.fingers.left, s.fingers.nextLeft);
    cross(s.fingers.right, s.fingers.nextRight);
    a = {w.x + t0 * t.x, w.y + t0 * t.y}, b = {w.x + t1 * t.x, w.y + t1 * t.y};
    return true;
}

// The horizontal segment at the water vertex's height, from bank to bank of the active gorge:
// the extreme crossings of that height with the chain and the two finger edges. Along another
// direction the level line runs across it (tiltedWaterLevel).
bool waterLevel(const Polygon& poly, const ReplayState& s, Point& a, Point& b, Up up = Up::PlusY) {
    if (!valid(poly, s.water)) return false;
    if (up != Up::PlusY) return tiltedWaterLevel(poly, s, up, a, b);
    const auto& v = poly.vertices;
    double h = v[s.water].y, x0 = v[s.water].x, x1 = x0;
    auto cross = [&](Index i, Index j) {
        if (!valid(poly, i) || !valid(poly, j)) return;
        Point p = v[i], q = v[j];
        if ((p.y - h) * (q.y - h) > 0) return;
        double x = p.y == q.y ? p.x : p.x + (h - p.y) / (q.y - p.y) * (q.x - p.x);
        if (p.y == q.y) {
            x0 = std::min({x0, p.x, q.x}), x1 = std::max({x1, p.x, q.x});
        } else {
            x0 = std::min(x0, x), x1 = std::max(x1, x);
        }
    };
    for (size_t i = 0; i + 1 < s.chain.size(); ++i) cross(s.chain[i], s.chain[i + 1]);
    cross(s.fingers.left, s.fingers.nextLeft);
    cross(s.fingers.right, s.fingers.nextRight);
    a = {x0, h}, b = {x1, h};
    return true;
}

}  // namespace

Rgba vertexClassColor(VertexClass c) {
    switch (c) {
        case VertexClass::Bottom: return palette::kBottom;
        case VertexClass::Sag: return palette::kSag;
        case VertexClass::Top: return palette::kTop;
        case VertexClass::Ceiling: return palette::kCeiling;
        default: return palette::kRegular;
    }
}

Scene buildScene(const Model& model, const SceneOptions& o) {
    Scene sc;
    const Polygon& poly = model.polygon();
    const Trace& trace = model.trace();
    const ReplayState& s = model.state();
    const auto& v = poly.vertices;
    const Event* ev = model.currentEvent();

    const bool all = !o.perStepOnly;
    for (const Ring& r : poly.rings) {
        // A Steiner point (a one-point hole) has no boundary: its vertex marker shows it.
        if (!all || r.first + r.count > v.size() || r.count < 3) continue;
        sc.rings.emplace_back(v.begin() + r.first, v.begin() + r.first + r.count);
    }

    uint32_t n = all ? std::min<uint32_t>(s.triangleCount, uint32_t(trace.triangles.size())) : 0;
    uint32_t curFirst = ev ? ev->firstTriangle : 0, curEnd = ev ? curFirst + ev->triangleCount : 0;
    for (uint32_t t = 0; t < n; ++t) {
        const Triangle& tri = trace.triangles[t];
        if (!valid(poly, tri[0]) || !valid(poly, tri[1]) || !valid(poly, tri[2])) continue;
        Point a = v[tri[0]], b = v[tri[1]], c = v[tri[2]];
        bool cur = t >= curFirst && t < curEnd;
        (cur ? sc.current : sc.water)
            .push_back({a, b, c, cur ? palette::kCurrent : palette::kWater});
        if (o.triangleEdges) {
            sc.lines.push_back({a, b, palette::kTriangleEdge, 1});
            sc.lines.push_back({b, c, palette::kTriangleEdge, 1});
            sc.lines.push_back({c, a, palette::kTriangleEdge, 1});
        }
        if (o.triangleNumbers) {
            Scene::Label l{{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3},
                           std::to_string(t),
                           cur ? Rgba{0, 0, 0, 255} : Rgba{230, 240, 255, 255}};
            l.minArea = 700;  // about four times a label's own footprint
            l.worldArea = area(a, b, c);
            sc.labels.push_back(std::move(l));
        }
    }

    for (const auto& ring : sc.rings)
        for (size_t i = 0; i < ring.size(); ++i)
            sc.lines.push_back({ring[i], ring[(i + 1) % ring.size()], palette::kBoundary, 1.5f});

    if (o.bridges && all)
        for (auto [sag, to] : s.bridges)
            if (valid(poly, sag) && valid(poly, to))
                sc.lines.push_back({v[sag], v[to], palette::kBridge, 2});

    if (o.dormant)
        for (const Gorge& g : s.dormant) {
            for (size_t i = 0; i + 1 < g.chain.size(); ++i)
                if (valid(poly, g.chain[i]) && valid(poly, g.chain[i + 1]))
                    sc.lines.push_back({v[g.chain[i]], v[g.chain[i + 1]], palette::kDormant, 1.5f});
            Index anchor = valid(poly, g.top) ? g.top : (g.chain.empty() ? kNone : g.chain[0]);
            if (valid(poly, anchor)) {
                sc.markers.push_back({v[anchor], palette::kDormant, 9, Scene::Shape::Ring, true});
                Scene::Label l{v[anchor], (g.held ? "held " : "pending ") + std::to_string(g.id),
                               palette::kDormant, 10, 10};
                l.folds = true;
                l.kind = Scene::LabelKind::Gorge;
                sc.labels.push_back(std::move(l));
            }
        }

    if (o.jumps)
        for (auto [top, to] : s.jumps)
            if (valid(poly, top) && valid(poly, to))
                sc.lines.push_back({v[top], v[to], palette::kJump, 2, true});

    // The step as a transition (Python Tutor's before and after): the chain before it, faint
    // and wider, under the chain after; where they agree only the chain after shows.
    const bool ghost = o.ghost && ev && ev->action != Action::Start;
    if (ghost) {
        const std::vector<Index>& was = model.chainBefore();
        for (size_t i = 0; i + 1 < was.size(); ++i)
            if (valid(poly, was[i]) && valid(poly, was[i + 1]))
                sc.lines.push_back({v[was[i]], v[was[i + 1]], faint(palette::kChain), 7});
    }
    for (size_t i = 0; i + 1 < s.chain.size(); ++i)
        if (valid(poly, s.chain[i]) && valid(poly, s.chain[i + 1]))
            sc.lines.push_back({v[s.chain[i]], v[s.chain[i + 1]], palette::kChain, 3});

    sc.hasWater = waterLevel(poly, s, sc.waterA, sc.waterB, model.up());
    if (sc.hasWater) sc.lines.push_back({sc.waterA, sc.waterB, palette::kWaterLevel, 2});

    if (o.vertexClasses && all)
        for (Index i = 0; i < v.size() && i < model.classes().size(); ++i) {
            VertexClass c = model.classes()[i];
            sc.markers.push_back({v[i], vertexClassColor(c),
                                  c == VertexClass::Regular ? 2.5f : 4.5f, Scene::Shape::Disc,
                                  true});
        }

    for (Index i : model.offenders()) {
        sc.markers.push_back({v[i], palette::kCulprit, 11, Scene::Shape::Ring});
    }

    // The fingers, then Right, then Left last so Left is on top when they coincide; each
    // after a faint ghost of where it was before the step, if it moved.
    struct FingerLook {
        Index Fingers::*at;
        const char* name;
        Rgba color;
        float radius, dx, dy;
        Scene::Shape shape;
    };
    const FingerLook looks[] = {
        {&Fingers::nextLeft, "NL", palette::kNextLeft, 8, -26, -22, Scene::Shape::Finger},
        {&Fingers::nextRight, "NR", palette::kNextRight, 8, 10, -22, Scene::Shape::Finger},
        {&Fingers::right, "R", palette::kRight, 6.5f, 9, 4, Scene::Shape::Disc},
        {&Fingers::left, "L", palette::kLeft, 6.5f, -18, 4, Scene::Shape::Disc}};
    const Fingers& f = s.fingers;
    for (const FingerLook& k : looks) {
        const Index was = ghost ? ev->before.*k.at : kNone;
        if (valid(poly, was) && was != f.*k.at) {
            sc.markers.push_back({v[was], faint(k.color), k.radius, k.shape});
            Scene::Label l{v[was], std::string(k.name) + " before", faint(k.color), k.dx, k.dy};
            l.kind = Scene::LabelKind::Ghost, l.vertex = was;
            sc.labels.push_back(std::move(l));
        }
        if (!valid(poly, f.*k.at)) continue;
        sc.markers.push_back({v[f.*k.at], k.color, k.radius, k.shape});
        Scene::Label l{v[f.*k.at], k.name, k.color, k.dx, k.dy};
        l.kind = Scene::LabelKind::Finger, l.vertex = f.*k.at;
        sc.labels.push_back(std::move(l));
    }

    if (ev) {
        addNamedLabels(sc, model, *ev);
        // A ghost the sentence names already has its label ("14 NextRight before").
        auto named = [&](const Scene::Label& g) {
            return g.kind == Scene::LabelKind::Ghost &&
                   std::any_of(sc.labels.begin(), sc.labels.end(), [&](const Scene::Label& l) {
                       return l.kind == Scene::LabelKind::Named && l.vertex == g.vertex;
                   });
        };
        sc.labels.erase(std::remove_if(sc.labels.begin(), sc.labels.end(), named), sc.labels.end());
    }
    return sc;
}

void addNamedLabels(Scene& sc, const Model& model, const Event& e) {
    const Polygon& poly = model.polygon();
    const auto& v = poly.vertices;
    const Narration n = narration(poly, e);
    std::vector<Index> done;  // a vertex named twice keeps its first role
    for (const NamedVertex& nv : n.vertices) {
        if (!valid(poly, nv.vertex) || std::find(done.begin(), done.end(), nv.vertex) != done.end())
            continue;
        done.push_back(nv.vertex);
        sc.markers.push_back({v[nv.vertex], palette::kHover, 10, Scene::Shape::Ring});
        Scene::Label l{v[nv.vertex], std::to_string(nv.vertex) + " " + nv.role, palette::kHover, 8,
                       -30};
        l.kind = Scene::LabelKind::Named, l.vertex = nv.vertex;
        sc.labels.push_back(std::move(l));
    }
    // A fan of many triangles: its first and last, the ends of the range the sentence says.
    const auto& tris = model.trace().triangles;
    const uint32_t last = n.firstTriangle + n.triangleCount;
    for (uint32_t t = n.firstTriangle; t < last && t < tris.size(); ++t) {
        if (n.triangleCount > kNamedTriangles && t != n.firstTriangle && t + 1 != last) continue;
        const Triangle& tri = tris[t];
        if (!valid(poly, tri[0]) || !valid(poly, tri[1]) || !valid(poly, tri[2])) continue;
        Point c{(v[tri[0]].x + v[tri[1]].x + v[tri[2]].x) / 3,
                (v[tri[0]].y + v[tri[1]].y + v[tri[2]].y) / 3};
        Scene::Label l{c, "triangle " + std::to_string(t), palette::kHover, -30, -8};
        l.kind = Scene::LabelKind::Named, l.triangle = t;
        sc.labels.push_back(std::move(l));
    }
}

// ----------------------------------------------------------------------------------------
static std::string svgColor(Rgba c) { return svg::hex(c.r, c.g, c.b); }

// Picture coordinates to a hundredth of a pixel: short numbers, no visible difference.
static double hundredths(double v) { return std::round(v * 100) / 100; }

void writeSceneSvg(std::ostream& out, const Scene& sc, const Polygon& polygon, int width) {
    // Same fit as the canvas, onto a page whose aspect follows the polygon.
    double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
    if (!polygon.vertices.empty()) {
        x0 = x1 = polygon.vertices[0].x, y0 = y1 = polygon.vertices[0].y;
        for (Point p : polygon.vertices)
            x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y),
            y1 = std::max(y1, p.y);
    }
    double aspect = (x1 > x0 && y1 > y0) ? (y1 - y0) / (x1 - x0) : 1;
    int height = std::clamp(int(width * aspect), 64, 8 * width);
    Camera cam;
    cam.fit(polygon, Rect{0, 0, double(width), double(height)});
    writeSceneSvg(out, sc, cam, width, height);
}

void writeSceneSvg(std::ostream& out, const Scene& sc, const Camera& cam, int width, int height,
                   const CaptionLine* caption) {
    auto place = [&cam](Point p) {
        Vec2 s = cam.toScreen(p);
        return Point{hundredths(s.x), hundredths(s.y)};
    };
    svg::Document doc(out, {0, 0, double(width), double(height)}, width, height, place);
    // The canvas's rectangle clips the scene as the canvas does; a caption lies below it.
    const Rect& area = cam.viewport();
    doc.clip("canvas", {area.x, area.y, area.w, area.h});
    doc.background(svgColor(palette::kBackground));
    doc.beginGroup({}, "canvas");
    svg::Style land;
    land.fill = svgColor(palette::kPolygonFill), land.evenOdd = true;
    std::vector<svg::RingView> rings;
    for (const auto& ring : sc.rings) rings.push_back({ring.data(), ring.size()});
    doc.rings(land, rings);
    // One element per triangle, classed as the canvas colours it (water, or cut just now).
    for (const auto* tris : {&sc.water, &sc.current})
        for (const auto& t : *tris) {
            svg::Style s;
            s.className = tris == &sc.water ? "water" : "current", s.fill = svgColor(t.color);
            doc.triangle(s, t.a, t.b, t.c);
        }
    for (const auto& l : sc.lines) {
        svg::Style s;
        s.stroke = svgColor(l.color), s.strokeWidth = hundredths(l.width);
        doc.line(s, l.a, l.b);
    }
    for (const auto& m : sc.markers) {
        svg::Style s;
        if (m.shape == Scene::Shape::Ring) s.fill = "none", s.stroke = svgColor(m.color);
        else s.fill = svgColor(m.color);
        doc.circle(s, m.p, hundredths(m.radius));
    }
    for (const auto& l : sc.labels) {  // triangle numbers, at their centroid
        if (l.kind != Scene::LabelKind::Number) continue;
        if (l.worldArea > 0 && l.worldArea * cam.scale() * cam.scale() < l.minArea) continue;
        Point c = doc.place(l.p);
        doc.text({hundredths(c.x + l.dx), hundredths(c.y + l.dy + 10)}, 11,
                 {{l.text, svgColor(l.color)}});
    }
    // The step's labels placed apart as on the canvas (scene_labels.h), the sentence's names
    // larger; the text's size estimated (a sans-serif letter is about 0.6 of its size wide).
    auto px = [](const Scene::Label& l) { return l.kind == Scene::LabelKind::Named ? 16.0 : 11.0; };
    auto size = [&](const Scene::Label& l) {
        return Vec2{0.6 * px(l) * double(l.text.size()) + 4, px(l) + 4};
    };
    for (const ShownLabel& sl : placeSceneLabels(sc.labels, cam, area, {}, size, 1)) {
        const Scene::Label& l = *sl.label;
        if (sl.at.leader) {
            svg::Style s;
            s.stroke = svgColor(l.color), s.strokeWidth = 1;
            doc.line(s, cam.toWorld(sl.at.from), cam.toWorld(sl.at.to));
        }
        doc.text({hundredths(sl.at.box.x + 2), hundredths(sl.at.box.y + 2 + 0.8 * px(l))}, px(l),
                 {{l.text, svgColor(l.color), l.kind == Scene::LabelKind::Named}});
    }
    doc.endGroup();
    if (caption)
        doc.text({8, area.y + area.h + 18}, 13,
                 {{caption->head, svgColor(caption->headColor), true},
                  {" " + caption->text, svgColor(palette::kBoundary)}});
}

}  // namespace flood::view
