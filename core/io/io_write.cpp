// Writing triangulations: JSON (vertices + triangles), SVG (a picture), OBJ (a mesh).
// Doubles are written as the shortest text that reads back to the same value.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <string_view>

#include "flood/io/io.h"
#include "flood/io/svg.h"
#include "io/io_util.h"

namespace flood {

namespace {

// Text formatted straight into a buffer handed to the stream 64 KiB at a time: no document
// in memory, no stream call or string per number (at 10^6 vertices the stream's per-call
// cost was most of the writing time).
class Sink {
public:
    explicit Sink(std::ostream& out) : out_(out) {}
    ~Sink() { flush(); }
    Sink& operator<<(std::string_view s) {
        if (s.size() > sizeof buf_) {
            flush();
            out_.write(s.data(), std::streamsize(s.size()));
            return *this;
        }
        room(s.size());
        end_ = std::copy(s.begin(), s.end(), end_);
        return *this;
    }
    Sink& operator<<(double v) {
        room(io_detail::kDoubleChars);
        end_ = io_detail::writeDouble(end_, v);
        return *this;
    }
    Sink& operator<<(uint64_t v) {
        room(20);
        end_ = std::to_chars(end_, end_ + 20, v).ptr;
        return *this;
    }

private:
    void room(size_t k) {
        if (size_t(buf_ + sizeof buf_ - end_) < k) flush();
    }
    void flush() {
        out_.write(buf_, std::streamsize(end_ - buf_));
        end_ = buf_;
    }
    std::ostream& out_;
    char buf_[1 << 16]{};  // zeroed once per writer: 64 KiB, nothing per number
    char* end_ = buf_;
};

}  // namespace

void writeJson(std::ostream& out, const Polygon& p, const std::vector<Triangle>& t) {
    Sink o(out);
    o << "{\"vertices\": [";
    for (size_t i = 0; i < p.vertices.size(); ++i)
        o << (i ? ", [" : "[") << p.vertices[i].x << ", " << p.vertices[i].y << "]";
    o << "],\n \"triangles\": [";
    for (size_t i = 0; i < t.size(); ++i)
        o << (i ? ", [" : "[") << uint64_t(t[i][0]) << ", " << uint64_t(t[i][1]) << ", "
          << uint64_t(t[i][2]) << "]";
    o << "]}\n";
}

void writeObj(std::ostream& out, const Polygon& p, const std::vector<Triangle>& t) {
    Sink o(out);
    o << "# flood: " << uint64_t(p.vertices.size()) << " vertices, " << uint64_t(t.size())
      << " triangles\n";
    for (const Point& v : p.vertices) o << "v " << v.x << " " << v.y << " 0\n";
    for (const Triangle& tr : t)
        o << "f " << uint64_t(tr[0]) + 1 << " " << uint64_t(tr[1]) + 1 << " " << uint64_t(tr[2]) + 1
          << "\n";
}

// SVG has y down; we flip it (y_svg = -y) and fit the viewBox to the polygon with a margin.
// Coordinates are written times 2^shift (exact unless a tiny one goes subnormal): shift is 0
// unless a coordinate exceeds 2^500 (then the largest becomes ~1) or the extent is below
// 2^-500 (then it becomes ~1), so the viewBox's sums stay finite and its sizes normal at
// every extent. The longer side is 800 pixels, the shorter at least 1.
void writeSvg(std::ostream& out, const Polygon& p, const std::vector<Triangle>& t) {
    double minx = 0, maxx = 1, miny = 0, maxy = 1;
    if (!p.vertices.empty()) {
        minx = maxx = p.vertices[0].x;
        miny = maxy = p.vertices[0].y;
        for (const Point& v : p.vertices) {
            minx = std::min(minx, v.x), maxx = std::max(maxx, v.x);
            miny = std::min(miny, v.y), maxy = std::max(maxy, v.y);
        }
    }
    // The scale: a power of two, chosen on the exact box.
    int shift = 0, e = 0;
    const double big =
        std::max({std::fabs(minx), std::fabs(maxx), std::fabs(miny), std::fabs(maxy)});
    if (big > 0x1p500) {
        std::frexp(big, &e);
        shift = -e;
    } else if (double extent = std::max(maxx - minx, maxy - miny);
               extent > 0 && extent < 0x1p-500) {
        std::frexp(extent,
                   &e);  // distinct doubles near `big` differ by >= big·2^-53: big stays finite
        shift = -e;
    }
    auto S = [shift](double v) { return std::ldexp(v, shift); };
    auto flip = [](double y) { return y == 0 ? 0.0 : -y; };  // no "-0"
    const double x0 = S(minx), y1 = S(maxy), w = S(maxx) - x0, h = y1 - S(miny);
    double size = std::max(w, h);
    if (!(size > 0)) size = 1;
    const double margin = size * 0.02, stroke = size * 0.002;
    const double boxW = w + 2 * margin, boxH = h + 2 * margin, longer = std::max(boxW, boxH);
    auto pixels = [longer](double side) {
        return double(std::max(1L, std::lround(800 * (side / longer))));
    };
    svg::Document doc(out, {x0 - margin, flip(y1 + margin), boxW, boxH}, pixels(boxW), pixels(boxH),
                      [&](Point v) {
                          return Point{S(v.x), flip(S(v.y))};
                      });
    // The polygon: one path, rings as subpaths, even-odd fill makes holes empty.
    svg::Style land;
    land.fill = "#cde", land.evenOdd = true, land.stroke = "#024", land.strokeWidth = stroke * 2;
    std::vector<svg::RingView> rings;
    for (const Ring& r : p.rings) rings.push_back({p.vertices.data() + r.first, r.count});
    doc.rings(land, rings);
    svg::Style edges;
    edges.fill = "none", edges.stroke = "#a33", edges.strokeWidth = stroke, edges.roundJoins = true;
    doc.beginGroup(edges);
    const size_t n = p.vertices.size();
    for (const Triangle& tr : t)
        if (tr[0] < n && tr[1] < n && tr[2] < n)
            doc.triangle({}, p.vertices[tr[0]], p.vertices[tr[1]], p.vertices[tr[2]]);
}

}  // namespace flood
