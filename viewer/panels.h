// The viewer's panels, one file each (panel_*.cpp). They read the Model, change it only through
// its methods, and share the small UI state below. ImGui lives here, never in the model.
// A new panel: write panel_<name>.cpp with draw<Name>(Ui&), declare it below, call it from
// drawFrame in main.cpp, and tile it at a rectangle of computeLayout() (model.cpp) with
// beginTiled, or let it float (beginFloating). What it keeps between frames lives in Ui.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "canvas_geometry.h"
#include "edit.h"
#include "export.h"
#include "flood/teach/decision_tree.h"
#include "flood/teach/todo_list.h"
#include "model.h"
#include "presenter.h"
#include "renderer.h"
#include "scene.h"

struct ImVec2;
struct ImVec4;
struct ImFont;
struct ImDrawList;

namespace flood::view {
class ExportJob;  // export_job.h
}

namespace flood::view {

// What the canvas keeps between frames: which trace and step its GPU buffers hold, and the
// per-step overlay's labels and arrows (panel_canvas.cpp).
struct CanvasState {
    uint64_t generation = ~0ull;  // Model::generation() of the uploaded geometry
    uint32_t overlayStep = ~0u;
    SceneOptions overlayOptions;
    Point origin;
    float bbox[4] = {0, 0, 0, 0};             // of the polygon, minus the origin
    TriangleGrid grid;                        // triangle labels by cell
    TriangleGrid vertexGrid;                  // vertex labels by cell
    std::vector<MarkerVertex> vertexMarkers;  // classes first, then regular: thinned per camera
    std::array<double, 8> thinKey{};  // camera centre x, y, scale, viewport w, h, x, y, step
    size_t pixelBoundaryLines = 0;    // the thin boundary's lines when decimated, 0: every edge
    CanvasOverlay overlay;
    WorldView view;  // what Renderer::render draws this frame
    // Hover picking is a scan of the polygon: redo it only when something moved.
    std::array<double, 6> pickKey{};  // mouse x, y, camera centre x, y, scale, step
    Index pickedVertex = kNone;
    int64_t pickedTriangle = -1;
    // "Current gorge only": the dimmed rows outside the gorge's outline, and what they were
    // computed for (camera centre x, y, scale, canvas x, y, w, h, generation and step).
    std::array<double, 8> focusKey{};
    std::vector<Rect> focusDim;
    // The locator inset's rings as segment ends (panel_canvas.cpp), and the generation and
    // rectangle they were mapped for.
    std::array<double, 5> insetKey{};
    std::vector<Vec2> insetSegments;
    std::vector<Rect> obstacles;  // this frame, while the canvas paints: what floats over it
};

// Live editing's UI state (panel_edit.cpp); the edits themselves are viewer/edit.h's.
struct EditUi {
    explicit EditUi(Model& m);
    Editor editor;
    bool on = false;           // edit mode (M, or the canvas's Edit button)
    bool ringTool = false;     // "new ring" tool: clicks place corners (H)
    Index dragVertex = kNone;  // the vertex being dragged
    Index dragRing = kNone;    // the ring being dragged (Shift+drag)
    Point dragStart;           // where the ring drag began (world)
    Index selected = kNone;    // the last vertex clicked: what Delete removes when none is hovered
    Index hoverVertex = kNone, hoverEdge = kNone;
    Point onEdge;  // the hovered edge's point nearest the mouse
    bool showSave = false;
    bool overwrite = false;  // the save panel's "overwrite it" confirmation
    char savePath[1024] = "";
    std::string saveNote;
};

// The timeline strip's marks folded into 3-pixel buckets (panel_timeline.cpp), and the trace
// and window they were folded for.
struct TimelineFold {
    uint64_t generation = ~0ull;   // Model::generation()
    double first = -1, span = -1;  // TimelineView's
    std::vector<Action> buckets;   // the most telling action in each
};

// The transcript's text flowed into lines (panel_transcript.cpp), for a trace and a width.
struct TranscriptLines {
    uint64_t generation = ~0ull;  // Model::generation()
    float width = -1;
    std::vector<uint32_t> start;  // first item of each line, then the item count
};

// The Open panel's path box and teaching gallery (panel_open.cpp).
struct OpenUi {
    char path[1024] = "";
    bool galleryRead = false;  // read the first time the panel shows: it changes with the sources
    std::vector<GalleryEntry> gallery;
    std::string galleryDir;         // the folder `gallery` was read from
    uint32_t galleryOpensSeen = 0;  // Model::galleryOpens() when the panel last looked
    std::vector<Rect> galleryRows;  // each gallery entry's row as last drawn (the page's tests)
};

struct Ui {
    Ui(Model& m, Renderer& r) : model(m), renderer(r) {}
    Model& model;
    Renderer& renderer;
    float scale = 1;  // UI scale from the monitor's content scale
    Layout layout;
    SceneOptions sceneOptions;
    CanvasState canvas;
    bool showHelp = false;
    bool showOpen = false;
    bool showPredicates = false;
    bool showStateTable = false;
    std::vector<Index> highlight;      // vertices the predicate inspector's hovered row names
    Action seekKind = Action::Bridge;  // "previous/next event of kind" in the timeline
    std::string message;               // last status message (saved files, load errors)
    std::string pngRequest;            // non-empty: main writes this PNG after rendering
    uint32_t eventsScrolledTo = ~0u;   // events list follows the step when it changes
    uint32_t transcriptScrolledTo = ~0u;
    char findText[64] = "";  // the canvas's find box (Ctrl+F)
    bool focusFind = false;
    bool findFailed = false;              // ui.message is the find box's "why not"
    std::string browseDir;                // the Open panel's folder browser
    bool openFailed = false;              // the last open from the Open panel failed
    FeatureScan features;                 // the Open panel's verdicts of a collection's features
    uint64_t featuresGeneration = ~0ull;  // Model::generation() the scan was chosen for
    bool featuresOffered = false;  // the scan is of a collection that failed whole: shown once done
    ShrinkJob shrink;              // the Shrink panel's background shrink
    uint64_t shrinkGeneration = 0;  // Model::generation() the running shrink started from
    char savePath[1024] = "";       // where the Shrink panel saves the repro
    std::string shrinkNote;         // the Shrink panel's last outcome
    // Presenter mode (panel_caption.cpp, style.cpp). `scale` is uiScale.value() each frame.
    UiScale uiScale;
    Theme theme = Theme::Dark;      // wanted; main applies a change between frames
    bool presenter = false;         // Tab: the canvas and the caption only
    double bottomWanted = 0;        // height the timeline needed last frame (wrapped toolbar)
    double captionHeight = 0;       // height the caption needed last frame
    ImFont* captionFont = nullptr;  // the caption's larger font, rebuilt with the scale
    Rect toolbarEnd, captionRect;   // where the last toolbar button and the caption were
    Rect transcriptCopy;            // the Transcript panel's Copy button as last drawn
    Rect exportOpener;              // the toolbar's Export... button as last drawn
    bool showExport = false;        // the Export panel (panel_export.cpp)
    ExportSettings exportSettings;  // what it exports; its format and path below
    int exportFormat = 0;           // ExportFormat
    char exportPath[1024] = "";
    std::shared_ptr<ExportJob> exportJob;   // running, advanced by main after each frame
    std::string exportNote;                 // the last export's outcome
    bool exportFailed = false;              // ... and whether it failed (drawn red)
    bool showDecisionTree = false;          // the Fig. 9 tree in a window of its own
    std::vector<uint64_t> treeCounts;       // events through each node of the tree, over the trace
    uint64_t treeCountsGeneration = ~0ull;  // Model::generation() they were counted for
    bool showTodo = false;
    uint32_t todoGorge = kNone;  // the to-do list's chosen gorge, drawn on the canvas
    TodoList todo;               // the to-do list of the step below (panel_todo.cpp)
    std::array<uint64_t, 2> todoFor{~0ull, ~0ull};  // Model::generation() and step it was read at
    EditUi edit{model};                             // live editing (panel_edit.cpp)
    bool showDirection = false;  // the flood direction dial (panel_direction.cpp)
    TimelineFold timelineFold;
    TranscriptLines transcriptLines;
    OpenUi openPanel;
    // The findings panel (panel_findings.cpp): each row's rectangle this frame, and the row
    // it last scrolled to.
    std::vector<Rect> findingRows;
    size_t findingsScrolledTo = ~size_t(0);
    // What floats over the canvas, as last drawn (labels keep out from under them): the find
    // box, the Edit box, the Shrink window and the locator inset; empty when not shown.
    Rect findBox, editBox, shrinkBox, inset;
    Rect openingBox;  // an open's progress and Cancel (panel_opening.cpp); empty when none
    // The direction dial's and the State table's windows as last drawn (empty: not shown):
    // floating over the canvas, the fit keeps the polygon out from under them.
    Rect directionBox, stateTableBox;
    std::vector<Rect> fitOverlays;  // canvasOverlays() the canvas last fitted around (main.cpp)
    // Save PNG's confirmation on the canvas: the full path (or why not), until `toastUntil`
    // (platform::time()).
    std::string toast;
    bool toastFailed = false;
    double toastUntil = 0;
    std::string lastExportDir;  // the folder of the last export written: Save PNG writes there
    std::vector<Rect> labels;   // the error view's vertex labels this frame
    Rect stateDiagram;          // where the State machine panel drew its states this frame
    // The step's labels this frame (scene_labels.h), each named for what it labels:
    // "named-vertex-35", "finger-vertex-36", "ghost-vertex-14", "named-triangle-18", ...
    std::vector<std::pair<std::string, Rect>> stepLabels;
    QuizActions quizAsked = QuizActions::all();  // what Q starts the quiz with (panel_quiz.cpp)
    Rect quizBox;     // the quiz window this frame; empty when off (--print-layout)
    Rect quizColumn;  // presenter view: the quiz's column, carved from the canvas (main.cpp)
    // The pending question's words, and the generation and step they were made for (a scan of
    // the events before the step: once per step, not per frame).
    std::pair<uint64_t, std::string> quizPrompt{~0ull, ""};
};

void drawCanvas(Ui& ui);  // panel_canvas.cpp: geometry to the renderer, labels, input
// What drawCanvas paints, without its input and find box: the world to the renderer (as
// Renderer::render draws it next), labels and overlays to `dl`, at ui.layout.canvas through
// model.camera(). Exports call it with their own camera, rectangle and draw list.
void paintCanvas(Ui& ui, ImDrawList* dl);
// What floats over the canvas as last drawn, which a fit keeps the polygon out from under: the
// find and Edit boxes, the Shrink window, the direction dial and the State table (not in
// presenter view, which shows none of them), and the arrow of a turned flood direction.
std::vector<Rect> canvasOverlays(const Ui& ui);
// Where the canvas shows which way the water rises when the flood direction is not the
// default (+y): its bottom-left corner; empty otherwise.
Rect upArrowRect(const Ui& ui);
void drawTimeline(Ui& ui);      // panel_timeline.cpp: strip, transport, go-to, play
void drawStateMachine(Ui& ui);  // panel_state_machine.cpp: the six states of §4
void drawDecision(Ui& ui);      // panel_decision.cpp: the Fig. 9 tree, the current path lit
void drawPredicates(Ui& ui);    // panel_predicates.cpp: those tests' predicates, values, stages
void drawStateTable(Ui& ui);    // panel_state_table.cpp: Fig. 10, combinations against states
void drawBreakpoints(Ui& ui);   // panel_breakpoints.cpp: breakpoints, legend, display options
void drawEvents(Ui& ui);        // panel_events.cpp: every event, clipped
void drawTranscript(Ui& ui);    // panel_transcript.cpp: the paper-style transcript
void drawOpen(Ui& ui);          // panel_open.cpp: polygons/ and recent files
// panel_open.cpp: what a finished open in the window says (ui.message, the Open panel's red
// line, a collection's features listed); `path` is what was opened.
void noteOpened(Ui& ui, const std::string& path);
// panel_opening.cpp: an open under way, its progress and Cancel over the canvas.
void drawOpening(Ui& ui);
void drawShrink(Ui& ui);    // panel_shrink.cpp: shrink a failure, open and save the repro
void drawFindings(Ui& ui);  // panel_findings.cpp: every finding, click to frame, F8 / Shift+F8
// The height the findings panel wants (0: none): its header and up to four findings.
double findingsHeight(const Model& m, float scale);
void drawHelp(Ui& ui);             // panel_help.cpp: keys and glossary
void drawExport(Ui& ui);           // panel_export.cpp: canvas PNG/SVG, GIF, PNG sequence
void handleShortcuts(Ui& ui);      // panel_help.cpp: the keys the help window lists
void drawCaption(Ui& ui);          // panel_caption.cpp: presenter view's step, action, sentence
void handlePresenterKeys(Ui& ui);  // panel_caption.cpp: Tab, F11, Ctrl +/-/0
// style.cpp: ImGui's fonts rasterised at ui.uiScale and its colours for the current theme;
// between frames only (the font texture is uploaded again).
void applyStyle(Ui& ui);
void drawTodo(Ui& ui);  // panel_todo.cpp: pending and held gorges, shown when clicked
// panel_edit.cpp: live editing. editFrame every frame before the canvas (adopts a finished
// flood, carries a drag on); editCanvasInput with the mouse over the canvas, true when it took
// the left button; editOverlay draws handles, pending corners and the live diagnostic;
// editBar is the canvas's Edit toolbar and the save panel; editShortcuts its keys.
void editFrame(Ui& ui);
bool editCanvasInput(Ui& ui, Vec2 mouse);
void editOverlay(Ui& ui, ImDrawList* dl);
void editBar(Ui& ui);
void editShortcuts(Ui& ui);
void drawDirection(Ui& ui);  // panel_direction.cpp: the flood direction dial and its changes
// The Fig. 9 tree as "Tree..." draws it (labels where they fit, bars, a leaf's click seeks) with
// `path` lit, `size` logical pixels at the cursor.
void drawDecisionTree(Ui& ui, ImVec2 size, const DecisionPath& path);
// panel_quiz.cpp: predict the next action. drawQuiz: the question and its choices, or the
// answer revealed, and the score, while the quiz is on; quizShortcuts: Q, and 1-5 / R B S J F
// answering a pending question (true when a key answered it: F then does not fit).
void drawQuiz(Ui& ui);
bool quizShortcuts(Ui& ui);

// Helpers shared by panels (panel_common.cpp).
// Begins a panel's window tiled at a layout rectangle: placed and sized every frame, never
// moved, resized or collapsed by hand; `flags` (ImGuiWindowFlags) adds to that. End it with
// ImGui::End().
void beginTiled(const char* title, const Rect& r, int flags = 0);
// Begins a floating window of `w` x `h` (scaled) placed at (dx, dy) from the canvas corner
// the first time it is shown. False when it is collapsed: the window is already ended then.
bool beginFloating(Ui& ui, const char* title, bool* open, float w, float h, float dx, float dy);
// Begins a bar floating over the canvas 8 px in from its top corner (`right`: the top-right
// one), sized to its contents, translucent, never moved or focused; returns its rectangle
// (what the fit keeps clear). End it with ImGui::End().
Rect beginCanvasBar(Ui& ui, const char* id, bool right);
// A vertex ('v'), triangle ('t') or step ('s') number that finds its target when clicked
// (Model::find); "-" is drawn plain.
void clickable(Ui& ui, const char* text, char kind);
// Toolbars wrap: the next item goes on this line only if `width` more still fits in it.
void sameLineOrWrap(float width);
float buttonWidth(const char* label);
// The current ImGui window's rectangle (between Begin and End).
Rect windowRect();
// The last ImGui item's rectangle, as drawn (where the page's tests click it).
Rect itemRect();
// `text` on one line of at most `width` pixels: cut in the middle ("/home/.../face.json") when
// longer, the whole of it then in a tooltip. `colour` null: the text colour.
void textOneLine(const std::string& text, float width, const ImVec4* colour = nullptr);
// "first-last" (or "first" when count < 2), each end clickable as above.
void clickableRange(Ui& ui, uint32_t first, uint32_t count, char kind);
// "label v", v clickable; nothing for kNone.
void clickableVertex(Ui& ui, const char* label, Index v);
// The paper's letter of a state (Fig. 10): R, B, S, J, F, X; Start is the machine's entry,
// not one of its states ("start").
const char* actionLetter(Action a);
ImVec4 toImVec4(Rgba c);
unsigned toImU32(Rgba c);
// Writes the current step as "<name>-step<N>.svg" where Save PNG writes (pictureFolder).
std::string exportSvg(Ui& ui);
// Save PNG (the toolbar, key P): asks main for the canvas alone as pictureFolder()/
// "<name>-step<N>.png" after this frame (export.h).
void requestSavePng(Ui& ui);
// A confirmation over the canvas's bottom for a few seconds, red when `failed`.
void showToast(Ui& ui, const std::string& text, bool failed);

}  // namespace flood::view
