#include "sag_index.h"

#include <algorithm>
#include <numeric>

namespace flood {

void SagIndex::build(const std::vector<double>& xOfRank) {
    const uint32_t n = uint32_t(xOfRank.size());
    used_.assign(n, 0);
    std::vector<uint32_t> byX(n);
    std::iota(byX.begin(), byX.end(), 0u);
    std::stable_sort(byX.begin(), byX.end(), [&](uint32_t a, uint32_t b) { return xOfRank[a] < xOfRank[b]; });
    sortedX_.resize(n);
    for (uint32_t k = 0; k < n; ++k) sortedX_[k] = xOfRank[byX[k]];
    levels_.clear();
    levels_.push_back(byX);
    for (uint32_t w = 1; w < n; w *= 2) {
        const std::vector<uint32_t>& below = levels_.back();
        std::vector<uint32_t> level(n);
        for (uint32_t b = 0; b < n; b += 2 * w) {
            uint32_t mid = std::min(n, b + w), end = std::min(n, b + 2 * w);
            std::merge(below.begin() + b, below.begin() + mid, below.begin() + mid, below.begin() + end,
                       level.begin() + b);
        }
        levels_.push_back(std::move(level));
    }
}

// Canonical blocks covering positions [i, j): aligned blocks of 2^l at level l.
void SagIndex::blocks(uint32_t i, uint32_t j) {
    cursors_.clear();
    const uint32_t n = uint32_t(sortedX_.size());
    for (uint32_t l = 0; i < j; ++l) {
        uint32_t w = 1u << l;
        if (l + 1 >= levels_.size()) {  // the top level is one block: take the rest from it
            cursors_.push_back({i, j, uint32_t(levels_.size() - 1)});
            // The top block is sorted as a whole, so [i, j) must be the whole array here.
            if (i != 0 || j != n) cursors_.back() = {0, n, uint32_t(levels_.size() - 1)};
            break;
        }
        if ((i >> l) & 1) {
            cursors_.push_back({i, std::min(n, i + w), l});
            i += w;
        }
        if (i < j && ((j >> l) & 1) && j - w >= i) {
            j -= w;
            cursors_.push_back({j, std::min(n, j + w), l});
        }
    }
}

}  // namespace flood
