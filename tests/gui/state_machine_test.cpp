// The State machine panel (panel_state_machine.cpp) through a window-free Dear ImGui context:
// at the window sizes and UI scales a class uses, no state's name is cut by the panel's edge
// (a panel too narrow for the names shows the paper's letters). What ImGui would draw is read
// back from its draw lists: every glyph of the panel's text lies, across, inside the clip
// rectangle it is drawn under. No display and no GL.
#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <string>

#include "panels.h"
#include "windowless_imgui.h"

using namespace flood;
using namespace flood::view;

namespace {

// The panel drawn once at W x H and `scale` (fonts and sizes scaled as the viewer's Ctrl+
// does); the count of its glyphs' vertices outside their clip rectangle, and of all of them.
std::pair<int, int> drawnOutside(int W, int H, float scale) {
    ImGuiIO& io = createWindowlessImGui(float(W), float(H));
    io.FontGlobalScale = scale;
    ImGui::GetStyle().ScaleAllSizes(scale);
    Model m;
    m.open(polygonsDir() + "/paper-figure-7.json");
    m.seek(23);         // a Bridge after a Raise: the path between two states drawn bold
    Renderer renderer;  // never initialised: nothing here draws
    Ui ui(m, renderer);
    ui.scale = scale;
    ui.layout = computeLayout(W, H, scale);
    int outside = 0, all = 0;
    for (int frame = 0; frame < 2; ++frame) {  // windows settle on the second frame
        ImGui::NewFrame();
        drawStateMachine(ui);
        ImGui::Render();
    }
    const ImDrawData* d = ImGui::GetDrawData();
    const ImVec2 white = io.Fonts->TexUvWhitePixel;
    for (int l = 0; l < d->CmdListsCount; ++l) {
        const ImDrawList* list = d->CmdLists[l];
        if (!list->_OwnerName || std::string(list->_OwnerName) != "State machine") continue;
        for (const ImDrawCmd& c : list->CmdBuffer) {
            // The window's frame is drawn under the whole display's clip: not the panel's.
            if (c.ClipRect.x <= 0 && c.ClipRect.z >= float(W)) continue;
            for (unsigned i = 0; i < c.ElemCount; ++i) {
                const ImDrawVert& v =
                    list->VtxBuffer[list->IdxBuffer[c.IdxOffset + i] + c.VtxOffset];
                // Text only: a glyph samples the font atlas, a shape its white pixel.
                if (v.uv.x == white.x && v.uv.y == white.y) continue;
                // The states' names only (the widgets under them are ImGui's to fit), and
                // what shows: below the panel's foot its content scrolls, it is not cut.
                const Rect& r = ui.stateDiagram;
                if (v.pos.y < std::max<double>(r.y, c.ClipRect.y - 1) ||
                    v.pos.y > std::min<double>(r.y + r.h, c.ClipRect.w + 1))
                    continue;
                ++all;
                outside += v.pos.x < c.ClipRect.x - 1 || v.pos.x > c.ClipRect.z + 1;
            }
        }
    }
    m.cancelInvariants();
    ImGui::DestroyContext();
    return {outside, all};
}

}  // namespace

TEST(StateMachinePanel, NoNameIsCutAtAnySizeOrScale) {
    // 800x1080 at 250%: a tall narrow window, where the names were cut ("Fil", "aise").
    for (auto [W, H, scale] : {std::tuple{1280, 800, 1.f},
                               {900, 600, 1.f},
                               {1280, 800, 2.5f},
                               {800, 1080, 2.5f},
                               {800, 1080, 1.25f},
                               {1920, 1080, 1.5f},
                               {1920, 1080, 3.f},
                               {1024, 700, 2.f}}) {
        const auto [outside, all] = drawnOutside(W, H, scale);
        EXPECT_GT(all, 100) << W << "x" << H << " at " << scale << ": the panel drew nothing";
        EXPECT_EQ(outside, 0) << W << "x" << H << " at " << scale << ": " << outside << " of "
                              << all << " vertices cut by the panel's edge";
    }
}
