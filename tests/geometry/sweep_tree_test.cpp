// The sweep's ordered set (core/geometry/sweep_tree.h), as a treap and as a row that turns
// into the treap past rowMax and back below half of it: random insertions (by search, beside
// a neighbour, near a finger), erasures and replacements, checked after each step against a
// sorted list — the order both ways, membership, and the lower bound firstWhere() finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

#include "geometry/sweep_tree.h"

using namespace flood;

namespace {

struct ByKey {
    const std::vector<double>* key;
    bool operator()(Index a, Index b) const {
        const double ka = (*key)[a], kb = (*key)[b];
        return ka < kb || (ka == kb && a < b);
    }
};

template <typename Tree>
void expectSame(const Tree& tree, const std::vector<Index>& sorted, const std::vector<double>& key,
                size_t edges, uint64_t step) {
    std::vector<Index> forward;
    for (Index x = tree.first(); x != kNone; x = tree.next(x)) {
        forward.push_back(x);
        ASSERT_LE(forward.size(), sorted.size()) << "a cycle at step " << step;
    }
    ASSERT_EQ(forward, sorted) << "step " << step;
    EXPECT_EQ(tree.empty(), sorted.empty());
    for (size_t i = 0; i < sorted.size(); ++i)
        ASSERT_EQ(tree.prev(sorted[i]), i == 0 ? kNone : sorted[i - 1]) << "step " << step;
    std::vector<char> in(edges, 0);
    for (Index e : sorted) in[e] = 1;
    for (Index e = 0; e < edges; ++e) ASSERT_EQ(tree.contains(e), in[e] == 1) << "step " << step;
    for (double t : {-1.0, 250.0, 500.5, 999.0, 2000.0}) {  // the first with key >= t
        auto it = std::find_if(sorted.begin(), sorted.end(), [&](Index e) { return key[e] >= t; });
        EXPECT_EQ(tree.firstWhere([&](Index e) { return key[e] >= t; }),
                  it == sorted.end() ? kNone : *it)
            << "step " << step;
    }
}

}  // namespace

TEST(SweepTree, RowAndTreapKeepTheOrderThroughEveryOperation) {
    const size_t edges = 300;
    for (size_t rowMax : {0, 1, 4, 16, 64}) {
        uint64_t s = 11 + rowMax;
        auto rnd = [&](uint64_t n) {
            s = s * 6364136223846793005ull + 1442695040888963407ull;
            return (s >> 33) % n;
        };
        std::vector<double> key(edges);
        for (double& k : key) k = double(rnd(1000));  // repeated keys: ties go by index
        SweepTreeLinks links;
        ByKey less{&key};
        SweepTree<ByKey> tree(edges, less, links, rowMax);
        std::vector<Index> sorted;  // the reference
        auto place = [&](Index e) {
            return size_t(std::upper_bound(sorted.begin(), sorted.end(), e, less) - sorted.begin());
        };
        size_t toTreap = 0, toRow = 0;  // times the size passed rowMax, fell below half of it
        bool large = false;
        for (uint64_t step = 0; step < 3000; ++step) {
            // Grow to ~100 edges, then shrink to a few, then grow again: every switch.
            const bool growing = (step / 400) % 2 == 0;
            const uint64_t op = rnd(10);
            if ((growing ? op < 6 : op < 2) && sorted.size() < 100) {
                Index e;
                do e = Index(rnd(edges));
                while (std::count(sorted.begin(), sorted.end(), e));
                const size_t at = place(e);
                if (op % 3 == 0 || sorted.empty()) tree.insert(e);
                else if (op % 3 == 1) {
                    if (at < sorted.size()) tree.insertBeside(e, sorted[at], false);
                    else tree.insertBeside(e, sorted[at - 1], true);
                } else tree.insertNear(e, sorted[rnd(sorted.size())], 3);
                sorted.insert(sorted.begin() + std::ptrdiff_t(at), e);
            } else if (op < 8 && !sorted.empty()) {
                const size_t at = rnd(sorted.size());
                tree.erase(sorted[at]);
                sorted.erase(sorted.begin() + std::ptrdiff_t(at));
            } else if (!sorted.empty()) {  // a new edge in the place of an old one
                const size_t at = rnd(sorted.size());
                Index f;
                do f = Index(rnd(edges));
                while (std::count(sorted.begin(), sorted.end(), f));
                const double lo = at == 0 ? -10 : key[sorted[at - 1]];
                const double hi = at + 1 == sorted.size() ? 1010 : key[sorted[at + 1]];
                key[f] = (lo + hi) / 2;  // strictly between the neighbours (or on a tie: by index)
                if ((at > 0 && !less(sorted[at - 1], f)) ||
                    (at + 1 < sorted.size() && !less(f, sorted[at + 1])))
                    continue;  // no room between equal neighbours
                tree.replace(sorted[at], f);
                sorted[at] = f;
            }
            if (!large && sorted.size() > rowMax) large = true, ++toTreap;
            if (large && sorted.size() < rowMax / 2) large = false, ++toRow;
            expectSame(tree, sorted, key, edges, step);
            if (::testing::Test::HasFatalFailure()) return;
        }
        if (rowMax >= 4) {  // both ways, more than once
            EXPECT_GE(toTreap, 2u) << rowMax;
            EXPECT_GE(toRow, 2u) << rowMax;
        }
    }
}
