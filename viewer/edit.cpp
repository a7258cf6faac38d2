// [SECTION] Model's side of an edit  [SECTION] ring surgery  [SECTION] Editor
#include "edit.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>

#include "flood/geometry/predicates.h"
#include "flood/io/io.h"

namespace flood::view {

// ========================================================================================
// [SECTION] Model's side of an edit
Model::EditedRun Model::floodEdit(Polygon polygon, const std::string& name, Up up) {
    EditedRun run;
    floodRun(std::move(polygon), name, up, run);  // as an open floods and prepares its run
    return run;
}

void Model::adoptEdit(EditedRun run, bool deferScan) {
    const uint32_t at = step_;
    const uint32_t oldSteps = steps();
    const TimelineView tl = timeline;
    const size_t feature = feature_;
    const std::string origin = origin_, originName = originName_;
    const size_t originFeature = originFeature_;
    cancelInvariants();                    // the scan reads the trace about to be replaced
    if (!(run.trace->up == trace_->up)) {  // the dial turned: the direction panel compares
        previousSummary_ = summary();
        hasPrevious_ = true;
        up_ = run.trace->up;
    }
    ++generation_;
    openDiag_ = {};
    warnings_.clear();
    deferScan_ = deferScan;
    adopt(std::move(run));
    // What adopt() resets for an open stays as the user left it.
    feature_ = feature;
    origin_ = origin, originName_ = originName, originFeature_ = originFeature;
    needsFit_ = false;
    seek(at);
    if (tl.span == 0 || steps() == oldSteps) timeline = tl;
    landingPending_ = false;
}

void Model::startDeferredInvariants() {
    if (!scanWaiting_) return;
    scanWaiting_ = false;
    startInvariants();
}

// ========================================================================================
// [SECTION] ring surgery: Polygon keeps all rings' vertices in one array, so a ring growing
// or shrinking shifts the rings after it.
namespace {

Index partOfRing(const Polygon& p, Index ring) {
    for (Index k = 0; k < p.parts.size(); ++k)
        if (ring < p.parts[k].firstRing + p.parts[k].ringCount) return k;
    return Index(p.parts.size());
}

void shiftRings(Polygon& p, Index fromRing, long delta) {
    for (Index r = fromRing; r < p.rings.size(); ++r)
        p.rings[r].first = Index(long(p.rings[r].first) + delta);
}

void insertPoint(Polygon& p, Index ring, Index at, Point q) {
    Ring& g = p.rings[ring];
    p.vertices.insert(p.vertices.begin() + g.first + at, q);
    ++g.count;
    shiftRings(p, ring + 1, +1);
}

void erasePoint(Polygon& p, Index ring, Index at) {
    Ring& g = p.rings[ring];
    p.vertices.erase(p.vertices.begin() + g.first + at);
    --g.count;
    shiftRings(p, ring + 1, -1);
}

std::vector<Point> ringPoints(const Polygon& p, Index ring) {
    const Ring& g = p.rings[ring];
    return {p.vertices.begin() + g.first, p.vertices.begin() + g.first + g.count};
}

void setRingPoints(Polygon& p, Index ring, const std::vector<Point>& pts) {
    std::copy(pts.begin(), pts.end(), p.vertices.begin() + p.rings[ring].first);
}

// Ring `ring` through `pts`: the outer ring of a new part starting there (`ring` is where a
// part begins, or the end), or a hole at the end of the part before it.
void insertRing(Polygon& p, Index ring, const std::vector<Point>& pts, bool outer) {
    const Index first = ring < p.rings.size() ? p.rings[ring].first : Index(p.vertices.size());
    p.vertices.insert(p.vertices.begin() + first, pts.begin(), pts.end());
    shiftRings(p, ring, long(pts.size()));
    p.rings.insert(p.rings.begin() + ring, Ring{first, Index(pts.size())});
    if (outer) {
        Index k = 0;  // the part that begins at `ring`
        while (k < p.parts.size() && p.parts[k].firstRing < ring) ++k;
        p.parts.insert(p.parts.begin() + k, Part{ring, 1});
        for (Index j = k + 1; j < p.parts.size(); ++j) ++p.parts[j].firstRing;
    } else {
        Index k = partOfRing(p, ring - 1);
        ++p.parts[k].ringCount;
        for (Index j = k + 1; j < p.parts.size(); ++j) ++p.parts[j].firstRing;
    }
}

// The inverse of insertRing.
void eraseRing(Polygon& p, Index ring, bool outer) {
    const Ring g = p.rings[ring];
    const Index k = partOfRing(p, ring);
    p.vertices.erase(p.vertices.begin() + g.first, p.vertices.begin() + g.first + g.count);
    p.rings.erase(p.rings.begin() + ring);
    shiftRings(p, ring, -long(g.count));
    if (outer) p.parts.erase(p.parts.begin() + k);
    else --p.parts[k].ringCount;
    for (Index j = outer ? k : k + 1; j < p.parts.size(); ++j) --p.parts[j].firstRing;
}

// Winding number of ring `ring` around q, exact (orient decides every crossing).
bool ringContains(const Polygon& p, Index ring, Point q) {
    const Ring& g = p.rings[ring];
    int winding = 0;
    for (Index i = 0; i < g.count; ++i) {
        Point a = p.vertices[g.first + i], b = p.vertices[g.first + (i + 1) % g.count];
        if (a.y <= q.y && b.y > q.y && orient(a, b, q) > 0) ++winding;
        else if (b.y <= q.y && a.y > q.y && orient(a, b, q) < 0) --winding;
    }
    return winding != 0;
}

std::string where(const Polygon& p, Index v) {
    Index r = p.ringOf(v);
    return "vertex " + std::to_string(v - p.rings[r].first) + " of ring " + std::to_string(r);
}

bool finite(Point q) { return std::isfinite(q.x) && std::isfinite(q.y); }

}  // namespace

// ========================================================================================
// [SECTION] Editor
Editor::~Editor() { job_.wait(); }

void Editor::sync() {
    if (generation_ == model_.generation()) return;
    // Something else was opened (or nothing edited yet): edit what is loaded now.
    job_.reset();  // a flood of the polygon before: not adopted
    jobResult_ = {};
    dirty_ = false;
    polygon_ = model_.polygon();
    name_ = model_.path();
    up_ = model_.up();
    history_.clear();
    done_ = 0;
    corners.clear();
    generation_ = model_.generation();
}

const Polygon& Editor::polygon() {
    sync();
    return polygon_;
}

void Editor::beginGesture() {
    gesture_ = true;
    merging_ = false;
}

void Editor::endGesture() {
    gesture_ = false;
    merging_ = false;
    if (!pending()) model_.startDeferredInvariants();
}

const std::string& Editor::undoLabel() {
    static const std::string none;
    sync();
    return done_ > 0 ? history_[done_ - 1].label : none;
}

const std::string& Editor::redoLabel() {
    static const std::string none;
    sync();
    return done_ < history_.size() ? history_[done_].label : none;
}

void Editor::apply(const EditCommand& c, bool forward) {
    using K = EditCommand::Kind;
    Polygon& p = polygon_;
    switch (c.kind) {
        case K::MoveVertex:
            p.vertices[p.rings[c.ring].first + c.at] = forward ? c.to : c.from;
            break;
        case K::InsertVertex:
            if (forward) insertPoint(p, c.ring, c.at, c.to);
            else erasePoint(p, c.ring, c.at);
            break;
        case K::DeleteVertex:
            if (forward) erasePoint(p, c.ring, c.at);
            else insertPoint(p, c.ring, c.at, c.from);
            break;
        case K::AddRing:
            if (forward) insertRing(p, c.ring, c.after, c.outer);
            else eraseRing(p, c.ring, c.outer);
            break;
        case K::RemoveRing:
            if (forward) eraseRing(p, c.ring, c.outer);
            else insertRing(p, c.ring, c.before, c.outer);
            break;
        case K::MoveRing: setRingPoints(p, c.ring, forward ? c.after : c.before); break;
        case K::Replace: p = forward ? c.now : c.was; break;
    }
}

bool Editor::push(EditCommand c) {
    using K = EditCommand::Kind;
    // Within a gesture, a move of what the last command moved replaces its end point.
    if (merging_ && done_ == history_.size() && done_ > 0) {
        EditCommand& last = history_[done_ - 1];
        if (last.kind == c.kind && last.ring == c.ring && last.at == c.at &&
            (c.kind == K::MoveVertex || c.kind == K::MoveRing)) {
            last.to = c.to;
            last.after = std::move(c.after);
            apply(last, true);
            reflood();
            return true;
        }
    }
    apply(c, true);
    history_.resize(done_);  // a new edit forgets what was undone
    history_.push_back(std::move(c));
    done_ = history_.size();
    merging_ = gesture_;
    reflood();
    return true;
}

bool Editor::moveVertex(Index v, Point to) {
    sync();
    const Polygon& p = polygon_;
    if (v >= p.vertices.size()) return message_ = "no vertex " + std::to_string(v), false;
    if (!finite(to)) return message_ = "a vertex needs finite coordinates", false;
    EditCommand c;
    c.kind = EditCommand::Kind::MoveVertex;
    c.ring = p.ringOf(v);
    c.at = v - p.rings[c.ring].first;
    c.from = p.vertices[v];
    c.to = to;
    c.label = "move " + where(p, v);
    message_.clear();
    return push(std::move(c));
}

bool Editor::insertVertex(Index edge, Point q) {
    sync();
    const Polygon& p = polygon_;
    if (edge >= p.vertices.size())
        return message_ = "no edge from vertex " + std::to_string(edge), false;
    if (!finite(q)) return message_ = "a vertex needs finite coordinates", false;
    EditCommand c;
    c.kind = EditCommand::Kind::InsertVertex;
    c.ring = p.ringOf(edge);
    c.at = edge - p.rings[c.ring].first + 1;  // after the edge's first vertex in ring order
    c.to = q;
    c.label = "insert a vertex after " + where(p, edge);
    message_.clear();
    merging_ = false;
    return push(std::move(c));
}

bool Editor::deleteVertex(Index v) {
    sync();
    const Polygon& p = polygon_;
    if (v >= p.vertices.size()) return message_ = "no vertex " + std::to_string(v), false;
    EditCommand c;
    c.ring = p.ringOf(v);
    c.at = v - p.rings[c.ring].first;
    c.label = "delete " + where(p, v);
    const Index k = partOfRing(p, c.ring);
    if (p.rings[c.ring].count == 1) {
        // A ring cannot be empty: its last vertex goes with it.
        c.kind = EditCommand::Kind::RemoveRing;
        c.outer = p.parts[k].firstRing == c.ring;
        if (c.outer && p.parts[k].ringCount > 1)
            return message_ = "ring " + std::to_string(c.ring) +
                              " is an outer ring with holes: delete its holes first",
                   false;
        c.before = ringPoints(p, c.ring);
    } else {
        c.kind = EditCommand::Kind::DeleteVertex;
        c.from = p.vertices[v];
    }
    message_.clear();
    merging_ = false;
    return push(std::move(c));
}

bool Editor::addRing(const std::vector<Point>& pts) {
    sync();
    const Polygon& p = polygon_;
    if (pts.empty()) return message_ = "a ring needs corners", false;
    for (Point q : pts)
        if (!finite(q)) return message_ = "a vertex needs finite coordinates", false;
    EditCommand c;
    c.kind = EditCommand::Kind::AddRing;
    c.after = pts;
    c.outer = true;
    for (Index k = 0; k < p.parts.size() && c.outer; ++k)
        if (ringContains(p, p.parts[k].firstRing, pts[0])) {
            c.outer = false;
            c.ring = p.parts[k].firstRing + p.parts[k].ringCount;  // the part's last hole
            c.label = "add a hole to part " + std::to_string(k);
        }
    if (c.outer) {
        if (pts.size() < 3) return message_ = "an outer ring needs at least 3 corners", false;
        c.ring = Index(p.rings.size());
        c.label =
            p.parts.empty() ? "draw the outer ring" : "add part " + std::to_string(p.parts.size());
    }
    message_.clear();
    merging_ = false;
    return push(std::move(c));
}

bool Editor::moveRing(Index ring, Point offset) {
    sync();
    const Polygon& p = polygon_;
    if (ring >= p.rings.size()) return message_ = "no ring " + std::to_string(ring), false;
    EditCommand c;
    c.kind = EditCommand::Kind::MoveRing;
    c.ring = ring;
    const bool merge = merging_ && done_ > 0 && history_[done_ - 1].kind == c.kind &&
                       history_[done_ - 1].ring == ring;
    c.before = merge ? history_[done_ - 1].before : ringPoints(p, ring);
    c.after = c.before;
    for (Point& q : c.after) q = {q.x + offset.x, q.y + offset.y};
    for (Point q : c.after)
        if (!finite(q)) return message_ = "the ring would leave the finite plane", false;
    c.label = "move ring " + std::to_string(ring);
    message_.clear();
    return push(std::move(c));
}

void Editor::newEmpty() {
    sync();
    EditCommand c;
    c.kind = EditCommand::Kind::Replace;
    c.was = polygon_;
    c.label = "start from an empty canvas";
    corners.clear();
    message_.clear();
    merging_ = false;
    push(std::move(c));
}

bool Editor::closeRing() {
    if (!addRing(corners)) return false;
    corners.clear();
    return true;
}

bool Editor::setUp(Up up) {
    sync();
    if (!up.valid() || up == up_) return false;
    up_ = up;
    reflood();
    return true;
}

bool Editor::undo() {
    sync();
    if (done_ == 0) return message_ = "nothing to undo", false;
    apply(history_[--done_], false);
    merging_ = false;
    message_ = "undid: " + history_[done_].label;
    reflood();
    return true;
}

bool Editor::redo() {
    sync();
    if (done_ == history_.size()) return message_ = "nothing to redo", false;
    apply(history_[done_++], true);
    merging_ = false;
    message_ = "redid: " + history_[done_ - 1].label;
    reflood();
    return true;
}

// ---- flooding the edit -----------------------------------------------------------------
void Editor::reflood() {
    if (!background) {
        ++floods_;
        model_.adoptEdit(Model::floodEdit(polygon_, name_, up_), gesture_);
        generation_ = model_.generation();
        return;
    }
    // One flood at a time; what comes in meanwhile waits (dirty_) for the next frame's poll(),
    // which adopts the finished flood and starts one of the latest polygon and direction.
    dirty_ = true;
    if (!job_.started()) startJob();
}

void Editor::startJob() {
    ++floods_;
    dirty_ = false;
    // floodEdit's phases a step each: the page draws between them (job.h).
    auto steps = std::make_shared<RunSteps>(polygon_, name_, up_);
    job_.startSteps(
        [this, steps](Job&) {
            if (steps->next() == OpenPhase::Done) {
                jobResult_ = steps->take();
                return false;
            }
            steps->step();
            return true;
        },
        [this] {
            if (onReady) onReady();
        });
}

void Editor::finishJob() {
    job_.wait();
    // Adopted only if the model still shows what this editor edits.
    if (generation_ == model_.generation() && jobResult_.trace) {  // a whole run
        model_.adoptEdit(std::move(jobResult_), gesture_ || dirty_);
        generation_ = model_.generation();
    }
    jobResult_ = {};
    job_.reset();  // none pending
}

void Editor::poll() {
    if (job_.started()) {
        if (!job_.done()) return;
        finishJob();
    }
    if (dirty_ && generation_ == model_.generation()) startJob();
    else dirty_ = false;  // overtaken by an open: nothing to show
    if (!gesture_ && !pending()) model_.startDeferredInvariants();
}

void Editor::wait() {
    while (pending()) {
        if (job_.started()) finishJob();
        poll();
    }
}

// ---- saving --------------------------------------------------------------------------
namespace {
// The file an edited polygon came from: "FILE#3" is feature 3 of FILE, "X (shrunk)" a shrink of X.
std::string inputFile(std::string name) {
    const std::string shrunk = " (shrunk)";
    while (name.size() > shrunk.size() &&
           name.compare(name.size() - shrunk.size(), shrunk.size(), shrunk) == 0)
        name.resize(name.size() - shrunk.size());
    if (size_t hash = name.rfind('#'); hash != std::string::npos) name.resize(hash);
    return name;
}
}  // namespace

std::string Editor::defaultSavePath() const {
    namespace fs = std::filesystem;
    const std::string input = inputFile(name_);
    fs::path dir = input.empty() || input == "-" ? fs::path() : fs::path(input).parent_path();
    std::string stem = input.empty() || input == "-" ? "polygon" : fs::path(input).stem().string();
    std::error_code ec;
    for (int n = 1;; ++n) {
        fs::path candidate =
            dir / (stem + "-edited" + (n == 1 ? "" : "-" + std::to_string(n)) + ".json");
        if (!fs::exists(candidate, ec)) return candidate.string();
    }
}

Diagnostic Editor::save(const std::string& path, bool overwriteInput) {
    namespace fs = std::filesystem;
    sync();
    if (path.empty()) return {Status::Usage, "no file name to save to"};
    if (polygon_.vertices.empty())
        return {Status::Usage, path + ": nothing to save: the polygon is empty"};
    std::error_code ec;
    const std::string input = inputFile(name_);
    if (!overwriteInput && !input.empty() && fs::exists(input, ec) &&
        fs::equivalent(input, path, ec))
        return {Status::Usage, path + " is the file being edited: confirm to overwrite it"};
    return saveGeoJson(polygon_, path);
}

// ---- picking (display only: plain doubles choose what the mouse is over) --------------
Index Editor::pickVertex(Vec2 screen, double radiusPx) {
    sync();
    Index best = kNone;
    double bestD = radiusPx * radiusPx;
    for (Index i = 0; i < polygon_.vertices.size(); ++i) {
        Vec2 s = model_.camera().toScreen(polygon_.vertices[i]);
        double d = (s.x - screen.x) * (s.x - screen.x) + (s.y - screen.y) * (s.y - screen.y);
        if (d <= bestD) bestD = d, best = i;
    }
    return best;
}

Index Editor::pickEdge(Vec2 screen, double radiusPx, Point* onEdge) {
    sync();
    Index best = kNone;
    double bestD = radiusPx * radiusPx, bestT = 0;
    for (const Ring& g : polygon_.rings) {
        if (g.count < 2) continue;
        for (Index i = 0; i < g.count; ++i) {
            Vec2 a = model_.camera().toScreen(polygon_.vertices[g.first + i]);
            Vec2 b = model_.camera().toScreen(polygon_.vertices[g.first + (i + 1) % g.count]);
            double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
            double t = len2 > 0 ? std::clamp(((screen.x - a.x) * dx + (screen.y - a.y) * dy) / len2,
                                             0.0, 1.0)
                                : 0;
            double px = a.x + t * dx - screen.x, py = a.y + t * dy - screen.y;
            if (px * px + py * py <= bestD)
                bestD = px * px + py * py, best = g.first + i, bestT = t;
        }
    }
    if (best != kNone && onEdge) {
        const Ring& g = polygon_.rings[polygon_.ringOf(best)];
        Point a = polygon_.vertices[best],
              b = polygon_.vertices[best + 1 == g.first + g.count ? g.first : best + 1];
        *onEdge = {a.x + bestT * (b.x - a.x), a.y + bestT * (b.y - a.y)};
    }
    return best;
}

}  // namespace flood::view
