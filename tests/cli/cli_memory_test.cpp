// `flood triangulate` end to end in bounded memory: its peak resident size, less that of a
// run on a tiny polygon, per vertex (measured by GNU time as the kernel reports it; not
// timed). Before the streaming reader and writer and the edge lists of the checker it was
// 227 bytes a vertex at this size, the checker's hash tables of edges the peak; then 111. The
// flood step is the peak now: circle-holes 79, circle-smooth 109 (143 before the machine's
// 16-byte nodes and its scratch given back, docs/BENCHMARKS.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "flood/tools/generate.h"
#include "flood/tools/shrink.h"
#include "test_support.h"

namespace {

using flood::testing::runShell;

constexpr double kBytesPerVertex = 120;

// Peak resident kilobytes of `flood ARGS`, or -1 when it failed.
long peakKb(const std::string& args) {
    auto r = runShell("/usr/bin/time -f 'peak %M' " + std::string(FLOOD_CLI) + " " + args +
                      " 2>&1 >/dev/null");
    size_t at = r.out.rfind("peak ");
    if (r.code != 0 || at == std::string::npos) return -1;
    return std::stol(r.out.substr(at + 5));
}

TEST(CliMemory, TriangulatePeakPerVertex) {
    if (!std::filesystem::exists("/usr/bin/time")) GTEST_SKIP() << "no GNU time (Debian: time)";
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer's shadow memory and quarantine make peak sizes meaningless; "
                    "the plain build (scripts/test.sh) holds this bound";
#endif
    auto dir = flood::testing::scratch("cli-memory");
    const std::string tiny = (dir / "tiny.json").string(), out = (dir / "out.json").string();
    ASSERT_EQ(runShell(std::string(FLOOD_CLI) + " generate circle-smooth 8 -o " + tiny).code, 0);
    const long base = peakKb("triangulate " + tiny + " -o " + out);
    ASSERT_GT(base, 0);
    // circle-smooth: the most sags of the two (a sixth of its vertices), so the largest machine.
    // islands: many parts, so the checker's rule 8 sweep runs, and its arrays were the peak
    // (172 bytes a vertex here before its edges and ends indexed the points instead of copying
    // them; 77 now).
    // staircase: a sag every other vertex, so the sag index is the largest here (137.5 bytes a
    // vertex before its leaves held ranks rather than points and the sorted keys were given
    // back; 115.9 now).
    // circle-jagged, grid-holes, t-junctions: the spill walks' one-node stretches, kept before
    // (131.7, 122.6, 129.7 bytes a vertex; 109, 98, 112 once dropped and the sag index read
    // the points through the sags' vertices).
    // comb: the bank sweep's edges across the line, 48-byte slots that held both ends' points,
    // were the peak (119.1 bytes a vertex; 91.0 with 16-byte slots reading the points).
    // steiner: its peak is the run's end, the sag search held to the last sag; the bank lists
    // over every edge (8 bytes an edge) and the initial links (4) were most of it (117.9 bytes
    // a vertex; 107.8 with lists for the listed edges alone and a byte a link).
    for (const char* family : {"circle-holes", "circle-smooth", "islands", "staircase",
                               "circle-jagged", "grid-holes", "t-junctions", "comb", "steiner"}) {
        SCOPED_TRACE(family);
        const std::string in = (dir / "in.json").string();
        size_t n = 0;
        {
            flood::Polygon p = flood::generate(family, 1, 400000);
            n = p.vertices.size();
            std::ofstream file(in);
            flood::writePolygonJson(file, p);
        }
        const long peak = peakKb("triangulate " + in + " -o " + out);
        ASSERT_GT(peak, 0);
        EXPECT_LE(double(peak - base) * 1024 / double(n), kBytesPerVertex)
            << "peak " << peak << " kB, " << base << " kB on a tiny polygon";
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
