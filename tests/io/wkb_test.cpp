// The WKB reader (core/io_wkb.cpp): both byte orders, ISO z/m codes, EWKB flags and SRID,
// MultiPolygon parts, and truncated or non-polygon input refused as malformed.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "flood/io/io.h"

using namespace flood;

namespace {

// Writes WKB by hand, in either byte order.
struct Wkb {
    bool little = true;
    std::string bytes;
    void u8(uint8_t b) { bytes.push_back(char(b)); }
    void u32(uint32_t v) {
        for (int k = 0; k < 4; ++k) u8(uint8_t(v >> (8 * (little ? k : 3 - k))));
    }
    void f64(double d) {
        uint64_t u;
        std::memcpy(&u, &d, 8);
        for (int k = 0; k < 8; ++k) u8(uint8_t(u >> (8 * (little ? k : 7 - k))));
    }
    void header(uint32_t code) {
        u8(little ? 1 : 0);
        u32(code);
    }
    // A polygon body: rings of (x, y) closed, `extra` more coordinates a point (z, m).
    void rings(const std::vector<std::vector<std::pair<double, double>>>& rs, int extra = 0) {
        u32(uint32_t(rs.size()));
        for (const auto& r : rs) {
            u32(uint32_t(r.size()));
            for (auto [x, y] : r) {
                f64(x), f64(y);
                for (int k = 0; k < extra; ++k) f64(99);
            }
        }
    }
};

const std::vector<std::vector<std::pair<double, double>>> kSquareWithHole = {
    {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}}, {{1, 1}, {1, 2}, {2, 2}, {2, 1}, {1, 1}}};

}  // namespace

TEST(Wkb, PolygonInBothByteOrdersAndEveryDimension) {
    for (bool little : {true, false})
        for (auto [code, extra] : std::vector<std::pair<uint32_t, int>>{
                 {3, 0}, {1003, 1}, {2003, 1}, {3003, 2}, {0x80000003u, 1}, {0xC0000003u, 2}}) {
            Wkb w{little, {}};
            w.header(code);
            w.rings(kSquareWithHole, extra);
            ASSERT_TRUE(wkbLike(w.bytes));
            ReadResult r = parseWkb(w.bytes, "w");
            ASSERT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
            ASSERT_EQ(r.polygon.rings.size(), 2u);
            EXPECT_EQ(r.polygon.vertices.size(), 8u);  // the closing points dropped
            EXPECT_EQ(r.polygon.vertices[2], (Point{4, 4}));
            EXPECT_EQ(r.polygon.parts.size(), 1u);
        }
}

TEST(Wkb, EwkbSridIsSkippedAndMultiPolygonPartsRead) {
    Wkb w;
    w.header(0x20000006u);  // MultiPolygon with an SRID
    w.u32(4326);
    w.u32(2);
    for (int p = 0; p < 2; ++p) {
        Wkb part{p == 0, {}};  // parts may switch byte order
        part.header(3);
        part.rings({{{10.0 * p, 0}, {10.0 * p + 1, 0}, {10.0 * p, 1}, {10.0 * p, 0}}});
        w.bytes += part.bytes;
    }
    ReadResult r = parseWkb(w.bytes, "w");
    ASSERT_TRUE(r.diagnostic.ok()) << r.diagnostic.message;
    EXPECT_EQ(r.polygon.parts.size(), 2u);
    EXPECT_EQ(r.polygon.vertices[3], (Point{10, 0}));
}

TEST(Wkb, TruncatedOrNotAPolygonIsMalformed) {
    Wkb w;
    w.header(3);
    w.rings(kSquareWithHole);
    for (size_t cut : {size_t(3), size_t(9), w.bytes.size() - 1}) {
        ReadResult r = parseWkb(w.bytes.substr(0, cut), "w");
        EXPECT_EQ(r.diagnostic.status, Status::Malformed) << cut;
        EXPECT_NE(r.diagnostic.message.find("w: WKB: truncated"), std::string::npos)
            << r.diagnostic.message;
    }
    ReadResult extra = parseWkb(w.bytes + "x", "w");
    EXPECT_NE(extra.diagnostic.message.find("left over"), std::string::npos);
    Wkb line;
    line.header(2);
    line.u32(0);
    ReadResult l = parseWkb(line.bytes, "w");
    EXPECT_NE(l.diagnostic.message.find("not LineString"), std::string::npos)
        << l.diagnostic.message;
    // A huge ring count in a short blob is refused without allocating it.
    Wkb huge;
    huge.header(3);
    huge.u32(1);
    huge.u32(0xFFFFFFFFu);
    EXPECT_EQ(parseWkb(huge.bytes, "w").diagnostic.status, Status::Malformed);
    // Text never looks like WKB.
    for (const char* text : {"POLYGON ((0 0, 1 0, 0 1))", "{\"type\":\"Polygon\"}", "[[[0,0]]]"})
        EXPECT_FALSE(wkbLike(text)) << text;
}
