// Edit mode's mouse and keys (panel_edit.cpp) driven through a window-free Dear ImGui context:
// the mouse positions, buttons and keys a user would give, frame by frame, in the order the
// canvas calls edit mode (editFrame, then editCanvasInput over the canvas; the shortcuts).
// No display and no GL: ImGui runs on its own, the renderer is never initialised.
#include <gtest/gtest.h>
#include <imgui.h>

#include <cmath>

#include "flood/flood_api.h"
#include "panels.h"
#include "windowless_imgui.h"

using namespace flood;
using namespace flood::view;

namespace {

// GLFW's key codes, which the viewer's ImGui backend puts in io.KeysDown.
constexpr int kDelete = 261, kEnter = 257, kEscape = 256;

class EditInput : public ::testing::Test {
protected:
    void SetUp() override {
        ImGuiIO& io = createWindowlessImGui(1200, 1000);
        io.KeyMap[ImGuiKey_Delete] = kDelete;
        io.KeyMap[ImGuiKey_Enter] = kEnter;
        io.KeyMap[ImGuiKey_Escape] = kEscape;
        io.KeyMap[ImGuiKey_Backspace] = 259;
        Polygon p =
            makePolygon({{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{4, 4}, {4, 6}, {6, 6}, {6, 4}}}});
        model.openPolygon(p, "square.json", validate(p, "square.json"));
        ui.layout.canvas = {100, 0, 1000, 1000};
        model.fitCamera(ui.layout.canvas);  // 88 px per unit: clicks round to 0.01
        ui.edit.editor.onReady = nullptr;   // no event loop to wake
        ui.edit.on = true;
    }
    void TearDown() override {
        ui.edit.editor.wait();
        ImGui::DestroyContext();
    }

    // One frame with the mouse at `world`, the left button and keys as given.
    void frame(Point world, bool down, std::initializer_list<int> keys = {}, bool shift = false,
               bool ctrl = false) {
        ImGuiIO& io = ImGui::GetIO();
        Vec2 s = model.camera().toScreen(world);
        io.MousePos = ImVec2(float(s.x), float(s.y));
        io.MouseDown[0] = down;
        io.KeyShift = shift;
        io.KeyCtrl = ctrl;
        for (bool& k : io.KeysDown) k = false;
        for (int k : keys) io.KeysDown[k] = true;
        ImGui::NewFrame();
        editFrame(ui);
        if (!io.WantCaptureMouse) editCanvasInput(ui, {io.MousePos.x, io.MousePos.y});
        editShortcuts(ui);
        ImGui::EndFrame();
    }
    void key(int k, bool shift = false, bool ctrl = false, Point at = {20, 20}) {
        frame(at, false, {k}, shift, ctrl);
        frame(at, false, {}, shift, ctrl);
    }
    void settle() { ui.edit.editor.wait(); }
    Point vertex(Index v) const { return model.polygon().vertices[v]; }

    Model model;
    Renderer renderer;  // never initialised: nothing here draws
    Ui ui{model, renderer};
};

}  // namespace

TEST_F(EditInput, DragAVertexMovesItToTheRoundedMousePositionAndCtrlZUndoes) {
    frame({10, 10}, false);
    frame({10, 10}, true);  // press on vertex 2
    frame({10.5, 11}, true);
    frame({11, 12}, true);
    frame({11, 12}, false);  // release
    settle();
    EXPECT_EQ(vertex(2), (Point{11, 12}));
    EXPECT_EQ(ui.edit.editor.historySize(), 1u) << "one drag, one command";
    EXPECT_FALSE(model.failed()) << model.verdict();
    key('Z', false, true);
    settle();
    EXPECT_EQ(vertex(2), (Point{10, 10}));
    key('Z', true, true);  // Ctrl+Shift+Z
    settle();
    EXPECT_EQ(vertex(2), (Point{11, 12}));
    key('Z', false, true);
    key('Y', false, true);
    settle();
    EXPECT_EQ(vertex(2), (Point{11, 12}));
}

TEST_F(EditInput, DoubleClickOnAnEdgeInsertsAVertexThere) {
    frame({5, 0}, false);
    frame({5, 0}, true);
    frame({5, 0}, false);
    frame({5, 0}, true);  // the second click
    frame({5, 0}, false);
    settle();
    ASSERT_EQ(model.polygon().rings[0].count, 5u);
    EXPECT_EQ(vertex(1), (Point{5, 0}));
    EXPECT_EQ(vertex(2), (Point{10, 0}));
}

TEST_F(EditInput, ShiftDragMovesTheWholeRing) {
    frame({4, 5}, false, {}, true);  // on the hole's edge (4,4)-(4,6)
    frame({4, 5}, true, {}, true);
    frame({3.5, 5}, true, {}, true);
    frame({3, 6}, true, {}, true);
    frame({3, 6}, false, {}, true);
    settle();
    EXPECT_EQ(vertex(4), (Point{3, 5}));
    EXPECT_EQ(vertex(6), (Point{5, 7}));
    EXPECT_EQ(vertex(0), (Point{0, 0})) << "the outer ring stays";
}

TEST_F(EditInput, DeleteRemovesTheHoveredVertex) {
    frame({10, 10}, false);
    key(kDelete, false, false, {10, 10});
    settle();
    EXPECT_EQ(model.polygon().rings[0].count, 3u);
    EXPECT_EQ(vertex(2), (Point{0, 10}));
}

TEST_F(EditInput, RingToolClosesOnTheFirstCornerOrEnter) {
    key('H');
    ASSERT_TRUE(ui.edit.ringTool);
    for (Point c : {Point{1, 1}, Point{2, 1}, Point{2, 2}, Point{1, 1}}) {  // the last closes
        frame(c, true);
        frame(c, false);
    }
    settle();
    ASSERT_EQ(model.polygon().rings.size(), 3u);
    EXPECT_EQ(model.polygon().rings[2].count, 3u);
    EXPECT_FALSE(ui.edit.ringTool);
    EXPECT_FALSE(model.failed()) << model.verdict();

    // Ctrl+N: an empty canvas with the tool on; three corners and Enter give a triangle.
    key('N', false, true);
    settle();
    EXPECT_TRUE(model.polygon().vertices.empty());
    ASSERT_TRUE(ui.edit.ringTool);
    for (Point c : {Point{0, 0}, Point{4, 0}, Point{0, 3}}) {
        frame(c, true);
        frame(c, false);
    }
    key(kEnter);
    settle();
    ASSERT_EQ(model.polygon().vertices.size(), 3u);
    EXPECT_EQ(model.trace().triangles.size(), 1u);
    EXPECT_FALSE(model.failed()) << model.verdict();
}

TEST_F(EditInput, CtrlSOffersAPathBesideTheInput) {
    key('S', false, true);
    EXPECT_TRUE(ui.edit.showSave);
    EXPECT_EQ(std::string(ui.edit.savePath), ui.edit.editor.defaultSavePath());
    EXPECT_NE(std::string(ui.edit.savePath), "square.json");
}

TEST_F(EditInput, MOutsideEditModeTurnsItOnAndADragOnEmptySpaceIsLeftToPanning) {
    ui.edit.on = false;
    key('M');
    EXPECT_TRUE(ui.edit.on);
    frame({7, 2}, false);
    frame({7, 2}, true);
    frame({8, 3}, true);
    frame({8, 3}, false);
    settle();
    EXPECT_FALSE(ui.edit.editor.canUndo()) << "nothing was grabbed";
}
