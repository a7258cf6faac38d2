// Writing a polygon (not a triangulation) as JSON: the repro of `flood shrink`, `flood check
// --extract`'s bare rings, the viewer's Save. Coordinates in the shortest text that reads
// back to the same double; rings closed, as GeoJSON wants them.
#include <cmath>
#include <ostream>
#include <sstream>

#include "flood/io/io.h"
#include "flood/io/output.h"
#include "geometry/number_text.h"

namespace flood {

namespace {

void writeNumber(std::ostream& out, double x) {
    if (!std::isfinite(x)) {  // JSON has no NaN/inf; WKT would, but keep one output format
        out << (std::isnan(x) ? "null" : x > 0 ? "1e999" : "-1e999");
        return;
    }
    char buf[kDoubleChars];
    const char* end = writeDouble(buf, x);
    out.write(buf, end - buf);
}

// One part's rings: [[[x,y],...],...].
void writeRings(std::ostream& out, const Polygon& p, const Part& part) {
    out << '[';
    for (Index r = part.firstRing; r < part.firstRing + part.ringCount; ++r) {
        const Ring& ring = p.rings[r];
        out << (r == part.firstRing ? "" : ",\n ") << '[';
        for (Index i = 0; ring.count > 0 && i <= ring.count; ++i) {  // closed: the first again
            const Point& q = p.vertices[ring.first + (i == ring.count ? 0 : i)];
            out << (i ? "," : "") << '[';
            writeNumber(out, q.x);
            out << ',';
            writeNumber(out, q.y);
            out << ']';
        }
        out << ']';
    }
    out << ']';
}

void writeParts(std::ostream& out, const Polygon& p) {
    for (size_t i = 0; i < p.parts.size(); ++i) {
        if (i) out << ",\n";
        writeRings(out, p, p.parts[i]);
    }
}

}  // namespace

std::string geoJsonGeometry(const Polygon& p) {
    std::ostringstream out;
    if (p.parts.size() == 1) {
        out << "{\"type\":\"Polygon\",\"coordinates\":";
        writeRings(out, p, p.parts[0]);
        out << '}';
    } else {
        out << "{\"type\":\"MultiPolygon\",\"coordinates\":[";
        writeParts(out, p);
        out << "]}";
    }
    return out.str();
}

void writePolygonJson(std::ostream& out, const Polygon& polygon) {
    if (polygon.parts.size() == 1) {
        writeRings(out, polygon, polygon.parts[0]);
    } else {
        out << "{\"type\":\"MultiPolygon\",\"coordinates\":[";
        writeParts(out, polygon);
        out << "]}";
    }
    out << '\n';
}

Diagnostic saveGeoJson(const Polygon& polygon, const std::string& path) {
    Output out(path);
    out.stream() << geoJsonGeometry(polygon) << '\n';
    std::string message;
    if (out.commit(&message) == Status::Ok) return {};
    if (message.rfind("error: ", 0) == 0) message.erase(0, 7);  // a diagnostic, not a line
    return {Status::WriteFailed, message};
}

}  // namespace flood
