// The SVG writer (svg.h): markup only; callers place the points and choose the colours.
#include "flood/io/svg.h"

#include <cstdio>
#include <utility>

#include "io/io_util.h"

namespace flood::svg {

using io_detail::formatDouble;

std::string hex(uint8_t r, uint8_t g, uint8_t b) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", r, g, b);
    return buf;
}

std::string escaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c;
        }
    }
    return out;
}

Document::Document(std::ostream& out, const Box& viewBox, double width, double height, Place place)
    : out_(out), place_(std::move(place)) {
    out_ << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << formatDouble(viewBox.x) << " "
         << formatDouble(viewBox.y) << " " << formatDouble(viewBox.w) << " "
         << formatDouble(viewBox.h) << "\" width=\"" << formatDouble(width) << "\" height=\""
         << formatDouble(height) << "\">\n";
}

Document::~Document() {
    while (openGroups_ > 0) endGroup();
    out_ << "</svg>\n";
}

void Document::attributes(const Style& s) {
    if (!s.className.empty()) out_ << " class=\"" << s.className << "\"";
    if (!s.fill.empty()) out_ << " fill=\"" << s.fill << "\"";
    if (s.evenOdd) out_ << " fill-rule=\"evenodd\"";
    if (!s.stroke.empty()) out_ << " stroke=\"" << s.stroke << "\"";
    if (s.strokeWidth != 0) out_ << " stroke-width=\"" << formatDouble(s.strokeWidth) << "\"";
    if (s.roundJoins) out_ << " stroke-linejoin=\"round\"";
}

void Document::clip(const std::string& id, const Box& area) {
    out_ << "<clipPath id=\"" << id << "\"><rect x=\"" << formatDouble(area.x) << "\" y=\""
         << formatDouble(area.y) << "\" width=\"" << formatDouble(area.w) << "\" height=\""
         << formatDouble(area.h) << "\"/></clipPath>\n";
}

void Document::background(const std::string& fill) {
    out_ << "<rect width=\"100%\" height=\"100%\" fill=\"" << fill << "\"/>\n";
}

void Document::beginGroup(const Style& style, const std::string& clipId) {
    out_ << "<g";
    attributes(style);
    if (!clipId.empty()) out_ << " clip-path=\"url(#" << clipId << ")\"";
    out_ << ">\n";
    ++openGroups_;
}

void Document::endGroup() {
    if (openGroups_ == 0) return;
    out_ << "</g>\n";
    --openGroups_;
}

void Document::rings(const Style& style, const std::vector<RingView>& rings) {
    out_ << "<path";
    attributes(style);
    out_ << " d=\"";
    for (const RingView& r : rings) {
        for (size_t i = 0; i < r.count; ++i) {
            Point p = place_(r.points[i]);
            out_ << (i ? "L" : "M") << formatDouble(p.x) << " " << formatDouble(p.y) << " ";
        }
        out_ << "Z ";
    }
    out_ << "\"/>\n";
}

void Document::triangle(const Style& style, Point a, Point b, Point c) {
    out_ << "<polygon";
    attributes(style);
    out_ << " points=\"";
    const char* gap = "";
    for (Point w : {a, b, c}) {
        Point p = place_(w);
        out_ << gap << formatDouble(p.x) << "," << formatDouble(p.y);
        gap = " ";
    }
    out_ << "\"/>\n";
}

void Document::line(const Style& style, Point a, Point b) {
    Point p = place_(a), q = place_(b);
    out_ << "<line x1=\"" << formatDouble(p.x) << "\" y1=\"" << formatDouble(p.y) << "\" x2=\""
         << formatDouble(q.x) << "\" y2=\"" << formatDouble(q.y) << "\"";
    attributes(style);
    out_ << "/>\n";
}

void Document::circle(const Style& style, Point centre, double radius) {
    Point c = place_(centre);
    out_ << "<circle cx=\"" << formatDouble(c.x) << "\" cy=\"" << formatDouble(c.y) << "\" r=\""
         << formatDouble(radius) << "\"";
    attributes(style);
    out_ << "/>\n";
}

void Document::text(Point at, double size, const std::vector<Span>& spans) {
    out_ << "<text x=\"" << formatDouble(at.x) << "\" y=\"" << formatDouble(at.y)
         << "\" font-family=\"sans-serif\" font-size=\"" << formatDouble(size) << "\">";
    for (const Span& s : spans) {
        out_ << "<tspan" << (s.bold ? " font-weight=\"bold\"" : "");
        if (!s.fill.empty()) out_ << " fill=\"" << s.fill << "\"";
        out_ << ">" << escaped(s.text) << "</tspan>";
    }
    out_ << "</text>\n";
}

}  // namespace flood::svg
