// groupsApart(): a guillotine cut of boxes (core/geometry/boxes_apart.h).
#include "geometry/boxes_apart.h"

#include <algorithm>
#include <cstdint>

namespace flood {

std::vector<Index> groupsApart(const std::vector<Box>& boxes, size_t& groupCount) {
    std::vector<Index> group(boxes.size(), kNone);
    std::vector<Index> order;
    order.reserve(boxes.size());
    for (Index b = 0; b < boxes.size(); ++b)
        if (!boxes[b].empty()) order.push_back(b);
    // A piece of `order` to cut along x (axis 0) or y; `stuck`: the other axis cut nothing.
    struct Piece {
        size_t begin, end;
        int axis;
        bool stuck;
    };
    std::vector<Piece> todo;
    if (!order.empty()) todo.push_back({0, order.size(), 0, false});
    std::vector<std::pair<size_t, size_t>> groups;  // pieces of `order` no line cuts
    // Each pass sorts a piece; a cut that peels off one box at a time would make this
    // quadratic, so past the cap the remaining pieces are kept whole.
    const uint64_t cap = 64 * uint64_t(order.size()) + 4096;
    uint64_t work = 0;
    std::vector<size_t> cuts;  // where a line between the reach so far and the next box cuts
    while (!todo.empty()) {
        Piece piece = todo.back();
        todo.pop_back();
        const size_t size = piece.end - piece.begin;
        if (size == 1 || work > cap) {
            groups.emplace_back(piece.begin, piece.end);
            continue;
        }
        work += size;
        auto lo = [&](Index b) { return piece.axis == 0 ? boxes[b].x0 : boxes[b].y0; };
        auto hi = [&](Index b) { return piece.axis == 0 ? boxes[b].x1 : boxes[b].y1; };
        auto first = order.begin() + piece.begin, last = order.begin() + piece.end;
        std::sort(first, last,
                  [&](Index a, Index b) { return lo(a) < lo(b) || (lo(a) == lo(b) && a < b); });
        cuts.clear();
        double reach = hi(*first);
        for (size_t k = piece.begin + 1; k < piece.end; ++k) {
            if (reach < lo(order[k])) cuts.push_back(k);
            reach = std::max(reach, hi(order[k]));
        }
        if (cuts.empty()) {
            if (piece.stuck) groups.emplace_back(piece.begin, piece.end);
            else todo.push_back({piece.begin, piece.end, 1 - piece.axis, true});
            continue;
        }
        size_t from = piece.begin;
        cuts.push_back(piece.end);
        for (size_t to : cuts) {
            todo.push_back({from, to, 1 - piece.axis, false});
            from = to;
        }
    }
    // Number the groups by their first box, the empty boxes alone.
    std::vector<Index> least(groups.size());
    for (size_t g = 0; g < groups.size(); ++g)
        least[g] =
            *std::min_element(order.begin() + groups[g].first, order.begin() + groups[g].second);
    for (size_t g = 0; g < groups.size(); ++g)
        for (size_t k = groups[g].first; k < groups[g].second; ++k) group[order[k]] = least[g];
    groupCount = 0;
    std::vector<Index> number(boxes.size(), kNone);
    for (Index b = 0; b < boxes.size(); ++b) {
        Index key = group[b] == kNone ? b : group[b];
        if (number[key] == kNone) number[key] = Index(groupCount++);
        group[b] = number[key];
    }
    return group;
}

}  // namespace flood
