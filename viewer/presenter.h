// Presenter mode without a window: the UI scale (the monitor's content scale times the
// user's Ctrl +/- zoom), the settings remembered between runs (theme, zoom), the presenter
// layout (canvas and caption only) and the caption's text. panel_caption.cpp draws it;
// tests/viewer/presenter_test.cpp drives it.
#pragma once
#include <cstdint>
#include <string>

#include "model.h"
#include "palette.h"

namespace flood::view {

// The scale every size of the UI is multiplied by. Zoom moves through fixed steps (as a
// browser's Ctrl +/- does) so that a few presses reach any useful size and Ctrl+0 returns.
class UiScale {
public:
    static constexpr int kMinZoomStep = -5, kMaxZoomStep = 7;  // 50% .. 300%
    // The monitor's scale (glfwGetWindowContentScale) or --scale; not a positive finite
    // number: 1. False when nothing changed.
    bool setContentScale(float scale);
    float contentScale() const { return content_; }
    bool zoomIn() { return setZoomStep(step_ + 1); }   // false at the largest step
    bool zoomOut() { return setZoomStep(step_ - 1); }  // false at the smallest
    bool resetZoom() { return setZoomStep(0); }        // false when already at 100%
    bool setZoomStep(int step);                        // clamped; false when unchanged
    int zoomStep() const { return step_; }
    float zoom() const;  // 1 at step 0
    float value() const { return content_ * zoom(); }
    // The font size for this scale, whole pixels so glyphs are rasterised sharp at it.
    float fontPixels(float basePixels = 13) const;
    // Changes with every change of value(): fonts and style are rebuilt when it moves.
    uint64_t generation() const { return generation_; }

private:
    float content_ = 1;
    int step_ = 0;
    uint64_t generation_ = 0;
};

// What the viewer remembers between runs, beside the recent files.
struct ViewerSettings {
    Theme theme = Theme::Dark;
    int zoomStep = 0;
};
// "theme light" / "zoom 2" lines. A missing file gives the defaults; a line it does not
// understand is skipped (a newer viewer's setting must not break an older one).
ViewerSettings loadSettings(const std::string& file);
bool saveSettings(const std::string& file, const ViewerSettings& settings);

// Presenter view: the canvas over the whole width, the caption below it, `captionHeight`
// tall (what it needed last frame) but never more than half the window.
Layout presenterLayout(double width, double height, double captionHeight);

// The caption of a step: the presenter view shows it, exports draw it under the canvas.
struct Caption {
    std::string heading;     // "Step 12 of 40"
    bool hasAction = false;  // false at step 0 (no event yet)
    Action action = Action::Start;
    std::string sentence;  // core/teach/narrate's sentence, or what step 0 shows
};
Caption captionAt(const Model& model, uint32_t step);
Caption buildCaption(const Model& model);  // at the current step

}  // namespace flood::view
