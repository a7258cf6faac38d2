#include "flood/check/invariants.h"

#include <algorithm>
#include <cmath>

#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"

namespace flood {

namespace {
const char* const kNames[] = {
#define FLOOD_X(name, text) #name,
    FLOOD_INVARIANTS(FLOOD_X)
#undef FLOOD_X
};
const char* const kTexts[] = {
#define FLOOD_X(name, text) text,
    FLOOD_INVARIANTS(FLOOD_X)
#undef FLOOD_X
};

Violation violated(Invariant which, std::vector<Index> vertices, std::string detail) {
    Violation v;
    v.which = which;
    v.vertices = std::move(vertices);
    v.detail = std::move(detail);
    return v;
}

std::string vtx(Index v) { return "vertex " + std::to_string(v); }
}  // namespace

const char* invariantName(Invariant i) { return i < Invariant::Count ? kNames[int(i)] : "?"; }
const char* invariantText(Invariant i) { return i < Invariant::Count ? kTexts[int(i)] : "?"; }

// Node i of the chain (strictly inside it) turns right or goes straight. Any other i holds:
// a log that lies about the chain's length gives one past either end, or one wrapped around.
bool InvariantChecker::reflexAt(const std::vector<Index>& chain, size_t i, Violation& out) const {
    if (chain.size() < 3 || i == 0 || i > chain.size() - 2) return true;
    if (orient(P(chain[i - 1]), P(chain[i]), P(chain[i + 1])) <= 0) return true;
    out = violated(
        Invariant::ReflexChain, {chain[i], chain[i - 1], chain[i + 1]},
        vtx(chain[i]) + " at position " + std::to_string(i) + " of the active chain is convex");
    return false;
}

void InvariantChecker::buildGrid() {
    gridBuilt_ = true;
    const auto& vs = trace_->polygon.vertices;
    double x1 = 0, y1 = 0;
    bool any = false;
    for (Point p : vs) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
        if (!any) gx0_ = x1 = p.x, gy0_ = y1 = p.y, any = true;
        gx0_ = std::min(gx0_, p.x), x1 = std::max(x1, p.x);
        gy0_ = std::min(gy0_, p.y), y1 = std::max(y1, p.y);
    }
    if (!any) return;
    const double w = x1 - gx0_, h = y1 - gy0_;
    const double cells = std::max<double>(1, double(vs.size()));
    gcell_ = std::sqrt(std::max(w * h, 0.0) / cells);
    if (!(gcell_ > 0) || !std::isfinite(gcell_)) gcell_ = std::max(std::max(w, h) / cells, 1e-300);
    if (!std::isfinite(gcell_)) return;  // a box wider than the doubles: no grid, no check
    gw_ = uint32_t(std::min(cells, std::floor(w / gcell_)) + 1);
    gh_ = uint32_t(std::min(cells, std::floor(h / gcell_)) + 1);
    ringPrev_.assign(vs.size(), kNone);
    ringNext_.assign(vs.size(), kNone);
    for (const Ring& r : trace_->polygon.rings)
        for (Index i = 0; i < r.count && r.count > 1; ++i) {
            ringNext_[r.first + i] = r.first + (i + 1) % r.count;
            ringPrev_[r.first + i] = r.first + (i + r.count - 1) % r.count;
        }
    std::vector<uint32_t> cellOf(vs.size(), ~0u);
    gridStart_.assign(size_t(gw_) * gh_ + 1, 0);
    for (Index v = 0; v < vs.size(); ++v) {
        if (!std::isfinite(vs[v].x) || !std::isfinite(vs[v].y)) continue;
        // Clamped as doubles: a cell of 1e-300 makes the quotient far beyond any integer type.
        const auto cellIndex = [&](double offset, uint32_t count) {
            return uint32_t(std::min(double(count - 1), std::max(0.0, offset / gcell_)));
        };
        uint32_t cx = cellIndex(vs[v].x - gx0_, gw_);
        uint32_t cy = cellIndex(vs[v].y - gy0_, gh_);
        cellOf[v] = cy * gw_ + cx;
        ++gridStart_[cellOf[v] + 1];
    }
    for (size_t c = 1; c < gridStart_.size(); ++c) gridStart_[c] += gridStart_[c - 1];
    gridVertices_.resize(gridStart_.back());
    std::vector<uint32_t> fill(gridStart_.begin(), gridStart_.end() - 1);
    for (Index v = 0; v < vs.size(); ++v)
        if (cellOf[v] != ~0u) gridVertices_[fill[cellOf[v]]++] = v;
}

// Cells are found with rounded arithmetic, widened by one: the exact tests are orient's.
// Edges are the ones with an end in those cells (a vertex's edge to its ring successor and
// predecessor): an edge crossing the triangle with both ends far outside its box is missed.
Violation InvariantChecker::triangleEmpty(const Triangle& t, uint32_t number) {
    if (!gridBuilt_) buildGrid();
    if (gridStart_.empty()) return {};
    Point a = P(t[0]), b = P(t[1]), c = P(t[2]);
    const Point side[3][2] = {{a, b}, {b, c}, {c, a}};
    const double bx0 = std::min({a.x, b.x, c.x}), bx1 = std::max({a.x, b.x, c.x});
    const double by0 = std::min({a.y, b.y, c.y}), by1 = std::max({a.y, b.y, c.y});
    auto crosses = [&](Point p, Point q) {  // a proper crossing of the segment and a side
        if (std::max(p.x, q.x) <= bx0 || std::min(p.x, q.x) >= bx1 || std::max(p.y, q.y) <= by0 ||
            std::min(p.y, q.y) >= by1)
            return false;  // apart from the triangle's box (touching it is no proper crossing)
        for (const auto& s : side) {
            int o1 = orient(s[0], s[1], p), o2 = orient(s[0], s[1], q);
            if (o1 * o2 >= 0) continue;
            if (orient(p, q, s[0]) * orient(p, q, s[1]) < 0) return true;
        }
        return false;
    };
    // Cell numbers clamped to [-1, count] while still doubles (a far or non-finite corner
    // would overflow the integer; NaN goes to -1).
    auto toCell = [&](double q, uint32_t count) -> int64_t {
        if (!(q >= -1)) return -1;
        return q > double(count) ? int64_t(count) : int64_t(q);
    };
    auto cellX = [&](double x) { return toCell(std::floor((x - gx0_) / gcell_), gw_); };
    auto cellY = [&](double y) { return toCell(std::floor((y - gy0_) / gcell_), gh_); };
    const int64_t y0 = std::max<int64_t>(0, cellY(std::min({a.y, b.y, c.y})) - 1);
    const int64_t y1 = std::min<int64_t>(gh_ - 1, cellY(std::max({a.y, b.y, c.y})) + 1);
    // The triangle's x extent within the band [lo, hi]: its corners there and its sides'
    // crossings of the band's edges.
    auto extent = [&](double lo, double hi, double& xl, double& xr) {
        xl = HUGE_VAL, xr = -HUGE_VAL;
        for (const auto& sd : side) {
            Point p = sd[0], q = sd[1];
            if (p.y >= lo && p.y <= hi) xl = std::min(xl, p.x), xr = std::max(xr, p.x);
            for (double y : {lo, hi})
                if ((p.y - y) * (q.y - y) < 0) {
                    double x = p.x + (y - p.y) / (q.y - p.y) * (q.x - p.x);
                    xl = std::min(xl, x), xr = std::max(xr, x);
                }
        }
        return xl <= xr;
    };
    int cells = 0;
    for (int64_t y = y0; y <= y1; ++y) {
        double xl, xr;
        if (!extent(gy0_ + double(y - 1) * gcell_, gy0_ + double(y + 2) * gcell_, xl, xr)) continue;
        const int64_t x0 = std::max<int64_t>(0, cellX(xl) - 1),
                      x1 = std::min<int64_t>(gw_ - 1, cellX(xr) + 1);
        for (int64_t x = x0; x <= x1; ++x) {
            if (++cells > kMaxCells) return {};  // a long triangle: sampled from its lowest rows
            const uint32_t cell = uint32_t(y * gw_ + x);
            ++work().invariantSteps;
            for (uint32_t i = gridStart_[cell]; i < gridStart_[cell + 1]; ++i) {
                const Index v = gridVertices_[i];
                Point p = P(v);
                ++work().invariantSteps;
                for (Index u : {ringPrev_[v], ringNext_[v]}) {
                    if (u == kNone || !std::isfinite(P(u).x) || !std::isfinite(P(u).y)) continue;
                    ++work().invariantSteps;
                    if (crosses(p, P(u)))
                        return violated(Invariant::TriangleEmpty, {v, u, t[0], t[1], t[2]},
                                        "the edge between vertices " + std::to_string(v) + " and " +
                                            std::to_string(u) + " crosses triangle " +
                                            std::to_string(number) + ", just cut");
                }
                if (p.x <= bx0 || p.x >= bx1 || p.y <= by0 || p.y >= by1) continue;
                if (orient(a, b, p) > 0 && orient(b, c, p) > 0 && orient(c, a, p) > 0)
                    return violated(
                        Invariant::TriangleEmpty, {v, t[0], t[1], t[2]},
                        vtx(v) + " lies inside triangle " + std::to_string(number) + ", just cut");
            }
        }
    }
    return {};
}

Violation InvariantChecker::check(const ReplayState& s) {
    Violation out;
    if (s.step == 0 || s.step > trace_->events.size()) return out;
    const Event& e = trace_->events[s.step - 1];
    const size_t before = chainSize_;
    chainSize_ = s.chain.size();
    if (e.action == Action::Forbidden) return out;  // the machine said so itself
    const auto& tris = trace_->triangles;
    const Index w = s.water;
    // The paper's below along the trace's direction, with the machine's tie-break on index.
    auto higher = [&](Index a, Index b) {
        Point pa = P(a), pb = P(b);
        return pa != pb ? belowToward(trace_->up, pb, pa) : a > b;
    };

    // 1. The triangles this step cut turn the polygon's way: a flat or clockwise one covers
    // what is not between the loops (a Fill's fan reaches its ceiling, above the water).
    for (uint32_t t = e.firstTriangle; t < e.firstTriangle + e.triangleCount && t < tris.size();
         ++t) {
        const Triangle& tr = tris[t];
        if (orient(P(tr[0]), P(tr[1]), P(tr[2])) <= 0)
            return violated(Invariant::TrianglesCounterClockwise, {tr[0], tr[1], tr[2]},
                            "triangle " + std::to_string(t) + " is clockwise or flat");
        if (Violation v = triangleEmpty(tr, t); !v.ok()) return v;
    }

    // Loops: the chain runs from Left to Right; gorges taken were waiting, and as what.
    const Fingers& f = s.fingers;
    if (f.left != kNone &&
        (s.chain.empty() || s.chain.front() != f.left || s.chain.back() != f.right))
        return violated(Invariant::LoopsConsistent, {f.left, f.right},
                        "the active chain does not run from Left (" + vtx(f.left) + ") to Right (" +
                            vtx(f.right) + ")");
    if (e.gorgePopped != kNone) {
        auto it = gorges_.find(e.gorgePopped);
        const bool wantHeld = e.action == Action::Jump;
        if (it == gorges_.end() || it->second.held != wantHeld ||
            (wantHeld && it->second.top != e.top))
            return violated(Invariant::LoopsConsistent, {e.top == kNone ? f.left : e.top},
                            "gorge " + std::to_string(e.gorgePopped) + " taken by " +
                                actionName(e.action) +
                                (wantHeld ? " is not held at the top" : " is not pending"));
        if (it->second.held && --heldTops_[it->second.top] == 0) heldTops_.erase(it->second.top);
        gorges_.erase(it);
    }

    // 4. Jump pointers: set on a top no gorge is held at yet, followed only while one is.
    if (e.action == Action::Spill) {
        if (heldTops_.count(e.top))
            return violated(
                Invariant::JumpOnHeldTop, {e.top},
                "top " + vtx(e.top) + " already holds a gorge when a second spills over it");
        if (e.gorgePushed != kNone) {
            gorges_[e.gorgePushed] = {true, e.top};
            ++heldTops_[e.top];
        }
    } else if (e.action == Action::Bridge && e.gorgePushed != kNone) {
        gorges_[e.gorgePushed] = {false, kNone};
    }
    if (e.action == Action::Jump && e.gorgePopped == kNone)
        return violated(Invariant::JumpOnHeldTop, {e.top},
                        "the Jump at top " + vtx(e.top) + " took no held gorge");

    // 2. The reflex chain, where this step changed it.
    const std::vector<Index>& c = s.chain;
    switch (e.action) {
        case Action::Raise:
            if (!reflexAt(c, e.side == Side::Left ? 1 : c.size() - 2, out)) return out;
            break;
        case Action::Bridge:
            if (e.gorgePushed != kNone) {
                if (!reflexAt(c, c.size() - 2, out)) return out;
                if (!s.dormant.empty() && !reflexAt(s.dormant.back().chain, 1, out)) return out;
            } else {  // a Steiner sag inside the chain: its two joints and itself
                size_t k = e.chainIndex + 1 >= e.cutLeft ? e.chainIndex + 1 - e.cutLeft : 0;
                for (size_t i = k == 0 ? 0 : k - 1; i <= k + 1; ++i)
                    if (!reflexAt(c, i, out)) return out;
            }
            break;
        case Action::Jump: {  // the top joins the held chain to the active one
            if (before == 0 || before > c.size()) break;  // the log lies: no joint to look at
            size_t joint = e.side == Side::Right ? before - 1 : c.size() - before;
            for (size_t i = joint == 0 ? 0 : joint - 1; i <= joint + 1; ++i)
                if (!reflexAt(c, i, out)) return out;
            break;
        }
        default: break;  // Start, Spill and Fill bring a one-node chain or one checked when pushed
    }

    // 3. The fingers are above the water, but for one at a top: a finger below the water
    // is beside a concave end of the chain, where the next step spills or jumps. (A convex
    // end there is the ceiling the machine will find forbidden one step later.)
    if (f.left != kNone && w != kNone && f.nextLeft != f.nextRight) {
        for (Side side : {Side::Left, Side::Right}) {
            const bool left = side == Side::Left;
            const Index n = left ? f.nextLeft : f.nextRight, end = left ? f.left : f.right;
            if (n == w || higher(n, w)) continue;
            const Index inner =
                c.size() > 1 ? (left ? c[1] : c[c.size() - 2]) : (left ? f.nextRight : f.nextLeft);
            const Index pv = left ? n : inner, nv = left ? inner : n;  // end's loop neighbours
            if (orient(P(pv), P(end), P(nv)) <= 0) continue;
            return violated(Invariant::FingersAboveWater, {n, end, w},
                            std::string(left ? "NextLeft" : "NextRight") + " (" + vtx(n) +
                                ") is below the water at " + vtx(w) +
                                " beside a convex end of the chain (" + vtx(end) + ")");
        }
    }
    return out;
}

std::vector<Violation> checkInvariants(const Trace& trace, std::atomic<uint32_t>* progress,
                                       const std::atomic<bool>* cancel) {
    std::vector<Violation> out;
    Replay replay(trace);
    InvariantChecker checker(trace);
    for (uint32_t s = 1; s <= replay.size(); ++s) {
        if (cancel && cancel->load(std::memory_order_relaxed)) break;
        Violation v = checker.check(replay.seek(s));
        if (!v.ok()) {
            v.step = s;
            out.push_back(std::move(v));
        }
        if (progress) progress->store(s, std::memory_order_relaxed);
    }
    return out;
}

}  // namespace flood
