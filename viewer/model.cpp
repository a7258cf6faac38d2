// [SECTION] vertex classes  [SECTION] layout and camera  [SECTION] breakpoints
// [SECTION] text views  [SECTION] Model  [SECTION] polygon files
#include "model.h"

#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <system_error>
#include <utility>

#include <nlohmann/json.hpp>

#include "flood/check/diagnostic_where.h"
#include "flood/geometry/predicates.h"
#include "flood/io/gdal/read_any.h"
#include "flood/io/io.h"
#include "flood/log/trace_io.h"
#include "view_fit.h"

#ifndef FLOOD_DATA_SUBDIR  // share/flood, relative to the install prefix
#define FLOOD_DATA_SUBDIR "share/flood"
#define FLOOD_INSTALL_DATA_DIR "/usr/local/share/flood"
#endif
#ifndef FLOOD_SOURCE_DIR
#define FLOOD_SOURCE_DIR "."
#endif
#ifndef FLOOD_VIEWER_DEFAULT_POLYGON
#define FLOOD_VIEWER_DEFAULT_POLYGON "paper-figure-7.json"
#endif

namespace flood::view {

// [SECTION] vertex classes: core/machine/vertex_class.cpp (the state table uses them too)

// ========================================================================================
// [SECTION] layout and camera
Layout computeLayout(double width, double height, double uiScale, double bottomWanted,
                     double findingsWanted) {
    // Side columns shrink on small windows so the canvas keeps at least half the width.
    double side = std::min(300.0 * uiScale, width * 0.25);
    double bottom = std::min(128.0 * uiScale, height * 0.3);
    if (bottomWanted > bottom) bottom = std::min(bottomWanted, height * 0.5);
    Layout l;
    l.left = {0, 0, side, height - bottom};
    l.right = {width - side, 0, side, height - bottom};
    l.bottom = {0, height - bottom, width, bottom};
    const double column = std::max(1.0, height - bottom);
    const double findings = findingsWanted > 0 ? std::min(findingsWanted, column / 3) : 0;
    l.canvas = {side, 0, std::max(1.0, width - 2 * side), std::max(1.0, column - findings)};
    if (findings > 0) l.findings = {side, l.canvas.h, l.canvas.w, findings};
    return l;
}

void Camera::fit(const Polygon& polygon, const Rect& viewport) {
    viewport_ = viewport;
    if (polygon.vertices.empty()) {
        cx_ = cy_ = 0;
        scale_ = 1;
        return;
    }
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    for (Point p : polygon.vertices) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    if (!(x0 <= x1)) x0 = x1 = y0 = y1 = 0;
    fitBox(x0, y0, x1, y1, viewport);
}

void Camera::fitBox(double x0, double y0, double x1, double y1, const Rect& viewport,
                    double minSide) {
    viewport_ = viewport;
    cx_ = (x0 + x1) / 2;
    cy_ = (y0 + y1) / 2;
    double w = std::max(x1 - x0, minSide), h = std::max(y1 - y0, minSide);
    const double usable = 0.88;  // 6% margin on each side
    scale_ = std::min(viewport.w * usable / w, viewport.h * usable / h);
    if (!std::isfinite(scale_) || scale_ <= 0) scale_ = 1;
}

void Camera::centerOn(Point p, double scale) {
    cx_ = p.x, cy_ = p.y;
    scale_ = std::clamp(scale, 1e-12, 1e15);
}

Vec2 Camera::toScreen(Point p) const {
    return {viewport_.x + viewport_.w / 2 + (p.x - cx_) * scale_,
            viewport_.y + viewport_.h / 2 - (p.y - cy_) * scale_};
}

Point Camera::toWorld(Vec2 s) const {
    return {cx_ + (s.x - viewport_.x - viewport_.w / 2) / scale_,
            cy_ - (s.y - viewport_.y - viewport_.h / 2) / scale_};
}

void Camera::pan(double dx, double dy) {
    cx_ -= dx / scale_;
    cy_ += dy / scale_;
}

void Camera::zoomAt(Vec2 screen, double factor) {
    Point before = toWorld(screen);
    scale_ = std::clamp(scale_ * factor, 1e-12, 1e15);
    Point after = toWorld(screen);
    cx_ += before.x - after.x;
    cy_ += before.y - after.y;
}

// ========================================================================================
// [SECTION] framing
void WorldBox::add(Point p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
}

WorldBox visibleBox(const Camera& camera) {
    const Rect& r = camera.viewport();
    WorldBox b;
    b.add(camera.toWorld({r.x, r.y}));
    b.add(camera.toWorld({r.x + r.w, r.y + r.h}));
    return b;
}

Camera frameNeighbourhood(const WorldBox& target, double minSide, const Rect& viewport) {
    Camera c;
    c.setViewport(viewport);
    if (target.empty()) return c;
    if (!std::isfinite(minSide) || minSide < 0) minSide = 0;
    const Point m = target.centre();
    const double w = std::max(target.w(), minSide) * 1.5, h = std::max(target.h(), minSide) * 1.5;
    // A box of no size at all (one point, nothing beside it): fitBox's fallback scale.
    c.fitBox(m.x - w / 2, m.y - h / 2, m.x + w / 2, m.y + h / 2, viewport);
    return c;
}

bool culpritBox(const Polygon& P, const std::vector<Triangle>& triangles, const Culprits& c,
                bool ringsAtFault, WorldBox& box, double& minSide) {
    const auto& V = P.vertices;
    box = {};
    minSide = 0;
    auto next = [&](Index v) {
        const Ring& r = P.rings[P.ringOf(v)];
        return v + 1 == r.first + r.count ? r.first : v + 1;
    };
    auto prev = [&](Index v) {
        const Ring& r = P.rings[P.ringOf(v)];
        return v == r.first ? r.first + r.count - 1 : v - 1;
    };
    // A culprit vertex and its nearer ring neighbour (not at its point): the neighbourhood
    // that tells its edges from the rest.
    std::vector<Point> neighbours;
    auto vertex = [&](Index v) {
        if (v >= V.size()) return;
        box.add(V[v]);
        double nearest = std::numeric_limits<double>::infinity();
        Point at;
        for (Index u : {prev(v), next(v)}) {
            double d = std::hypot(V[u].x - V[v].x, V[u].y - V[v].y);
            if (d > 0 && d < nearest) nearest = d, at = V[u];
        }
        if (std::isfinite(nearest)) neighbours.push_back(at);
    };
    size_t budget = 256;  // a finding names a few; the error view of a huge ring stays cheap
    for (Index e : c.edges)
        if (e < V.size() && budget) --budget, vertex(e), vertex(next(e));
    for (Index v : c.vertices)
        if (budget) --budget, vertex(v);
    for (uint32_t t : c.triangles)
        if (t < triangles.size() && budget) {
            --budget;
            for (Index v : triangles[t]) vertex(v);
        }
    for (Point q : neighbours) box.add(q);
    Point p;
    if (diagnosticPoint(P, c, p)) box.add(p);
    // Whole rings blamed, nothing finer (a hole outside its outer ring, holes inside each
    // other, a ring of zero area): the ring at fault is the first; the others are context,
    // of which the nearest point is enough.
    const bool ringLevel =
        (ringsAtFault && c.edges.empty() && c.triangles.empty() && !c.hasPoint) || box.empty();
    if (ringLevel && !c.rings.empty() && c.rings[0] < P.rings.size()) {
        const Ring& g = P.rings[c.rings[0]];
        for (Index i = 0; i < g.count; ++i) box.add(V[g.first + i]);
        if (!box.empty()) {
            const Point m = box.centre();
            const double reach = 8 * std::max(box.w(), box.h());
            // The nearest point of each other ring's edges, when it is near enough that the
            // ring at fault stays large in the view.
            for (size_t k = 1; k < c.rings.size() && k < 4; ++k) {
                if (c.rings[k] >= P.rings.size()) continue;
                const Ring& o = P.rings[c.rings[k]];
                double best = std::numeric_limits<double>::infinity();
                Point nearest;
                for (Index i = 0; i < o.count; ++i) {
                    const Point a = V[o.first + i], b = V[o.first + (i + 1) % o.count];
                    const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
                    double t = len2 > 0 ? ((m.x - a.x) * dx + (m.y - a.y) * dy) / len2 : 0;
                    t = std::clamp(t, 0.0, 1.0);
                    const Point q{a.x + t * dx, a.y + t * dy};
                    const double d = std::hypot(q.x - m.x, q.y - m.y);
                    if (d < best) best = d, nearest = q;
                }
                if (best <= reach) box.add(nearest);
            }
        }
    }
    if (box.empty()) return false;
    // One point and nothing beside it: a fiftieth of the face around it.
    minSide = 0;
    if (box.w() == 0 && box.h() == 0) {
        WorldBox face;
        for (size_t i = 0; i < V.size(); i += 1 + V.size() / 100000) face.add(V[i]);
        minSide = 0.02 * std::max(face.w(), face.h());
    }
    return true;
}

bool frameCulprits(const Polygon& P, const std::vector<Triangle>& triangles, const Culprits& c,
                   bool ringsAtFault, const Rect& viewport, Camera& camera) {
    WorldBox box;
    double minSide = 0;
    if (!culpritBox(P, triangles, c, ringsAtFault, box, minSide)) return false;
    camera = frameNeighbourhood(box, minSide, viewport);
    return true;
}

// ========================================================================================
// [SECTION] breakpoints
bool Breakpoints::any() const {
    return forbidden || vertex != kNone || triangle >= 0 ||
           std::any_of(actions.begin(), actions.end(), [](bool b) { return b; });
}

bool hits(const Breakpoints& b, const Event& e) {
    if (b.actions[size_t(e.action)]) return true;
    if (b.forbidden && (e.action == Action::Forbidden || e.reason != Forbidden::None)) return true;
    if (b.vertex != kNone) {
        const Fingers &x = e.before, &y = e.after;
        if ((y.left == b.vertex && x.left != b.vertex) ||
            (y.right == b.vertex && x.right != b.vertex) ||
            (y.nextLeft == b.vertex && x.nextLeft != b.vertex) ||
            (y.nextRight == b.vertex && x.nextRight != b.vertex))
            return true;
    }
    if (b.triangle >= 0 && e.triangleCount > 0 && uint64_t(b.triangle) >= e.firstTriangle &&
        uint64_t(b.triangle) < uint64_t(e.firstTriangle) + e.triangleCount)
        return true;
    return false;
}

// [SECTION] text views: core/teach/describe.cpp (an event in one line),
// core/teach/transcript.cpp (items)

// ========================================================================================
// [SECTION] Predicate inspector
namespace {
// The machine's lower() on vertices: heights along `up`, then across it, then vertex index
// (bridge copies of one vertex are ordered by node, which the log does not keep: they compare
// equal here).
int compareHeight(const Polygon& p, Up up, Index a, Index b) {
    Point pa = p.vertices[a], pb = p.vertices[b];
    if (pa != pb) return belowToward(up, pa, pb) ? -1 : 1;
    return a < b ? -1 : a > b ? 1 : 0;
}

PredicateRow belowRow(const Polygon& p, Up up, Test t, const char* text, Index a, Index b) {
    PredicateRow r;
    r.test = t;
    r.predicate = text;
    r.args = {a, b};
    r.sign = compareHeight(p, up, a, b);
    r.result = r.sign < 0;
    r.stage = "comparison";
    return r;
}
}  // namespace

std::vector<PredicateRow> inspectDecision(const Trace& trace, const ReplayState& before,
                                          const Event& e, const std::vector<VertexClass>& classes,
                                          size_t maxSags) {
    std::vector<PredicateRow> rows;
    const Polygon& p = trace.polygon;
    const Fingers& f = e.before;
    if (f.left == kNone || e.tested == 0 || f.left >= p.vertices.size()) return rows;
    auto pt = [&](Index v) { return p.vertices[v]; };
    auto add = [&](PredicateRow r) {
        if (r.test != Test::Count && e.didTest(r.test)) {
            r.hasRecorded = true;
            r.recorded = e.testResult(r.test);
        }
        rows.push_back(std::move(r));
    };
    // SameNext: an identity of nodes; the log keeps vertices.
    PredicateRow same;
    same.test = Test::SameNext;
    same.predicate = "NextLeft == NextRight";
    same.args = {f.nextLeft, f.nextRight};
    same.result = f.nextLeft == f.nextRight;
    same.sign = same.result ? 0 : 1;
    same.stage = "identity";
    add(same);
    Index nx = f.nextLeft;  // Next: where the water rises to
    if (e.didTest(Test::LeftLower)) {
        PredicateRow r = belowRow(p, trace.up, Test::LeftLower, "below(NextLeft, NextRight)",
                                  f.nextLeft, f.nextRight);
        const bool leftLower = r.result;
        add(std::move(r));
        Index c = leftLower ? f.left : f.right;
        nx = leftLower ? f.nextLeft : f.nextRight;
        if (e.didTest(Test::NextAbove))
            add(belowRow(p, trace.up, Test::NextAbove, "below(C, Next)", c, nx));
        if (e.didTest(Test::CIsTop)) {
            // C's loop neighbours: the finger beyond it and the chain node inside it.
            const auto& ch = before.chain;
            Index prevC = leftLower ? f.nextLeft : (ch.size() > 1 ? ch[ch.size() - 2] : f.nextLeft);
            Index nextC = leftLower ? (ch.size() > 1 ? ch[1] : f.nextRight) : f.nextRight;
            OrientReport o = orientExplained(pt(prevC), pt(c), pt(nextC));
            PredicateRow r;
            r.test = Test::CIsTop;
            r.predicate = "orient(prev C, C, next C) <= 0";
            r.args = {prevC, c, nextC};
            r.result = o.sign <= 0;
            r.hasValue = true;
            r.value = o.det;
            r.sign = o.sign;
            r.stage = stageName(o.stage);
            add(std::move(r));
        }
        if (e.didTest(Test::JumpSet)) {
            PredicateRow r;
            r.test = Test::JumpSet;
            r.predicate = "jump(C) is set";
            r.args = {c};
            r.result = std::any_of(before.jumps.begin(), before.jumps.end(),
                                   [&](const std::pair<Index, Index>& j) { return j.first == c; });
            r.sign = r.result;
            r.stage = "identity";
            add(std::move(r));
        }
    }
    if (!e.didTest(Test::SagInside)) return rows;
    // The sag search: inside(s, Left, Right, NextRight, NextLeft) for the sags between the
    // water and Next; SagInside is whether any is inside (the machine takes the lowest).
    const Point l = pt(f.left), r = pt(f.right), nr = pt(f.nextRight), nl = pt(f.nextLeft);
    std::vector<Index> bridged;
    for (const auto& b : before.bridges) bridged.push_back(b.first);
    std::sort(bridged.begin(), bridged.end());
    std::vector<Index> sags;
    for (Index v = 0; v < classes.size() && v < p.vertices.size(); ++v)
        if (classes[v] == VertexClass::Sag && before.water != kNone &&
            compareHeight(p, trace.up, before.water, v) < 0 &&
            compareHeight(p, trace.up, v, nx) < 0 &&
            !std::binary_search(bridged.begin(), bridged.end(), v))
            sags.push_back(v);
    std::sort(sags.begin(), sags.end(),
              [&](Index a, Index b) { return compareHeight(p, trace.up, a, b) < 0; });
    // The one bridged is listed even when the cap cuts the rest. (Only a Bridge names a sag:
    // in other events the field holds their own subject, core/machine/events.h.)
    const Index bridging = e.action == Action::Bridge ? e.sag : kNone;
    if (bridging != kNone && std::find(sags.begin(), sags.end(), bridging) == sags.end())
        sags.insert(sags.begin(), bridging);
    if (sags.size() > maxSags) {
        auto it = std::find(sags.begin(), sags.end(), bridging);
        if (it != sags.end() && size_t(it - sags.begin()) >= maxSags)
            std::rotate(sags.begin(), it, it + 1);
        sags.resize(maxSags);
    }
    bool any = false;
    for (Index s : sags) {
        InsideReport in = insideExplained(pt(s), l, r, nr, nl);
        PredicateRow row;
        row.predicate = "inside(s, Left, Right, NextRight, NextLeft)";
        row.args = {s, f.left, f.right, f.nextRight, f.nextLeft};
        row.result = in.inside;
        row.sign = in.inside;
        row.stage =
            std::string(stageName(in.stage)) + " (" + std::to_string(in.orients) + " orients)";
        any = any || in.inside;
        rows.push_back(std::move(row));
    }
    PredicateRow sagRow;
    sagRow.test = Test::SagInside;
    sagRow.predicate = "some sag is inside (the rows below)";
    if (e.action == Action::Bridge) sagRow.args = {e.sag};
    sagRow.result =
        e.action == Action::Bridge ? insideExplained(pt(e.sag), l, r, nr, nl).inside : any;
    sagRow.sign = sagRow.result;
    sagRow.stage = "inside";
    add(std::move(sagRow));
    // The summary row goes before its inside() rows.
    std::rotate(rows.end() - long(sags.size()) - 1, rows.end() - 1, rows.end());
    return rows;
}

const std::vector<PredicateRow>& Model::inspection() {
    uint64_t key = generation_ << 32 | step_;
    if (key == inspectedFor_) return inspection_;
    inspectedFor_ = key;
    inspection_.clear();
    if (const Event* e = currentEvent()) {
        uint32_t at = step_;
        inspection_ = inspectDecision(*trace_, replay_->seek(at - 1), *e, classes_);
        replay_->seek(at);
    }
    return inspection_;
}

// ========================================================================================
// [SECTION] Timeline
uint32_t TimelineView::eventAt(double x, double width, uint32_t events) const {
    if (events == 0) return 0;
    double i = std::floor(first + x / perEvent(width, events));  // the mark x falls in
    return uint32_t(std::clamp(i, 0.0, double(events - 1)));
}

void TimelineView::zoomAt(double x, double width, double factor, uint32_t events) {
    if (events == 0 || width <= 0 || factor <= 0) return;
    double at = first + x / perEvent(width, events);
    // Zoomed in: never fewer than 8 events across; zoomed out: the whole log.
    span = std::clamp(visible(events) / factor, std::min(8.0, double(events)), double(events));
    first = at - x / perEvent(width, events);
    clamp(events);
}

void TimelineView::pan(double dx, double width, uint32_t events) {
    if (events == 0 || width <= 0) return;
    first -= dx / perEvent(width, events);
    clamp(events);
}

void TimelineView::clamp(uint32_t events) {
    if (span >= double(events)) span = 0;  // all of it: follow the log's length
    first = std::clamp(first, 0.0, std::max(0.0, double(events) - visible(events)));
}

// ========================================================================================
// [SECTION] Model
Model::Model() : trace_(std::make_unique<Trace>()), replay_(std::make_unique<Replay>(*trace_)) {
    verdict_ = computeVerdict();
    scan_.done = true;  // nothing to check before the first open
}
Model::~Model() { cancelInvariants(); }

// A trace by its name (*.jsonl, what `flood trace` is given) or by its header line, so a
// trace saved under any name opens as one.
static bool isTracePath(const std::string& path) {
    if (path.size() > 6 && path.compare(path.size() - 6, 6, ".jsonl") == 0) return true;
    std::ifstream in(path, std::ios::binary);
    char head[64] = {};
    in.read(head, sizeof head - 1);
    std::string h(head, size_t(in.gcount()));
    h.erase(std::remove_if(h.begin(), h.end(),
                           [](char c) { return std::isspace(static_cast<unsigned char>(c)); }),
            h.end());
    return h.rfind("{\"format\":\"flood-trace\"", 0) == 0 || isBinaryTrace(h);
}

void Model::open(const std::string& path) {
    // A gallery file opens the gallery: its first polygon, and its list in the Open panel.
    if (std::filesystem::path(path).filename() == "gallery.json") {
        std::string dir = std::filesystem::path(path).parent_path().string();
        if (dir.empty()) dir = ".";
        if (std::vector<GalleryEntry> entries = readGallery(dir); !entries.empty()) {
            galleryDir_ = dir;
            ++galleryOpens_;
            return open(entries.front().file);
        }
    }
    ReadResult r;
    Trace t;
    const bool isTrace = isTracePath(path);
    try {
        if (isTrace) r.diagnostic = readTraceFile(path, t);
        // GIS datasets (Shapefile, GeoPackage, ...) through GDAL: the selected layer's
        // polygonal features as one polygon, as `flood triangulate FILE` reads them.
        else r = gdal::readAny(path, {gisLayer, -1, gisWhere});
    } catch (const std::exception& ex) {
        r.diagnostic = {Status::Malformed, path + ": " + ex.what()};
    }
    if (!r.diagnostic.ok()) {
        // A failed open keeps what was loaded; with nothing loaded, the failure is the verdict.
        openDiag_ = r.diagnostic;
        if (trace_->polygon.vertices.empty()) {
            openPolygon({}, path, r.diagnostic);
            openDiag_ = r.diagnostic;
        }
        return;
    }
    if (isTrace) {
        openTrace(std::move(t), path);
    } else {
        Diagnostic d = validate(r.polygon, path);
        openPolygon(std::move(r.polygon), path, d, std::move(r.warnings));
    }
    remember(path);
}

void Model::remember(const std::string& path) {
    std::error_code ec;
    std::string abs = std::filesystem::absolute(path, ec).lexically_normal().string();
    if (ec || path == "-") abs = path;
    recent_.erase(std::remove(recent_.begin(), recent_.end(), abs), recent_.end());
    recent_.insert(recent_.begin(), abs);
    if (recent_.size() > 10) recent_.resize(10);
    if (!recentPath.empty()) saveRecent(recentPath);
}

void Model::openTrace(Trace trace, const std::string& name) {
    playing_ = false;
    ++generation_;
    path_ = name;
    openDiag_ = {};
    warnings_.clear();
    // The trace holds the run; validation of a copy only says whether its input was valid.
    Polygon copy = trace.polygon;
    input_ = copy.vertices.empty() ? Diagnostic{} : validate(copy, name);
    up_ = trace.up;
    adopt(std::make_unique<Trace>(std::move(trace)));
}

void Model::openPolygon(Polygon polygon, const std::string& name, Diagnostic input,
                        std::vector<std::string> warnings) {
    playing_ = false;
    ++generation_;
    path_ = name;
    openDiag_ = input.status == Status::Malformed ? input : Diagnostic{};
    input_ = std::move(input);
    warnings_ = std::move(warnings);
    cancelInvariants();  // the scan reads the trace about to be replaced
    auto trace = std::make_unique<Trace>();
    if (!polygon.vertices.empty()) {
        try {
            *trace = record(polygon, Options{up_});
        } catch (const std::exception& ex) {
            trace->diagnostic = {Status::Internal, name + ": " + ex.what()};
        }
    }
    trace->polygon = std::move(polygon);
    adopt(std::move(trace));
}

void Model::adopt(std::unique_ptr<Trace> trace) {
    errorView_ = false;
    feature_ = kNoFeature;  // openFeature / openShrunk set these again after adopting
    origin_.clear();
    // The replay points into the trace: replace both together, replay first.
    replay_.reset();
    trace_ = std::move(trace);
    replay_ = std::make_unique<Replay>(*trace_);
    classes_ = classifyVertices(trace_->polygon, trace_->up);
    transcript_ = transcriptItems(trace_->events);
    triangleStep_.assign(trace_->triangles.size(), 0);
    for (const Event& e : trace_->events)
        for (uint32_t t = e.firstTriangle;
             t < e.firstTriangle + e.triangleCount && t < triangleStep_.size(); ++t)
            triangleStep_[t] = e.step + 1;
    computeVerdictLines();  // runs the exact checker: once, not every frame
    computeFindings();
    computeOffenders();
    verdict_ = computeVerdict();
    needsFit_ = true;
    step_ = 0;
    replay_->seek(0);
    timeline = {};
    findBreakpointSteps();
    countTransitions();
    forbiddenStep_ = 0;
    // Land where the trouble is: the forbidden event, so its state is on screen.
    for (const Event& e : trace_->events)
        if (e.action == Action::Forbidden) {
            forbiddenStep_ = e.step + 1;
            seek(forbiddenStep_);
            break;
        }
    landedStep_ = step_;
    landingPending_ = true;
    scanWaiting_ = std::exchange(deferScan_, false);  // live editing: started once the drag ends
    if (scanWaiting_) scan_.done = false, scan_.progress = 0;  // no scan yet: nothing done
    else startInvariants();
}

bool Model::landOnFirstViolation() {
    if (!landingPending_ || !invariantsDone()) return false;
    landingPending_ = false;
    if (step_ != landedStep_ || firstViolationStep() == 0) return false;
    seek(firstViolationStep());
    return true;
}

void Model::startInvariants() {
    scan_.cancel = false;
    scan_.done = false;
    scan_.progress = 0;
    scan_.found.clear();
    scan_.thread = std::thread([this, trace = trace_.get()] {
        scan_.found = checkInvariants(*trace, &scan_.progress, &scan_.cancel);
        scan_.done.store(true, std::memory_order_release);
    });
}

void Model::cancelInvariants() {
    scan_.cancel = true;
    waitForInvariants();
}

void Model::waitForInvariants() {
    if (scan_.thread.joinable()) scan_.thread.join();
}

const std::vector<Violation>& Model::violations() const {
    static const std::vector<Violation> none;
    return invariantsDone() ? scan_.found : none;
}

uint32_t Model::firstViolationStep() const {
    const std::vector<Violation>& v = violations();
    return v.empty() ? 0 : v.front().step;
}

void Model::computeOffenders() {
    offenders_.clear();
    auto add = [&](Index v) {
        if (v != kNone && v < trace_->polygon.vertices.size()) offenders_.push_back(v);
    };
    for (const Event& e : trace_->events) {
        if (e.action != Action::Forbidden) continue;
        add(e.culprit), add(e.culprit2);
        add(e.before.left), add(e.before.right), add(e.before.nextLeft), add(e.before.nextRight);
    }
    for (Index v : error_.vertices) add(v);
    std::sort(offenders_.begin(), offenders_.end());
    offenders_.erase(std::unique(offenders_.begin(), offenders_.end()), offenders_.end());
}

std::string Model::computeVerdict() const {
    std::string s;
    for (const VerdictLine& l : verdictLines_) s += (s.empty() ? "" : "\n") + l.text;
    return s;
}

void Model::computeVerdictLines() {
    verdictLines_.clear();
    check_ = {};
    error_ = {};
    firstErrorStep_ = kNone;
    const Polygon& P = trace_->polygon;
    auto line = [&](Verdict k, std::string text, bool note = false) {
        verdictLines_.push_back({k, std::move(text), note});
    };
    if (!input_.ok() && P.vertices.empty()) {
        line(input_.status == Status::Malformed ? Verdict::Malformed : Verdict::Invalid,
             input_.message);
        return;
    }
    if (!input_.ok()) {
        line(Verdict::Invalid, "invalid input: " + input_.message);
        error_ = input_.culprits;
    }
    const Event* forbidden = nullptr;
    for (const Event& e : trace_->events)
        if (e.action == Action::Forbidden) {
            forbidden = &e;
            break;
        }
    if (forbidden) {
        line(Verdict::Forbidden, "forbidden at step " + std::to_string(forbidden->step + 1) + ": " +
                                     describeForbidden(P, *forbidden));
        if (error_.empty()) error_ = forbiddenCulprits(P, *forbidden);
        firstErrorStep_ = forbidden->step + 1;
        return;
    }
    if (!trace_->diagnostic.ok()) {
        line(Verdict::Internal, trace_->diagnostic.message);
        if (error_.empty()) error_ = trace_->diagnostic.culprits;
        return;
    }
    if (P.vertices.empty()) return;  // nothing loaded
    // A completed run: the exact checker decides, never the triangle count.
    check_ = checked_ ? std::move(*checked_) : checkTriangulation(P, trace_->triangles);
    checked_.reset();
    if (!check_.ok) {
        line(Verdict::Checker, "the exact checker rejects the triangulation: " + check_.reason);
        if (error_.empty()) error_ = check_.culprits;
        for (uint32_t t : check_.culprits.triangles)
            if (t < triangleStep_.size() && triangleStep_[t] &&
                (firstErrorStep_ == kNone || triangleStep_[t] < firstErrorStep_))
                firstErrorStep_ = triangleStep_[t];
    } else if (input_.ok()) {
        line(Verdict::Ok, "ok: " + std::to_string(trace_->triangles.size()) +
                              " triangles, exact checker passed");
    } else {
        line(Verdict::Ok,
             "the exact checker accepts the " + std::to_string(trace_->triangles.size()) +
                 " triangles, but the input is invalid",
             true);
    }
    if (firstErrorStep_ == kNone && !input_.ok()) {
        // Invalid input that floods through: the first step a culprit is a finger.
        for (const Event& e : trace_->events) {
            for (Index v : {e.after.left, e.after.right, e.after.nextLeft, e.after.nextRight})
                if (v != kNone && std::find(error_.vertices.begin(), error_.vertices.end(), v) !=
                                      error_.vertices.end())
                    firstErrorStep_ = e.step + 1;
            if (firstErrorStep_ != kNone) break;
        }
    }
}

bool Model::failed() const {
    return std::any_of(verdictLines_.begin(), verdictLines_.end(),
                       [](const VerdictLine& l) { return l.failure(); });
}

int Model::exitCode() const {
    if (!openDiag_.ok()) return int(openDiag_.status);
    for (const VerdictLine& l : verdictLines_)  // the first failure decides, as in the CLI
        if (l.failure()) return int(verdictStatus(l.kind));
    return 0;
}

bool Model::errorPoint(Point& p) const { return diagnosticPoint(trace_->polygon, error_, p); }

void Model::computeFindings() {
    findings_.clear();
    findingsOmitted_ = 0;
    findingsComplete_ = true;
    currentFinding_ = 0;
    const Polygon& P = trace_->polygon;
    auto add = [&](Verdict kind, const Diagnostic& d, const std::string& name) {
        Finding f;
        f.kind = kind;
        f.message = d.message;
        f.culprits = d.culprits;
        Where w = whereOf(P, d.culprits);
        f.where = w.text;
        f.reason = reasonOf(d.message, name, w);
        f.hasPoint = diagnosticPoint(P, d.culprits, f.point, true);
        findings_.push_back(std::move(f));
    };
    // One line of the verdict, one finding; the input's line, every validation finding.
    for (const VerdictLine& line : verdictLines_) {
        switch (line.kind) {
            case Verdict::Malformed: add(line.kind, input_, path_); break;
            case Verdict::Invalid: {
                if (P.vertices.empty()) {
                    add(line.kind, input_, path_);
                    break;
                }
                // validate()'s verdict first (an edit's findings came with its flood).
                Findings all = validated_ ? std::move(*validated_) : validateAll(P, path_);
                if (all.list.empty() || all.list.front().message != input_.message)
                    all.list.insert(all.list.begin(), input_);
                for (const Diagnostic& d : all.list) add(line.kind, d, path_);
                findingsOmitted_ = all.omitted;
                findingsComplete_ = all.complete;
                break;
            }
            case Verdict::Forbidden:
                for (const Event& e : trace_->events)
                    if (e.action == Action::Forbidden) {
                        Finding f;
                        f.kind = line.kind;
                        f.step = e.step + 1;
                        f.where = "step " + std::to_string(f.step);
                        f.reason = describeForbidden(P, e);
                        f.message = line.text;
                        f.culprits = forbiddenCulprits(P, e);
                        f.hasPoint = diagnosticPoint(P, f.culprits, f.point, true);
                        findings_.push_back(std::move(f));
                        break;
                    }
                break;
            case Verdict::Internal:
                add(line.kind, trace_->diagnostic, path_);
                findings_.back().message = line.text;
                break;
            case Verdict::Checker: {
                Finding f;
                f.kind = line.kind;
                f.reason = check_.reason;
                f.message = line.text;
                f.culprits = check_.culprits;
                f.where = check_.culprits.triangles.empty()
                              ? whereOf(P, check_.culprits).text
                              : "triangle " + std::to_string(check_.culprits.triangles.front());
                f.hasPoint = diagnosticPoint(P, f.culprits, f.point, true);
                for (uint32_t t : f.culprits.triangles)
                    if (t < triangleStep_.size() && triangleStep_[t] &&
                        (f.step == kNone || triangleStep_[t] < f.step))
                        f.step = triangleStep_[t];
                findings_.push_back(std::move(f));
                break;
            }
            default: break;
        }
    }
    validated_.reset();
    if (!findings_.empty()) error_ = findings_.front().culprits;
}

// A validation finding shows at the first step one of its vertices is a finger.
uint32_t Model::findingStep(const Finding& f) const {
    if (f.step != kNone || f.kind != Verdict::Invalid) return f.step;
    const auto& blamed = f.culprits.vertices;
    if (blamed.empty()) return kNone;
    for (const Event& e : trace_->events)
        for (Index v : {e.after.left, e.after.right, e.after.nextLeft, e.after.nextRight})
            if (v != kNone && std::find(blamed.begin(), blamed.end(), v) != blamed.end())
                return e.step + 1;
    return kNone;
}

bool Model::showFinding(size_t i) {
    if (i >= findings_.size()) return false;
    Finding& f = findings_[i];
    Camera framed = camera_;
    if (!frameCulprits(trace_->polygon, trace_->triangles, f.culprits, f.kind == Verdict::Invalid,
                       camera_.viewport(), framed))
        return false;
    camera_ = framed;
    currentFinding_ = i;
    error_ = f.culprits;
    errorView_ = true;
    needsFit_ = false;
    f.step = findingStep(f);
    if (f.step != kNone) seek(f.step);
    return true;
}

bool Model::nextFinding(int direction) {
    const size_t n = findings_.size();
    if (n == 0) return false;
    if (!errorView_ && showFinding(currentFinding_)) return true;
    // A finding with nothing to frame is skipped.
    for (size_t k = 1; k <= n; ++k) {
        size_t i = direction > 0 ? (currentFinding_ + k) % n : (currentFinding_ + n - k % n) % n;
        if (showFinding(i)) return true;
    }
    return false;
}

bool Model::frameVertices(const std::vector<Index>& vertices) {
    const Polygon& P = trace_->polygon;
    Culprits c;
    for (Index v : vertices)
        if (v < P.vertices.size()) c.vertices.push_back(v);
    if (c.vertices.empty()) return false;
    WorldBox box;
    double minSide = 0;
    if (!culpritBox(P, trace_->triangles, c, false, box, minSide)) return false;
    if (c.vertices.size() == 1) {
        // One vertex stays at the centre: its nearer neighbour's distance on every side.
        const Point v = P.vertices[c.vertices[0]];
        const double r = std::max({v.x - box.x0, box.x1 - v.x, v.y - box.y0, box.y1 - v.y});
        box = {};
        box.add({v.x - r, v.y - r}), box.add({v.x + r, v.y + r});
    }
    camera_ = frameNeighbourhood(box, minSide, camera_.viewport());
    needsFit_ = false;
    return true;
}

void Model::goToViolation(const Violation& v) {
    seek(v.step);
    frameVertices(v.vertices);
}

FindTarget findTarget(const Trace& trace, const std::string& query) {
    FindTarget f;
    std::string q;
    for (char c : query)
        if (!std::isspace(static_cast<unsigned char>(c)))
            q += char(std::tolower(static_cast<unsigned char>(c)));
    if (q.empty()) return f.message = "type v<vertex>, t<triangle>, s<step> or r<ring>", f;
    f.kind = q[0];
    if (std::string("vtsr").find(f.kind) == std::string::npos)
        return f.message =
                   "'" + query + "': start with v (vertex), t (triangle), s (step) or r (ring)",
               f;
    if (q.size() == 1 || q.size() > 12 || q.find_first_not_of("0123456789", 1) != std::string::npos)
        return f.message = "'" + query + "': a number must follow '" + std::string(1, f.kind) + "'",
               f;
    f.index = std::stoull(q.substr(1));
    const Polygon& P = trace.polygon;
    const auto& V = P.vertices;
    auto outOfRange = [&](const char* what, size_t count) {
        f.message = std::string("no ") + what + " " + std::to_string(f.index) + ": there are " +
                    std::to_string(count) + (count ? " (0-" + std::to_string(count - 1) + ")" : "");
        return f;
    };
    auto at = [&](Point p) {
        f.hasCenter = true, f.center = p, f.x0 = f.x1 = p.x, f.y0 = f.y1 = p.y;
    };
    switch (f.kind) {
        case 'v': {
            if (f.index >= V.size()) return outOfRange("vertex", V.size());
            Index v = Index(f.index);
            at(V[v]);
            f.vertices = {v};
            // Its first event: the first step it is a finger or the event's subject.
            for (const Event& e : trace.events)
                for (Index u : {e.after.left, e.after.right, e.after.nextLeft, e.after.nextRight,
                                e.bottom, e.sag})  // sag, top and culprit share storage
                    if (u == v && f.seekTo == kNone) f.seekTo = e.step + 1;
            Index r = P.ringOf(v);
            f.message = "vertex " + std::to_string(v) + ": ring " + std::to_string(r) + " vertex " +
                        std::to_string(v - P.rings[r].first);
            break;
        }
        case 't': {
            if (f.index >= trace.triangles.size())
                return outOfRange("triangle", trace.triangles.size());
            const Triangle& t = trace.triangles[f.index];
            if (t[0] >= V.size() || t[1] >= V.size() || t[2] >= V.size())
                return f.message =
                           "triangle " + std::to_string(f.index) + " has a vertex out of range",
                       f;
            at({(V[t[0]].x + V[t[1]].x + V[t[2]].x) / 3, (V[t[0]].y + V[t[1]].y + V[t[2]].y) / 3});
            for (Index v : t)
                f.x0 = std::min(f.x0, V[v].x), f.x1 = std::max(f.x1, V[v].x),
                f.y0 = std::min(f.y0, V[v].y), f.y1 = std::max(f.y1, V[v].y);
            for (const Event& e : trace.events)
                if (e.triangleCount && f.index >= e.firstTriangle &&
                    f.index < uint64_t(e.firstTriangle) + e.triangleCount) {
                    f.seekTo = e.step + 1;
                    break;
                }
            f.message = "triangle " + std::to_string(f.index);
            break;
        }
        case 's': {
            if (f.index > trace.events.size())
                return f.message = "no step " + std::to_string(f.index) + ": there are " +
                                   std::to_string(trace.events.size()) + " steps",
                       f;
            f.seekTo = uint32_t(f.index);
            f.message = "step " + std::to_string(f.index);
            if (f.index == 0) return f.ok = true, f.message += " (before anything)", f;
            const Event& e = trace.events[f.index - 1];
            Index v = e.water != kNone ? e.water : e.after.left;
            if (v == kNone || v >= V.size()) v = e.before.left;
            if (v != kNone && v < V.size()) at(V[v]);
            else return f.ok = true, f;  // nothing to centre on: seek only
            // Framed with its fingers: where the water is and where it goes next.
            f.vertices = {v};
            for (Index u : {e.after.left, e.after.right, e.after.nextLeft, e.after.nextRight})
                if (u != kNone && u < V.size() &&
                    std::find(f.vertices.begin(), f.vertices.end(), u) == f.vertices.end())
                    f.vertices.push_back(u);
            break;
        }
        case 'r': {
            if (f.index >= P.rings.size()) return outOfRange("ring", P.rings.size());
            const Ring& r = P.rings[f.index];
            if (r.count == 0) return f.message = "ring " + std::to_string(f.index) + " is empty", f;
            at(V[r.first]);
            for (Index i = 0; i < r.count; ++i) {
                Point p = V[r.first + i];
                if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
                f.x0 = std::min(f.x0, p.x), f.x1 = std::max(f.x1, p.x);
                f.y0 = std::min(f.y0, p.y), f.y1 = std::max(f.y1, p.y);
            }
            f.center = {(f.x0 + f.x1) / 2, (f.y0 + f.y1) / 2};
            f.message =
                "ring " + std::to_string(f.index) + ": " + std::to_string(r.count) + " vertices";
            break;
        }
    }
    f.ok = true;
    return f;
}

FindTarget Model::find(const std::string& query) {
    FindTarget f = findTarget(*trace_, query);
    if (!f.ok) return f;
    if (f.seekTo != kNone) seek(f.seekTo);
    if (!f.hasCenter) return f;
    // Framed, never only centred: a vertex with its nearest neighbours, a step's fingers, a
    // triangle or a ring whole with a margin.
    if (!f.vertices.empty() && frameVertices(f.vertices)) return f;
    WorldBox box;
    box.add({f.x0, f.y0}), box.add({f.x1, f.y1});
    if (f.kind == 'r' && (f.x1 > f.x0 || f.y1 > f.y0))
        camera_.fitBox(f.x0, f.y0, f.x1, f.y1, camera_.viewport());
    else if (!box.empty() && (box.w() > 0 || box.h() > 0))
        camera_ = frameNeighbourhood(box, 0, camera_.viewport());
    else camera_.centerOn(f.center);
    needsFit_ = false;
    return f;
}

const Event* Model::currentEvent() const {
    return step_ == 0 || step_ > steps() ? nullptr : &trace_->events[step_ - 1];
}

void Model::seek(uint32_t step) {
    step_ = std::min(step, steps());
    replay_->seek(step_);
}

const std::vector<Index>& Model::chainBefore() const {
    const uint64_t key = generation_ << 32 | step_;
    if (chainBeforeFor_ != key) {
        chainBeforeFor_ = key;
        chainBefore_.clear();
        if (step_ > 0) {  // the replay ends where it was: state() is unchanged
            chainBefore_ = replay_->seek(step_ - 1).chain;
            replay_->seek(step_);
        }
    }
    return chainBefore_;
}

bool Model::seekAction(Action a, int direction) {
    const auto& ev = trace_->events;
    if (direction > 0) {
        for (uint32_t s = step_ + 1; s <= ev.size(); ++s)
            if (ev[s - 1].action == a) return seek(s), true;
    } else {
        for (uint32_t s = step_; s-- > 1;)
            if (ev[s - 1].action == a) return seek(s), true;
    }
    return false;
}

bool Model::runToBreakpoint(int direction) {
    const auto& ev = trace_->events;
    if (direction > 0) {
        for (uint32_t s = step_ + 1; s <= ev.size(); ++s)
            if (hits(breakpoints_, ev[s - 1])) return seek(s), true;
        last();
    } else {
        for (uint32_t s = step_; s-- > 1;)
            if (hits(breakpoints_, ev[s - 1])) return seek(s), true;
        first();
    }
    return false;
}

void Model::setPlaying(bool on) {
    if (on == playing_) return;
    playing_ = on;
    playClock_ = 0;
    if (playing_ && step_ >= steps()) seek(0);  // play again from the start
}

void Model::advance(double seconds) {
    if (!playing_) return;
    playClock_ += seconds * std::max(speed_, 0.01);
    while (playClock_ >= 1 && playing_) {
        playClock_ -= 1;
        if (step_ >= steps() || pendingQuestion() >= 0) {  // the end, or a question
            playing_ = false;
            break;
        }
        stepForward();
        if (breakpoints_.any() && hits(breakpoints_, *currentEvent())) playing_ = false;
    }
    if (step_ >= steps()) playing_ = false;
}

void Model::setBreakpoints(const Breakpoints& b) {
    breakpoints_ = b;
    findBreakpointSteps();
}

void Model::findBreakpointSteps() {
    breakpointSteps_.clear();
    if (breakpoints_.any())
        for (const Event& e : trace_->events)
            if (hits(breakpoints_, e)) breakpointSteps_.push_back(e.step + 1);
}

void Model::countTransitions() {
    transitions_ = {};
    const auto& ev = trace_->events;
    for (size_t i = 1; i < ev.size(); ++i)
        ++transitions_[size_t(ev[i - 1].action)][size_t(ev[i].action)];
}

void Model::fitCamera(const Rect& viewport, const std::vector<Rect>& overlays) {
    WorldBox box;
    for (Point p : trace_->polygon.vertices) box.add(p);
    camera_ = view::fitCamera(box, viewport, overlays);
    fitted_ = camera_;
    needsFit_ = false;
    errorView_ = false;
}

bool Model::viewIsFit() const {
    if (needsFit_) return true;
    const Camera& c = camera_;
    return !errorView_ && c.scale() == fitted_.scale() && c.center().x == fitted_.center().x &&
           c.center().y == fitted_.center().y;
}

void Model::loadRecent(const std::string& file) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line) && recent_.size() < 10;)
        if (!line.empty()) recent_.push_back(line);
}

void Model::saveRecent(const std::string& file) const {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(file).parent_path(), ec);
    std::ofstream out(file);
    for (const auto& r : recent_) out << r << "\n";
}

uint32_t Model::triangleStep(uint32_t t) const {
    return t < triangleStep_.size() ? triangleStep_[t] : 0;
}

Index Model::pickVertex(Vec2 screen, double radiusPx) const {
    Index best = kNone;
    double bestD = radiusPx * radiusPx;
    const auto& v = trace_->polygon.vertices;
    for (Index i = 0; i < v.size(); ++i) {
        Vec2 s = camera_.toScreen(v[i]);
        double d = (s.x - screen.x) * (s.x - screen.x) + (s.y - screen.y) * (s.y - screen.y);
        if (d <= bestD) bestD = d, best = i;
    }
    return best;
}

int64_t Model::pickTriangle(Vec2 screen) const {
    Point p = camera_.toWorld(screen);
    const auto& v = trace_->polygon.vertices;
    uint32_t n = std::min<uint32_t>(state().triangleCount, uint32_t(trace_->triangles.size()));
    // Display-only hit test: plain doubles are fine here, exactness lives in the core.
    auto side = [](Point a, Point b, Point c) {
        return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    };
    for (uint32_t t = 0; t < n; ++t) {
        const Triangle& tri = trace_->triangles[t];
        if (tri[0] >= v.size() || tri[1] >= v.size() || tri[2] >= v.size()) continue;
        double a = side(v[tri[0]], v[tri[1]], p), b = side(v[tri[1]], v[tri[2]], p),
               c = side(v[tri[2]], v[tri[0]], p);
        if ((a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0)) return t;
    }
    return -1;
}

// ========================================================================================
// [SECTION] polygon files
// The installed polygons are found beside the executable (PREFIX/bin/flood-viewer ->
// PREFIX/share/flood/polygons), so an installed tree can move; a build in the source tree
// finds the source's; the install path the build was configured with comes last.
std::string polygonsDir() {
    namespace fs = std::filesystem;
    if (const char* d = std::getenv("FLOOD_POLYGONS_DIR")) return d;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed = exe.parent_path().parent_path() / FLOOD_DATA_SUBDIR / "polygons";
        if (fs::is_directory(installed, ec)) return installed.string();
    }
    const std::string source = std::string(FLOOD_SOURCE_DIR) + "/polygons";
    if (fs::is_directory(source, ec)) return source;
    return std::string(FLOOD_INSTALL_DATA_DIR) + "/polygons";
}

std::string Model::galleryDir() const { return galleryDir_.empty() ? polygonsDir() : galleryDir_; }

std::vector<GalleryEntry> readGallery(const std::string& dir) {
    std::vector<GalleryEntry> out;
    std::ifstream in(dir + "/gallery.json");
    if (!in) return out;
    nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (!j.is_array()) return out;
    for (const auto& e : j) {
        if (!e.is_object() || !e.contains("file") || !e["file"].is_string()) continue;
        GalleryEntry g;
        g.file = dir + "/" + e["file"].get<std::string>();
        g.title = e.value("title", e["file"].get<std::string>());
        g.description = e.value("description", "");
        out.push_back(std::move(g));
    }
    return out;
}

std::string defaultPolygonPath() {
    std::string dir = polygonsDir();
    std::string preferred = dir + "/" FLOOD_VIEWER_DEFAULT_POLYGON;
    std::error_code ec;
    if (std::filesystem::exists(preferred, ec)) return preferred;
    auto files = polygonFiles(dir);
    return files.empty() ? std::string() : files.front();
}

}  // namespace flood::view

// ----------------------------------------------------------------------------------------
// Features of a collection, shrinking, saving a repro.

namespace flood::view {

bool Model::openFeature(const std::string& path, size_t index) {
    DatasetRead d;
    try {
        // A GIS layer's features, by FID (--where keeps some of them: the others are not there).
        bool gis = false;
        d = gdal::readAnyFeatures(path, {gisLayer, -1, gisWhere}, kDefaultMaxInputBytes, false,
                                  gis);
    } catch (const std::exception& ex) {
        openDiag_ = {Status::Malformed, path + ": " + ex.what()};
        return false;
    }
    if (d.features.size() == 1 && d.features[0].wholeFile) {
        const Diagnostic& r = d.features[0].read.diagnostic;
        openDiag_ = !r.ok() ? r
                            : Diagnostic{Status::Usage,
                                         path + ": not a FeatureCollection, it has no feature " +
                                             std::to_string(index)};
        return false;
    }
    // By FID, as `flood check` and `flood --feature` name them (FeatureRead::fid); a
    // non-polygonal feature has none here.
    auto it = std::find_if(d.features.begin(), d.features.end(),
                           [&](const FeatureRead& f) { return f.fid == int64_t(index); });
    if (it == d.features.end()) {
        int64_t first = INT64_MAX, last = INT64_MIN;
        for (const auto& f : d.features)
            first = std::min(first, f.fid), last = std::max(last, f.fid);
        openDiag_ = {Status::Usage,
                     path + ": no polygonal feature " + std::to_string(index) +
                         " (the collection's " +
                         (d.features.empty()
                              ? std::string("features are not polygons")
                              : "FIDs run " + std::to_string(first) + ".." + std::to_string(last)) +
                         ")"};
        return false;
    }
    FeatureRead& f = *it;
    const std::string name = path + "#" + std::to_string(index);
    if (!f.read.diagnostic.ok()) {
        openDiag_ = f.read.diagnostic;
        return false;
    }
    Diagnostic v = validate(f.read.polygon, name);
    openPolygon(std::move(f.read.polygon), name, v, std::move(f.read.warnings));
    feature_ = index;
    remember(path);
    return true;
}

void Model::openShrunk(const ShrinkResult& result) {
    const std::string from = path_;
    const size_t fromFeature = feature_;
    Polygon p = result.polygon;
    Diagnostic v = validate(p, from + " (shrunk)");
    openPolygon(std::move(p), from + " (shrunk)", v);
    // What it came from: a file (the feature's file for "FILE#N"), one click away.
    originName_ = from;
    origin_ = fromFeature == kNoFeature ? from : from.substr(0, from.rfind('#'));
    originFeature_ = fromFeature;
}

void Model::openOrigin() {
    if (origin_.empty()) return;
    const std::string file = origin_;
    if (originFeature_ == kNoFeature) open(file);
    else openFeature(file, originFeature_);
}

void ShrinkJob::start(const Polygon& polygon, ShrinkOptions options) {
    reset();
    maxTries_ = options.maxTries;
    options.onTry = [this, user = std::move(options.onTry)](size_t tries, size_t vertices) {
        tries_.store(tries, std::memory_order_relaxed);
        if (user && !user(tries, vertices)) return false;
        return !cancel_.load(std::memory_order_relaxed);
    };
    thread_ = std::thread([this, polygon, options] {
        try {
            result_ = shrink(polygon, options);
        } catch (const std::exception& ex) {
            result_ = {};
            result_.polygon = polygon;
            result_.failure.kind = Failure::Kind::Crash;
            result_.failure.message = std::string("the shrinker failed: ") + ex.what();
        }
        done_.store(true, std::memory_order_release);
    });
}

void ShrinkJob::cancel() {
    requestCancel();
    wait();
}

void ShrinkJob::wait() {
    if (thread_.joinable()) thread_.join();
}

void ShrinkJob::reset() {
    cancel();
    cancel_.store(false);
    done_.store(false);
    tries_.store(0);
    result_ = {};
}

Diagnostic saveGeoJson(const Polygon& polygon, const std::string& path) {
    namespace fs = std::filesystem;
    std::ostringstream json;
    // writePolygonJson: a bare ring array for one part (the coordinates of a GeoJSON
    // Polygon), a GeoJSON MultiPolygon for several.
    if (polygon.parts.size() > 1) writePolygonJson(json, polygon);
    else {
        json << "{\"type\": \"Polygon\", \"coordinates\": ";
        writePolygonJson(json, polygon);
        json << "}";
    }
    json << "\n";
    // Beside the target, so the rename stays on one file system and is atomic.
    const std::string tmp = path + ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << json.str();
        out.flush();
        if (!out) {
            std::error_code ec;
            fs::remove(tmp, ec);
            return {Status::WriteFailed, path + ": cannot write " + tmp};
        }
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
        fs::remove(tmp, ec);
        return {Status::WriteFailed, path + ": cannot replace the file: " + ec.message()};
    }
    return {};
}

FeatureVerdict judgeFeature(const FeatureRead& f) {
    FeatureVerdict v;
    v.index = size_t(f.fid);
    v.id = f.id;
    v.name = f.name;
    v.vertices = f.read.polygon.vertices.size();
    try {
        ReadResult read = f.read;  // validation records T-junctions in the polygon
        Judgement j = judge(read, "feature " + std::to_string(f.index));
        v.kind = j.verdict;
        // The checker's reason without the name the list shows already.
        v.reason = j.verdict == Verdict::Checker
                       ? "the exact checker rejects the triangulation: " + j.check.reason
                       : j.diagnostic.message;
    } catch (const std::exception& ex) {
        v.kind = Verdict::Internal;
        v.reason = std::string("exception: ") + ex.what();
    }
    return v;
}

void orderFailingFirst(std::vector<FeatureVerdict>& list) {
    std::stable_sort(list.begin(), list.end(),
                     [](const FeatureVerdict& a, const FeatureVerdict& b) {
                         return a.failure() != b.failure() ? a.failure() : a.index < b.index;
                     });
}

void FeatureScan::start(const std::string& path) {
    cancel();
    path_ = path;
    cancel_ = false;
    done_ = false;
    progress_ = 0;
    total_ = 0;
    features_.clear();
    diag_ = {};
    thread_ = std::thread([this, path] {
        DatasetRead d;
        try {
            d = readFeaturesFile(path, kDefaultMaxInputBytes, false);
        } catch (const std::exception& ex) {
            diag_ = {Status::Malformed, path + ": " + ex.what()};
        }
        if (d.features.size() == 1 && d.features[0].wholeFile) {
            diag_ = d.features[0].read.diagnostic;  // not a collection: nothing to list
            d.features.clear();
        }
        total_.store(d.features.size(), std::memory_order_relaxed);
        std::vector<FeatureVerdict> list;
        for (const FeatureRead& f : d.features) {
            if (cancel_.load(std::memory_order_relaxed)) break;
            list.push_back(judgeFeature(f));
            progress_.store(list.size(), std::memory_order_relaxed);
        }
        orderFailingFirst(list);
        features_ = std::move(list);
        done_.store(true, std::memory_order_release);
    });
}

void FeatureScan::cancel() {
    cancel_.store(true, std::memory_order_relaxed);
    wait();
}

void FeatureScan::wait() {
    if (thread_.joinable()) thread_.join();
}

const StateTable& Model::stateTable() const {
    if (stateTableFor_ != generation_) {
        stateTable_ = buildStateTable(polygon(), trace().events, trace().up);
        stateTableFor_ = generation_;
    }
    return stateTable_;
}

// ========================================================================================
// [SECTION] Flood direction
FloodSummary summarizeFlood(const Trace& trace, const std::vector<VertexClass>& classes) {
    FloodSummary s;
    for (VertexClass c : classes) ++s.classes[size_t(c)];
    for (const Event& e : trace.events) {
        ++s.actions[size_t(e.action)];
        s.gorges += e.bottom != kNone;
    }
    s.triangles = uint32_t(trace.triangles.size());
    return s;
}

std::vector<SummaryChange> compareSummaries(const FloodSummary& before, const FloodSummary& after) {
    std::vector<SummaryChange> out;
    out.push_back({"gorges", before.gorges, after.gorges});
    for (VertexClass c :
         {VertexClass::Bottom, VertexClass::Sag, VertexClass::Top, VertexClass::Ceiling})
        out.push_back({std::string(vertexClassName(c)) + "s", before.classes[size_t(c)],
                       after.classes[size_t(c)]});
    for (size_t a = 0; a < size_t(Action::Count); ++a)
        if (Action(a) != Action::Forbidden || before.actions[a] || after.actions[a])
            out.push_back({actionName(Action(a)), before.actions[a], after.actions[a]});
    out.push_back({"triangles", before.triangles, after.triangles});
    return out;
}

bool Model::setUp(Up up) {
    if (!up.valid() || up == trace_->up) return false;
    previousSummary_ = summary();
    hasPrevious_ = true;
    up_ = up;
    const uint32_t at = step_;
    // What opened stays what it was: the name, the input's verdict, the feature or the
    // shrink's origin; only the run is new.
    const std::string name = path_;
    Diagnostic input = input_;
    std::vector<std::string> warnings = warnings_;
    const size_t feature = feature_, originFeature = originFeature_;
    const std::string origin = origin_, originName = originName_;
    const bool fit = needsFit_;  // the polygon does not move: fit only if not yet fitted
    openPolygon(trace_->polygon, name, std::move(input), std::move(warnings));
    feature_ = feature, originFeature_ = originFeature;
    origin_ = origin, originName_ = originName;
    needsFit_ = fit;
    seek(at);
    return true;
}

}  // namespace flood::view
