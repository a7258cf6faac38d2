// The Open panel's list of a collection's features (panel_open.cpp), window-free as
// ui_state_test.cpp: a collection that cannot be read whole (one feature broken) shows the
// list of its features at once instead of an empty canvas; a broken single polygon, or a
// readable file, does not open the panel by itself.
#include <gtest/gtest.h>
#include <imgui.h>

#include <fstream>
#include <string>

#include "flood/flood_api.h"
#include "panels.h"
#include "windowless_imgui.h"

using namespace flood;
using namespace flood::view;

namespace {

class OpenPanel : public ::testing::Test {
protected:
    void SetUp() override { createWindowlessImGui(1280, 800); }
    void TearDown() override { ImGui::DestroyContext(); }

    // Frames of the Open panel until the feature scan it started (if any) is done.
    void settle() {
        for (int i = 0; i < 3; ++i) {
            ImGui::NewFrame();
            drawOpen(ui);
            ImGui::EndFrame();
            ui.features.wait();
        }
    }

    Model model;
    Renderer renderer;  // never initialised: nothing here draws
    Ui ui{model, renderer};
};

std::string source(const std::string& rel) { return std::string(FLOOD_SOURCE_DIR) + "/" + rel; }

}  // namespace

TEST_F(OpenPanel, ACollectionThatFailsWholeListsItsFeatures) {
    model.open(source("polygons/datasets/mixed.geojson"));
    ASSERT_EQ(model.inputDiagnostic().status, Status::Malformed) << "feature 5 is broken";
    ASSERT_TRUE(model.polygon().vertices.empty());
    ASSERT_FALSE(ui.showOpen);
    settle();
    EXPECT_TRUE(ui.showOpen) << "the list of the features that open, not an empty canvas";
    EXPECT_EQ(ui.features.path(), model.path());
    EXPECT_EQ(ui.features.features().size(), 9u) << "every polygonal feature, judged";
    // Once shown and closed, the same file does not bring it back frame after frame.
    ui.showOpen = false;
    settle();
    EXPECT_FALSE(ui.showOpen);
}

TEST_F(OpenPanel, ABrokenPolygonOrAGoodFileLeavesThePanelClosed) {
    const std::string broken = std::string(::testing::TempDir()) + "flood-open-panel-broken.json";
    std::ofstream(broken) << "[[[0,0],[4,0],[4,\"four\"]]]";
    model.open(broken);
    ASSERT_EQ(model.inputDiagnostic().status, Status::Malformed);
    settle();
    EXPECT_FALSE(ui.showOpen) << "one polygon: nothing to list";

    model.open(source("polygons/paper-figure-7.json"));
    ASSERT_TRUE(model.inputDiagnostic().ok());
    settle();
    EXPECT_FALSE(ui.showOpen);
    EXPECT_NE(ui.features.path(), model.path()) << "no scan of a file that opened whole";
}
