// The window's open in the background (viewer/open_job.h, Model::openInBackground): the
// outline adopted before the flood, its flood and preparation cut in steps, progress monotone
// to its total, Cancel at each phase,
// a second open cancelling the first, a failing read's diagnostic, and the run adopted equal
// to the synchronous open's. A Gate held by the open's hook stops it at a phase.
#if __has_include("model.h")
#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <thread>

#include "canvas_geometry.h"
#include "flood/tools/generate.h"
#include "model.h"
#include "test_support.h"

using namespace flood;
using namespace flood::view;
using namespace flood::testing;

namespace {

// Holds the open of `path` as `phase` begins, until released.
struct Gate {
    std::mutex mu;
    std::condition_variable cv;
    std::string path;
    OpenPhase phase = OpenPhase::Done;
    bool reached = false, released = false;
    std::vector<std::pair<std::string, OpenPhase>> entered;  // every phase each open began

    std::function<void(const std::string&, OpenPhase)> hook() {
        return [this](const std::string& p, OpenPhase at) {
            std::unique_lock<std::mutex> lock(mu);
            entered.push_back({p, at});
            if (p != path || at != phase) return;
            reached = true;
            cv.notify_all();
            cv.wait(lock, [&] { return released; });
        };
    }
    void waitReached() {
        std::unique_lock<std::mutex> lock(mu);
        ASSERT_TRUE(cv.wait_for(lock, std::chrono::seconds(60), [&] { return reached; }));
    }
    void release() {
        std::lock_guard<std::mutex> lock(mu);
        released = true;
        cv.notify_all();
    }
    ~Gate() { release(); }  // never leave an open waiting
};

const std::string kComb = sourcePath("polygons/comb.json");

size_t verticesIn(const std::string& path) { return readPolygonFile(path).polygon.vertices.size(); }

}  // namespace

// A file that cannot be read is not flooded: the lane claims nothing of it either.
TEST(OpenJob, AnUnreadableFileClaimsNoInvariant) {
    Model m;
    m.open(std::string(FLOOD_SOURCE_DIR) + "/polygons/datasets/mixed.geojson");  // feature 5
    ASSERT_EQ(m.inputDiagnostic().status, Status::Malformed);
    ASSERT_EQ(m.steps(), 0u);
    m.waitForInvariants();
    EXPECT_EQ(m.invariantStatus(), Model::InvariantStatus::NoRun);
}

TEST(OpenJob, OutlineIsAdoptedBeforeTheFlood) {
    Gate gate;
    gate.path = kComb, gate.phase = OpenPhase::Flood;
    Model m;
    m.openHook = gate.hook();
    const uint64_t before = m.generation();
    m.openInBackground(kComb);
    gate.waitReached();
    EXPECT_FALSE(m.pollOpen());  // not done: the outline only
    ASSERT_TRUE(m.opening());
    EXPECT_EQ(m.openPhase(), OpenPhase::Flood);
    EXPECT_EQ(m.polygon().vertices.size(), verticesIn(kComb));
    EXPECT_EQ(m.steps(), 0u);
    EXPECT_EQ(m.path(), kComb);
    EXPECT_GT(m.generation(), before);
    const std::string n = std::to_string(verticesIn(kComb));
    EXPECT_EQ(m.verdict(), "flooding... " + n + " vertices");
    EXPECT_FALSE(m.failed());
    // The outline has no run: the invariant lane claims nothing of it (not "none broken").
    EXPECT_EQ(m.invariantStatus(), Model::InvariantStatus::NoRun);
    gate.release();
    m.waitOpen();
    EXPECT_FALSE(m.opening());
    m.waitForInvariants();
    EXPECT_EQ(m.invariantStatus(), Model::InvariantStatus::NoneBroken);
    Model sync;
    sync.open(kComb);
    EXPECT_GT(m.steps(), 0u);
    EXPECT_EQ(m.steps(), sync.steps());
    EXPECT_EQ(m.verdict(), sync.verdict());
    EXPECT_EQ(m.trace().triangles.size(), sync.trace().triangles.size());
    ASSERT_FALSE(m.recentFiles().empty());  // remembered, as open() does
}

TEST(OpenJob, InvalidAndTraceOpensEqualTheSynchronousOnes) {
    const std::string trace = (scratch("open-job-trace") / "comb.jsonl").string();
    {
        Trace t = record(readPolygonFile(kComb).polygon);
        std::ofstream out(trace);
        writeTrace(out, t);
    }
    for (const std::string& file : {sourcePath("polygons/invalid/self-intersection.json"), trace,
                                    sourcePath("polygons/invalid/checker-rejects.json"),
                                    sourcePath("polygons/invalid/forbidden-left-behind.json")}) {
        SCOPED_TRACE(file);
        Model bg, sync;
        bg.openInBackground(file);
        bg.waitOpen();
        sync.open(file);
        EXPECT_EQ(bg.verdict(), sync.verdict());
        EXPECT_EQ(bg.steps(), sync.steps());
        EXPECT_EQ(bg.exitCode(), sync.exitCode());
        EXPECT_EQ(bg.findings().size(), sync.findings().size());
        EXPECT_EQ(bg.step(), sync.step());  // the landing on the forbidden step
    }
}

TEST(OpenJob, ProgressIsMonotoneAndReachesTheTotal) {
    constexpr int kPhases = int(OpenPhase::Done);  // read, validate, flood, check, prepare
    Model m;
    Gate gates[kPhases];
    // One gate per phase, each released in turn: the progress at each is where it stands.
    std::function<void(const std::string&, OpenPhase)> hooks[kPhases];
    for (int k = 0; k < kPhases; ++k) {
        gates[k].path = kComb, gates[k].phase = OpenPhase(k);
        hooks[k] = gates[k].hook();
    }
    m.openHook = [&](const std::string& p, OpenPhase at) { hooks[int(at)](p, at); };
    m.openInBackground(kComb);
    uint32_t last = 0;
    for (int k = 0; k < kPhases; ++k) {
        gates[k].waitReached();
        m.pollOpen();
        EXPECT_EQ(m.openTotal(), kPhases * OpenJob::kPerPhase);
        EXPECT_GE(m.openProgress(), last);
        EXPECT_EQ(m.openProgress(), uint32_t(k) * OpenJob::kPerPhase);
        last = m.openProgress();
        gates[k].release();
    }
    // To the end, polled as the window does: never back, the total at the last.
    while (m.opening()) {
        const uint32_t p = m.openProgress();
        EXPECT_GE(p, last);
        last = p;
        if (m.pollOpen()) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_GT(m.steps(), 0u);
}

TEST(OpenJob, ProgressReachesTheTotalWhenDone) {
    Model m;
    m.openInBackground(kComb);
    // Done but not yet polled: the bar is full.
    while (m.openProgress() < m.openTotal() || m.openTotal() == 0)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    EXPECT_EQ(m.openProgress(), OpenJob::kTotal);
    m.waitOpen();
    EXPECT_GT(m.steps(), 0u);
}

TEST(OpenJob, CancelWhileReadingKeepsWhatWasLoaded) {
    Model m;
    m.open(sourcePath("polygons/hole.json"));
    const uint32_t steps = m.steps();
    const std::string verdict = m.verdict();
    const uint64_t generation = m.generation();
    Gate gate;
    gate.path = kComb, gate.phase = OpenPhase::Read;
    m.openHook = gate.hook();
    m.openInBackground(kComb);
    gate.waitReached();
    m.cancelOpen();
    EXPECT_FALSE(m.opening());
    gate.release();
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_FALSE(m.pollOpen());
    EXPECT_EQ(m.path(), sourcePath("polygons/hole.json"));
    EXPECT_EQ(m.steps(), steps);
    EXPECT_EQ(m.verdict(), verdict);
    EXPECT_EQ(m.generation(), generation);
}

TEST(OpenJob, CancelAfterTheReadKeepsTheOutlineNotFlooded) {
    for (OpenPhase at :
         {OpenPhase::Validate, OpenPhase::Flood, OpenPhase::Check, OpenPhase::Prepare}) {
        SCOPED_TRACE(openPhaseName(at));
        Model m;
        m.open(sourcePath("polygons/hole.json"));
        Gate gate;
        gate.path = kComb, gate.phase = at;
        m.openHook = gate.hook();
        m.openInBackground(kComb);
        gate.waitReached();
        m.pollOpen();  // the outline
        m.cancelOpen();
        gate.release();
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        m.pollOpen();
        EXPECT_FALSE(m.opening());
        EXPECT_EQ(m.path(), kComb);
        EXPECT_EQ(m.polygon().vertices.size(), verticesIn(kComb));
        EXPECT_EQ(m.steps(), 0u);
        EXPECT_EQ(m.verdict(), "not flooded: the open was cancelled while " +
                                   std::string(openPhaseName(at)) + " (" +
                                   std::to_string(verticesIn(kComb)) + " vertices read)");
        EXPECT_FALSE(m.failed());
        EXPECT_EQ(m.invariantStatus(), Model::InvariantStatus::NoRun);  // nothing flooded
        // The job ended its phase in the background: nothing of it is adopted later.
        m.waitOpen();
        EXPECT_EQ(m.steps(), 0u);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        std::lock_guard<std::mutex> lock(gate.mu);
        for (const auto& [path, phase] : gate.entered) EXPECT_LE(int(phase), int(at));
    }
}

// Everything of the run but its GL upload is prepared in the job (prepared_run.h): while the
// job prepares, the window still shows the outline; then pollOpen moves in the replay's
// keyframes and the canvas's arrays and grids, the same as the synchronous open prepares.
TEST(OpenJob, TheRunArrivesPreparedAsTheSynchronousOpenPreparesIt) {
    for (const std::string& file : {kComb, sourcePath("polygons/invalid/self-intersection.json")}) {
        SCOPED_TRACE(file);
        Gate gate;
        gate.path = file, gate.phase = OpenPhase::Prepare;
        Model bg;
        bg.openHook = gate.hook();
        bg.openInBackground(file);
        gate.waitReached();
        EXPECT_FALSE(bg.pollOpen());
        EXPECT_TRUE(bg.outlineOnly());  // the outline, prepared in the job too
        std::shared_ptr<PreparedCanvas> outline = bg.takeCanvas();
        ASSERT_TRUE(outline);
        EXPECT_TRUE(outline->geometry.triangles.empty());
        EXPECT_TRUE(outline->geometry.fans.empty());  // an outline is not filled
        EXPECT_EQ(outline->geometry.positions.size(), 2 * verticesIn(file));
        gate.release();
        bg.waitOpen();
        Model sync;
        sync.open(file);
        EXPECT_FALSE(bg.outlineOnly());
        EXPECT_EQ(bg.verdict(), sync.verdict());
        EXPECT_EQ(bg.keyframeCount(), sync.keyframeCount());
        EXPECT_GT(bg.keyframeCount(), 0u);
        EXPECT_EQ(bg.transcript().size(), sync.transcript().size());
        EXPECT_EQ(bg.classes(), sync.classes());
        std::shared_ptr<PreparedCanvas> a = bg.takeCanvas(), b = sync.takeCanvas();
        ASSERT_TRUE(a && b);
        EXPECT_EQ(a->geometry.triangles, b->geometry.triangles);
        EXPECT_EQ(a->geometry.triangles.size(), 3 * bg.trace().triangles.size());
        EXPECT_EQ(a->geometry.positions, b->geometry.positions);
        EXPECT_EQ(a->geometry.fans, b->geometry.fans);
        EXPECT_EQ(a->vertexMarkers.size(), bg.polygon().vertices.size());
        EXPECT_FALSE(bg.takeCanvas());  // taken once: the canvas owns it now
    }
}

// No step of an open holds the page for a whole phase of a large run: the flood is cut in
// slices of machine steps (its log reserved and trimmed apart), the preparation in parts, and
// within a phase the progress only grows. The run is the one record() makes whole.
TEST(OpenJob, AFloodIsCutInSlicesAndItsPreparationInParts) {
    const Polygon polygon = generate("comb", 1, 100000);
    RunSteps steps(polygon, "comb", Up::PlusY);
    std::map<OpenPhase, size_t> taken;
    OpenPhase phase = OpenPhase::Done;
    double done = 0;
    for (OpenPhase p; (p = steps.next()) != OpenPhase::Done; steps.step(), ++taken[p]) {
        if (p != phase) phase = p, done = 0;
        EXPECT_GE(steps.phaseDone(), done) << openPhaseName(p);
        EXPECT_LT(steps.phaseDone(), 1.0) << openPhaseName(p);
        done = steps.phaseDone();
    }
    const PreparedRun run = steps.take();
    const Trace whole = record(polygon);
    ASSERT_TRUE(run.trace);
    EXPECT_GT(done, 0.5) << "the preparation's last part began past its half";
    EXPECT_EQ(taken[OpenPhase::Validate], 1u);
    EXPECT_GE(taken[OpenPhase::Flood], whole.events.size() / RunSteps::kFloodSlice + 2);
    EXPECT_EQ(taken[OpenPhase::Prepare], size_t(PrepareSteps::kParts));
    EXPECT_TRUE(run.trace->events == whole.events);
    EXPECT_TRUE(run.trace->triangles == whole.triangles);
    EXPECT_TRUE(run.verdict.check.ok) << run.verdict.text;
}

TEST(OpenJob, ASecondOpenCancelsTheFirst) {
    const std::string hole = sourcePath("polygons/hole.json");
    Gate gate;
    gate.path = kComb, gate.phase = OpenPhase::Flood;
    {
        Model m;
        m.openHook = gate.hook();
        m.openInBackground(kComb);
        gate.waitReached();
        m.openInBackground(hole);
        m.waitOpen();  // the second, while the first is held
        EXPECT_EQ(m.path(), hole);
        EXPECT_GT(m.steps(), 0u);
        gate.release();
    }  // ~Model joins the first
    for (const auto& [path, phase] : gate.entered)
        if (path == kComb) {
            EXPECT_LE(int(phase), int(OpenPhase::Flood));
        }
}

TEST(OpenJob, AFailingReadReportsItsDiagnostic) {
    const std::string missing = (scratch("open-job-missing") / "no-such.json").string();
    // Polled as fast as it goes, many times: the job marks its phase Done a moment before
    // done(), and a poll in between once adopted an outline the failed read never made.
    for (int k = 0; k < 200; ++k) {
        Model m;
        m.openInBackground(missing);
        bool finished = false;
        while (m.opening()) finished |= m.pollOpen();
        ASSERT_TRUE(finished) << k;
        ASSERT_EQ(m.openDiagnostic().status, Status::Malformed) << k;
    }
    Model empty;
    empty.openInBackground(missing);
    bool finished = false;
    while (empty.opening()) finished |= empty.pollOpen();
    EXPECT_TRUE(finished);
    EXPECT_EQ(empty.openDiagnostic().status, Status::Malformed);
    EXPECT_NE(empty.openDiagnostic().message.find(missing), std::string::npos);
    EXPECT_EQ(empty.exitCode(), 3);
    EXPECT_NE(empty.verdict().find("cannot open"), std::string::npos) << empty.verdict();

    Model loaded;  // what was loaded stays
    loaded.open(kComb);
    const uint32_t steps = loaded.steps();
    loaded.openInBackground(missing);
    loaded.waitOpen();
    EXPECT_EQ(loaded.path(), kComb);
    EXPECT_EQ(loaded.steps(), steps);
    EXPECT_NE(loaded.openDiagnostic().message.find(missing), std::string::npos);
}

#endif
