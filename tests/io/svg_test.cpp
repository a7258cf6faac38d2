// The SVG picture at every extent: every number written is finite, the viewBox holds every
// point drawn, and the pixel size is sane (longer side 800, shorter at least 1), from a
// single point or a zero-width outline up to coordinates of ±1.7e308 and down to 2^-1074.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "flood/io/io.h"

using namespace flood;

namespace {

double number(const std::string& s, const std::string& what) {
    char* end = nullptr;
    double v = std::strtod(s.c_str(), &end);
    EXPECT_TRUE(end && *end == 0 && !s.empty()) << what << ": not a number: '" << s << "'";
    EXPECT_TRUE(std::isfinite(v)) << what << ": " << s;
    return v;
}

std::vector<double> numbers(const std::string& list, const std::string& what) {
    std::vector<double> out;
    std::istringstream in(list);
    for (std::string tok; in >> tok;) out.push_back(number(tok, what));
    return out;
}

// Writes the SVG of `pts` as one ring (and one triangle when there are three or more) and
// checks every number in it.
void expectSaneSvg(const std::vector<Point>& pts, const std::string& what) {
    SCOPED_TRACE(what);
    Polygon p;
    p.addRing(pts, true);
    std::vector<Triangle> t;
    if (pts.size() >= 3) t.push_back({0, 1, 2});
    std::ostringstream os;
    writeSvg(os, p, t);
    const std::string svg = os.str();
    std::smatch m;
    ASSERT_TRUE(std::regex_search(svg, m, std::regex("viewBox=\"([^\"]*)\"")));
    std::vector<double> box = numbers(m[1], "viewBox");
    ASSERT_EQ(box.size(), 4u);
    EXPECT_GT(box[2], 0);
    EXPECT_GT(box[3], 0);
    ASSERT_TRUE(std::regex_search(svg, m, std::regex("width=\"([0-9]+)\" height=\"([0-9]+)\"")));
    long width = std::stol(m[1]), height = std::stol(m[2]);
    EXPECT_GE(std::min(width, height), 1);
    EXPECT_EQ(std::max(width, height), 800);
    std::regex stroke("stroke-width=\"([^\"]*)\"");
    int strokes = 0;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), stroke);
         it != std::sregex_iterator(); ++it, ++strokes)
        EXPECT_GT(number((*it)[1], "stroke-width"), 0);
    EXPECT_EQ(strokes, 2);
    // Every point drawn (M or L of the rings' path, x then y; "x,y" of a triangle's
    // polygon) lies in the viewBox.
    std::regex point("[ML](\\S+) (\\S+)|([^\\s,\"]+),([^\\s,\"]+)");
    size_t drawn = 0;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), point);
         it != std::sregex_iterator(); ++it, ++drawn) {
        const int at = (*it)[1].matched ? 1 : 3;
        double x = number((*it)[at], "point x"), y = number((*it)[at + 1], "point y");
        EXPECT_TRUE(box[0] <= x && x <= box[0] + box[2]) << x << " outside the viewBox";
        EXPECT_TRUE(box[1] <= y && y <= box[1] + box[3]) << y << " outside the viewBox";
    }
    EXPECT_EQ(drawn, pts.size() + 3 * t.size());
}

}  // namespace

TEST(Svg, FiniteAndSaneAtEveryExtent) {
    const double max = 1.7976931348623157e308, tiny = 0x1p-1074;
    expectSaneSvg({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, "a square");
    expectSaneSvg({{0, 0}, {0, 5}, {0, 10}}, "zero width");
    expectSaneSvg({{0, 3}, {7, 3}, {9, 3}}, "zero height");
    expectSaneSvg({{4, 4}}, "one point");
    expectSaneSvg({{-max, -max}, {max, -max}, {max, max}, {-max, max}}, "an extent of 2 DBL_MAX");
    expectSaneSvg({{0, 0}, {max, 0}, {max, max}}, "an extent of DBL_MAX");
    expectSaneSvg({{0, -max}, {0, max}, {0, 0}}, "zero width, 2 DBL_MAX tall");
    expectSaneSvg({{0, 0}, {tiny, 0}, {tiny, tiny}, {0, tiny}}, "an extent of 2^-1074");
    expectSaneSvg({{0x1p-1000, 0x1p-1000}, {0x1.8p-1000, 0x1p-1000}, {0x1p-1000, 0x1.8p-1000}},
                  "at 2^-1000");
    expectSaneSvg({{1e300, 1e300},
                   {std::nextafter(1e300, 2e300), 1e300},
                   {1e300, std::nextafter(1e300, 2e300)}},
                  "one ulp wide at 1e300");
    expectSaneSvg({{-max, 0}, {-max, tiny}, {std::nextafter(-max, 0.0), 0}},
                  "one ulp wide at -DBL_MAX");
}

// Ordinary pictures keep their coordinates as written (no scaling below 2^500).
TEST(Svg, OrdinaryCoordinatesUnscaled) {
    Polygon p;
    p.addRing({{0, 0}, {1024, 0}, {0, 3.25}}, true);
    std::ostringstream os;
    writeSvg(os, p, {});
    EXPECT_NE(os.str().find("M0 0 L1024 0 L0 -3.25 "), std::string::npos) << os.str();
    EXPECT_NE(os.str().find("width=\"800\""), std::string::npos);
}
