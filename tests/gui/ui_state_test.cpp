// What the panels compute for a trace lives in the Ui they draw, never in function-local
// statics: two viewers (two Models, two Uis) whose traces share a generation number each keep
// their own. Window-free Dear ImGui, as edit_input_test.cpp; nothing is rendered.
#include <gtest/gtest.h>
#include <imgui.h>

#include "flood/flood_api.h"
#include "flood/tools/generate.h"
#include "panels.h"
#include "windowless_imgui.h"

using namespace flood;
using namespace flood::view;

namespace {

class PanelState : public ::testing::Test {
protected:
    void SetUp() override {
        createWindowlessImGui(1200, 800);
        big.openPolygon(generate("circle-holes", 7, 1500), "circle-holes", {});
        Polygon p = makePolygon({{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}}});
        small.openPolygon(p, "square", validate(p, "square"));
        for (Ui* ui : {&a, &b}) ui->layout = computeLayout(1200, 800, 1);
    }
    void TearDown() override { ImGui::DestroyContext(); }

    // One frame in which both viewers draw `panel`.
    template <class Panel>
    void frame(Panel panel) {
        ImGui::NewFrame();
        panel(a);
        panel(b);
        ImGui::EndFrame();
    }

    Model big, small;
    Renderer renderer;  // never initialised: nothing here draws
    Ui a{big, renderer}, b{small, renderer};
};

}  // namespace

TEST_F(PanelState, EachUiFlowsItsOwnTranscript) {
    ASSERT_EQ(big.generation(), small.generation()) << "the case a shared cache gets wrong";
    ASSERT_GT(big.transcript().size(), small.transcript().size());
    frame(drawTranscript);
    ASSERT_FALSE(a.transcriptLines.start.empty());
    ASSERT_FALSE(b.transcriptLines.start.empty());
    EXPECT_EQ(a.transcriptLines.start.back(), big.transcript().size());
    EXPECT_EQ(b.transcriptLines.start.back(), small.transcript().size());
}

TEST_F(PanelState, EachUiFoldsItsOwnTimeline) {
    frame(drawTimeline);
    // The big run has more events than the strip has 3-pixel buckets: folded, for its trace.
    EXPECT_FALSE(a.timelineFold.buckets.empty());
    EXPECT_EQ(a.timelineFold.generation, big.generation());
    // The square's few events are drawn one mark each: nothing folded, nothing borrowed.
    EXPECT_TRUE(b.timelineFold.buckets.empty());
}
