// ReadProgress (flood/io/io.h): a long read tells how far it has come while it reads — the
// bytes, the Features the parser meets, the features made polygons — not only at the end, as
// `flood check`'s progress line needs (it sat at "0/0 features" through a 7 s read).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "flood/io/io.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

struct Snapshot {
    uint64_t total, bytes;
    size_t parsed, read;
};

// A FeatureCollection of `n` small squares, some 40 bytes of coordinates each.
std::filesystem::path squares(const std::filesystem::path& dir, size_t n) {
    std::filesystem::path p = dir / "squares.geojson";
    std::ofstream out(p);
    out << "{\"type\": \"FeatureCollection\", \"features\": [\n";
    for (size_t i = 0; i < n; ++i) {
        const size_t x = 3 * (i % 1000), y = 3 * (i / 1000);
        out << (i ? ",\n" : "") << "{\"type\": \"Feature\", \"properties\": {\"n\": " << i
            << "}, \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[" << x << ", " << y
            << "], [" << x + 2 << ", " << y << "], [" << x + 2 << ", " << y + 2 << "], [" << x
            << ", " << y + 2 << "], [" << x << ", " << y << "]]]}}";
    }
    out << "\n]}\n";
    return p;
}

}  // namespace

TEST(ReadProgress, TellsTheBytesAndFeaturesAsTheReadGoes) {
    const size_t n = 6000;
    std::filesystem::path dir = scratch("read-progress");
    const std::filesystem::path file = squares(dir, n);
    const uint64_t size = std::filesystem::file_size(file);
    ASSERT_GT(size, uint64_t(8) << 16) << "more than a few read blocks";

    ReadProgress progress;
    std::vector<Snapshot> seen;
    progress.changed = [&] {
        seen.push_back({progress.bytesTotal, progress.bytesRead, progress.featuresParsed,
                        progress.featuresRead});
    };
    DatasetRead d = readFeaturesFile(file.string(), kDefaultMaxInputBytes, false, &progress);
    ASSERT_EQ(d.features.size(), n);

    // The end: every byte, every feature parsed and read.
    EXPECT_EQ(progress.bytesTotal, size);
    EXPECT_EQ(progress.bytesRead, size);
    EXPECT_EQ(progress.featuresParsed, n);
    EXPECT_EQ(progress.featuresRead, n);

    // Along the way, counted by the calls, not by a clock: the total is known before the first
    // block is read; the bytes arrive in several steps, then each feature is parsed, then read.
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.front().total, size);
    EXPECT_EQ(seen.front().bytes, 0u);
    size_t byteSteps = 0, parsedSteps = 0, readSteps = 0;
    for (size_t k = 1; k < seen.size(); ++k) {
        const Snapshot &a = seen[k - 1], &b = seen[k];
        EXPECT_GE(b.bytes, a.bytes);
        EXPECT_GE(b.parsed, a.parsed);
        EXPECT_GE(b.read, a.read);
        byteSteps += b.bytes > a.bytes && b.bytes < size;
        parsedSteps += b.parsed > a.parsed && b.parsed < n;
        readSteps += b.read > a.read && b.read < n;
        if (b.parsed > 0) {
            EXPECT_EQ(b.bytes, size) << "parsing starts once the text is read";
        }
        if (b.read > 0) {
            EXPECT_EQ(b.parsed, n) << "polygons are made once the parse is done";
        }
    }
    EXPECT_GE(byteSteps, 7u);
    EXPECT_EQ(parsedSteps, n - 1);
    EXPECT_EQ(readSteps, n - 1);

    // Two files into one record add up (flood check reads files on several threads).
    DatasetRead again = readFeaturesFile(file.string(), kDefaultMaxInputBytes, false, &progress);
    EXPECT_EQ(progress.bytesRead, 2 * size);
    EXPECT_EQ(progress.featuresRead, 2 * n);
    std::filesystem::remove_all(dir);
}

TEST(ReadProgress, NoRecordNoCalls) {
    // Without a record the reader is as before: the same features.
    std::filesystem::path dir = scratch("read-progress-none");
    const std::filesystem::path file = squares(dir, 10);
    EXPECT_EQ(readFeaturesFile(file.string(), kDefaultMaxInputBytes, false).features.size(), 10u);
    std::filesystem::remove_all(dir);
}
