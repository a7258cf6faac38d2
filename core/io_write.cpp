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
    double w = maxx - minx, h = maxy - miny;
    double size = std::max(w, h);
    if (!(size > 0) || !std::isfinite(size)) size = 1;
    double margin = size * 0.02;
    double stroke = size * 0.002;
    auto X = [&](double x) { return formatDouble(x); };
    auto Y = [&](double y) { return formatDouble(y == 0 ? 0.0 : -y); };  // no "-0"
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << X(minx - margin) << " "
        << Y(maxy + margin) << " " << X(w + 2 * margin) << " " << X(h + 2 * margin)
        << "\" width=\"800\" height=\"" << int(800 * (h + 2 * margin) / (w + 2 * margin) + 0.5)
        << "\">\n";
    // The polygon: one path, rings as subpaths, even-odd fill makes holes empty.
    out << "<path fill=\"#cde\" fill-rule=\"evenodd\" stroke=\"#024\" stroke-width=\""
        << X(stroke * 2) << "\" d=\"";
    for (const Ring& r : p.rings) {
        for (Index i = 0; i < r.count; ++i) {
            const Point& v = p.vertices[r.first + i];
            out << (i ? "L" : "M") << X(v.x) << " " << Y(v.y) << " ";
        }
        out << "Z ";
    }
    out << "\"/>\n<g fill=\"none\" stroke=\"#a33\" stroke-width=\"" << X(stroke)
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
