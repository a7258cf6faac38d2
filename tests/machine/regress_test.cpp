// Regression inputs found by fuzzing and random search (polygons/regress/). Each file is run
// in a forked child with a time limit (flood/tools/shrink.h classify), with validation skipped, so a
// crash or a hang fails the test instead of killing the suite.
//   - A file must never crash or hang: the machine ends in a Forbidden diagnostic or an exact
//     triangulation; if validate() accepts it, an exact triangulation.
//   - `*.fuzz` files are raw fuzz_flood inputs (byte encoding of fuzz/fuzz_poly.h) for polygons
//     no file format can carry (e.g. zero-length edges, which readers drop).
//   - `open-*` files are known open bugs of the flood machine (core/machine/flood.cpp), with the
//     failure class in the name (open-crash-*, open-hang-*, or open-empty-ring: crash). The
//     test asserts they still fail that way and says so; when the machine is fixed this
//     test fails: rename the file without `open-` and it joins the must-not-fail set.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "../../fuzz/fuzz_poly.h"
#include "flood/tools/shrink.h"
#include "test_support.h"

using namespace flood;
using namespace flood::testing;

namespace {

bool startsWith(const std::string& s, const std::string& p) {
    return s.compare(0, p.size(), p) == 0;
}

}  // namespace

TEST(Regress, NoCrashNoHangOnRegressionInputs) {
    auto files = filesIn(sourcePath("polygons/regress"), ".json");
    ASSERT_FALSE(files.empty()) << "polygons/regress/ holds the regression inputs";
    for (const std::string& f : filesIn(sourcePath("polygons/regress"), ".fuzz"))
        files.push_back(f);
    ShrinkOptions o;
    o.timeoutSeconds = 10;  // generous for sanitizer builds; a real hang never ends
    for (const std::string& path : files) {
        std::string name = std::filesystem::path(path).filename().string();
        ReadResult rr;
        if (path.size() > 5 && path.compare(path.size() - 5, 5, ".fuzz") == 0) {
            std::ifstream in(path, std::ios::binary);
            std::string bytes((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
            rr.polygon =
                fuzzpoly::decode(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size())
                    .polygon;
        } else {
            rr = readPolygonFile(path);
        }
        ASSERT_TRUE(rr.diagnostic.ok()) << name << ": " << rr.diagnostic.message;
        bool valid = validate(rr.polygon, name).ok();
        Failure f = classify(rr.polygon, o);
        if (startsWith(name, "open-")) {
            Failure::Kind expected =
                startsWith(name, "open-hang") ? Failure::Kind::Hang : Failure::Kind::Crash;
            EXPECT_EQ(failureKindName(f.kind), std::string(failureKindName(expected)))
                << name
                << " is a known open bug of core/machine/flood.cpp; if it is fixed, drop the "
                << "'open-' prefix from its name";
            std::cout << "[ KNOWN BUG ] " << name << ": still a " << failureKindName(f.kind)
                      << " with validation skipped (validate(): " << (valid ? "valid" : "invalid")
                      << ")\n";
            continue;
        }
        EXPECT_NE(f.kind, Failure::Kind::Crash) << name << ": " << f.message;
        EXPECT_NE(f.kind, Failure::Kind::Hang) << name << ": " << f.message;
        if (valid) {
            EXPECT_EQ(f.kind, Failure::Kind::None) << name << ": " << f.message;
        }
    }
}

// Empty rings reach the machine only with validation skipped; validation must name them.
TEST(Regress, ValidationRejectsEmptyAndShortRings) {
    ReadResult rr = readPolygonFile(sourcePath("polygons/regress/empty-ring-no-validate.json"));
    ASSERT_TRUE(rr.diagnostic.ok());
    Diagnostic d = validate(rr.polygon, "e");
    EXPECT_EQ(d.status, Status::Invalid);
    EXPECT_NE(d.message.find("ring 1: ring is empty"), std::string::npos) << d.message;
    // Unvalidated, the machine refuses it too (it used to divide by zero).
    FloodResult r = triangulate(rr.polygon);
    EXPECT_EQ(r.diagnostic.status, Status::Forbidden);
    EXPECT_EQ(r.failure.reason, Forbidden::ShortLoop);
}

// JSON nested far deeper than the limit must be refused quickly, without recursion.
TEST(Regress, HugeNestingIsRefusedWithoutStackExhaustion) {
    for (size_t depth : {65, 1000, 1000000}) {
        std::string text(depth, '[');
        text += std::string(depth, ']');
        ReadResult r = parsePolygon(text, "deep");
        EXPECT_EQ(r.diagnostic.status, Status::Malformed) << depth;
        EXPECT_NE(r.diagnostic.message.find("nested deeper than 64"), std::string::npos)
            << r.diagnostic.message;
    }
    // Exactly at the limit parses (and then fails on structure, not depth).
    std::string ok = std::string(64, '[') + std::string(64, ']');
    ReadResult r = parsePolygon(ok, "deep");
    EXPECT_EQ(r.diagnostic.message.find("nested deeper"), std::string::npos)
        << r.diagnostic.message;
}
