// The step's labels on screen: where each of buildScene's labels (scene.h) goes so that none
// covers another, none covers a labelled point and none goes under what floats over the
// canvas (label_layout.h). The sentence's names first, then the fingers, the ghosts of the
// fingers before the step and the gorges; a ghost or a gorge that finds no free place is left
// out, a name or a finger never. No ImGui, no GL: the canvas measures the text and draws,
// tests/viewer/scene_labels_test.cpp checks every step of the gallery.
#pragma once
#include <functional>
#include <vector>

#include "label_layout.h"
#include "scene.h"

namespace flood::view {

struct ShownLabel {
    const Scene::Label* label = nullptr;  // into the list placed
    PlacedLabel at;
};

// More gorge labels than this on screen fold away (hundreds of pending gorges are a smear).
constexpr size_t kMaxGorgeLabels = 40;

// `size`: a label's text size in pixels (the canvas's font for its kind), padding included.
// `scale`: the UI scale (gaps and reach). Labels whose point is outside `area` are left out;
// so are Number labels (the canvas draws triangle numbers itself).
std::vector<ShownLabel> placeSceneLabels(const std::vector<Scene::Label>& labels,
                                         const Camera& camera, const Rect& area,
                                         const std::vector<Rect>& obstacles,
                                         const std::function<Vec2(const Scene::Label&)>& size,
                                         double scale);

}  // namespace flood::view
