// An export in progress: the canvas alone rendered offscreen (offscreen.h) at the export's
// size, through paintCanvas with a camera that shows what the canvas shows, for the current
// step (PNG, SVG) or a range of steps (a numbered PNG sequence, an animated GIF: rendered once
// to build the palette, once more to encode). The Export panel advances it a slice per frame
// so the window stays live; the command line runs it to the end. Every file is written
// atomically (flood/io/output.h): a failure leaves no half-written file and says why.
#pragma once
#include <memory>
#include <string>

#include "export.h"
#include "flood/geometry/status.h"
#include "panels.h"

namespace flood::view {

class ExportJob {
public:
    // Takes the current step and canvas view; needs the GL context and an ImGui frame done.
    ExportJob(Ui& ui, ExportSettings settings);
    ~ExportJob();  // restores the step the export started at
    ExportJob(const ExportJob&) = delete;
    ExportJob& operator=(const ExportJob&) = delete;

    // Works for about `seconds` (0: to the end). False once finished, well or not.
    bool advance(double seconds);
    void cancel();                       // stops at the next frame; files already complete are kept
    Status status() const;               // Ok, WriteFailed, or Internal (the GL refused)
    const std::string& message() const;  // "wrote ..." or the first failure
    double progress() const;             // 0..1

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace flood::view
