#include "presenter.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "flood/teach/narrate.h"

namespace flood::view {

namespace {
// From 50% to 300%; index 5 is 100%.
constexpr float kZooms[] = {0.5f,  0.67f, 0.75f, 0.8f, 0.9f, 1.f, 1.1f,
                            1.25f, 1.5f,  1.75f, 2.f,  2.5f, 3.f};
constexpr int kOne = 5;
static_assert(kOne + UiScale::kMinZoomStep == 0 &&
              kOne + UiScale::kMaxZoomStep + 1 == int(sizeof kZooms / sizeof kZooms[0]));
}  // namespace

bool UiScale::setContentScale(float scale) {
    if (!(scale > 0) || !std::isfinite(scale)) scale = 1;
    if (scale == content_) return false;
    content_ = scale;
    ++generation_;
    return true;
}

bool UiScale::setZoomStep(int step) {
    step = std::clamp(step, kMinZoomStep, kMaxZoomStep);
    if (step == step_) return false;
    step_ = step;
    ++generation_;
    return true;
}

float UiScale::zoom() const { return kZooms[kOne + step_]; }

float UiScale::fontPixels(float basePixels) const {
    return std::max(6.f, std::round(basePixels * value()));
}

ViewerSettings loadSettings(const std::string& file) {
    ViewerSettings s;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string key, value;
        if (!(words >> key >> value)) continue;
        if (key == "theme") {
            palette::parseTheme(value.c_str(), s.theme);
        } else if (key == "zoom") {
            char* end = nullptr;
            long z = std::strtol(value.c_str(), &end, 10);
            if (*end == 0)
                s.zoomStep = int(std::clamp<long>(z, UiScale::kMinZoomStep, UiScale::kMaxZoomStep));
        }
    }
    return s;
}

bool saveSettings(const std::string& file, const ViewerSettings& s) {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(file).parent_path(), ec);
    std::ofstream out(file);
    out << "theme " << palette::themeName(s.theme) << "\nzoom " << s.zoomStep << "\n";
    return bool(out.flush());
}

Layout presenterLayout(double width, double height, double captionHeight) {
    double caption = std::clamp(captionHeight, 0.0, height / 2);
    Layout l;
    l.canvas = {0, 0, std::max(1.0, width), std::max(1.0, height - caption)};
    l.bottom = {0, height - caption, width, caption};
    l.left = {0, 0, 0, height - caption};
    l.right = {width, 0, 0, height - caption};
    return l;
}

Caption buildCaption(const Model& m) { return captionAt(m, m.step()); }

Caption captionAt(const Model& m, uint32_t step) {
    Caption c;
    c.heading = "Step " + std::to_string(step) + " of " + std::to_string(m.steps());
    const auto& events = m.trace().events;
    if (step > 0 && step <= events.size()) {
        const Event& e = events[step - 1];
        c.hasAction = true;
        c.action = e.action;
        c.sentence = narrate(m.polygon(), e);
    } else if (m.polygon().vertices.empty()) {
        c.sentence =
            m.inputDiagnostic().ok() ? "No polygon: open one." : m.inputDiagnostic().message;
    } else {
        c.sentence = "The polygon is dry: the water has not started to rise.";
    }
    return c;
}

}  // namespace flood::view
