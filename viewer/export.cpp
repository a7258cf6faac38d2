#include "export.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "flood/teach/narrate.h"
#include "presenter.h"

namespace flood::view {

namespace {

// A step number: digits only, at most 2^32 - 2 (kNone means "the end").
bool parseStep(const std::string& s, uint32_t& out) {
    if (s.empty() || s.size() > 10 || s.find_first_not_of("0123456789") != std::string::npos)
        return false;
    unsigned long long v = std::strtoull(s.c_str(), nullptr, 10);
    if (v >= kNone) return false;
    out = uint32_t(v);
    return true;
}

}  // namespace

namespace {

bool isDirectory(const std::string& dir) {
    struct stat st;
    return !dir.empty() && ::stat(dir.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? v : "";
}

// XDG_PICTURES_DIR="$HOME/Pictures" in user-dirs.dirs (the format xdg-user-dirs-update
// writes: one variable a line, quoted, $HOME the only expansion); "" when not there.
std::string userDirsPictures(const std::string& home) {
    std::string config = env("XDG_CONFIG_HOME");
    if (config.empty() && !home.empty()) config = home + "/.config";
    if (config.empty()) return "";
    std::ifstream in(config + "/user-dirs.dirs");
    const std::string key = "XDG_PICTURES_DIR=";
    for (std::string line; std::getline(in, line);) {
        if (line.compare(0, key.size(), key) != 0) continue;
        std::string v = line.substr(key.size());
        if (v.size() >= 2 && v.front() == '"' && v.back() == '"') v = v.substr(1, v.size() - 2);
        if (v.compare(0, 5, "$HOME") == 0) v = home + v.substr(5);
        return v;
    }
    return "";
}

}  // namespace

std::string exportBaseName(const Model& m) {
    std::string base = m.path().empty() ? "flood" : m.path();
    const size_t slash = base.find_last_of('/');
    if (slash != std::string::npos) base = base.substr(slash + 1);
    const size_t dot = base.find_last_of('.');
    if (dot != std::string::npos && dot > 0) base.resize(dot);
    return base.empty() ? "flood" : base;
}

std::string stepPngName(const Model& m) {
    return exportBaseName(m) + "-step" + std::to_string(m.step()) + ".png";
}

std::string pictureFolder(const std::string& lastExportDir) {
    if (isDirectory(lastExportDir)) return lastExportDir;
    const std::string home = env("HOME");
    for (const std::string& dir :
         {env("XDG_PICTURES_DIR"), userDirsPictures(home), home.empty() ? "" : home + "/Pictures"})
        // xdg-user-dir answers $HOME for a Pictures folder set to it: that is the fallback too.
        if (isDirectory(dir)) return dir;
    return isDirectory(home) ? home : ".";
}

std::string folderOf(const std::string& file) {
    const size_t slash = file.find_last_of('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : file.substr(0, slash);
}

bool parseStepArg(const std::string& text, uint32_t& step) {
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return false;
    uint64_t v = 0;  // saturates at UINT32_MAX: no digit string overflows it
    for (char c : text) v = std::min<uint64_t>(v * 10 + uint64_t(c - '0'), UINT32_MAX);
    step = uint32_t(v);
    return true;
}

bool parseStepRange(const std::string& text, uint32_t& first, uint32_t& last, std::string* error) {
    size_t colon = text.find(':');
    std::string a = colon == std::string::npos ? text : text.substr(0, colon);
    std::string b = colon == std::string::npos ? "" : text.substr(colon + 1);
    uint32_t f = 0, l = kNone;
    bool ok = colon != std::string::npos && (a.empty() || parseStep(a, f)) &&
              (b.empty() || parseStep(b, l));
    if (ok && f > l) {
        if (error) *error = "--steps " + text + ": the first step is after the last";
        return false;
    }
    if (!ok) {
        if (error)
            *error =
                "--steps wants A:B (step numbers, A: or :B for an open end), got '" + text + "'";
        return false;
    }
    first = f, last = l;
    return true;
}

std::vector<uint32_t> exportSteps(uint32_t first, uint32_t last, uint32_t every, uint32_t steps) {
    last = std::min(last, steps);
    every = std::max<uint32_t>(every, 1);
    std::vector<uint32_t> out;
    if (first > last) return out;
    for (uint64_t s = first; s <= last; s += every) out.push_back(uint32_t(s));
    if (out.back() != last) out.push_back(last);
    return out;
}

Camera exportCamera(const Camera& canvas, const Rect& area) {
    // fitBox keeps 6% on each side: hand it the canvas's visible box shrunk by that much, so
    // the result is the canvas's scale times min(area.w / canvas.w, area.h / canvas.h).
    const Rect& v = canvas.viewport();
    double w = v.w > 0 ? v.w / canvas.scale() : 1, h = v.h > 0 ? v.h / canvas.scale() : 1;
    const double usable = 0.88;
    Camera cam;
    Point c = canvas.center();
    cam.fitBox(c.x - w * usable / 2, c.y - h * usable / 2, c.x + w * usable / 2,
               c.y + h * usable / 2, area);
    cam.centerOn(c);  // exactly the canvas's centre, not a rounded midpoint
    return cam;
}

// The presenter's caption (presenter.h) as one line: an export shows no step count.
CaptionLine captionOf(const Model& model, uint32_t step) {
    const Caption c = captionAt(model, step);
    CaptionLine line;
    line.head = "Step " + std::to_string(step);
    if (c.hasAction) line.head += std::string("  ") + actionName(c.action);
    line.headColor = palette::action(c.hasAction ? c.action : Action::Start);
    line.text = c.sentence;
    return line;
}

std::string sequenceFile(const std::string& dir, size_t frame, size_t count) {
    int digits = 4;
    for (size_t n = 10000; n < count; n *= 10) ++digits;
    char name[32];
    std::snprintf(name, sizeof name, "frame-%0*zu.png", digits, frame);
    return dir.empty() || dir.back() == '/' ? dir + name : dir + "/" + name;
}

bool makeDirectory(const std::string& dir, std::string* error) {
    struct stat st;
    if (::stat(dir.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) return true;
        if (error) *error = "error: " + dir + ": cannot write: " + std::strerror(ENOTDIR);
        return false;
    }
    if (::mkdir(dir.c_str(), 0777) == 0) return true;
    if (error) *error = "error: " + dir + ": cannot write: " + std::strerror(errno);
    return false;
}

}  // namespace flood::view
