// The viewer's data model: one recorded flood (Trace + Replay), the current step, playback,
// breakpoints, camera and picking. No ImGui, no GL, no GLFW: the panels read it and call its
// methods, and tests/viewer/viewer_model_test.cpp drives it without a window.
//
// Steps: step s means "the first s events applied" (Replay::seek(s)); the current event is
// events[s - 1], the one that produced what is on screen. Step 0 has no current event.
#pragma once
#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "flood/check/checker.h"
#include "flood/check/invariants.h"
#include "flood/check/verdict.h"
#include "flood/geometry/polygon.h"
#include "flood/geometry/status.h"
#include "flood/io/io.h"
#include "flood/log/replay.h"
#include "flood/machine/events.h"
#include "flood/machine/flood.h"
#include "flood/machine/vertex_class.h"
#include "flood/teach/describe.h"
#include "flood/teach/quiz.h"
#include "flood/teach/state_table.h"
#include "flood/teach/transcript.h"
#include "flood/tools/shrink.h"
#include "geometry.h"  // Vec2, Rect

#include <thread>

namespace flood::view {

// Vertex classes of §3 (Fig. 1): core/machine/vertex_class.h.
using flood::classifyVertices;
using flood::VertexClass;
using flood::vertexClassName;

// ----------------------------------------------------------------------------------------
// The tiled window layout: panels on the left and right, timeline at the bottom, canvas in
// the middle, and under the canvas the findings of a failing face. Shared with the
// screenshot test so it can find a vertex on the PNG.
struct Layout {
    Rect canvas, left, right, bottom;
    Rect findings;  // between the canvas and the timeline; empty (h 0) when nothing failed
};
// `bottomWanted`: what the timeline needed last frame (its toolbar wraps at a large scale or
// on a narrow window); it gets that much, up to half the window, when its share is smaller.
// `findingsWanted`: what the findings panel needs (0: none), taken from the canvas's column,
// at most a third of it.
Layout computeLayout(double width, double height, double uiScale, double bottomWanted = 0,
                     double findingsWanted = 0);

// World (polygon coordinates, y up) to screen (y down): screen = origin + (p - center) * scale.
class Camera {
public:
    void fit(const Polygon& polygon, const Rect& viewport);  // whole polygon, 6% margin
    // The box [x0, x1] x [y0, y1] (world), 6% margin; a box of no size (one point) is
    // shown at the scale of a box `minSide` wide.
    void fitBox(double x0, double y0, double x1, double y1, const Rect& viewport,
                double minSide = 1e-300);
    void centerOn(Point p) { cx_ = p.x, cy_ = p.y; }
    // Centres on `p` at `scale` pixels per world unit (clamped as zoomAt clamps).
    void centerOn(Point p, double scale);
    void setViewport(const Rect& viewport) { viewport_ = viewport; }
    Vec2 toScreen(Point p) const;
    Point toWorld(Vec2 s) const;
    void pan(double dx, double dy);              // by screen pixels
    void zoomAt(Vec2 screen, double factor);     // keeps the world point under `screen`
    double scale() const { return scale_; }      // pixels per world unit
    Point center() const { return {cx_, cy_}; }  // world point at the viewport centre
    const Rect& viewport() const { return viewport_; }

private:
    Rect viewport_;
    double cx_ = 0, cy_ = 0, scale_ = 1;
};

// ----------------------------------------------------------------------------------------
// Breakpoints: stop when an event matches any enabled condition.
struct Breakpoints {
    std::array<bool, size_t(Action::Count)> actions{};  // on these action kinds
    bool forbidden = false;                             // on a Forbidden event
    Index vertex = kNone;   // when this vertex becomes Left, Right, NextLeft or NextRight
    int64_t triangle = -1;  // when this triangle number is cut
    bool any() const;
};
bool hits(const Breakpoints& b, const Event& e);

// ----------------------------------------------------------------------------------------
// Text views of the log: an event in one line (flood/teach/describe.h), the transcript's items
// (flood/teach/transcript.h).

// ----------------------------------------------------------------------------------------
// The verdict, one line per finding, of the core's kinds (flood/check/verdict.h). Ok only
// when the exact checker passed on valid input; every failure (malformed, invalid input,
// forbidden state, checker rejection, internal) has its own line, drawn red. A note (the
// checker accepting the triangles of invalid input) is an Ok line drawn grey.
struct VerdictLine {
    Verdict kind = Verdict::Ok;
    std::string text;
    bool note = false;
    bool failure() const { return kind != Verdict::Ok; }
};

// One finding of the open face, as the findings panel lists it: a validation finding
// (validateAll, the first being validate()'s verdict), the forbidden transition, the exact
// checker's rejection, an internal failure or an unreadable file.
struct Finding {
    Verdict kind = Verdict::Invalid;
    std::string message;    // the diagnostic's whole line
    std::string where;      // "ring R vertex V (x, y)", "step N", "triangle T", or ""
    std::string reason;     // what is wrong, the location apart
    Culprits culprits;      // what it blames (drawn thick in the error view)
    bool hasPoint = false;  // `point` is where it is (diagnosticPoint, any vertex)
    Point point;
    uint32_t step = kNone;  // the step it shows at; kNone: none (or not known yet)
};

// ----------------------------------------------------------------------------------------
// Framing: what E, a click in the findings panel, Find and the invariant lane's Go show.
// A world box, x0 > x1 when empty.
struct WorldBox {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    void add(Point p);  // non-finite points are left out
    bool empty() const { return !(x0 <= x1 && y0 <= y1); }
    double w() const { return x1 - x0; }
    double h() const { return y1 - y0; }
    Point centre() const { return {(x0 + x1) / 2, (y0 + y1) / 2}; }
    bool contains(Point p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
};
// The camera showing the neighbourhood of `target` (world) in `viewport`: the target with a
// quarter of its size as margin on each side, never narrower than `minSide` across (a point,
// a short edge: a side the caller chooses so the nearest neighbours show).
Camera frameNeighbourhood(const WorldBox& target, double minSide, const Rect& viewport);
// The box the error view frames for `culprits`: the culprit edges, vertices, triangles and
// point. `ringsAtFault` (a validation finding): when it blames whole rings only (a hole
// outside its outer ring), its first ring (the one at fault) and the nearest vertex of each
// other ring it names, so the hole shows beside what it is judged against but the whole
// outer ring is not framed; the first ring too when nothing else is blamed. Each culprit
// vertex brings its nearer ring neighbour, so its edges show against the rest. `minSide`:
// what frameNeighbourhood is to keep across (a fiftieth of the face for a lone point, else
// 0). False when nothing finite is blamed.
bool culpritBox(const Polygon& polygon, const std::vector<Triangle>& triangles,
                const Culprits& culprits, bool ringsAtFault, WorldBox& box, double& minSide);
// The camera showing `culprits` in `viewport` (culpritBox, frameNeighbourhood). False when
// nothing finite is blamed: `camera` is left as it was.
bool frameCulprits(const Polygon& polygon, const std::vector<Triangle>& triangles,
                   const Culprits& culprits, bool ringsAtFault, const Rect& viewport,
                   Camera& camera);
// The world box a camera shows.
WorldBox visibleBox(const Camera& camera);

// Find: "v2999" (vertex), "t77022" (triangle), "s12051" (step), "r3" (ring), parsed and
// looked up against a trace. A bad query says why in `message`.
struct FindTarget {
    bool ok = false;
    std::string message;
    char kind = 0;  // 'v', 't', 's' or 'r'
    uint64_t index = 0;
    bool hasCenter = false;
    Point center;                           // where to centre the view
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // what to show (a ring's box; a point otherwise)
    uint32_t seekTo = kNone;                // step to seek to, kNone: stay
    std::vector<Index> vertices;            // what to frame: a vertex, a step's fingers
};
FindTarget findTarget(const Trace& trace, const std::string& query);
// Predicate inspector: the tests of one event's decision path (Fig. 9), recomputed from the
// replay state before the event, each with its predicate, arguments, floating-point value,
// exact result and the stage of the exact predicate that decided it.
struct PredicateRow {
    Test test = Test::Count;  // Test::Count: one of the sag search's inside() tests
    std::string predicate;    // "below(NextLeft, NextRight)", "orient(prev C, C, next C) <= 0", ...
    std::vector<Index> args;  // vertex ids, in the predicate's order
    bool result = false;      // recomputed
    bool recorded = false;    // what the event says (decision tests only)
    bool hasRecorded = false;
    bool hasValue = false;  // orient-based: `value` and `stage` mean something
    double value = 0;       // the filter's determinant
    int sign = 0;           // exact sign (orient) or the comparison's outcome
    std::string stage;      // "filter" / "expansion" / "rationals" / "comparison" / "identity"
};
// The sag search's inside() tests are listed for the sags it could test: unbridged sags
// strictly between the water and Next (at most `maxSags` of them; the machine's sag index
// tests fewer, Event::sagTests of them).
std::vector<PredicateRow> inspectDecision(const Trace& trace, const ReplayState& before,
                                          const Event& e, const std::vector<VertexClass>& classes,
                                          size_t maxSags = 64);

// ----------------------------------------------------------------------------------------
// The timeline strip: which events a strip `width` pixels wide shows, zoomed and panned.
// Event i is the mark [x(i), x(i + 1)); hovering it names step i + 1 (the state after it),
// and a click there lands on that same step.
struct TimelineView {
    double first = 0;  // event index (fractional) at the strip's left edge
    double span = 0;   // events across the strip; 0: the whole log
    double visible(uint32_t events) const { return span > 0 ? span : double(events); }
    double perEvent(double width, uint32_t events) const {
        return width / std::max(1.0, visible(events));
    }
    double xOfStep(uint32_t step, double width, uint32_t events) const {
        return (step - first) * perEvent(width, events);
    }
    // The event whose mark is under x (clamped to the log), and the step a click there means.
    uint32_t eventAt(double x, double width, uint32_t events) const;
    uint32_t stepAt(double x, double width, uint32_t events) const {
        return events == 0 ? 0 : eventAt(x, width, events) + 1;
    }
    // Wheel: zoom by `factor` (> 1 magnifies) keeping the event under x in place; drag: pan.
    void zoomAt(double x, double width, double factor, uint32_t events);
    void pan(double dx, double width, uint32_t events);

private:
    void clamp(uint32_t events);
};

// ----------------------------------------------------------------------------------------
// Shrink from the viewer: flood/tools/shrink.h run in a background thread, with the tries made as
// progress and a Cancel that stops it before its next classification. An `onTry` in the
// options is still called (before the cancel is looked at).
class ShrinkJob {
public:
    ShrinkJob() = default;
    ShrinkJob(const ShrinkJob&) = delete;
    ShrinkJob& operator=(const ShrinkJob&) = delete;
    ~ShrinkJob() { cancel(); }
    void start(const Polygon& polygon, ShrinkOptions options);  // cancels a running one first
    bool started() const { return thread_.joinable() || done(); }
    bool done() const { return done_.load(std::memory_order_acquire); }
    size_t tries() const { return tries_.load(std::memory_order_relaxed); }
    size_t maxTries() const { return maxTries_; }
    void cancel();  // asks the thread to stop and joins it; the result so far stays readable
    void requestCancel() { cancel_.store(true, std::memory_order_relaxed); }  // without joining
    void wait();                                                              // joins (tests)
    const ShrinkResult& result() const { return result_; }                    // once done()
    void reset();  // cancels and forgets the result

private:
    std::thread thread_;
    std::atomic<bool> cancel_{false}, done_{false};
    std::atomic<size_t> tries_{0};
    size_t maxTries_ = 0;
    ShrinkResult result_;  // written by the thread before `done_`
};

// Writes `polygon` as a GeoJSON Polygon or MultiPolygon to `path` atomically: a temporary
// file beside it, renamed over it once complete. WriteFailed (nothing left behind) if not.
Diagnostic saveGeoJson(const Polygon& polygon, const std::string& path);

// ----------------------------------------------------------------------------------------
// The features of a FeatureCollection with their verdicts (read, validate, flood, exact
// check: the first failure), as `flood check` judges them.
struct FeatureVerdict {
    size_t index = 0;  // the feature's FID (FeatureRead::fid): what openFeature() takes
    std::string id, name;
    size_t vertices = 0;
    Verdict kind = Verdict::Ok;
    std::string reason;  // the diagnostic's message; "" when ok
    bool failure() const { return kind != Verdict::Ok; }
};
FeatureVerdict judgeFeature(const FeatureRead& feature);
// Failing features first, each group in collection order.
void orderFailingFirst(std::vector<FeatureVerdict>& list);

// Judges a collection's features in a background thread (a dataset may hold thousands).
class FeatureScan {
public:
    FeatureScan() = default;
    FeatureScan(const FeatureScan&) = delete;
    FeatureScan& operator=(const FeatureScan&) = delete;
    ~FeatureScan() { cancel(); }
    void start(const std::string& path);  // cancels a running scan first
    const std::string& path() const { return path_; }
    bool done() const { return done_.load(std::memory_order_acquire); }
    size_t progress() const { return progress_.load(std::memory_order_relaxed); }  // judged so far
    size_t total() const { return total_.load(std::memory_order_relaxed); }  // known once read
    void cancel();
    void wait();
    // Once done: the verdicts, failing first; empty when the file is not a FeatureCollection.
    const std::vector<FeatureVerdict>& features() const { return features_; }
    const Diagnostic& diagnostic() const { return diag_; }  // the file could not be read

private:
    std::thread thread_;
    std::string path_;
    std::atomic<bool> cancel_{false}, done_{false};
    std::atomic<size_t> progress_{0}, total_{0};
    std::vector<FeatureVerdict> features_;  // written by the thread before `done_`
    Diagnostic diag_;
};
// ----------------------------------------------------------------------------------------
// How a run decomposed the polygon along its direction: the vertex classes that direction
// gives (§3), the gorges flooded from a bottom, and the count of each action. The paper's
// remark that the decomposition into gorges is not unique, as numbers (the direction dial).
struct FloodSummary {
    std::array<uint32_t, size_t(VertexClass::Count)> classes{};  // bottoms, sags, tops, ceilings
    uint32_t gorges = 0;  // gorges started at a bottom (Start, and each later bottom reached)
    std::array<uint32_t, size_t(Action::Count)> actions{};
    uint32_t triangles = 0;
};
FloodSummary summarizeFlood(const Trace& trace, const std::vector<VertexClass>& classes);
// One line per quantity, in a fixed order: its name, before and after ("gorges", 3, 5).
struct SummaryChange {
    std::string what;
    int64_t before = 0, after = 0;
    bool changed() const { return before != after; }
};
std::vector<SummaryChange> compareSummaries(const FloodSummary& before, const FloodSummary& after);

// ----------------------------------------------------------------------------------------
class Model {
public:
    Model();
    ~Model();
    Model(const Model&) = delete;
    Model& operator=(const Model&) = delete;

    // Reads, validates and floods a file of any format io.h knows, or loads a trace written
    // by `flood trace` (*.jsonl). Never throws. An unreadable file or malformed trace keeps
    // whatever was loaded (nothing loaded: an empty polygon) and says why in openDiagnostic()
    // and the verdict; invalid polygons are flooded anyway so the viewer can show where the
    // machine stops. Recent files get the absolute path, saved to `recentPath` if set.
    void open(const std::string& path);
    // A recorded run as it is (the polygon is validated again only to report the input).
    void openTrace(Trace trace, const std::string& name);
    const Diagnostic& openDiagnostic() const { return openDiag_; }  // the last open's read
    std::string recentPath;
    // A GIS dataset's layer and OGR SQL attribute filter (--layer, --where), for what
    // open() and openFeature() read through GDAL; "" = the only layer, every feature. Set
    // without GDAL, an open fails (Usage) saying so rather than ignoring them.
    std::string gisLayer, gisWhere;
    void openPolygon(Polygon polygon, const std::string& name, Diagnostic input,
                     std::vector<std::string> warnings = {});
    // The feature of FID `index` (FeatureRead::fid: a GeoJSON's position in "features", or
    // its integer "id"; a GIS layer's FID) of a FeatureCollection or GIS layer, named
    // "FILE#index". Not a collection, or no such feature: false, the loaded polygon kept,
    // openDiagnostic() says why (Usage for a bad index, else the read's failure).
    bool openFeature(const std::string& path, size_t index);
    size_t feature() const { return feature_; }  // the open feature's FID, kNoFeature if none
    static constexpr size_t kNoFeature = ~size_t(0);

    // Shrink: opens a shrunk polygon as "<name> (shrunk)", remembering what it came from so
    // that openOrigin() brings the original back in one click (it also stays in Recent).
    void openShrunk(const ShrinkResult& result);
    bool shrunk() const { return !origin_.empty(); }
    const std::string& originName() const { return originName_; }
    void openOrigin();

    const std::string& path() const { return path_; }
    uint64_t generation() const { return generation_; }  // changes with every open
    // The Fig. 10 state table of the loaded trace, built on first use after each open.
    const StateTable& stateTable() const;
    const Trace& trace() const { return *trace_; }
    const Polygon& polygon() const { return trace_->polygon; }
    const Diagnostic& inputDiagnostic() const { return input_; }
    const std::vector<std::string>& warnings() const { return warnings_; }
    const std::vector<VertexClass>& classes() const { return classes_; }
    const std::vector<Index>& offenders() const { return offenders_; }  // vertices to blame
    const std::vector<TranscriptItem>& transcript() const { return transcript_; }
    const std::vector<std::string>& recentFiles() const { return recent_; }
    // The folder whose gallery the Open panel lists: polygonsDir(), or the folder of the
    // gallery file last opened (open(".../gallery.json") opens its first polygon). Each such
    // open counts, so the UI can show the gallery when the count moves.
    std::string galleryDir() const;
    uint32_t galleryOpens() const { return galleryOpens_; }
    void loadRecent(const std::string& file);  // one path per line; missing file: no-op
    void saveRecent(const std::string& file) const;
    const std::string& verdict() const {
        return verdict_;
    }  // "ok: 64 triangles" / "Forbidden at step 12: ..."
    const std::vector<VerdictLine>& verdictLines() const { return verdictLines_; }
    const CheckResult& check() const { return check_; }  // the exact checker, on a completed run
    bool failed() const;                                 // any failure line in the verdict
    // The CLI's exit code for what is loaded: 0, 3 unreadable, 4 invalid, 5 forbidden,
    // 6 checker rejection or internal error (docs/ERRORS.md).
    int exitCode() const;

    // Every finding of what is loaded, in the verdict's order: the input's validation
    // findings (validateAll, at most 100; the first is validate()'s verdict), then the
    // forbidden transition, the checker's rejection or an internal failure. Empty when ok.
    const std::vector<Finding>& findings() const { return findings_; }
    size_t findingsOmitted() const { return findingsOmitted_; }  // beyond the 100 listed
    bool findingsComplete() const { return findingsComplete_; }  // false: the search gave up
    size_t currentFinding() const { return currentFinding_; }    // what the error view shows
    // The error view on finding i: its culprits framed (frameCulprits), the step it shows at
    // sought. False (nothing changed) when there is no such finding or nothing to frame.
    bool showFinding(size_t i);
    // F8 / Shift+F8: the next (direction > 0) or previous finding, round the list; out of the
    // error view, the current one first.
    bool nextFinding(int direction);

    // The current finding's culprits (the first failure's until another is chosen: input
    // validation, then the forbidden event, then the checker), the first failure's step
    // (kNone: none), and a display point for the current finding if any.
    const Culprits& errorCulprits() const { return error_; }
    // Marked on the timeline (panel_timeline.cpp).
    uint32_t firstErrorStep() const { return firstErrorStep_; }
    bool errorPoint(Point& p) const;
    // The error view: frames the current finding's culprits, seeks to its step; the canvas
    // draws the culprits thick and dims the rest while errorView() holds. A fit ends it.
    bool showError() { return showFinding(currentFinding_); }
    bool errorView() const { return errorView_; }
    void hideError() { errorView_ = false; }

    // Find (see findTarget): frames the target (a vertex with its nearest neighbours, a
    // triangle, a step's fingers, a ring) and seeks where it says.
    FindTarget find(const std::string& query);
    // The invariant lane's Go: seeks to the violation's step and frames its vertices.
    void goToViolation(const Violation& v);
    // Frames vertices (their box, never narrower than twice the shortest edge at one of
    // them); false when none is a finite vertex.
    bool frameVertices(const std::vector<Index>& vertices);

    // Time.
    uint32_t steps() const { return uint32_t(trace_->events.size()); }
    uint32_t step() const { return step_; }
    const ReplayState& state() const { return replay_->state(); }
    size_t keyframeCount() const { return replay_->keyframeCount(); }
    size_t keyframeBytes() const { return replay_->keyframeBytes(); }
    const Event* currentEvent() const;
    // The active chain before the current event (the canvas's ghost of the step before);
    // empty at step 0. Found by a seek back and forth, cached per step.
    const std::vector<Index>& chainBefore() const;
    void seek(uint32_t step);  // clamps to [0, steps()]
    void stepForward() {       // never past a quiz question not answered yet
        if (pendingQuestion() < 0) seek(step_ + 1);
    }
    void stepBack() { seek(step_ == 0 ? 0 : step_ - 1); }
    void first() { seek(0); }
    void last() { seek(steps()); }
    // Moves to the next (direction > 0) or previous event of kind `a`; false if none.
    bool seekAction(Action a, int direction);
    // Runs to the next/previous step whose event hits a breakpoint; false (and stops at the
    // end of the log) if none does.
    bool runToBreakpoint(int direction);
    const Breakpoints& breakpoints() const { return breakpoints_; }
    void setBreakpoints(const Breakpoints& b);
    // The steps whose event hits an enabled breakpoint (the timeline's ticks), found again
    // when the breakpoints or the trace change.
    const std::vector<uint32_t>& breakpointSteps() const { return breakpointSteps_; }
    TimelineView timeline;  // reset by every open

    // The quiz (flood/teach/quiz.h; model_quiz.cpp): predict the next action. While it is on,
    // stepping forward and playback stop before each asked step until it is answered, so
    // the canvas never shows the answer first; answering shows the step, its Fig. 9 path
    // lit. Seeking (the timeline, Home/End, breakpoints) is the teacher's and may pass a
    // question: it stays unanswered and counts for nothing until the student is back
    // before it. A new session with every open or edit (the events change).
    void startQuiz(QuizActions asked);  // a new session: no answers yet
    void stopQuiz() { quizOn_ = false; }
    bool quizOn() const { return quizOn_; }
    const QuizSession& quiz() const;
    // The question asked about the next event and not answered yet; -1 when none (or off).
    int pendingQuestion() const;
    // Answers the pending question and steps onto its event; false when none is pending or
    // `choice` is not one of the five actions.
    bool answerQuiz(Action choice);
    // The answered question whose event is the current one (what the panels reveal), -1.
    int revealedQuestion() const;

    // Playback: speed() steps per second; advance() is fed the frame time.
    bool playing() const { return playing_; }
    void setPlaying(bool on);  // starting at the end plays again from the start
    void togglePlay() { setPlaying(!playing_); }
    double speed() const { return speed_; }
    void setSpeed(double stepsPerSecond) { speed_ = stepsPerSecond; }
    void advance(double seconds);

    // Triangles: the step whose event cut triangle t (its event index + 1).
    uint32_t triangleStep(uint32_t t) const;

    // Camera and picking (screen coordinates). An open (or requestFit) leaves a fit pending:
    // the canvas fits once it knows its viewport.
    const Camera& camera() const { return camera_; }
    bool fitPending() const { return needsFit_; }
    void requestFit() { needsFit_ = true; }
    // The whole polygon in the part of `viewport` no overlay covers (view_fit.h); ends the
    // error view.
    void fitCamera(const Rect& viewport, const std::vector<Rect>& overlays = {});
    // The view is the last fit's: no pan, zoom or framing since. A layout change refits it
    // then (main.cpp), and keeps a view the user chose.
    bool viewIsFit() const;
    void keepView() { needsFit_ = false; }  // the view chosen stays: no pending fit
    void setViewport(const Rect& viewport) { camera_.setViewport(viewport); }
    void pan(double dx, double dy) { camera_.pan(dx, dy); }  // screen pixels
    void zoomAt(Vec2 screen, double factor) { camera_.zoomAt(screen, factor); }
    void centerOn(Point p) { camera_.centerOn(p); }
    void fitBox(double x0, double y0, double x1, double y1) {
        camera_.fitBox(x0, y0, x1, y1, camera_.viewport());
    }
    void setCamera(const Camera& camera) { camera_ = camera; }  // an export's, for its frames
    Index pickVertex(Vec2 screen, double radiusPx) const;
    int64_t pickTriangle(Vec2 screen) const;  // among the triangles cut so far, -1 if none

    // The current event's decision path, recomputed (cached per step).
    const std::vector<PredicateRow>& inspection();

    // The first Forbidden step (its event index + 1), 0 when the run has none.
    uint32_t forbiddenStep() const { return forbiddenStep_; }
    // How often event `to` follows event `from` in the trace (the state machine's edges),
    // counted once per open.
    using Transitions =
        std::array<std::array<uint32_t, size_t(Action::Count)>, size_t(Action::Count)>;
    const Transitions& transitions() const { return transitions_; }

    // Invariant lane: flood/check/invariants.h run over the trace in a background thread, started
    // by every open. Results are readable once done; progress counts the steps checked.
    bool invariantsDone() const { return scan_.done.load(std::memory_order_acquire); }
    uint32_t invariantProgress() const { return scan_.progress.load(std::memory_order_relaxed); }
    const std::vector<Violation>& violations() const;  // empty until done
    uint32_t firstViolationStep() const;               // 0 until done or when none
    void cancelInvariants();                           // stops and joins the scan
    // Once the scan is done: moves to the first violation if the user has not moved since
    // the open landed (on the forbidden step, or step 0). True when it moved. Every frame.
    bool landOnFirstViolation();
    void waitForInvariants();  // joins it (tests)

    // Live editing (viewer/edit.h). An edited polygon validated and flooded: touches no
    // Model state, so it may run in a background thread.
    struct EditedRun {
        Trace trace;        // trace.polygon: the edited polygon, its T-junctions recorded
        Diagnostic input;   // the validator's verdict on it
        CheckResult check;  // the exact checker on a completed run (checked: it ran)
        bool checked = false;
        Findings findings;  // validateAll's, when `input` is invalid
    };
    static EditedRun floodEdit(Polygon polygon, const std::string& name, Up up = Up::PlusY);
    // Makes `run` the loaded run under the same name. Unlike an open, the step (clamped to
    // the new trace), the camera and the timeline stay, and no landing moves the step.
    // A run along another direction (the dial, Editor::setUp) makes previousSummary() the
    // run before, as setUp() does.
    // `deferScan` (a drag goes on): the invariant scan waits for startDeferredInvariants(),
    // since stopping a scan still setting up would stall the UI thread at the next edit.
    void adoptEdit(EditedRun run, bool deferScan = false);
    void startDeferredInvariants();  // no-op unless a scan waits
    // The flood direction (the direction dial): the loaded polygon floods again along `up`
    // (a trace opened as it was recorded: its polygon), at the same step as far as the new
    // run goes; later opens flood along it too. False, nothing changed, when `up` is not a
    // direction or is the current one. previousSummary() is then the run before the turn.
    bool setUp(Up up);
    Up up() const { return trace_->up; }
    FloodSummary summary() const { return summarizeFlood(*trace_, classes_); }
    const FloodSummary& previousSummary() const { return previousSummary_; }
    bool hasPreviousSummary() const { return hasPrevious_; }

private:
    Camera camera_;
    bool needsFit_ = true;
    Camera fitted_;  // what the last fitCamera chose (viewIsFit)
    bool errorView_ = false;
    Breakpoints breakpoints_;
    std::vector<uint32_t> breakpointSteps_;
    void findBreakpointSteps();
    bool playing_ = false;
    double speed_ = 8;
    Transitions transitions_{};
    void countTransitions();
    Up up_ = Up::PlusY;  // the direction opens flood along
    FloodSummary previousSummary_;
    bool hasPrevious_ = false;
    struct InvariantScan {
        std::thread thread;
        std::atomic<bool> cancel{false}, done{false};
        std::atomic<uint32_t> progress{0};
        std::vector<Violation> found;  // written by the thread before `done`
    };
    void startInvariants();
    InvariantScan scan_;
    uint32_t forbiddenStep_ = 0;
    uint32_t landedStep_ = 0;      // where open() put the step
    bool landingPending_ = false;  // the scan's result has not been looked at yet
    std::vector<PredicateRow> inspection_;
    mutable std::vector<Index> chainBefore_;
    mutable uint64_t chainBeforeFor_ = ~0ull;  // generation and step of chainBefore_
    uint64_t inspectedFor_ = ~0ull;            // generation and step of inspection_
    void computeOffenders();
    std::string computeVerdict() const;
    void adopt(std::unique_ptr<Trace> trace);  // makes `trace` the loaded run
    void computeVerdictLines();
    void remember(const std::string& path);
    Diagnostic openDiag_;
    std::string galleryDir_;
    uint32_t galleryOpens_ = 0;
    size_t feature_ = kNoFeature;
    std::string origin_, originName_;  // the shrunk polygon's source file, and its display name
    size_t originFeature_ = kNoFeature;
    CheckResult check_;
    std::optional<CheckResult> checked_;  // adoptEdit: the checker already ran with the flood
    bool deferScan_ = false, scanWaiting_ = false;  // adoptEdit's deferred invariant scan
    std::vector<VerdictLine> verdictLines_;
    std::vector<Finding> findings_;
    size_t findingsOmitted_ = 0, currentFinding_ = 0;
    bool findingsComplete_ = true;
    std::optional<Findings> validated_;  // adoptEdit: validateAll already ran with the flood
    void computeFindings();
    uint32_t findingStep(const Finding& f) const;
    Culprits error_;
    uint32_t firstErrorStep_ = kNone;
    std::unique_ptr<Trace> trace_;  // owned here, at a stable address for Replay
    std::unique_ptr<Replay> replay_;
    std::string path_;
    Diagnostic input_;
    std::vector<std::string> warnings_;
    std::vector<VertexClass> classes_;
    std::vector<Index> offenders_;
    std::vector<TranscriptItem> transcript_;
    std::string verdict_;
    std::vector<uint32_t> triangleStep_;
    std::vector<std::string> recent_;
    uint32_t step_ = 0;
    double playClock_ = 0;
    uint64_t generation_ = 0;
    bool quizOn_ = false;
    mutable QuizSession quiz_;  // for the trace of generation quizFor_
    mutable uint64_t quizFor_ = ~0ull;
    mutable StateTable stateTable_;           // cache of stateTable()
    mutable uint64_t stateTableFor_ = ~0ull;  // the generation it was built for
};

// Where to look for polygons: $FLOOD_POLYGONS_DIR; else the installed share/flood/polygons
// beside the executable; else the source tree's polygons/ (a build); else the configured
// install prefix's.
std::string polygonsDir();
// polygons/FLOOD_VIEWER_DEFAULT_POLYGON (CMake cache, default paper-figure-7.json) if it
// exists, else the first polygon file, else "". FLOOD_POLYGONS_DIR overrides the directory.
std::string defaultPolygonPath();
// The teaching gallery, dir/gallery.json: a list of {"file", "title", "description"} in
// teaching order, files relative to dir. Missing or malformed: empty (the Open panel then
// lists the files only).
struct GalleryEntry {
    std::string file, title, description;  // file: full path
};
std::vector<GalleryEntry> readGallery(const std::string& dir);

}  // namespace flood::view
