// The one judge (flood/check/verdict.h): its verdicts and their exit statuses, each step's
// failure, and `flood check` agreeing with it on every polygon of polygons/invalid/.
#include "flood/check/verdict.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "flood/check/checker.h"
#include "flood/io/io.h"
#include "test_support.h"

using namespace flood;
using flood::testing::runCli;
using flood::testing::sourcePath;

namespace {
ReadResult parsed(const std::string& text) { return parsePolygon(text, "p"); }
}  // namespace

TEST(Verdict, WordsAndExitStatusesAreThoseOfErrorsMd) {
    const std::vector<std::pair<Verdict, std::pair<std::string, int>>> want = {
        {Verdict::Ok, {"ok", 0}},           {Verdict::Malformed, {"malformed", 3}},
        {Verdict::Invalid, {"invalid", 4}}, {Verdict::Forbidden, {"forbidden", 5}},
        {Verdict::Checker, {"checker", 6}}, {Verdict::Internal, {"internal", 6}}};
    ASSERT_EQ(want.size(), size_t(Verdict::Count));
    for (const auto& [v, w] : want) {
        EXPECT_EQ(verdictName(v), w.first);
        EXPECT_EQ(int(verdictStatus(v)), w.second) << w.first;
        EXPECT_GT(std::string(verdictMeaning(v)).size(), 10u) << w.first;
    }
}

TEST(Verdict, EachStepsFailureIsTheVerdict) {
    ReadResult square = parsed("[[[0,0],[2,0],[2,2],[0,2]]]");
    Judgement ok = judge(square, "square");
    EXPECT_EQ(ok.verdict, Verdict::Ok) << ok.diagnostic.message;
    EXPECT_EQ(ok.triangles.size(), 2u);
    EXPECT_TRUE(ok.check.ok);

    ReadResult broken = parsed("[[[0,0],[2,0]");
    Judgement malformed = judge(broken, "broken");
    EXPECT_EQ(malformed.verdict, Verdict::Malformed);
    EXPECT_EQ(malformed.diagnostic.message, broken.diagnostic.message);

    ReadResult failedReader;
    failedReader.diagnostic = {Status::Internal, "p: exception: boom"};
    EXPECT_EQ(judge(failedReader, "p").verdict, Verdict::Internal);

    ReadResult bowtie = parsed("[[[0,0],[4,2],[4,0],[0,3]]]");
    Judgement invalid = judge(bowtie, "bowtie");
    EXPECT_EQ(invalid.verdict, Verdict::Invalid);
    EXPECT_EQ(invalid.diagnostic.message.rfind("bowtie: ring 0", 0), 0u)
        << invalid.diagnostic.message;
    EXPECT_TRUE(invalid.triangles.empty());
}

TEST(Verdict, WithoutValidationTheMachineOrTheCheckerCatchesInvalidInput) {
    size_t forbidden = 0;
    for (const std::string& f : flood::polygonFiles(sourcePath("polygons/invalid"))) {
        if (f.find("forbidden-") == std::string::npos) continue;
        ReadResult r = readPolygonFile(f);
        ASSERT_TRUE(r.diagnostic.ok()) << f;
        Judgement j = judge(r, f, {false, true, {}});
        ASSERT_EQ(j.verdict, Verdict::Forbidden) << f << ": " << j.diagnostic.message;
        EXPECT_EQ(j.diagnostic.status, Status::Forbidden) << f;
        EXPECT_EQ(j.failure.action, Action::Forbidden) << f;
        ++forbidden;
    }
    EXPECT_GE(forbidden, 8u);

    ReadResult rejected = readPolygonFile(sourcePath("polygons/invalid/checker-rejects.json"));
    Judgement j = judge(rejected, "cr", {false, true, {}});
    ASSERT_EQ(j.verdict, Verdict::Checker) << j.diagnostic.message;
    EXPECT_EQ(j.diagnostic.status, Status::Internal);
    EXPECT_EQ(j.diagnostic.message,
              "cr: the exact checker rejects the triangulation: " + j.check.reason);
    EXPECT_FALSE(j.check.ok);
    // Unchecked, the same run is taken as it is.
    ReadResult again = readPolygonFile(sourcePath("polygons/invalid/checker-rejects.json"));
    EXPECT_EQ(judge(again, "cr", {false, false, {}}).verdict, Verdict::Ok);
}

TEST(Verdict, JudgeRunChecksTheTrianglesItIsGiven) {
    ReadResult square = parsed("[[[0,0],[2,0],[2,2],[0,2]]]");
    ASSERT_TRUE(validate(square.polygon, "square").ok());
    const std::vector<Triangle> half = {{0, 1, 2}};  // half the square: not a triangulation
    Judgement j = judgeRun(square.polygon, half, Diagnostic{}, "square");
    EXPECT_EQ(j.verdict, Verdict::Checker);
    EXPECT_EQ(judgeRun(square.polygon, half, Diagnostic{}, "square", false).verdict, Verdict::Ok);
    Judgement stopped =
        judgeRun(square.polygon, half, Diagnostic{Status::Forbidden, "stopped"}, "square");
    EXPECT_EQ(stopped.verdict, Verdict::Forbidden);
    EXPECT_EQ(stopped.diagnostic.message, "stopped");
}

// The CLI's `flood check` is one front end of the judge: its verdict and code for each file
// are the judge's, with validation and without.
TEST(Verdict, FloodCheckSaysWhatTheJudgeSays) {
    size_t compared = 0;
    for (const std::string& f : flood::polygonFiles(sourcePath("polygons/invalid")))
        for (bool validated : {true, false}) {
            ReadResult r = readPolygonFile(f);
            const Judgement j = judge(r, f, {validated, true, {}});
            auto run = runCli("check --json " + std::string(validated ? "" : "--no-validate ") +
                              "'" + f + "' 2>/dev/null");
            nlohmann::json doc = nlohmann::json::parse(run.out, nullptr, false);
            ASSERT_FALSE(doc.is_discarded()) << f << ": " << run.out;
            // A FeatureCollection is judged feature by feature: its worst row is the file's.
            std::string worst = "ok";
            int code = 0;
            for (const auto& row : doc["features"])
                if (row["code"].get<int>() > code)
                    code = row["code"].get<int>(), worst = row["verdict"].get<std::string>();
            if (doc["features"].size() != 1) continue;
            EXPECT_EQ(worst, verdictName(j.verdict)) << f << (validated ? "" : " --no-validate");
            EXPECT_EQ(run.code, int(verdictStatus(j.verdict))) << f;
            ++compared;
        }
    EXPECT_GE(compared, 60u);
}

TEST(Verdict, AMachineThatFailedOtherwiseThanForbiddenIsInternal) {
    // judgeRun is handed the machine's diagnostic: a forbidden state is the paper's verdict,
    // anything else (an exception while flooding) is Flood failing itself.
    ReadResult square = parsed("[[[0,0],[2,0],[2,2],[0,2]]]");
    Judgement forbidden = judgeRun(square.polygon, {}, {Status::Forbidden, "stopped"}, "square");
    EXPECT_EQ(forbidden.verdict, Verdict::Forbidden);
    Judgement internal =
        judgeRun(square.polygon, {}, {Status::Internal, "square: bad_alloc"}, "square");
    EXPECT_EQ(internal.verdict, Verdict::Internal);
    EXPECT_EQ(internal.diagnostic.message, "square: bad_alloc");
    EXPECT_EQ(int(verdictStatus(internal.verdict)), 6);
}
