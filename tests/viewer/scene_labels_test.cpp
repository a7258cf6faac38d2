// The canvas's labels of a step, computed without a window (viewer/scene.h, scene_labels.h):
// at every step of every gallery polygon each vertex and triangle the step's sentence names is
// labelled on the canvas, no two labels cover each other, and the step shows as a transition
// (a faint ghost of the chain and fingers before it). Compiles to nothing without the viewer.
#if __has_include("scene_labels.h")
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "flood/teach/narrate.h"
#include "model.h"
#include "presenter.h"
#include "scene_labels.h"

using namespace flood;
using namespace flood::view;

namespace {

// The text's size as the canvas measures it, near enough: the default font is 7 pixels wide
// per character at 13 pixels; the sentence's names are in the caption's 20-pixel font.
Vec2 textSize(const Scene::Label& l) {
    const double px = l.kind == Scene::LabelKind::Named ? 20 : 13;
    return {double(l.text.size()) * px * 7 / 13 + 4, px + 4};
}

// The canvas's overlay at the model's step: what paintCanvas places (its per-step scene).
Scene stepScene(const Model& m, bool ghost = true) {
    SceneOptions o;
    o.perStepOnly = true;
    o.ghost = ghost;
    return buildScene(m, o);
}

const ShownLabel* find(const std::vector<ShownLabel>& shown, Index vertex, uint32_t triangle) {
    for (const ShownLabel& s : shown)
        if (s.label->kind == Scene::LabelKind::Named && s.label->vertex == vertex &&
            s.label->triangle == triangle)
            return &s;
    return nullptr;
}

bool within(const Rect& in, const Rect& out) {
    return in.x >= out.x && in.y >= out.y && in.x + in.w <= out.x + out.w &&
           in.y + in.h <= out.y + out.h;
}

// Every step of `m` in `canvas`, the find box at its corner: the sentence's names labelled,
// inside the canvas, clear of the find box and of each other. Returns the labels checked.
size_t checkEveryStep(Model& m, const Rect& canvas, const std::string& what) {
    m.fitCamera(canvas);
    const Rect findBox{canvas.x + 8, canvas.y + 8, 300, 30};
    size_t checked = 0;
    for (uint32_t step = 1; step <= m.steps(); ++step) {
        m.seek(step);
        const Scene sc = stepScene(m);
        const std::vector<ShownLabel> shown =
            placeSceneLabels(sc.labels, m.camera(), canvas, {findBox}, textSize, 1);
        const Narration n = narration(m.polygon(), *m.currentEvent());
        const std::string at = what + " step " + std::to_string(step) + ": " + n.text;
        for (const NamedVertex& v : n.vertices) {
            const ShownLabel* l = find(shown, v.vertex, kNone);
            if (!l) {
                ADD_FAILURE() << "vertex " << v.vertex << " is not labelled, " << at;
                continue;
            }
            EXPECT_EQ(l->label->text.rfind(std::to_string(v.vertex) + " ", 0), 0u)
                << l->label->text << ", " << at;
            ++checked;
        }
        const uint32_t last = n.firstTriangle + n.triangleCount;
        for (uint32_t t = n.firstTriangle; t < last; ++t)
            if (n.triangleCount <= kNamedTriangles || t == n.firstTriangle || t + 1 == last) {
                const ShownLabel* l = find(shown, kNone, t);
                if (!l) {
                    ADD_FAILURE() << "triangle " << t << " is not labelled, " << at;
                    continue;
                }
                EXPECT_EQ(l->label->text, "triangle " + std::to_string(t)) << at;
                ++checked;
            }
        for (size_t i = 0; i < shown.size(); ++i) {
            const ShownLabel& a = shown[i];
            EXPECT_TRUE(within(a.at.box, canvas)) << a.label->text << " leaves the canvas, " << at;
            EXPECT_FALSE(overlap(a.at.box, findBox)) << a.label->text << " under the find box";
            for (size_t j = 0; j < i; ++j)
                EXPECT_FALSE(overlap(a.at.box, shown[j].at.box))
                    << "\"" << shown[j].label->text << "\" and \"" << a.label->text
                    << "\" overlap, " << at;
        }
    }
    return checked;
}

}  // namespace

// Issue 27 §1: what the sentence names, the student sees numbered on the canvas, at the
// window's default size and at a projector's in presenter view.
TEST(SceneLabels, EveryNamedVertexOfEveryGalleryStepIsLabelled) {
    const std::vector<GalleryEntry> gallery = readGallery(polygonsDir());
    ASSERT_GE(gallery.size(), 10u);
    size_t checked = 0;
    for (const GalleryEntry& g : gallery) {
        Model m;
        m.open(g.file);
        ASSERT_GT(m.steps(), 0u) << g.file;
        checked += checkEveryStep(m, computeLayout(1280, 800, 1).canvas, g.file + " 1280x800");
        checked += checkEveryStep(m, presenterLayout(1920, 1080, 130).canvas,
                                  g.file + " presenter 1920x1080");
        m.cancelInvariants();
    }
    EXPECT_GT(checked, 1000u);
}

// Fig. 7 step 23: "below NextRight (vertex 14)" points at something drawn: NextRight's ghost
// sits at 14 (the marker after the Bridge is at 36), and the chain before the step shows
// faint where it differs from the chain after.
TEST(SceneLabels, Figure7Step23ShowsNextRightBeforeAsAGhost) {
    Model m;
    m.open(polygonsDir() + "/paper-figure-7.json");
    m.seek(23);
    ASSERT_EQ(m.currentEvent()->action, Action::Bridge);
    const Point v14 = m.polygon().vertices[14];
    auto ghostAt14 = [&](const Scene& sc) {
        return std::any_of(sc.markers.begin(), sc.markers.end(), [&](const Scene::Marker& k) {
            return k.p == v14 && k.shape == Scene::Shape::Finger &&
                   k.color.r == palette::kNextRight.r && k.color.g == palette::kNextRight.g &&
                   k.color.a < 255;
        });
    };
    auto faintChain = [](const Scene& sc) {
        return std::count_if(sc.lines.begin(), sc.lines.end(), [](const Scene::Line& l) {
            return l.color.r == palette::kChain.r && l.color.g == palette::kChain.g &&
                   l.color.a < 255;
        });
    };
    const Scene with = stepScene(m), without = stepScene(m, false);
    EXPECT_EQ(m.state().fingers.nextRight, 36u);
    EXPECT_TRUE(ghostAt14(with));
    EXPECT_FALSE(ghostAt14(without));
    EXPECT_EQ(size_t(faintChain(with)), m.chainBefore().size() - 1);
    EXPECT_EQ(faintChain(without), 0);
    EXPECT_NE(m.chainBefore(), m.state().chain);
    // The chain before is the state a step back, and leaves the replay where it was.
    const std::vector<Index> before = m.chainBefore(), after = m.state().chain;
    m.seek(22);
    EXPECT_EQ(m.state().chain, before);
    m.seek(23);
    EXPECT_EQ(m.state().chain, after);
    // Its labels: the three names, each with its role; NextRight's ghost is named once.
    std::vector<std::string> named;
    for (const Scene::Label& l : with.labels)
        if (l.kind == Scene::LabelKind::Named) named.push_back(l.text);
    EXPECT_EQ(named, (std::vector<std::string>{"35 sag", "14 NextRight before", "51 bridge end",
                                               "triangle 18"}));
    for (const Scene::Label& l : with.labels)
        EXPECT_FALSE(l.kind == Scene::LabelKind::Ghost && l.vertex == 14) << l.text;
    m.cancelInvariants();
}

// The SVG export places the step's labels as the canvas does, the sentence's names larger.
TEST(SceneLabels, TheSvgNamesWhatTheSentenceNames) {
    Model m;
    m.open(polygonsDir() + "/paper-figure-7.json");
    m.seek(23);
    m.fitCamera({0, 0, 1280, 800});
    std::ostringstream out;
    writeSceneSvg(out, buildScene(m), m.camera(), 1280, 800);
    const std::string svg = out.str();
    for (const char* name :
         {">35 sag<", ">14 NextRight before<", ">51 bridge end<", ">triangle 18<"}) {
        const size_t at = svg.find(name);
        ASSERT_NE(at, std::string::npos) << name;
        const size_t text = svg.rfind("<text", at);
        EXPECT_NE(svg.substr(text, at - text).find("font-size=\"16\""), std::string::npos) << name;
    }
    m.cancelInvariants();
}

// A ghost or a gorge label that finds no free place is left out; a name never is.
TEST(SceneLabels, OptionalLabelsGiveWayNamesStay) {
    Camera cam;
    cam.fitBox(0, 0, 100, 100, {0, 0, 200, 200});
    std::vector<Scene::Label> labels(3);
    for (Scene::Label& l : labels) l.p = {50, 50};
    labels[0].kind = Scene::LabelKind::Gorge, labels[0].text = "pending 1";
    labels[1].kind = Scene::LabelKind::Named, labels[1].text = "7 sag";
    labels[2].kind = Scene::LabelKind::Finger, labels[2].text = "L";
    // Room for one label only: the name takes it, the finger stays (overlapping), the gorge
    // goes.
    auto huge = [](const Scene::Label&) { return Vec2{150, 150}; };
    std::vector<ShownLabel> shown = placeSceneLabels(labels, cam, {0, 0, 200, 200}, {}, huge, 1);
    ASSERT_EQ(shown.size(), 2u);
    EXPECT_EQ(shown[0].label->text, "7 sag");
    EXPECT_EQ(shown[1].label->text, "L");
    // With room, all three, named first.
    auto small = [](const Scene::Label&) { return Vec2{20, 10}; };
    shown = placeSceneLabels(labels, cam, {0, 0, 200, 200}, {}, small, 1);
    ASSERT_EQ(shown.size(), 3u);
    EXPECT_EQ(shown[2].label->text, "pending 1");
    for (size_t i = 0; i < shown.size(); ++i)
        for (size_t j = 0; j < i; ++j) EXPECT_FALSE(overlap(shown[i].at.box, shown[j].at.box));
}

#endif
