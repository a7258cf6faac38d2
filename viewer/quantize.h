// A palette of at most 256 colours for GIF frames, built from the frames themselves. The canvas
// paints few flat colours plus the anti-aliased edges of lines and text: when the frames hold
// 256 colours or fewer the palette is exactly them; otherwise the most frequent colours (the
// flat fills, which slides must show true) are kept exactly and median cut shares the
// remaining entries among the rest.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace flood::view {

using Rgb = std::array<uint8_t, 3>;

class PaletteBuilder {
public:
    // Counts the colours of RGBA pixels (alpha ignored).
    void add(const uint8_t* rgba, size_t pixels);
    size_t distinct() const { return counts_.size(); }
    // At most `size` colours (1..256); every colour seen when distinct() <= size.
    std::vector<Rgb> build(size_t size = 256) const;

private:
    std::unordered_map<uint32_t, uint64_t> counts_;  // 0xRRGGBB -> pixels
};

// Maps colours to the index of the nearest palette entry (squared RGB distance), remembering
// every colour it has seen.
class PaletteMap {
public:
    explicit PaletteMap(std::vector<Rgb> palette);
    // Indices of RGBA pixels into `out` (one byte each).
    void map(const uint8_t* rgba, size_t pixels, uint8_t* out);
    const std::vector<Rgb>& palette() const { return palette_; }

private:
    uint8_t nearest(uint32_t rgb) const;
    std::vector<Rgb> palette_;
    std::unordered_map<uint32_t, uint8_t> cache_;
};

}  // namespace flood::view
