// Shared by the fuzz harnesses: the byte encoding of a polygon, so seeds can be generated
// from polygon files (scripts/fuzz-seeds.py writes the same format).
//
//   byte 0          options: bits 0-1 = the vertical, +y -y +x -x; bit 2 set: off the axes
//                   instead, at 17 + 11.25 k degrees for k = bits 3-7
//   then rings:     header byte H: bits 0-5 = point count (63 = a uint16 LE count follows),
//                   bit 6 = starts a new part (ignored for the first ring: always outer),
//                   bit 7 = coordinates are raw little-endian doubles (16 bytes a point);
//                   otherwise each coordinate is a signed byte (2 bytes a point), so the
//                   fuzzer reaches coincident points, collinear edges and touching rings.
// A ring cut short by the end of the data keeps the points read so far.
#pragma once
#include <cstdint>
#include <cstring>
#include <vector>

#include "flood/geometry/polygon.h"
#include "flood/machine/flood.h"

namespace fuzzpoly {

struct Decoded {
    flood::Polygon polygon;
    flood::Options options;
};

inline Decoded decode(const uint8_t* data, size_t size, size_t maxVertices = 4096) {
    Decoded d;
    size_t pos = 0;
    if (size == 0) return d;
    const flood::Up axes[] = {flood::Up::PlusY, flood::Up::MinusY, flood::Up::PlusX,
                              flood::Up::MinusX};
    d.options.up =
        (data[pos] & 4) ? flood::upFromDegrees(17 + 11.25 * (data[pos] >> 3)) : axes[data[pos] & 3];
    ++pos;
    while (pos < size && d.polygon.vertices.size() < maxVertices) {
        uint8_t h = data[pos++];
        size_t count = h & 63;
        if (count == 63 && pos + 2 <= size) {
            count = size_t(data[pos]) | size_t(data[pos + 1]) << 8;
            pos += 2;
        }
        bool raw = h & 128;
        bool outer = d.polygon.rings.empty() || (h & 64);
        std::vector<flood::Point> pts;
        for (size_t i = 0; i < count && d.polygon.vertices.size() + pts.size() < maxVertices; ++i) {
            flood::Point p;
            if (raw) {
                if (pos + 16 > size) break;
                std::memcpy(&p.x, data + pos, 8);
                std::memcpy(&p.y, data + pos + 8, 8);
                pos += 16;
            } else {
                if (pos + 2 > size) break;
                p.x = double(int8_t(data[pos]));
                p.y = double(int8_t(data[pos + 1]));
                pos += 2;
            }
            pts.push_back(p);
        }
        d.polygon.addRing(pts, outer);
    }
    return d;
}

}  // namespace fuzzpoly
