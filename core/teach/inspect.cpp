#include "flood/teach/inspect.h"

#include <algorithm>

#include "flood/geometry/predicates.h"

namespace flood {

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

}  // namespace flood
