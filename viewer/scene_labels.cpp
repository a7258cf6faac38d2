#include "scene_labels.h"

#include <algorithm>

namespace flood::view {

std::vector<ShownLabel> placeSceneLabels(const std::vector<Scene::Label>& labels,
                                         const Camera& camera, const Rect& area,
                                         const std::vector<Rect>& obstacles,
                                         const std::function<Vec2(const Scene::Label&)>& size,
                                         double scale) {
    using Kind = Scene::LabelKind;
    size_t gorges = 0;
    for (const Scene::Label& l : labels)
        gorges += l.kind == Kind::Gorge && area.contains(camera.toScreen(l.p));
    std::vector<const Scene::Label*> order;
    for (Kind k : {Kind::Named, Kind::Finger, Kind::Ghost, Kind::Gorge})
        for (const Scene::Label& l : labels)
            if (l.kind == k && area.contains(camera.toScreen(l.p)) &&
                (k != Kind::Gorge || gorges <= kMaxGorgeLabels))
                order.push_back(&l);
    std::vector<LabelRequest> requests;
    for (const Scene::Label* l : order) {
        const Vec2 wh = size(*l);
        // The side the scene's offset points to (NL above left, R below right), beside the
        // point whatever the text's size.
        const double d = 7 * scale;
        requests.push_back({camera.toScreen(l->p),
                            wh.x,
                            wh.y,
                            true,
                            {l->dx < 0 ? -d - wh.x : d, l->dy < 0 ? -d - wh.y : d}});
    }
    const std::vector<PlacedLabel> placed =
        placeLabels(requests, area, obstacles, 3 * scale, 14 * scale, 260 * scale);
    std::vector<ShownLabel> shown;
    std::vector<Rect> kept;  // a label dropped leaves its place free for the next
    for (size_t i = 0; i < order.size(); ++i) {
        const bool optional = order[i]->kind == Kind::Ghost || order[i]->kind == Kind::Gorge;
        const bool covers = std::any_of(kept.begin(), kept.end(),
                                        [&](const Rect& r) { return overlap(r, placed[i].box); });
        if (optional && (placed[i].overlaps || covers)) continue;
        kept.push_back(placed[i].box);
        shown.push_back({order[i], placed[i]});
    }
    return shown;
}

}  // namespace flood::view
