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
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "camera.h"
#include "find.h"
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
#include "flood/teach/inspect.h"
#include "flood/teach/quiz.h"
#include "flood/teach/state_table.h"
#include "flood/teach/transcript.h"
#include "flood/tools/shrink.h"
#include "gallery.h"
#include "geometry.h"  // Vec2, Rect
#include "job.h"
#include "jobs.h"
#include "open_job.h"
#include "summary.h"
#include "timeline.h"

namespace flood::view {

// Vertex classes of §3 (Fig. 1): core/machine/vertex_class.h.
using flood::classifyVertices;
using flood::VertexClass;
using flood::vertexClassName;

// ----------------------------------------------------------------------------------------
// Text views of the log: an event in one line (flood/teach/describe.h), the transcript's items
// (flood/teach/transcript.h).

// The verdict's lines and the findings: prepared_run.h (VerdictLine, Finding).

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
    // The window's open (open_job.h): what open() does, with the read, validation, flood and
    // check in a background Job. pollOpen(), each frame, adopts the polygon as soon as it is
    // read, as an outline with no events (its verdict a note: "flooding... N vertices"), and
    // then the judged run in its place, as adoptEdit does; a failed read keeps what was
    // loaded, as open() does. A second open, open() or openFeature() cancels it first.
    void openInBackground(const std::string& path);
    bool opening() const { return opening_ != nullptr; }
    const std::string& openingPath() const;  // "" when none
    OpenPhase openPhase() const;             // of the open under way
    uint32_t openProgress() const;           // of openTotal(); monotone, the total once done
    uint32_t openTotal() const;
    // Adopts what the open has ready. True once, in the call that finished it (the run
    // adopted, or the read failed: openDiagnostic() says why).
    bool pollOpen();
    // Stops the open without waiting for it: while it reads, what was loaded stays; once it
    // has read, the outline stays with a verdict saying it was not flooded.
    void cancelOpen();
    void waitOpen();  // polls until the open is done (tests, screenshots)
    // Given to each open started after it is set (OpenJob::Request::onPhase): a test holds
    // an open at a phase with it.
    std::function<void(const std::string& path, OpenPhase)> openHook;
    void setOpenDirection(Up up) { up_ = up; }  // opens from now on flood along `up`
    // What is loaded is an open's outline (flooding, or cancelled): the polygon, no run.
    bool outlineOnly() const { return !note_.empty(); }
    // A recorded run as it is (the polygon is validated again only to report the input).
    void openTrace(Trace trace, const std::string& name);
    const Diagnostic& openDiagnostic() const { return openDiag_; }  // the last open's read
    std::string recentPath;
    // A GIS dataset's layer and OGR SQL attribute filter (--layer, --where), for what
    // open() and openFeature() read through GDAL; "" = the only layer, every feature. Set
    // without GDAL, an open fails (Usage) saying so rather than ignoring them.
    std::string gisLayer, gisWhere;
    // Floods `polygon` under `name`, its input's verdict given (validated already, or not at
    // all as --no-validate: then flooded as it is), as the open of a file does.
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
    using Transitions = view::Transitions;  // prepared_run.h
    const Transitions& transitions() const { return transitions_; }

    // Invariant lane: flood/check/invariants.h run over the trace in a background thread, started
    // by every open. Results are readable once done; progress counts the steps checked.
    bool invariantsDone() const;
    // What the lane may say: nothing while what is loaded is an open's outline (no run yet, or
    // none: cancelled), else the scan checking, cancelled, or done with or without violations.
    enum class InvariantStatus { NoRun, Checking, Cancelled, NoneBroken, Broken };
    InvariantStatus invariantStatus() const;
    uint32_t invariantProgress() const { return scan_.progress(); }
    const std::vector<Violation>& violations() const;  // empty until done
    uint32_t firstViolationStep() const;               // 0 until done or when none
    void cancelInvariants() { scan_.cancel(); }        // stops and joins the scan
    // Once the scan is done: moves to the first violation if the user has not moved since
    // the open landed (on the forbidden step, or step 0). True when it moved. Every frame.
    bool landOnFirstViolation();
    void waitForInvariants() { scan_.wait(); }  // joins it (tests)

    // Live editing (viewer/edit.h). An edited polygon validated and flooded: touches no
    // Model state, so it may run in a background thread.
    using EditedRun = PreparedRun;  // prepared_run.h: what floodRun computes and prepares
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
    // The canvas's arrays and label grids prepared with the run last adopted, for the canvas
    // to take and upload (null once taken; prepareCanvas(model) builds them again).
    std::shared_ptr<PreparedCanvas> takeCanvas() { return std::move(canvas_); }

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
    Up up_ = Up::PlusY;  // the direction opens flood along
    FloodSummary previousSummary_;
    bool hasPrevious_ = false;
    void startInvariants();
    std::vector<Violation> found_;  // the invariant scan's, written by it
    Job scan_;                      // after found_: destroyed (joined) before it
    uint32_t forbiddenStep_ = 0;
    uint32_t landedStep_ = 0;      // where open() put the step
    bool landingPending_ = false;  // the scan's result has not been looked at yet
    std::vector<PredicateRow> inspection_;
    mutable std::vector<Index> chainBefore_;
    mutable uint64_t chainBeforeFor_ = ~0ull;  // generation and step of chainBefore_
    uint64_t inspectedFor_ = ~0ull;            // generation and step of inspection_
    // Makes `run` the loaded run (its note, an open under way, is its verdict instead).
    void adopt(PreparedRun run);
    void setVerdict(RunVerdict v);
    // The synchronous open: `name` opened, its run computed (floodRun, judgeTrace) and adopted.
    void adoptOpen(const std::string& name, std::vector<std::string> warnings, PreparedRun run);
    void failedOpen(const std::string& path, const Diagnostic& why);
    std::string note_;  // the verdict of an outline: its open's phase, or cancelled
    std::shared_ptr<PreparedCanvas> canvas_;         // the run's, until the canvas takes it
    std::unique_ptr<OpenJob> opening_;               // the open under way
    std::vector<std::unique_ptr<OpenJob>> retired_;  // cancelled opens ending their phase
    bool outlineShown_ = false;                      // opening_'s outline is adopted
    void adoptOutline();
    void adoptOpened();
    void setNote(std::string note);
    void remember(const std::string& path);
    Diagnostic openDiag_;
    std::string galleryDir_;
    uint32_t galleryOpens_ = 0;
    size_t feature_ = kNoFeature;
    std::string origin_, originName_;  // the shrunk polygon's source file, and its display name
    size_t originFeature_ = kNoFeature;
    CheckResult check_;
    bool deferScan_ = false, scanWaiting_ = false;  // adoptEdit's deferred invariant scan
    std::vector<VerdictLine> verdictLines_;
    std::vector<Finding> findings_;
    size_t findingsOmitted_ = 0, currentFinding_ = 0;
    bool findingsComplete_ = true;
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

}  // namespace flood::view
