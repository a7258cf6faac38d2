// The page's shrinker (viewer/shrink_worker.h): what the Shrink panel makes of a worker's report.
// The worker runs the flood CLI's `flood shrink`; here the native CLI stands in for it, so the
// reading is checked against the very output it reads in the page, and against the shrink the
// desktop's ShrinkJob makes in process.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "jobs.h"
#include "shrink_worker.h"
#include "test_support.h"

using namespace flood;
using namespace flood::view;
using flood::testing::runShell;
using flood::testing::scratch;
using flood::testing::slurp;
using flood::testing::sourcePath;

namespace {

// `flood shrink IN -o OUT` as the worker runs it: its stderr is the report's log.
WorkerReport cliShrink(const std::string& in, const std::filesystem::path& dir) {
    const std::filesystem::path out = dir / "repro.geojson", log = dir / "stderr.txt";
    WorkerReport r;
    r.exitCode = runShell(std::string(FLOOD_CLI) + " shrink " + in + " -o " + out.string() + " 2>" +
                          log.string())
                     .code;
    r.end = WorkerReport::End::Finished;
    if (std::filesystem::exists(out)) r.repro = slurp(out);
    r.log = slurp(log);
    return r;
}

}  // namespace

TEST(ShrinkWorker, TheCliReproIsTheShrinkTheDesktopMakes) {
    const std::string in = sourcePath("polygons/tutorial/crossing-face.json");
    const WorkerReport report = cliShrink(in, scratch("shrink-worker-repro"));
    ASSERT_EQ(report.exitCode, 0) << report.log;
    const ShrinkResult page = shrinkResultFromWorker(report, "the repro");
    EXPECT_TRUE(workerStopNote(report).empty());

    ShrinkJob job;  // the desktop's: in process, the same polygon as read
    job.start(readPolygonFile(in).polygon, {});
    job.wait();
    const ShrinkResult& desk = job.result();
    ASSERT_NE(desk.failure.kind, Failure::Kind::None);
    EXPECT_TRUE(job.stoppedNote().empty());
    EXPECT_EQ(job.vertices(), desk.polygon.vertices.size()) << "the progress's smallest size";

    EXPECT_EQ(page.failure.kind, desk.failure.kind);
    EXPECT_EQ(page.failure.reason, desk.failure.reason);
    EXPECT_EQ(page.failure.message, desk.failure.message);
    EXPECT_EQ(page.tries, desk.tries) << report.log;
    EXPECT_EQ(page.inputValid, desk.inputValid);
    EXPECT_EQ(page.origin, desk.origin);
    ASSERT_EQ(page.polygon.vertices.size(), desk.polygon.vertices.size());
    for (size_t i = 0; i < page.polygon.vertices.size(); ++i)
        EXPECT_TRUE(page.polygon.vertices[i] == desk.polygon.vertices[i]) << "vertex " << i;
    EXPECT_TRUE(page.reproduces);
}

TEST(ShrinkWorker, TheCliSummaryGivesTheTriesAndWhetherTheInputWasValid) {
    WorkerReport report = cliShrink(sourcePath("polygons/tutorial/crossing-face.json"),
                                    scratch("shrink-worker-summary"));
    ASSERT_EQ(report.exitCode, 0) << report.log;
    // Progress lines and a message line around the summary, as the CLI writes them.
    const std::string progress = "shrink: 3 tries, 40 vertices\nshrink: 9 tries, 12 vertices\n";
    report.log = progress +
                 "shrink: forbidden transition SpillNoBottom (input valid, kept valid): 40 "
                 "vertices in 1 rings -> 4 vertices in 1 rings (17 runs)\n"
                 "shrink: spilling over a top found no bottom (not a summary: 3 runs)\n";
    ShrinkResult r = shrinkResultFromWorker(report, "the repro");
    EXPECT_EQ(r.tries, 17u);
    EXPECT_TRUE(r.inputValid);
    report.log = progress +
                 "shrink: forbidden transition SpillNoBottom: 992 vertices in 1 rings -> 4 "
                 "vertices in 1 rings (85 runs)";  // the last line, no newline
    r = shrinkResultFromWorker(report, "the repro");
    EXPECT_EQ(r.tries, 85u);
    EXPECT_FALSE(r.inputValid);
    report.log = progress;  // no summary: the tries are not known
    r = shrinkResultFromWorker(report, "the repro");
    EXPECT_EQ(r.tries, 0u);
    EXPECT_FALSE(r.inputValid);
    EXPECT_NE(r.failure.kind, Failure::Kind::None) << "the repro itself still reads";
}

TEST(ShrinkWorker, NothingToShrinkSaysTheCliError) {
    const WorkerReport report =
        cliShrink(sourcePath("polygons/paper-figure-7.json"), scratch("shrink-worker-none"));
    EXPECT_EQ(report.exitCode, 2);
    const ShrinkResult r = shrinkResultFromWorker(report, "the repro");
    EXPECT_EQ(r.failure.kind, Failure::Kind::None);
    EXPECT_EQ(r.failure.message.rfind("nothing to shrink: ", 0), 0u) << r.failure.message;
    EXPECT_NE(r.failure.message.find("paper-figure-7.json"), std::string::npos);
}

TEST(ShrinkWorker, ARepoWithoutItsFailureIsNoResult) {
    WorkerReport report;
    report.end = WorkerReport::End::Finished;
    report.exitCode = 0;
    report.repro = slurp(sourcePath("polygons/tutorial/crossing-face.json"));  // no properties
    const ShrinkResult r = shrinkResultFromWorker(report, "the repro");
    EXPECT_EQ(r.failure.kind, Failure::Kind::None);
    EXPECT_EQ(r.failure.message, "the repro does not say how it fails");
}

TEST(ShrinkWorker, ACrashOrACancelSaysWhereTheShrinkWas) {
    WorkerReport report;
    report.end = WorkerReport::End::Crashed;
    report.tries = 31, report.vertices = 120;
    report.error = "Uncaught RuntimeError: unreachable";
    const std::string crash = workerStopNote(report);
    EXPECT_EQ(crash.rfind("the shrink stopped with a crash after 31 tries, at 120 vertices "
                          "(Uncaught RuntimeError: unreachable)",
                          0),
              0u)
        << crash;
    report.end = WorkerReport::End::Cancelled;
    report.tries = 0;
    EXPECT_EQ(workerStopNote(report).rfind("shrink cancelled before its first progress report", 0),
              0u);
    report.end = WorkerReport::End::Running;
    EXPECT_EQ(workerStopNote(report), "");
}

TEST(ShrinkWorker, NotOnTheDesktop) {
    EXPECT_FALSE(ShrinkWorker::available());
    ShrinkWorker w;
    w.start(readPolygonFile(sourcePath("polygons/invalid/self-intersection.json")).polygon, {});
    EXPECT_FALSE(w.started());
}
