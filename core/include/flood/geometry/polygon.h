// Polygon model of the paper (§3): an array of vertices and loops of vertex references.
// Input rings are kept exactly as read (either orientation); the flood machine orients
// loops itself. A multipolygon is a list of parts, each an outer ring followed by its holes.
#pragma once
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace flood {

struct Point {
    double x = 0, y = 0;
};
inline bool operator==(Point a, Point b) { return a.x == b.x && a.y == b.y; }
inline bool operator!=(Point a, Point b) { return !(a == b); }

// A hash of a point's exact coordinates, equal for equal points (-0.0 is 0.0), with every bit
// mixed into the top ones (integer coordinates differ only in their high bits). For finding
// coincident points: the flood machine's touching rings, the checker's canonical vertices.
inline uint64_t pointHash(Point p) {
    double x = p.x + 0.0, y = p.y + 0.0;
    uint64_t a, b;
    std::memcpy(&a, &x, 8);
    std::memcpy(&b, &y, 8);
    uint64_t h = a ^ (b * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull);
    h = (h ^ (h >> 31)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 29)) * 0x94D049BB133111EBull;
    return h ^ (h >> 32);
}

using Index = uint32_t;
constexpr Index kNone = 0xffffffffu;

struct Ring {
    Index first = 0;  // first vertex in Polygon::vertices
    Index count = 0;  // number of vertices (no repeated closing point)
};

struct Part {
    Index firstRing = 0;  // outer ring; holes follow
    Index ringCount = 0;
};

// A T-junction: `vertex` (of one ring) lies strictly inside the edge `edge` -> next(edge) of
// another ring of its part. The rings touch there at a single point (§1's non-manifold
// vertices), so the boundary passes through that vertex twice: the flood machine and the
// checker split the edge there. validate() finds them; nothing else adds any.
struct EdgeSplit {
    Index edge = 0;    // first vertex of the split edge
    Index vertex = 0;  // the touching vertex
};

// Vertices of all rings concatenated in file order (closing points dropped).
struct Polygon {
    std::vector<Point> vertices;
    std::vector<Ring> rings;
    std::vector<Part> parts;
    std::vector<EdgeSplit> splits;  // T-junction touches, sorted by edge (see validate())
    // Set by validate() on a valid polygon where no two vertices are at one point (bit-equal
    // coordinates) and no T-junction: no rings touch, so the flood machine skips its search
    // for touching points. False means not known. Edit the vertices, validate again (as for
    // splits).
    bool pointsDistinct = false;

    Index ringOf(Index v) const;  // ring containing vertex v (binary search)
    // The parts take the rings in order and the rings the vertices, with nothing left over,
    // as every reader builds them: then a run of parts owns a run of vertices of its own.
    bool tiled() const;
    size_t holeCount() const { return rings.size() - parts.size(); }
    // The vertices of parts[k]'s rings, stored one ring after the other.
    size_t partVertices(Index k) const {
        const Part& p = parts[k];
        if (p.ringCount == 0) return 0;
        const Ring& last = rings[p.firstRing + p.ringCount - 1];
        return last.first + last.count - rings[p.firstRing].first;
    }
    // n + 2h - 2 per part, summed: the triangle count of any triangulation (§1); two fewer
    // for each extra copy of a point where rings touch, one fewer for each T-junction and
    // for each hole that is a single point (a Steiner point).
    size_t expectedTriangles() const;
    // Adds a ring; starts a new part when `outer` is true.
    void addRing(const std::vector<Point>& pts, bool outer);
};

// The same vertices (compared as values), rings and parts: what a reader read, apart from
// what validation later records (splits, pointsDistinct).
bool sameGeometry(const Polygon& a, const Polygon& b);

using Triangle = std::array<Index, 3>;

}  // namespace flood
