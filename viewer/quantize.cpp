#include "quantize.h"

#include <algorithm>

namespace flood::view {

namespace {

uint32_t pack(const uint8_t* p) { return uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]; }
Rgb unpack(uint32_t c) { return {uint8_t(c >> 16), uint8_t(c >> 8), uint8_t(c)}; }

struct Entry {
    Rgb c;
    uint64_t n;
};

// Median cut: splits the box whose widest channel range is largest (weighted by its pixels)
// at the pixel-weighted median of that channel, until there are `boxes` boxes; each box
// gives its pixel-weighted mean.
std::vector<Rgb> medianCut(std::vector<Entry> colours, size_t boxes) {
    struct Box {
        size_t begin, end;
    };
    auto widest = [&](const Box& b, int& channel) {
        int best = -1;
        for (int k = 0; k < 3; ++k) {
            uint8_t lo = 255, hi = 0;
            for (size_t i = b.begin; i < b.end; ++i)
                lo = std::min(lo, colours[i].c[k]), hi = std::max(hi, colours[i].c[k]);
            if (hi - lo > best) best = hi - lo, channel = k;
        }
        return best;
    };
    std::vector<Box> out{{0, colours.size()}};
    while (out.size() < boxes) {
        size_t pick = out.size();
        int channel = 0;
        double score = 0;
        for (size_t i = 0; i < out.size(); ++i) {
            if (out[i].end - out[i].begin < 2) continue;
            int k = 0;
            uint64_t pixels = 0;
            for (size_t j = out[i].begin; j < out[i].end; ++j) pixels += colours[j].n;
            double s = double(widest(out[i], k)) * double(pixels);
            if (s > score) score = s, pick = i, channel = k;
        }
        if (pick == out.size()) break;  // every box is one colour
        Box b = out[pick];
        std::sort(colours.begin() + long(b.begin), colours.begin() + long(b.end),
                  [&](const Entry& x, const Entry& y) { return x.c[channel] < y.c[channel]; });
        uint64_t total = 0, run = 0;
        for (size_t j = b.begin; j < b.end; ++j) total += colours[j].n;
        size_t mid = b.begin + 1;
        for (size_t j = b.begin; j + 1 < b.end; ++j) {
            run += colours[j].n;
            mid = j + 1;
            if (2 * run >= total) break;
        }
        out[pick] = {b.begin, mid};
        out.push_back({mid, b.end});
    }
    std::vector<Rgb> palette;
    for (const Box& b : out) {
        double sum[3] = {0, 0, 0}, n = 0;
        for (size_t j = b.begin; j < b.end; ++j) {
            for (int k = 0; k < 3; ++k) sum[k] += double(colours[j].c[k]) * double(colours[j].n);
            n += double(colours[j].n);
        }
        if (n > 0)
            palette.push_back(
                {uint8_t(sum[0] / n + 0.5), uint8_t(sum[1] / n + 0.5), uint8_t(sum[2] / n + 0.5)});
    }
    return palette;
}

}  // namespace

void PaletteBuilder::add(const uint8_t* rgba, size_t pixels) {
    // Canvas rows are long runs of one colour: count a run with one hash look-up.
    size_t i = 0;
    while (i < pixels) {
        uint32_t c = pack(rgba + 4 * i);
        size_t j = i + 1;
        while (j < pixels && pack(rgba + 4 * j) == c) ++j;
        counts_[c] += j - i;
        i = j;
    }
}

std::vector<Rgb> PaletteBuilder::build(size_t size) const {
    size = std::clamp<size_t>(size, 1, 256);
    std::vector<Entry> all;
    all.reserve(counts_.size());
    for (auto [c, n] : counts_) all.push_back({unpack(c), n});
    // Most frequent first, ties by colour: the same frames always give the same palette.
    std::sort(all.begin(), all.end(),
              [](const Entry& a, const Entry& b) { return a.n != b.n ? a.n > b.n : a.c < b.c; });
    std::vector<Rgb> palette;
    if (all.size() <= size) {
        for (const Entry& e : all) palette.push_back(e.c);
        return palette;
    }
    const size_t exact = size / 2;
    for (size_t i = 0; i < exact; ++i) palette.push_back(all[i].c);
    std::vector<Rgb> rest =
        medianCut(std::vector<Entry>(all.begin() + long(exact), all.end()), size - exact);
    palette.insert(palette.end(), rest.begin(), rest.end());
    return palette;
}

PaletteMap::PaletteMap(std::vector<Rgb> palette) : palette_(std::move(palette)) {
    if (palette_.empty()) palette_.push_back({0, 0, 0});
}

uint8_t PaletteMap::nearest(uint32_t rgb) const {
    Rgb c = unpack(rgb);
    size_t best = 0;
    int bestD = 1 << 30;
    for (size_t i = 0; i < palette_.size(); ++i) {
        int d = 0;
        for (int k = 0; k < 3; ++k)
            d += (int(c[k]) - palette_[i][k]) * (int(c[k]) - palette_[i][k]);
        if (d < bestD) bestD = d, best = i;
    }
    return uint8_t(best);
}

void PaletteMap::map(const uint8_t* rgba, size_t pixels, uint8_t* out) {
    uint32_t last = ~0u;
    uint8_t index = 0;
    for (size_t i = 0; i < pixels; ++i) {
        uint32_t c = pack(rgba + 4 * i);
        if (c != last) {
            auto it = cache_.find(c);
            index = it != cache_.end() ? it->second : (cache_[c] = nearest(c));
            last = c;
        }
        out[i] = index;
    }
}

}  // namespace flood::view
