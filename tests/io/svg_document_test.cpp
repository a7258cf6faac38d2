// The one SVG writer (flood/io/svg.h) that the CLI's picture and the viewer's export share: the
// markup of each shape, points placed by the caller, attributes only where a style sets them,
// text escaped, and the document closed however its writer leaves it.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "flood/io/svg.h"

using namespace flood;

namespace {
Point flipY(Point p) { return {p.x, p.y == 0 ? 0.0 : -p.y}; }
}  // namespace

TEST(SvgDocument, ShapesArePlacedAndStyledAsAsked) {
    std::ostringstream out;
    {
        svg::Document doc(out, {0, -3, 2.5, 3}, 800, 960, flipY);
        svg::Style land;
        land.fill = "#cde", land.evenOdd = true, land.stroke = "#024", land.strokeWidth = 0.25;
        const Point ring[] = {{0, 0}, {2.5, 0}, {1, 3}};
        doc.rings(land, {{ring, 3}});
        svg::Style water;
        water.className = "water", water.fill = svg::hex(10, 11, 255);
        doc.triangle(water, {0, 0}, {2.5, 0}, {1, 3});
        doc.triangle({}, {0, 0}, {2.5, 0}, {1, 3});
        svg::Style dot;
        dot.fill = "none", dot.stroke = "#fff";
        doc.circle(dot, {1, 3}, 6.5);
        svg::Style edge;
        edge.stroke = "#a33", edge.strokeWidth = 1.5, edge.roundJoins = true;
        doc.line(edge, {0, 0}, {1, 3});
    }
    EXPECT_EQ(out.str(),
              "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 -3 2.5 3\" width=\"800\" "
              "height=\"960\">\n"
              "<path fill=\"#cde\" fill-rule=\"evenodd\" stroke=\"#024\" stroke-width=\"0.25\" "
              "d=\"M0 0 L2.5 0 L1 -3 Z \"/>\n"
              "<polygon class=\"water\" fill=\"#0a0bff\" points=\"0,0 2.5,0 1,-3\"/>\n"
              "<polygon points=\"0,0 2.5,0 1,-3\"/>\n"
              "<circle cx=\"1\" cy=\"-3\" r=\"6.5\" fill=\"none\" stroke=\"#fff\"/>\n"
              "<line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"-3\" stroke=\"#a33\" stroke-width=\"1.5\" "
              "stroke-linejoin=\"round\"/>\n"
              "</svg>\n");
}

TEST(SvgDocument, TextIsEscapedAndOpenGroupsAreClosed) {
    std::ostringstream out;
    {
        svg::Document doc(out, {0, 0, 10, 10}, 10, 10, [](Point p) { return p; });
        doc.clip("canvas", {1, 2, 3, 4});
        doc.background("#000");
        doc.beginGroup({}, "canvas");
        doc.text({8, 20}, 13, {{"Step 3", "#fff", true}, {" <&> \"it's\"", ""}});
        // No endGroup(): the document closes the group, then itself.
    }
    const std::string s = out.str();
    EXPECT_NE(s.find("<clipPath id=\"canvas\"><rect x=\"1\" y=\"2\" width=\"3\" height=\"4\"/>"
                     "</clipPath>\n<rect width=\"100%\" height=\"100%\" fill=\"#000\"/>\n"
                     "<g clip-path=\"url(#canvas)\">\n"),
              std::string::npos)
        << s;
    EXPECT_NE(s.find("<text x=\"8\" y=\"20\" font-family=\"sans-serif\" font-size=\"13\">"
                     "<tspan font-weight=\"bold\" fill=\"#fff\">Step 3</tspan>"
                     "<tspan> &lt;&amp;&gt; &quot;it&apos;s&quot;</tspan></text>\n"),
              std::string::npos)
        << s;
    EXPECT_EQ(s.substr(s.size() - 12), "</g>\n</svg>\n") << s;
}
