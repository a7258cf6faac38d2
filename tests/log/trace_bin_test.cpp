// The binary trace (core/log/trace_bin.cpp, `flood trace --format bin`): the same Trace as the
// JSON Lines form on every family and direction, at most 40 bytes a event, and every damaged
// file a Malformed diagnostic naming it — never a crash or a trace that reads wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "flood/io/io.h"
#include "flood/log/replay.h"
#include "flood/log/trace_io.h"
#include "flood/tools/generate.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

std::string binaryOf(const Trace& t) {
    std::ostringstream out;
    writeBinaryTrace(out, t);
    return out.str();
}

void expectSameTrace(const Trace& back, const Trace& t) {
    ASSERT_EQ(back.events.size(), t.events.size());
    for (size_t i = 0; i < t.events.size(); ++i)  // every field (FLOOD_EVENT_FIELDS)
        ASSERT_TRUE(back.events[i] == t.events[i]) << "event " << i << " changed on the way";
    EXPECT_EQ(back.triangles, t.triangles);
    EXPECT_EQ(back.polygon.vertices.size(), t.polygon.vertices.size());
    for (size_t v = 0; v < t.polygon.vertices.size(); ++v)  // bit for bit, NaN included
        ASSERT_EQ(0, std::memcmp(&back.polygon.vertices[v], &t.polygon.vertices[v], 16)) << v;
    ASSERT_EQ(back.polygon.rings.size(), t.polygon.rings.size());
    for (size_t r = 0; r < t.polygon.rings.size(); ++r) {
        EXPECT_EQ(back.polygon.rings[r].first, t.polygon.rings[r].first);
        EXPECT_EQ(back.polygon.rings[r].count, t.polygon.rings[r].count);
    }
    ASSERT_EQ(back.polygon.parts.size(), t.polygon.parts.size());
    for (size_t k = 0; k < t.polygon.parts.size(); ++k)
        EXPECT_EQ(back.polygon.parts[k].ringCount, t.polygon.parts[k].ringCount);
    ASSERT_EQ(back.polygon.splits.size(), t.polygon.splits.size());
    for (size_t k = 0; k < t.polygon.splits.size(); ++k) {
        EXPECT_EQ(back.polygon.splits[k].edge, t.polygon.splits[k].edge);
        EXPECT_EQ(back.polygon.splits[k].vertex, t.polygon.splits[k].vertex);
    }
    EXPECT_TRUE(back.up == t.up);
    EXPECT_EQ(back.diagnostic.status, t.diagnostic.status);
    EXPECT_EQ(back.diagnostic.message, t.diagnostic.message);
}

TEST(TraceBinary, SameTraceOnEveryFamilyAndDirection) {
    for (const std::string& family : familyNames())
        for (Up up : {Up::PlusY, Up{-1, 0}, Up{0.5, -2}}) {
            SCOPED_TRACE(family + " up " + std::to_string(up.x) + "," + std::to_string(up.y));
            Polygon p = generate(family, 5, 800);
            ASSERT_TRUE(validate(p, family).ok());  // records the T-junctions (splits)
            Options o;
            o.up = up;
            Trace t = record(p, o);
            expectSameTrace(writtenAndRead(t, true), t);
        }
}

TEST(TraceBinary, ForbiddenRunsAndSamplesComeBack) {
    std::vector<std::string> files = filesIn(sourcePath("polygons"), ".json");
    for (const std::string& f : filesIn(sourcePath("polygons/invalid"), ".json"))
        if (f.find("forbidden-") != std::string::npos) files.push_back(f);
    ASSERT_GT(files.size(), 10u);
    size_t forbidden = 0;
    for (const std::string& f : files) {
        SCOPED_TRACE(f);
        Trace t = record(readOrFail(f));  // floods without validating: forbidden runs too
        forbidden += t.diagnostic.status == Status::Forbidden;
        expectSameTrace(writtenAndRead(t, true), t);
    }
    EXPECT_GT(forbidden, 0u);
}

// Non-finite coordinates (an unvalidated run may hold them) come back bit for bit.
TEST(TraceBinary, NonFiniteCoordinatesComeBack) {
    Polygon p;
    p.addRing({{0, 0}, {1, 0}, {std::nan(""), 1}, {-HUGE_VAL, 2}}, true);
    Trace t = record(p);
    expectSameTrace(writtenAndRead(t, true), t);
}

// The bound: at most 40 bytes a event for the whole file, polygon and triangles
// included, on every family at 20,000 vertices (the JSON Lines form spends ~370).
TEST(TraceBinary, AtMostFortyBytesAnEvent) {
    for (const std::string& family : familyNames()) {
        SCOPED_TRACE(family);
        Trace t = record(generate(family, 1, 20000));
        ASSERT_GT(t.events.size(), 1000u);
        const double perEvent = double(binaryOf(t).size()) / double(t.events.size());
        EXPECT_LE(perEvent, 40.0);
        RecordProperty(family, std::to_string(perEvent));
    }
}

// Every prefix of a trace is refused with a message naming the file; the whole reads.
TEST(TraceBinary, EveryTruncationIsMalformed) {
    Trace t = record(readOrFail(sourcePath("polygons/paper-figure-7.json")));
    const std::string bin = binaryOf(t);
    Trace back;
    ASSERT_TRUE(parseTrace(bin, "fig7.bin", back).ok());
    for (size_t n = 0; n < bin.size(); ++n) {
        Diagnostic d = parseTrace(std::string_view(bin).substr(0, n), "fig7.bin", back);
        ASSERT_EQ(d.status, Status::Malformed) << "prefix of " << n << " bytes";
        ASSERT_EQ(d.message.rfind("fig7.bin", 0), 0u) << d.message;
        ASSERT_TRUE(back.events.empty());
    }
    Diagnostic extra = parseTrace(bin + "x", "fig7.bin", back);
    EXPECT_EQ(extra.status, Status::Malformed);
    EXPECT_NE(extra.message.find("after the end"), std::string::npos) << extra.message;
}

// Every byte changed, three ways: the result reads (and then replays to the end) or is
// refused; a read trace holds only events the replay and the invariant scan can index.
TEST(TraceBinary, EveryDamagedByteIsReadOrRefused) {
    Trace t = record(readOrFail(sourcePath("polygons/hole.json")));
    const std::string bin = binaryOf(t);
    size_t refused = 0, read = 0;
    for (size_t i = 8; i < bin.size(); ++i)
        for (int change : {0x01, 0x80, 0xff}) {
            std::string bad = bin;
            bad[i] = char(uint8_t(bad[i]) ^ change);
            Trace back;
            Diagnostic d = parseTrace(bad, "hole.bin", back);
            if (!d.ok()) {
                ASSERT_EQ(d.status, Status::Malformed);
                ++refused;
                continue;
            }
            ++read;
            for (const Event& e : back.events)
                ASSERT_EQ(eventProblem(e, back.polygon.vertices.size(), back.polygon.parts.size()),
                          nullptr);
            Replay replay(back, 4);
            replay.seek(replay.size());
        }
    EXPECT_GT(refused, 0u);
    EXPECT_GT(read, 0u);  // a changed coordinate is still a trace
}

// A count that claims more than the file holds is refused before anything is allocated.
TEST(TraceBinary, CountsLargerThanTheFileAreRefused) {
    std::string bin = "FLOODTRB";
    bin += char(1);                                             // version
    bin += std::string(8, '\0');                                // up.x = 0 ...
    bin.replace(9, 8, std::string("\0\0\0\0\0\0\xf0\x3f", 8));  // ... 1.0: valid up (1, y)
    bin += std::string(8, '\0');                                // up.y = 0
    bin += "\xff\xff\xff\xff\x0f";                              // 2^32 - 1 vertices
    Trace back;
    Diagnostic d = parseTrace(bin, "lie.bin", back);
    EXPECT_EQ(d.status, Status::Malformed);
    EXPECT_NE(d.message.find("cannot fit"), std::string::npos) << d.message;
}

// readTraceFile() takes the binary form from disk; any other binary file is named as such.
TEST(TraceBinary, ReadFromFileAndOtherBinaryRefused) {
    Trace t = record(readOrFail(sourcePath("polygons/hole.json")));
    auto path = scratch("trace-bin-read") / "hole.bin";
    {
        std::ofstream f(path, std::ios::binary);
        f << binaryOf(t);
    }
    Trace back;
    Diagnostic d = readTraceFile(path.string(), back);
    ASSERT_TRUE(d.ok()) << d.message;
    expectSameTrace(back, t);

    auto png = path.parent_path() / "picture.png";
    {
        std::ofstream f(png, std::ios::binary);
        f << std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16);
    }
    d = readTraceFile(png.string(), back);
    EXPECT_EQ(d.status, Status::Malformed);
    EXPECT_NE(d.message.find("binary data"), std::string::npos) << d.message;
}

// `flood trace --format bin` (or -o NAME.bin) writes the binary form of the run; jsonl the text.
TEST(TraceBinary, CliWritesEitherForm) {
    const std::string in = sourcePath("polygons/paper-figure-7.json");
    const auto dir = scratch("trace-bin-cli");
    const auto bin = dir / "fig7.bin", forced = dir / "fig7-forced.trace",
               text = dir / "fig7-text.bin";
    ASSERT_EQ(runCli("trace " + in + " -o " + bin.string()).code, 0);
    ASSERT_EQ(runCli("trace " + in + " --format bin -o " + forced.string()).code, 0);
    ASSERT_EQ(runCli("trace " + in + " --format jsonl -o " + text.string()).code, 0);
    Trace expected = record(readOrFail(in));
    for (const auto& path : {bin, forced}) {
        EXPECT_EQ(slurp(path), binaryOf(expected)) << path;
        Trace back;
        ASSERT_TRUE(readTraceFile(path.string(), back).ok());
    }
    EXPECT_EQ(slurp(text).rfind("{\"format\":\"flood-trace\"", 0), 0u);
    RunResult bad = runCli("trace " + in + " --format xml -o " + (dir / "x").string());
    EXPECT_EQ(bad.code, 2);
}

}  // namespace
