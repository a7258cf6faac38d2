// The paper's Fig. 9 drawn live: the decision tree (flood/teach/decision_tree.h) as boxes and edges,
// the current event's path lit, the nodes it did not reach (or reached without running) grey,
// forbidden states red; below it the event narrated in a sentence, and the vertices, triangles
// and step it names, each clickable. The panel's tree is a thumbnail (a dozen rows in a fifth of
// the window cannot carry labels): hovering names a box, clicking opens the tree large,
// labelled and with each node's count over the trace, as "Tree..." does; clicking a leaf there
// seeks to the next event that ends in it. Colours: palette::tree(), per theme.
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "flood/teach/decision_tree.h"
#include "flood/teach/narrate.h"
#include "panels.h"

namespace flood::view {

namespace {

using Kind = DecisionNode::Kind;

// Halfway to the panel's background: what the current event did not take, in either theme.
Rgba dim(Rgba c) {
    const ImVec4 bg = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
    auto mix = [](uint8_t a, float b) { return uint8_t((float(a) + b * 255.0f) / 2 + 0.5f); };
    return {mix(c.r, bg.x), mix(c.g, bg.y), mix(c.b, bg.z), 255};
}

// The events through each node, counted once per opened trace.
const std::vector<uint64_t>& counts(Ui& ui) {
    if (ui.treeCountsGeneration != ui.model.generation()) {
        ui.treeCounts = countPaths(ui.model.trace().events);
        ui.treeCountsGeneration = ui.model.generation();
    }
    return ui.treeCounts;
}

void tooltip(const DecisionNode& n, uint64_t count, bool full) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30);
    ImGui::TextUnformatted(n.label);
    if (n.kind == Kind::Stop) {
        for (Forbidden f : n.reasons)
            ImGui::TextColored(toImVec4(palette::kCulprit), "%s: %s", forbiddenName(f),
                               forbiddenText(f));
    } else {
        ImGui::TextDisabled("%s", n.detail);
    }
    ImGui::Text("%llu events of this run pass here", static_cast<unsigned long long>(count));
    if (!full) ImGui::TextDisabled("click: the whole tree, labelled");
    else if (n.leaf()) ImGui::TextDisabled("click: the next step that ends here");
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

// Seeks to the first step after the current one whose event ends at `leaf`, wrapping round.
void seekLeaf(Ui& ui, int leaf) {
    Model& m = ui.model;
    const auto& events = m.trace().events;
    size_t i = nextEventEndingAt(events, leaf, m.step());  // events[step] is the next event
    if (i == events.size()) i = nextEventEndingAt(events, leaf, 0);
    if (i == events.size()) {
        ui.message =
            std::string("no step of this run ends in ") + decisionTree().nodes[size_t(leaf)].label;
        return;
    }
    m.seek(uint32_t(i + 1));
}

// Draws the tree into the rectangle at the cursor, `size` logical pixels; labels where they
// fit. Hovering a node shows what it tests. The `full` tree (its own window) has a bar along
// each box's foot, the share of the run's events that pass there, and a click on a leaf
// seeks; a click on the thumbnail opens the full tree.
void drawTree(Ui& ui, ImVec2 size, const DecisionPath& path, bool full) {
    const DecisionTree& t = decisionTree();
    const palette::TreeColours& colour = palette::tree();
    const std::vector<uint64_t>& count = counts(ui);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 o = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("tree", size);
    const bool hovered = ImGui::IsItemHovered();
    // The thumbnail says what a click does in a strip of its own under the boxes.
    const char* hint = "click to enlarge";
    const ImVec2 hintSize = full ? ImVec2(0, 0) : ImGui::CalcTextSize(hint);
    const float cw = size.x / float(t.columns), ch = (size.y - hintSize.y) / float(t.rows);
    const float bw = cw * float(DecisionTree::kBoxWidth), bh = ch * float(DecisionTree::kBoxHeight);
    auto centre = [&](const DecisionNode& n) {
        return ImVec2(o.x + (float(n.column) + 0.5f) * cw, o.y + (float(n.row) + 0.5f) * ch);
    };
    std::vector<const PathStep*> on(t.nodes.size(), nullptr);
    for (const PathStep& s : path.steps) on[size_t(s.node)] = &s;
    // Answers twice as wide as plain edges, so their colour reads in the thumbnail too.
    const float line = std::max(1.0f, ui.scale), answerLine = 2 * line,
                thick = std::max(3.0f, 3.5f * ui.scale);
    // Each label at the largest size up to the UI's that fits its box; none below a legible size.
    ImFont* fontFace = ImGui::GetFont();
    const float base = ImGui::GetFontSize(), legible = 7 * ui.scale;
    auto labelSize = [&](const char* text) {
        ImVec2 ts = fontFace->CalcTextSizeA(base, 1e9f, 0, text);
        return base * std::min({1.0f, (bw - 6) / ts.x, (bh - 4) / ts.y});
    };

    // Edges first (lit ones last, on top): an elbow from the parent's right to the child's left,
    // green for a yes, blue for a no (never the forbidden red); the path's are thick, in the
    // path colour, with the answer's colour down their middle.
    for (int lit = 0; lit < 2; ++lit)
        for (size_t i = 0; i < t.nodes.size(); ++i) {
            const DecisionNode& n = t.nodes[i];
            for (int k = 0; k < 2; ++k) {
                const int c = k ? n.no : n.yes;
                if (c < 0 || (k && n.no == n.yes)) continue;  // a pass-through test has one edge
                const DecisionNode& child = t.nodes[size_t(c)];
                const bool litEdge = on[i] && on[size_t(c)];
                if (litEdge != bool(lit)) continue;
                const bool answers = n.kind != Kind::Action && n.yes != n.no;
                const Rgba answer = c == n.yes ? colour.yes : colour.no;
                ImVec2 a = centre(n), b = centre(child);
                float mx = a.x + cw * 0.5f;
                ImVec2 pts[4] = {{a.x + bw / 2, a.y}, {mx, a.y}, {mx, b.y}, {b.x - bw / 2, b.y}};
                if (litEdge) dl->AddPolyline(pts, 4, toImU32(palette::kTreePath), 0, thick);
                if (answers)
                    dl->AddPolyline(pts, 4, toImU32(litEdge ? answer : dim(answer)), 0, answerLine);
                else if (!litEdge) dl->AddPolyline(pts, 4, toImU32(colour.edge), 0, line);
            }
        }
    // Boxes.
    int hoveredNode = -1;
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    for (size_t i = 0; i < t.nodes.size(); ++i) {
        const DecisionNode& n = t.nodes[i];
        const ImVec2 c = centre(n), p0(c.x - bw / 2, c.y - bh / 2), p1(c.x + bw / 2, c.y + bh / 2);
        const PathStep* s = on[i];
        const bool reached = s && s->ran;  // a test on the path that did not run stays grey
        Rgba fill = colour.test, border = colour.border, text = colour.label;
        if (n.kind == Kind::Stop) {
            fill = reached ? palette::kCulprit : colour.stop;
            text = reached ? colour.stopLitLabel : colour.leafLabel;
        } else if (n.kind == Kind::Action) {
            fill = reached ? palette::action(n.action) : dim(palette::action(n.action));
            text = reached ? colour.actionLitLabel : colour.leafLabel;
        } else if (reached) {
            fill = colour.testLit, text = colour.testLitLabel;
        }
        if (reached) border = palette::kTreePath;
        const float r = 3 * ui.scale;
        dl->AddRectFilled(p0, p1, toImU32(fill), r);
        dl->AddRect(p0, p1, toImU32(border), r, 0, reached ? thick : line);
        if (full && count[i]) {
            const float share =
                float(double(count[i]) / double(std::max<size_t>(1, ui.model.steps())));
            const float foot = std::max(2.0f, bh * 0.12f);
            dl->AddRectFilled(ImVec2(p0.x + 2, p1.y - foot - 1),
                              ImVec2(p0.x + 2 + (bw - 4) * share, p1.y - 1),
                              toImU32(palette::kTreePath));
        }
        if (const float f = labelSize(n.label); f >= legible) {
            ImVec2 ts = fontFace->CalcTextSizeA(f, 1e9f, 0, n.label);
            dl->AddText(fontFace, f, ImVec2(c.x - ts.x / 2, c.y - ts.y / 2), toImU32(text),
                        n.label);
        }
        if (hovered && mouse.x >= p0.x && mouse.x < p1.x && mouse.y >= p0.y && mouse.y < p1.y)
            hoveredNode = int(i);
    }
    if (!full) {
        dl->AddText(ImVec2(o.x + size.x - hintSize.x - 2, o.y + size.y - hintSize.y),
                    ImGui::GetColorU32(ImGuiCol_TextDisabled), hint);
        if (hovered) {
            ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
            if (ImGui::IsItemClicked()) ui.showDecisionTree = true;
        }
    }
    if (hoveredNode < 0) return;
    tooltip(t.nodes[size_t(hoveredNode)], count[size_t(hoveredNode)], full);
    if (full && t.nodes[size_t(hoveredNode)].leaf() && ImGui::IsMouseClicked(ImGuiMouseButton_Left))
        seekLeaf(ui, hoveredNode);
}

// "label N" with N clickable (a vertex, triangle or step number); nothing for kNone.
void number(Ui& ui, const char* label, uint64_t value, char kind) {
    if (value == kNone) return;
    ImGui::SameLine(0, ImGui::GetStyle().ItemSpacing.x * 2);
    ImGui::TextDisabled("%s", label);
    ImGui::SameLine(0, 3 * ui.scale);
    char text[24];
    std::snprintf(text, sizeof text, "%llu", static_cast<unsigned long long>(value));
    clickable(ui, text, kind);
}

// The vertices, triangles and step the event names.
void eventNumbers(Ui& ui, const Event& e) {
    ImGui::TextDisabled("step");
    ImGui::SameLine(0, 3 * ui.scale);
    clickable(ui, std::to_string(e.step + 1).c_str(), 's');
    const Fingers& f = e.before;
    number(ui, "L", f.left, 'v');
    number(ui, "R", f.right, 'v');
    number(ui, "NL", f.nextLeft, 'v');
    number(ui, "NR", f.nextRight, 'v');
    bool any = false;  // the second line starts with the action's name
    auto item = [&](const char* label, uint64_t value, char kind) {
        if (value == kNone) return;
        if (!any) ImGui::TextDisabled("%s", actionName(e.action));
        any = true;
        number(ui, label, value, kind);
    };
    // The subject fields share storage (flood/machine/events.h): only the event's own
    // action's are shown.
    auto subject = [&](const char* label, Index value, Field f) {
        if (usesField(e.action, f)) item(label, value, 'v');
    };
    subject("sag", e.sag, Field::sag);
    subject("to", e.bridgeTo, Field::bridgeTo);
    subject("top", e.top, Field::top);
    subject("jump", e.jumpTarget, Field::jumpTarget);
    item("bottom", e.bottom, 'v');
    subject("culprit", e.culprit, Field::culprit);
    subject("and", e.culprit2, Field::culprit2);
    if (e.triangleCount) {
        item("triangles", e.firstTriangle, 't');
        if (e.triangleCount > 1) item("to", e.firstTriangle + e.triangleCount - 1, 't');
    }
}

}  // namespace

void drawDecisionTree(Ui& ui, ImVec2 size, const DecisionPath& path) {
    drawTree(ui, size, path, true);
}

void drawDecision(Ui& ui) {
    Model& m = ui.model;
    const Rect& col = ui.layout.left;
    beginTiled("Decision", {col.x, col.y + col.h * 0.38, col.w, col.h * 0.27});
    const Event* e = m.currentEvent();
    const DecisionPath path = e ? decisionPath(*e) : DecisionPath{};
    if (ImGui::SmallButton("Tree...")) ui.showDecisionTree = true;
    ImGui::SameLine();
    if (ImGui::SmallButton("Predicates...")) ui.showPredicates = true;
    ImGui::SameLine();
    if (ImGui::SmallButton("To-do list...")) ui.showTodo = true;
    // The tree first, in at least half of the panel (a thumbnail: hover for labels, click or
    // "Tree..." for the large one); the sentence and the numbers below it.
    ImVec2 avail = ImGui::GetContentRegionAvail();
    avail.y = std::max(avail.y * 0.5f, 7 * decisionTree().rows * ui.scale);
    drawTree(ui, avail, path, false);
    if (!e) {
        ImGui::TextDisabled("no event yet: step forward to see the decision tree at work");
    } else {
        ImGui::PushTextWrapPos(0);
        // What happened and why, in one sentence of the flood metaphor (flood/teach/narrate.h).
        ImGui::TextUnformatted(narrate(m.polygon(), *e).c_str());
        if (e->action == Action::Forbidden)
            ImGui::TextColored(toImVec4(palette::kCulprit), "%s", forbiddenText(e->reason));
        ImGui::PopTextWrapPos();
        if (e->sagTests) ImGui::TextDisabled("%u inside() tests against the sag list", e->sagTests);
        eventNumbers(ui, *e);
    }
    ImGui::End();

    if (!ui.showDecisionTree) return;
    if (!beginFloating(ui, "Decision tree (Fig. 9)", &ui.showDecisionTree, 680, 460, 0, 40)) return;
    ImGui::TextDisabled(
        "%s", e ? (std::string("step ") + std::to_string(m.step()) + ": " + actionName(e->action) +
                   (e->side == Side::Left ? ", C is Left" : ", C is Right"))
                      .c_str()
                : "step 0: nothing decided yet");
    ImGui::SameLine();
    ImGui::TextDisabled(
        "  edges: green yes, blue no; bars: share of the run's events through a box; "
        "hover: what it tests; click a leaf: seek");
    drawTree(ui, ImGui::GetContentRegionAvail(), path, true);
    ImGui::End();
}

}  // namespace flood::view
