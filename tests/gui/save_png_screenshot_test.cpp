// GUI test (issue 27 §4): Save PNG (key P, as the toolbar's button) writes the canvas alone,
// at the canvas's size and not the window's, named after the polygon and the step, in the
// user's Pictures folder, else home; the run says where. And --screenshot follows the theme
// the viewer saved, unless --theme is given. Each run gets a home and a config folder of its
// own. Exit 77 (skipped) without a display, except in CI.
#include <stb_image.h>  // implementation lives in Debian's libstb

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "gui_test_display.h"
#include "model.h"
#include "viewer_run.h"

using namespace flood::view;
using namespace flood::view::testing;
namespace fs = std::filesystem;

namespace {

// flood-viewer on Fig. 7 at step 23 with HOME=`home`, no XDG_PICTURES_DIR, XDG_CONFIG_HOME=
// `config`; the layout it prints and its whole output.
ViewerRun viewer(const fs::path& home, const fs::path& config, const std::string& args) {
    const std::string input = std::string(FLOOD_SOURCE_DIR) + "/polygons/paper-figure-7.json";
    const std::string cmd = "env -u XDG_PICTURES_DIR HOME='" + home.string() +
                            "' XDG_CONFIG_HOME='" + config.string() + "' '" + FLOOD_VIEWER + "' '" +
                            input + "' --step 23 --print-layout " + args + " 2>&1";
    return runViewer(cmd);
}

// The PNG's size; false when it cannot be read.
bool pngSize(const fs::path& png, int& w, int& h) {
    int channels = 0;
    return stbi_info(png.string().c_str(), &w, &h, &channels) == 1;
}

// The luminance of the pixel at (x, y) of a PNG; -1 when unreadable.
double luminanceAt(const fs::path& png, int x, int y) {
    int w = 0, h = 0, channels = 0;
    unsigned char* px = stbi_load(png.string().c_str(), &w, &h, &channels, 4);
    if (!px || x < 0 || y < 0 || x >= w || y >= h) return -1;
    const unsigned char* p = px + (size_t(y) * w + x) * 4;
    const double l = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    stbi_image_free(px);
    return l;
}

int savePng(const fs::path& root, int W, int H) {
    int failures = 0;
    const fs::path home = root / ("home-" + std::to_string(W)), config = home / ".config";
    fs::create_directories(config);
    const std::string size = " --size " + std::to_string(W) + "x" + std::to_string(H);
    const std::string shot = " --screenshot '" + (root / "window.png").string() + "'" + size;
    fs::remove("flood-step23.png"), fs::remove("paper-figure-7-step23.png");
    // No Pictures folder: home.
    ViewerRun a = viewer(home, config, "--press p" + shot);
    const fs::path inHome = home / "paper-figure-7-step23.png";
    if (a.exitCode != 0) failures += failWith("flood-viewer --press p did not exit 0");
    if (!fs::exists(inHome)) return failures + failWith(inHome.string() + " not written");
    if (a.output.find("wrote " + inHome.string()) == std::string::npos)
        failures += failWith("the run does not say where the PNG went");
    const Rect canvas = a.layout["canvas"];
    int w = 0, h = 0;
    if (!pngSize(inHome, w, h)) return failures + failWith(inHome.string() + " is no PNG");
    std::printf("Save PNG at %dx%d: %d x %d, the canvas %.0f x %.0f\n", W, H, w, h, canvas.w,
                canvas.h);
    if (w != int(canvas.w + 0.5) || h != int(canvas.h + 0.5))
        failures += failWith("the PNG is " + std::to_string(w) + "x" + std::to_string(h) +
                             ", not the canvas's size");
    if (w == W || h == H) failures += failWith("the PNG has the window's size");
    // Nothing in the working directory, as the old flood-stepN.png was.
    if (fs::exists("flood-step23.png") || fs::exists("paper-figure-7-step23.png"))
        failures += failWith("a PNG in the working directory");
    // ~/Pictures once there is one.
    fs::create_directories(home / "Pictures");
    ViewerRun b = viewer(home, config, "--press p" + shot);
    if (b.exitCode != 0 || !fs::exists(home / "Pictures" / "paper-figure-7-step23.png"))
        failures += failWith("Save PNG did not write into ~/Pictures");
    return failures;
}

int theme(const fs::path& root) {
    int failures = 0;
    const fs::path home = root / "home-theme", config = home / ".config";
    fs::create_directories(config / "flood-viewer");
    std::ofstream(config / "flood-viewer" / "settings.txt") << "theme light\nzoom 0\n";
    const fs::path png = root / "theme.png";
    const std::string shot = " --screenshot '" + png.string() + "' --size 1280x800";
    // A corner of the canvas, clear of the polygon and the boxes over it.
    ViewerRun light = viewer(home, config, shot);
    const Rect c = light.layout["canvas"];
    const int x = int(c.x + c.w - 4), y = int(c.y + c.h - 4);
    const double saved = luminanceAt(png, x, y);
    ViewerRun dark = viewer(home, config, "--theme dark" + shot);
    const double given = luminanceAt(png, x, y);
    std::printf("canvas corner: %.0f with the saved light theme, %.0f with --theme dark\n", saved,
                given);
    if (light.exitCode != 0 || dark.exitCode != 0)
        failures += failWith("flood-viewer did not exit 0");
    if (saved < 180) failures += failWith("--screenshot does not follow the saved light theme");
    if (given < 0 || given > 80) failures += failWith("--theme dark does not win over it");
    // The screenshot leaves the settings as they were.
    std::ifstream in(config / "flood-viewer" / "settings.txt");
    std::string first;
    std::getline(in, first);
    if (first != "theme light") failures += failWith("--screenshot rewrote the settings");
    return failures;
}

}  // namespace

int main() {
    if (int skip = displayOrSkip()) return skip;
    const fs::path root =
        fs::path(FLOOD_WORK_DIR) / ("save-png-test-" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root);
    const int failures = savePng(root, 1280, 800) + savePng(root, 1920, 1080) + theme(root);
    if (failures) return 1;
    fs::remove_all(root);
    std::printf(
        "ok: Save PNG writes the canvas alone at its size, named after the polygon and step, in "
        "~/Pictures or home; --screenshot follows the saved theme unless --theme\n");
    return 0;
}
