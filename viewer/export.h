// Exports for slides, the part without GL: what to export (one settings struct shared by the
// command line and the Export panel), which steps become frames, the view an export shows,
// the caption of a step, and the files of a numbered PNG sequence. Rendering is in
// export_job.cpp, GIF encoding in gif_writer.cpp, the colour palette in quantize.cpp.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "model.h"
#include "palette.h"
#include "scene.h"  // CaptionLine

namespace flood::view {

struct ExportSettings {
    int width = 1280, height = 800;  // pixels of every picture
    // The step range, inclusive; kNone as last: the flood's last step.
    uint32_t first = 0, last = kNone;
    uint32_t every = 1;    // one frame every K steps (the last step of the range always ends it)
    double fps = 10;       // GIF frames per second
    bool caption = false;  // a line under the canvas: step, action, narration
    std::string png;       // one canvas-only PNG of the current step
    std::string svg;       // one SVG of the current step
    std::string gif;       // an animated GIF of the range
    std::string pngDir;    // a numbered PNG sequence of the range, in this directory
    bool animated() const { return !gif.empty() || !pngDir.empty(); }
};

// GIF delays are in hundredths of a second, and browsers slow down delays under 2.
constexpr double kMaxFps = 50, kMinFps = 0.1;

// --step N: digits only; a number past the last step, however large, is the last
// (UINT32_MAX, which seek() clamps). Worked out in fixed-width types: with `long` (32 bits on
// Windows and wasm32) every N made the viewer jump to the end.
bool parseStepArg(const std::string& text, uint32_t& step);

// Parses "A:B" ("A:" to the end, ":B" from 0) into `first`/`last`; false with a reason.
bool parseStepRange(const std::string& text, uint32_t& first, uint32_t& last, std::string* error);

// The steps shown, in order: first, first + every, ... and `last` itself (clamped to the
// flood's steps) when the stride does not land on it, so an animation ends on its last state.
// Empty when the range is empty (first > last).
std::vector<uint32_t> exportSteps(uint32_t first, uint32_t last, uint32_t every, uint32_t steps);

// What the canvas shows, enlarged (or shrunk) to `area`: the same centre, the canvas's scale
// times the factor by which its viewport fits into `area`, so nothing visible is cut off.
Camera exportCamera(const Camera& canvas, const Rect& area);

// The caption of the current step: "Step N  Action" (in the action's colour) and the
// narration sentence (core/teach/narrate); at step 0, the polygon before the first event.
CaptionLine captionOf(const Model& model, uint32_t step);

// The files of a PNG sequence: DIR/frame-0000.png, ... wide enough for `count` frames.
std::string sequenceFile(const std::string& dir, size_t frame, size_t count);

// What an export of the open polygon is called: its file name without folder or extension
// ("polygons/paper-figure-7.json" -> "paper-figure-7"), "flood" with none open.
std::string exportBaseName(const Model& model);

// Save PNG's file: "<exportBaseName>-step<N>.png" at the current step.
std::string stepPngName(const Model& model);

// Where Save PNG writes: `lastExportDir` (the folder of the last export written) when it is a
// directory; else the user's Pictures folder ($XDG_PICTURES_DIR, else XDG_PICTURES_DIR in
// $XDG_CONFIG_HOME/user-dirs.dirs, ~/.config/user-dirs.dirs, as `xdg-user-dir PICTURES` reads
// it, else ~/Pictures), when it is a directory; else $HOME; else the working directory (".").
std::string pictureFolder(const std::string& lastExportDir);

// The folder a written file is in ("." for a bare name), for lastExportDir.
std::string folderOf(const std::string& file);

// Creates `dir` (one level) unless it is a directory already; false with the system's reason.
bool makeDirectory(const std::string& dir, std::string* error);

}  // namespace flood::view
