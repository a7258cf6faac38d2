// Points that repeat, where rings touch at a shared vertex: the one search for them, used by
// the flood machine (merging touching loops), the triangle count (Polygon::expectedTriangles)
// and the unvalidated T-junction search (touches.cpp). Validation needs none: its sweep's
// sorted events put coincident vertices side by side. The exact checker keeps its own (an oracle).
// Internal to core/, not a public API.
#pragma once
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "flood/geometry/polygon.h"

namespace flood {

// For each position i < n whose point pointAt(i) equals the point of an earlier position, the
// pair (the first position with that point, i) — equal as operator== says: -0.0 is 0.0, a NaN
// equals nothing. Most inputs have none. Grouped by hash bucket, ascending i within a group of
// equal points; sort the pairs for any other order.
//
// Cache-friendly at any size: each point is hashed, the (hash, position) pairs are bucketed by
// the hash's top bits (a stable counting sort), and each bucket, small enough for the cache,
// is searched with its own open-addressing table. Linear expected time.
// Its working arrays, kept by a caller that searches often (the flood machine reuses them, so
// a warm run allocates nothing).
struct RepeatedPointsScratch {
    std::vector<std::pair<uint32_t, uint32_t>> copies;  // the answer
    std::vector<uint64_t> hash;
    std::vector<uint32_t> start, fill, table;
    std::vector<std::pair<uint64_t, uint32_t>> byBucket;  // (hash, position)
};

template <typename PointAt>
std::vector<std::pair<uint32_t, uint32_t>>& repeatedPoints(size_t n, PointAt pointAt,
                                                           RepeatedPointsScratch& s) {
    constexpr uint32_t kEmpty = 0xffffffffu;
    std::vector<std::pair<uint32_t, uint32_t>>& copies = s.copies;
    copies.clear();
    int bits = 0;
    while (bits < 20 && (size_t(2048) << bits) < n) ++bits;  // about 2048 points a bucket
    std::vector<uint64_t>& hash = s.hash;
    std::vector<uint32_t>& start = s.start;
    hash.resize(n);
    start.assign((size_t(1) << bits) + 1, 0);
    auto bucketOf = [&](uint64_t h) { return bits ? size_t(h >> (64 - bits)) : 0; };
    for (size_t i = 0; i < n; ++i) {
        hash[i] = pointHash(pointAt(i));
        ++start[bucketOf(hash[i]) + 1];
    }
    for (size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
    std::vector<std::pair<uint64_t, uint32_t>>& byBucket = s.byBucket;
    byBucket.resize(n);
    s.fill.assign(start.begin(), start.end() - 1);
    for (size_t i = 0; i < n; ++i) byBucket[s.fill[bucketOf(hash[i])]++] = {hash[i], uint32_t(i)};
    std::vector<uint32_t>& table = s.table;  // indices into byBucket, kEmpty when empty
    for (size_t k = 0; k + 1 < start.size(); ++k) {
        size_t cap = 16;
        while (cap < size_t(start[k + 1] - start[k]) * 2) cap <<= 1;
        table.assign(cap, kEmpty);
        for (uint32_t j = start[k]; j < start[k + 1]; ++j) {
            auto [h, i] = byBucket[j];
            for (size_t t = h & (cap - 1);; t = (t + 1) & (cap - 1)) {
                if (table[t] == kEmpty) {
                    table[t] = j;
                    break;
                }
                auto [h2, i2] = byBucket[table[t]];
                if (h2 == h && pointAt(i2) == pointAt(i)) {
                    copies.emplace_back(i2, i);
                    break;
                }
            }
        }
    }
    return copies;
}

template <typename PointAt>
std::vector<std::pair<uint32_t, uint32_t>> repeatedPoints(size_t n, PointAt pointAt) {
    RepeatedPointsScratch s;
    repeatedPoints(n, pointAt, s);
    return std::move(s.copies);
}

}  // namespace flood
