// Writing triangulations: JSON (vertices + triangles), SVG (a picture), OBJ (a mesh).
// Doubles are written as the shortest text that reads back to the same value.
#include <algorithm>
#include <cmath>
#include <ostream>

#include "io.h"
#include "io_util.h"

namespace flood {

using io_detail::formatDouble;

void writeJson(std::ostream& out, const Polygon& p, const std::vector<Triangle>& t) {
    out << "{\"vertices\": [";
    for (size_t i = 0; i < p.vertices.size(); ++i)
        out << (i ? ", [" : "[") << formatDouble(p.vertices[i].x) << ", "
            << formatDouble(p.vertices[i].y) << "]";
    out << "],\n \"triangles\": [";
    for (size_t i = 0; i < t.size(); ++i)
        out << (i ? ", [" : "[") << t[i][0] << ", " << t[i][1] << ", " << t[i][2] << "]";
    out << "]}\n";
}

void writeObj(std::ostream& out, const Polygon& p, const std::vector<Triangle>& t) {
    out << "# flood: " << p.vertices.size() << " vertices, " << t.size() << " triangles\n";
    for (const Point& v : p.vertices)
        out << "v " << formatDouble(v.x) << " " << formatDouble(v.y) << " 0\n";
    for (const Triangle& tr : t)
        out << "f " << tr[0] + 1 << " " << tr[1] + 1 << " " << tr[2] + 1 << "\n";
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
    const double big = std::max({std::fabs(minx), std::fabs(maxx), std::fabs(miny), std::fabs(maxy)});
    if (big > 0x1p500) {
        std::frexp(big, &e);
        shift = -e;
    } else if (double extent = std::max(maxx - minx, maxy - miny); extent > 0 && extent < 0x1p-500) {
        std::frexp(extent, &e);  // distinct doubles near `big` differ by >= big·2^-53: big stays finite
        shift = -e;
    }
    auto S = [shift](double v) { return std::ldexp(v, shift); };
    auto flip = [](double y) { return y == 0 ? 0.0 : -y; };  // no "-0"
    auto X = [&](double x) { return formatDouble(S(x)); };
    auto Y = [&](double y) { return formatDouble(flip(S(y))); };
    const double x0 = S(minx), y1 = S(maxy), w = S(maxx) - x0, h = y1 - S(miny);
    double size = std::max(w, h);
    if (!(size > 0)) size = 1;
    const double margin = size * 0.02, stroke = size * 0.002;
    const double boxW = w + 2 * margin, boxH = h + 2 * margin, longer = std::max(boxW, boxH);
    auto pixels = [longer](double side) { return std::max(1L, std::lround(800 * (side / longer))); };
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << formatDouble(x0 - margin) << " "
        << formatDouble(flip(y1 + margin)) << " " << formatDouble(boxW) << " " << formatDouble(boxH)
        << "\" width=\"" << pixels(boxW) << "\" height=\"" << pixels(boxH) << "\">\n";
    // The polygon: one path, rings as subpaths, even-odd fill makes holes empty.
    out << "<path fill=\"#cde\" fill-rule=\"evenodd\" stroke=\"#024\" stroke-width=\""
        << formatDouble(stroke * 2) << "\" d=\"";
    for (const Ring& r : p.rings) {
        for (Index i = 0; i < r.count; ++i) {
            const Point& v = p.vertices[r.first + i];
            out << (i ? "L" : "M") << X(v.x) << " " << Y(v.y) << " ";
        }
        out << "Z ";
    }
    out << "\"/>\n<g fill=\"none\" stroke=\"#a33\" stroke-width=\"" << formatDouble(stroke)
        << "\" stroke-linejoin=\"round\">\n";
    for (const Triangle& tr : t) {
        out << "<path d=\"";
        for (int k = 0; k < 3; ++k) {
            Index i = tr[k];
            if (i >= p.vertices.size()) continue;
            out << (k ? "L" : "M") << X(p.vertices[i].x) << " " << Y(p.vertices[i].y) << " ";
        }
        out << "Z\"/>\n";
    }
    out << "</g>\n</svg>\n";
}

}  // namespace flood
