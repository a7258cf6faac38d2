// An animated GIF written frame by frame with Debian's giflib: one global palette (so colours
// do not flicker between frames), the same delay for every frame, looping forever.
#pragma once
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "quantize.h"

struct GifFileType;

namespace flood::view {

class GifWriter {
public:
    // Writes the header to `out`: `palette` (1..256 colours), `delay` in hundredths of a second.
    GifWriter(std::ostream& out, int width, int height, const std::vector<Rgb>& palette, int delay);
    ~GifWriter();  // closes the file if finish() was not called
    GifWriter(const GifWriter&) = delete;
    GifWriter& operator=(const GifWriter&) = delete;

    // One frame of width x height palette indices, top row first.
    bool addFrame(const std::vector<uint8_t>& indices);
    bool finish();                                       // the trailer; false if anything failed
    const std::string& error() const { return error_; }  // giflib's reason of the first failure

private:
    bool check(int rc);
    GifFileType* gif_ = nullptr;
    int width_, height_, delay_;
    std::string error_;
};

}  // namespace flood::view
