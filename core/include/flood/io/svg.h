// The one SVG writer, for the CLI's picture (`flood triangulate --format svg`, io_write.cpp)
// and the viewer's canvas export (viewer/scene.cpp): a document with its viewBox, the
// polygon's rings as one even-odd path, triangles, lines, dots and text. Callers bring where a
// point lands in the picture (SVG has y down) and their colours; the markup is written here.
// Every number is the shortest text that reads back to the same double.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "flood/geometry/polygon.h"

namespace flood::svg {

std::string hex(uint8_t r, uint8_t g, uint8_t b);  // "#rrggbb"
std::string escaped(const std::string& text);      // XML's five reserved characters escaped

// How a shape is painted; empty strings and a zero width leave their attribute out.
struct Style {
    std::string className;  // class="…": readers of the file pick shapes out by it
    std::string fill;       // a colour, or "none"
    bool evenOdd = false;   // fill-rule="evenodd": holes stay empty
    std::string stroke;
    double strokeWidth = 0;
    bool roundJoins = false;
};

struct Box {
    double x = 0, y = 0, w = 0, h = 0;
};

// A ring's points, contiguous (a Polygon's ring, or a vector of points).
struct RingView {
    const Point* points = nullptr;
    size_t count = 0;
};

// An SVG document written to `out` as it is drawn; closed (any open group first) when it
// goes out of scope. Shapes take world points, placed by `place`; clip(), text() and the
// view box take picture coordinates.
class Document {
public:
    using Place = std::function<Point(Point)>;
    Document(std::ostream& out, const Box& viewBox, double width, double height, Place place);
    ~Document();
    Document(const Document&) = delete;
    Document& operator=(const Document&) = delete;

    Point place(Point world) const { return place_(world); }
    void clip(const std::string& id, const Box& area);  // a rectangular <clipPath>
    void background(const std::string& fill);           // paints the whole page
    void beginGroup(const Style& style, const std::string& clipId = "");
    void endGroup();
    void rings(const Style& style, const std::vector<RingView>& rings);  // one path
    void triangle(const Style& style, Point a, Point b, Point c);        // a <polygon>
    void line(const Style& style, Point a, Point b);
    void circle(const Style& style, Point centre, double radius);
    struct Span {
        std::string text, fill;
        bool bold = false;
    };
    void text(Point at, double size, const std::vector<Span>& spans);  // sans-serif

private:
    void attributes(const Style& style);
    std::ostream& out_;
    Place place_;
    int openGroups_ = 0;
};

}  // namespace flood::svg
