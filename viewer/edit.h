// Live editing (issue 12): the loaded polygon's rings changed by undoable commands — move a
// vertex, insert one on an edge, delete one, add a ring from clicked corners, move a whole
// ring, start from nothing. No ImGui, no GL: the canvas (panel_edit.cpp) turns the mouse and
// keys into these calls, tests/viewer/viewer_edit_test.cpp calls them directly.
//
// Every edit hands the new polygon to the Model at once (Model::adoptEdit): validated and
// flooded again under the same name, at the same step (clamped to the new trace). An edit
// that makes the polygon invalid is kept, and the verdict shows the validator's diagnostic;
// undo brings the valid polygon back. With `background` set the flood runs in a thread and
// the old trace stays on screen until the new one is ready (poll() adopts it). The direction
// dial floods through here too (setUp), so turning it never floods on the UI thread either.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "model.h"

namespace flood::view {

// One undoable change of the rings, with what it takes to do it again and to take it back.
// Vertices are named by ring and position in it, which stay meaningful while other commands
// are undone and redone around them (global vertex numbers shift on insert and delete).
struct EditCommand {
    enum class Kind : uint8_t {
        MoveVertex,    // rings[ring][at]: from -> to
        InsertVertex,  // `to` becomes rings[ring][at]
        DeleteVertex,  // rings[ring][at] (it was `from`) removed
        AddRing,     // `after` becomes ring `ring`: a new part's outer ring if `outer`, else a hole
        RemoveRing,  // the inverse: ring `ring` (`before`) removed, with its part if `outer`
        MoveRing,    // ring `ring`'s points: before -> after
        Replace,     // the whole polygon: `was` -> `now` (a new empty canvas)
    };
    Kind kind = Kind::MoveVertex;
    Index ring = 0, at = 0;
    bool outer = false;
    Point from, to;
    std::vector<Point> before, after;
    Polygon was, now;
    std::string label;  // "move vertex 3 of ring 0", for the Undo button's tooltip
};

class Editor {
public:
    explicit Editor(Model& model) : model_(model) {}
    ~Editor();
    Editor(const Editor&) = delete;
    Editor& operator=(const Editor&) = delete;

    // Flood in a thread (the viewer); tests leave it off or call wait(). `onReady` is
    // called from that thread when a flood is done (the viewer wakes its event loop).
    bool background = false;
    std::function<void()> onReady;

    // The polygon being edited: the model's, ahead of it while a background flood runs.
    // When the model opened something else, the history is dropped and editing starts
    // again from what is loaded.
    const Polygon& polygon();

    // A gesture (one mouse drag) makes one command however many moves it has: between
    // beginGesture() and endGesture(), moves of the same vertex or ring are merged.
    void beginGesture();
    void endGesture();

    // Each returns false, with why in message(), when it does nothing.
    bool moveVertex(Index v, Point to);
    // A new vertex at `p` on the edge from `edge` to the next vertex of its ring.
    bool insertVertex(Index edge, Point p);
    // Removes vertex v; the last vertex of a hole removes the hole, of an outer ring the part
    // (refused while the part still has holes).
    bool deleteVertex(Index v);
    // A ring through `corners`: a hole of the part whose outer ring has corners[0] inside
    // (exact winding number), else the outer ring of a new part (on an empty canvas, the
    // polygon). Outer rings need 3 corners; a hole may be a single Steiner point.
    bool addRing(const std::vector<Point>& corners);
    // Ring `ring` moved by `offset` from where it was when the gesture began (so a drag never
    // accumulates rounding).
    bool moveRing(Index ring, Point offset);
    // An empty canvas ("draw your own"); undo brings the polygon back.
    void newEmpty();

    // The flood direction (the direction dial): the edited polygon floods again along `up`,
    // as after an edit (in the background, one flood at a time, the latest direction next),
    // at the same step; the Model's previousSummary() is then the run before. Not an edit:
    // nothing to undo. False, nothing done, when `up` is not a direction or is up() already.
    bool setUp(Up up);
    Up up() { return sync(), up_; }  // the direction asked for, ahead of the Model's
    // Floods started (each edit's, each turn's) since this editor was made: a drag of the
    // dial through many angles starts few of them in the background.
    uint64_t floods() const { return floods_; }

    bool undo();
    bool redo();
    // These follow the model too: after an open there is nothing to undo.
    bool canUndo() { return sync(), done_ > 0; }
    bool canRedo() { return sync(), done_ < history_.size(); }
    const std::string& undoLabel();  // "" when there is nothing to undo
    const std::string& redoLabel();
    size_t historySize() { return sync(), history_.size(); }
    const std::string& message() const { return message_; }

    // The "new ring" tool: corners clicked so far, not yet in the polygon.
    std::vector<Point> corners;
    // Closes the pending ring (addRing(corners)), clearing the corners when it is added.
    bool closeRing();

    // The Model shows the latest edit: adopts a finished background flood, starts the next
    // one if edits came in meanwhile. Every frame; a no-op when nothing is pending.
    void poll();
    bool pending() const { return job_.started() || dirty_; }
    void wait();  // until the Model shows the latest edit (tests)

    // Where Ctrl+S saves by default: beside the input, "<stem>-edited.json", with -2, -3, ...
    // added while such a file exists (the input is never the default).
    std::string defaultSavePath() const;
    // Saves the edited polygon as GeoJSON (saveGeoJson: atomic). Refuses an empty polygon,
    // and the input file itself unless `overwriteInput`.
    Diagnostic save(const std::string& path, bool overwriteInput = false);

    // Picking on the edited polygon (screen coordinates, the model's camera), so indices match
    // the calls above even while a flood is pending. kNone when nothing is that close.
    Index pickVertex(Vec2 screen, double radiusPx);
    Index pickEdge(Vec2 screen, double radiusPx, Point* onEdge = nullptr);  // its first vertex

private:
    void sync();               // follow the model if it opened something else
    bool push(EditCommand c);  // applies and records it (merging within a gesture)
    void apply(const EditCommand& c, bool forward);
    void reflood();  // hands polygon_ to the model (now, or in a thread)
    void startJob();
    void finishJob();  // joins the flood and adopts it unless an open overtook it

    Model& model_;
    Polygon polygon_;
    uint64_t generation_ = ~0ull;  // the model generation polygon_ belongs to
    std::string name_;             // the loaded file's name, kept by every edit
    Up up_ = Up::PlusY;            // the direction polygon_ floods along
    std::vector<EditCommand> history_;
    size_t done_ = 0;  // commands applied: history_[0, done_)
    bool gesture_ = false, merging_ = false;
    std::string message_;

    // Background flood: one at a time; edits made meanwhile wait (dirty_) for the next.
    Model::EditedRun jobResult_;
    Job job_;  // after what it writes: destroyed (joined) first
    bool dirty_ = false;
    uint64_t floods_ = 0;
};

}  // namespace flood::view
