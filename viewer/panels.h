// The viewer's panels, one file each (panel_*.cpp). They read the Model, change it only through
// its methods, and share the small UI state below. ImGui lives here, never in the model.
// A new panel: write panel_<name>.cpp with draw<Name>(Ui&), declare it below, call it from the
// frame in main.cpp, and give it a rectangle of computeLayout() (model.cpp) or let it float.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "canvas_geometry.h"
#include "model.h"
#include "renderer.h"
#include "scene.h"

struct ImVec4;

namespace flood::view {

// What the canvas keeps between frames: which trace and step its GPU buffers hold, and the
// per-step overlay's labels and arrows (panel_canvas.cpp).
struct CanvasState {
    uint64_t generation = ~0ull;  // Model::generation() of the uploaded geometry
    uint32_t overlayStep = ~0u;
    SceneOptions overlayOptions;
    Point origin;
    float bbox[4] = {0, 0, 0, 0};  // of the polygon, minus the origin
    TriangleGrid grid;  // triangle labels by cell
    TriangleGrid vertexGrid;  // vertex labels by cell
    std::vector<MarkerVertex> vertexMarkers;  // classes first, then regular: thinned per camera
    std::array<double, 8> thinKey{};  // camera centre x, y, scale, viewport w, h, x, y, step
    CanvasOverlay overlay;
    WorldView view;     // what Renderer::render draws this frame
    // Hover picking is a scan of the polygon: redo it only when something moved.
    std::array<double, 6> pickKey{};  // mouse x, y, camera centre x, y, scale, step
    Index pickedVertex = kNone;
    int64_t pickedTriangle = -1;
};

struct Ui {
    Ui(Model& m, Renderer& r) : model(m), renderer(r) {}
    Model& model;
    Renderer& renderer;
    float scale = 1;   // UI scale from the monitor's content scale
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
    char findText[64] = "";            // the canvas's find box (Ctrl+F)
    bool focusFind = false;
    bool findFailed = false;           // ui.message is the find box's "why not"
    std::string browseDir;             // the Open panel's folder browser
    bool openFailed = false;           // the last open from the Open panel failed
    FeatureScan features;              // the Open panel's verdicts of a collection's features
    uint64_t featuresGeneration = ~0ull;  // Model::generation() the scan was chosen for
    ShrinkJob shrink;                  // the Shrink panel's background shrink
    uint64_t shrinkGeneration = 0;     // Model::generation() the running shrink started from
    char savePath[1024] = "";          // where the Shrink panel saves the repro
    std::string shrinkNote;            // the Shrink panel's last outcome
    bool showDirection = false;        // the flood direction dial (panel_direction.cpp)
};

void drawCanvas(Ui& ui);         // panel_canvas.cpp: geometry to the renderer, labels, input
void drawTimeline(Ui& ui);       // panel_timeline.cpp: strip, transport, go-to, play
void drawStateMachine(Ui& ui);   // panel_state_machine.cpp: the six states of §4
void drawDecision(Ui& ui);       // panel_decision.cpp: the Fig. 9 tests of the current event
void drawPredicates(Ui& ui);     // panel_predicates.cpp: those tests' predicates, values, stages
void drawStateTable(Ui& ui);     // panel_state_table.cpp: Fig. 10, combinations against states
void drawBreakpoints(Ui& ui);    // panel_breakpoints.cpp: breakpoints, legend, display options
void drawEvents(Ui& ui);         // panel_events.cpp: every event, clipped
void drawTranscript(Ui& ui);     // panel_transcript.cpp: the paper-style transcript
void drawOpen(Ui& ui);           // panel_open.cpp: polygons/ and recent files
void drawShrink(Ui& ui);         // panel_shrink.cpp: shrink a failure, open and save the repro
void drawHelp(Ui& ui);           // panel_help.cpp: keys and glossary
void handleShortcuts(Ui& ui);    // panel_help.cpp: the keys the help window lists
void drawDirection(Ui& ui);      // panel_direction.cpp: the flood direction dial and its changes

// Helpers shared by panels (panel_common.cpp).
void placeWindow(const Rect& r);  // tiles a panel at a layout rectangle
// Begins a floating window of `w` x `h` (scaled) placed at (dx, dy) from the canvas corner
// the first time it is shown. False when it is collapsed: the window is already ended then.
bool beginFloating(Ui& ui, const char* title, bool* open, float w, float h, float dx, float dy);
// A vertex ('v'), triangle ('t') or step ('s') number that finds its target when clicked
// (Model::find); "-" is drawn plain.
void clickable(Ui& ui, const char* text, char kind);
ImVec4 toImVec4(Rgba c);
unsigned toImU32(Rgba c);
// Writes the current step as "<name>-step<N>.svg" in the working directory.
std::string exportSvg(Ui& ui);

}  // namespace flood::view
