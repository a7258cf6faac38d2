// The sag search (sag_search.h).
#include "machine/sags/sag_search.h"

#include <algorithm>

#include "flood/geometry/predicates.h"
#include "flood/geometry/work.h"

namespace flood {

void SagSearch::index(const Heights& heights, NodeId partFirstNode, Index partFirstVertex,
                      bool touching, bool simple) {
    heights_ = &heights;
    simple_ = simple;
    partFirstNode_ = partFirstNode;
    const Nodes& nodes = heights.nodes();
    heights.sort(sags_, heightsOf_.keys());
    // The sags' vertices for the plane index, and their heights for the ranks (the sorted keys
    // given back before the plane index is built).
    const size_t count = sags_.size();
    std::vector<uint32_t>& vertices = index_.vertices();
    vertices.resize(count);
    for (size_t k = 0; k < count; ++k) vertices[k] = nodes[sags_[k]].v;
    heightsOf_.index(heights, sags_, heights.points(), vertices);
    index_.build(heights.points());
    unused_ = uint32_t(count);
    // Node ids grow from part to part within a run, so the entries of an earlier part never
    // match; those of an earlier run might. Only the entries written are cleared: a small
    // run writes a few.
    if (partFirstNode == NodeId(0)) {
        for (uint64_t set = recentSet_; set != 0; set &= set - 1)
            recent_[__builtin_ctzll(set)] = {};
        recentSet_ = 0;
    }
    // The bank lists are built once they pay (banksPay()): a part whose gorges the plane
    // index prunes well never pays the sweep. Labels are only sound on loops whose edges are
    // the input's and meet only at their ends; where points are shared (touching rings,
    // T-junctions) the plane index alone is used. The initial links are kept for the sweep,
    // which may run after edits. Off the axes the sweep runs along the direction itself (its
    // rays are the lines across it).
    // With at most kProbes sags every bracket is probed whole before the plane index is asked
    // (search()), so the index never works and the lists are never built: no initial links.
    if (banks_.built()) banks_.clear();  // a failed build clears itself (buildBanks())
    banksTried_ = touching || count <= size_t(kProbes);
    rent_ = 0;
    buy_ = false;
    partFirstVertex_ = partFirstVertex;
    initialNodes_ = nodes.end() - partFirstNode_;
    initialStep_.clear();
    initialListed_.clear();
    if (banksTried_) return;
    initialStep_.resize(initialNodes_);
    for (uint32_t i = 0; i < initialNodes_; ++i) {
        const uint32_t next = nodes[partFirstNode_ + i].next - partFirstNode_;
        const int8_t step = next == i + 1 ? 1 : next + 1 == i ? -1 : next == i ? 0 : kListed;
        initialStep_[i] = step;
        if (step == kListed) initialListed_.emplace_back(i, next);
    }
}

// The initial link of the part's node t (local ids).
uint32_t SagSearch::initialNext(uint32_t t) const {
    const int8_t step = initialStep_[t];
    if (step != kListed) return t + uint32_t(int32_t(step));
    return std::lower_bound(initialListed_.begin(), initialListed_.end(),
                            std::pair<uint32_t, uint32_t>(t, 0))
        ->second;
}

// The ranks the sought sag lies strictly between: `lo`, the last sag not above the water (the
// water itself when it is a sag), and `hi`, the first sag not below Next.
inline void SagSearch::bracket(NodeId water, NodeId nx, int64_t& lo, int64_t& hi) {
    uint32_t a, b;                       // the sags below the water and below Next
    if (sags_.size() <= kCountedSags) {  // a few keys, counted in one pass
        const std::vector<HeightKey>& keys = heightsOf_.keys();
        const HeightKey kw = heights_->key(water), kn = heights_->key(nx);
        const uint32_t count = uint32_t(keys.size());
        a = 0;
        while (a < count && keys[a] < kw) ++a;
        b = a;  // Next is above the water (were it not, both ends give an empty bracket)
        while (b < count && keys[b] < kn) ++b;
    } else {
        a = sagsBelow(water), b = sagsBelow(nx);
    }
    lo = a < sags_.size() && sags_[a] == water ? int64_t(a) : int64_t(a) - 1;  // water a sag?
    hi = b;
}

// The search, its work counted as the sag search's. An empty bracket (most steps once the
// sags are below the water) counts nothing, so it is ruled out before the counters are read.
NodeId SagSearch::counted(NodeId left, NodeId right, NodeId water, NodeId next, Event& e) {
    int64_t lo, hi;
    bracket(water, next, lo, hi);
    if (hi <= lo + 1) return kNil;
    WorkCounters& w = work();
    const uint64_t before = w.nodeVisits + w.sagTests + w.orientCalls;  // not all ten counters
    NodeId s = search(left, right, water, next, lo, hi, e);
    w.sagSearch += w.nodeVisits + w.sagTests + w.orientCalls - before;
    return s;
}

// Number of sags strictly below node n, by binary search on the contiguous height keys. The
// answers for recent nodes are kept, by node id modulo kRecent (the water is usually a recent
// step's Next, and the chain's nodes have neighbouring ids): no array over every node.
uint32_t SagSearch::sagsBelow(NodeId n) {
    const uint32_t slot = uint32_t(n) % kRecent;
    Recent& r = recent_[slot];
    if (r.node != n) r = {n, heightsOf_.below(heights_->key(n))}, recentSet_ |= uint64_t(1) << slot;
    return r.below;
}

// Sags are sorted, so the search starts at the water level and stops at Next: ranks lo < k < hi
// (bracket()).
NodeId SagSearch::search(NodeId left, NodeId right, NodeId water, NodeId nx, int64_t lo, int64_t hi,
                         Event& e) {
    const Heights& h = *heights_;
    const Nodes& nodes = h.nodes();
    Point l = h.at(left), r = h.at(right), nl = h.at(nodes[left].prev),
          nr = h.at(nodes[right].next);
    // Where such a sag can be: the quadrangle's box, the water's height band, and the
    // interior side of both banks (left of NextLeft->Left and of Right->NextRight).
    SagIndex::Region region;
    region.xMin = std::min(std::min(l.x, r.x), std::min(nl.x, nr.x));
    region.xMax = std::max(std::max(l.x, r.x), std::max(nl.x, nr.x));
    if (h.general()) {  // no coordinate is a height: the quadrangle's box bounds y too
        region.yMin = std::min(std::min(l.y, r.y), std::min(nl.y, nr.y));
        region.yMax = std::max(std::max(l.y, r.y), std::max(nl.y, nr.y));
    } else {
        region.yMin = h.at(water).y;
        region.yMax = h.at(nx).y;
    }
    region.lines[0][0] = nl, region.lines[0][1] = l;
    region.lines[1][0] = r, region.lines[1][1] = nr;
    region.lineCount = 2;
    auto test = [&](uint32_t rank) {
        ++e.sagTests;
        ++work().sagTests;
        return inside(index_.point(rank), l, r, nr, nl);
    };
    if (buy_) buildBanks();
    if (banks_.built()) {
        // The lowest such sag sees a bank that is an input edge across open water: it is
        // the first unused sag of the bank's list in the bracket (ALGORITHM.md §4). The
        // exact test confirms it; were it refused, the plane index below decides.
        int64_t k = bankCandidate(left, right, lo, hi);
        if (k == -1) return kNil;
        if (k >= 0 && test(uint32_t(k))) {
            return use(k);
        }
    }
    // The next few ranks first, in order: in a wide gorge (a strip under a row of holes)
    // the lowest sag is usually the next one up, which the tree would reach only after
    // visiting every box whose rank range begins below it.
    int64_t k = -1;
    for (int64_t end = std::min(hi, lo + 1 + kProbes); lo + 1 < end && k < 0;) {
        const uint32_t rank = uint32_t(++lo);
        ++work().nodeVisits;
        const Point s = index_.point(rank);
        if (!index_.used(rank) && s.x >= region.xMin && s.x <= region.xMax && test(rank)) k = rank;
    }
    if (k < 0) {
        const uint64_t before = work().nodeVisits;
        k = index_.lowest(lo, hi, region, test);
        rent_ += work().nodeVisits - before;
        buy_ = !banksTried_ && banksPay();
    }
    if (k < 0) return kNil;
    return use(k);
}

NodeId SagSearch::use(int64_t rank) {
    index_.markUsed(uint32_t(rank));
    --unused_;
    const NodeId s = sags_[size_t(rank)];
    if (sags_.size() > kCountedSags) {  // the bridged sag is the next water
        const uint32_t slot = uint32_t(s) % kRecent;
        recent_[slot] = {s, uint32_t(rank)};
        recentSet_ |= uint64_t(1) << slot;
    }
    return s;
}

// Ski rental: the plane index's box visits are the rent, the bank sweep the purchase, priced
// at kPrice box visits a node of the part. Nothing is bought below half a box a node (the old
// rule, which alone bought the sweep on families whose tree stays cheap: circle-holes from 10^5
// on, +62 % instructions a vertex from 10^4 to 10^6); past it, buy once the rent paid passes
// the price (never more than twice the cheaper choice), or once the rent per sag bridged so
// far, projected over the sags left and doubled, would: doubled, since a sliver family's
// searches grow costlier as the water rises (circle-smooth), so a plain projection falls short
// and the rent is paid twice (Growth.GeneratedFamiliesWorkPerVertexIsLinear).
bool SagSearch::banksPay() const {
    const uint64_t n = initialNodes_;
    if (rent_ * 2 <= n) return false;
    if (rent_ > kPrice * n) return true;
    const uint64_t bridged = sags_.size() - unused_;
    return 2 * rent_ * unused_ > kPrice * n * bridged;
}

void SagSearch::buildBanks() {
    banksTried_ = true, buy_ = false;
    // Without shared points the part's initial nodes are its vertices, in order (inputEdge()).
    const Point* point = heights_->points() + partFirstVertex_;
    std::vector<uint32_t>& sagOfRank = sagOfRank_;
    sagOfRank.resize(sags_.size());
    for (size_t k = 0; k < sags_.size(); ++k) sagOfRank[k] = sags_[k] - partFirstNode_;
    std::vector<uint32_t>& next = initialNext_;
    next.resize(initialNodes_);
    for (uint32_t i = 0; i < initialNodes_; ++i) next[i] = initialNext(i);
    if (!banks_.build(point, next, sagOfRank_, heights_->general() ? heights_->up() : Up::PlusY,
                      simple_))
        banks_.clear();          // crossing edges
    giveBackIfLarge(sagOfRank);  // read by the build alone
    giveBackIfLarge(next);
}

// The input edge from node a to node b, as its tail's initial node; kNone when a -> b is not
// an input edge (a diagonal). Without shared points a vertex has one initial node.
uint32_t SagSearch::inputEdge(NodeId a, NodeId b) const {
    const Nodes& nodes = heights_->nodes();
    uint32_t t = nodes[a].v - partFirstVertex_;
    if (t >= initialNodes_ || initialNext(t) + partFirstVertex_ != nodes[b].v) return kNone;
    return t;
}

// The bank lists' answer for the active gorge: a rank, -1 for no sag, -2 when neither bank is
// an input edge.
int64_t SagSearch::bankCandidate(NodeId left, NodeId right, int64_t lo, int64_t hi) const {
    const Nodes& nodes = heights_->nodes();
    auto used = [&](uint32_t rank) { return index_.used(rank); };
    uint32_t t = inputEdge(nodes[left].prev, left);
    if (t != kNone) return banks_.lowest(true, t, lo, hi, used);
    t = inputEdge(right, nodes[right].next);
    if (t != kNone) return banks_.lowest(false, t, lo, hi, used);
    return -2;
}

}  // namespace flood
